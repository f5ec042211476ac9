"""`shape: prism` against closed forms: a rectangle is a box, a regular polygon's exact polar
moment (and the cylinder it tends to), an I-beam's handbook second moments, a hole as a
subtracted prism, an L-angle's centroid and product of inertia, and trimesh's integration of the
same solid as a triangle mesh; the frame of the outline; refusals."""

from __future__ import annotations

import json
import math
import time

import numpy as np
import pytest
import trimesh
from scipy.spatial.transform import Rotation

import rbi
from rbi.core.polygon import trapezoids
from tests.conftest import one_line_exit_2, run_rbi_inprocess


def prism(outline, start=(0, 0, 0), end=(0, 0, 1), **fields) -> dict:
    return (
        {"shape": "prism", "outline": [list(map(float, p)) for p in outline], "start": list(start)}
        | {"end": list(end)}
        | fields
    )


def body(*parts) -> rbi.Body:
    return rbi.load({"parts": list(parts)})


def rectangle(a, b, x0=0.0, y0=0.0):
    return [[x0, y0], [x0 + a, y0], [x0 + a, y0 + b], [x0, y0 + b]]


def test_rectangle_is_a_box_in_any_frame_and_winding():
    a, b, length, rho = 0.3, 0.12, 0.8, 2700.0
    start, end, x_axis = np.array([0.1, -0.2, 0.3]), np.array([0.5, 0.4, 0.9]), [1.0, -2.0, 0.5]
    z = (end - start) / np.linalg.norm(end - start)
    x = np.asarray(x_axis) - (np.asarray(x_axis) @ z) * z
    x /= np.linalg.norm(x)
    R = np.column_stack((x, np.cross(z, x), z))
    assert np.linalg.norm(end - start) == pytest.approx(length, rel=0.2)
    length = float(np.linalg.norm(end - start))
    outline = rectangle(a, b, -0.1, 0.05)[::-1]  # clockwise
    p = body(prism(outline, start, end, x_axis=x_axis, density=rho))
    center = start + R @ [-0.1 + a / 2, 0.05 + b / 2, length / 2]
    w, qx, qy, qz = np.roll(Rotation.from_matrix(R).as_quat(), 1)
    box = body(
        {"shape": "box", "density": rho, "center": center.tolist(), "size": [a, b, length]}
        | {"rotation": {"quaternion": [w, qx, qy, qz]}}
    )
    assert p.mass == pytest.approx(box.mass, rel=1e-14)
    np.testing.assert_allclose(p.center_of_mass, box.center_of_mass, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(
        p.inertia(), box.inertia(), rtol=1e-13, atol=1e-13 * np.abs(box.inertia()).max()
    )


@pytest.mark.parametrize("n", [5, 64, 720])
def test_regular_polygon_exact_and_towards_the_cylinder(n):
    r, length, mass = 0.05, 0.2, 3.0
    angles = 2 * np.pi * np.arange(n) / n
    outline = np.column_stack((r * np.cos(angles), r * np.sin(angles)))
    I = body(prism(outline, (0, 0, 0), (0, 0, length), mass=mass)).inertia()
    # a regular n-gon of circumradius R: I_z = m R² (1 + 2 cos²(π/n)) / 6, I_x = I_y = I_z/2 + m L²/12
    polar = mass * r * r * (1 + 2 * math.cos(math.pi / n) ** 2) / 6
    np.testing.assert_allclose(
        I, np.diag([polar / 2 + mass * length**2 / 12] * 2 + [polar]), rtol=1e-13, atol=1e-16
    )
    cylinder = body(
        {"shape": "cylinder", "mass": mass, "radius": r, "start": [0, 0, 0], "end": [0, 0, length]}
    )
    error = abs(I[2, 2] / cylinder.inertia()[2, 2] - 1)
    assert error < 2 * (math.pi / n) ** 2  # 1 - (1 + 2cos²)/3 = (2/3) sin²(π/n)


def i_beam(b, h, tf, tw):
    x, y = b / 2, h / 2
    return [[-x, -y], [x, -y], [x, -y + tf], [tw / 2, -y + tf], [tw / 2, y - tf], [x, y - tf], [x, y]] + [
        [-x, y],
        [-x, y - tf],
        [-tw / 2, y - tf],
        [-tw / 2, -y + tf],
        [-x, -y + tf],
    ]


def test_i_beam_second_moments_are_the_handbook_sums_of_rectangles():
    b, h, tf, tw, length, rho = 0.1, 0.2, 0.0085, 0.0056, 2.0, 7850.0  # an IPE 200, near enough
    hw = h - 2 * tf
    area = 2 * b * tf + hw * tw
    ix = b * h**3 / 12 - (b - tw) * hw**3 / 12  # about the strong axis (section x)
    iy = 2 * tf * b**3 / 12 + hw * tw**3 / 12
    beam = body(prism(i_beam(b, h, tf, tw), (0, 0, 0), (0, 0, length), density=rho))
    mass = rho * area * length
    assert beam.mass == pytest.approx(mass, rel=1e-14)
    np.testing.assert_allclose(beam.center_of_mass, [0, 0, length / 2], atol=1e-16)
    expected = np.diag(
        [mass * (ix / area + length**2 / 12), mass * (iy / area + length**2 / 12), mass * (ix + iy) / area]
    )
    np.testing.assert_allclose(beam.inertia(), expected, rtol=1e-13, atol=1e-13 * expected.max())


def test_a_hole_is_the_prism_less_the_holes_prism():
    outline, hole = rectangle(0.2, 0.1), [[0.03, 0.02], [0.08, 0.03], [0.05, 0.07]]
    ends = {"start": [0.1, 0.2, 0.3], "end": [0.1, 0.2, 0.35]}
    holed = body(prism(outline, holes=[hole], density=2700.0, **ends) | ends)
    less = body(prism(outline, density=2700.0) | ends, prism(hole, density=2700.0, subtract=True) | ends)
    assert holed.mass == pytest.approx(less.mass, rel=1e-14)
    np.testing.assert_allclose(holed.center_of_mass, less.center_of_mass, rtol=1e-14)
    np.testing.assert_allclose(
        holed.inertia(), less.inertia(), rtol=1e-12, atol=1e-12 * np.abs(less.inertia()).max()
    )


def l_angle(a, b, t):
    return [[0, 0], [a, 0], [a, t], [t, t], [t, b], [0, b]]


def test_l_angle_centroid_and_product_of_inertia():
    a, b, t, length, mass = 0.08, 0.05, 0.006, 0.5, 1.7
    # two rectangles: a × t along x, t × (b − t) up the y leg
    pieces = [(a * t, a / 2, t / 2), (t * (b - t), t / 2, t + (b - t) / 2)]
    area = sum(p[0] for p in pieces)
    cx, cy = (sum(p[0] * p[1] for p in pieces) / area, sum(p[0] * p[2] for p in pieces) / area)
    product = sum(
        p[0] * (p[1] - cx) * (p[2] - cy) for p in pieces
    )  # ∫x'y' dA (rectangles add none of their own)
    angle = body(prism(l_angle(a, b, t), (0, 0, 0), (0, 0, length), mass=mass))
    np.testing.assert_allclose(angle.center_of_mass, [cx, cy, length / 2], rtol=1e-14)
    assert angle.inertia()[0, 1] == pytest.approx(-mass * product / area, rel=1e-13)
    assert angle.inertia()[0, 1] > 0  # the legs lie in x, y > centroid: ∫x'y' < 0


def test_a_triangle_mesh_of_the_same_prism_agrees_to_1e_12():
    a, b, t, rho = 0.08, 0.05, 0.006, 2700.0
    start, end = np.array([0.2, -0.1, 0.4]), np.array([0.2, 0.4, 0.4])  # along body y: x is body x
    section = np.array(l_angle(a, b, t), dtype=float)
    R = np.column_stack(([1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]))  # x, z × x, z
    ring = lambda z: (np.column_stack((section, np.full(6, z))) @ R.T) + start  # noqa: E731
    vertices = np.vstack((ring(0.0), ring(float(np.linalg.norm(end - start)))))
    cap = [[3, 4, 5], [3, 5, 0], [3, 0, 1], [3, 1, 2]]  # a fan from the inner corner
    walls = [[k, (k + 1) % 6, 6 + (k + 1) % 6] for k in range(6)] + [
        [k, 6 + (k + 1) % 6, 6 + k] for k in range(6)
    ]
    faces = np.array([f[::-1] for f in cap] + [[6 + i for i in f] for f in cap] + walls)
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    mesh.fix_normals()
    assert mesh.is_watertight and mesh.is_winding_consistent
    mesh.density = rho
    beam = body(prism(section, start, end, density=rho))
    assert beam.mass == pytest.approx(mesh.mass, rel=1e-12)
    np.testing.assert_allclose(beam.center_of_mass, mesh.center_mass, rtol=1e-12)
    np.testing.assert_allclose(
        beam.inertia(), mesh.moment_inertia, rtol=1e-12, atol=1e-12 * np.abs(mesh.moment_inertia).max()
    )


def test_the_outline_frame():
    triangle = [[0, 0], [0.3, 0], [0, 0.6]]  # centroid (0.1, 0.2)
    along_x = body(prism(triangle, (0, 0, 0), (1, 0, 0), mass=1.0))  # default x: body y, y = z × x: body z
    np.testing.assert_allclose(along_x.center_of_mass, [0.5, 0.1, 0.2], atol=1e-15)
    along_z = body(prism(triangle, (0, 0, 0), (0, 0, 1), mass=1.0))  # x: body x, y: body y
    np.testing.assert_allclose(along_z.center_of_mass, [0.1, 0.2, 0.5], atol=1e-15)
    nearly_x = body(prism(triangle, (0, 0, 0), (3, 1, 0), mass=1.0))  # body x projected: (1, -3, 0)/√10
    x, z = np.array([1, -3, 0]) / np.sqrt(10), np.array([3, 1, 0]) / np.sqrt(10)
    np.testing.assert_allclose(
        nearly_x.center_of_mass, 0.1 * x + 0.2 * np.cross(z, x) + [1.5, 0.5, 0], atol=1e-15
    )
    slanted = body(prism(triangle, (0, 0, 0), (0, 0, 1), mass=1.0, x_axis=[0, 3, 7]))  # made perpendicular: y
    np.testing.assert_allclose(slanted.center_of_mass, [-0.2, 0.1, 0.5], atol=1e-15)


def test_trapezoids_cover_the_section_exactly():
    outline, holes = i_beam(0.1, 0.2, 0.01, 0.006), [[[0.01, 0.09], [0.04, 0.09], [0.04, 0.095]]]
    quads = trapezoids(outline, holes)
    x, y = quads[..., 0], quads[..., 1]
    area = 0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)).sum()
    assert area == pytest.approx(0.1 * 0.02 + 0.18 * 0.006 - 0.03 * 0.005 / 2, rel=1e-12)


def spec_line(**fields) -> str:
    part = prism([[0, 0], [1, 0], [1, 1], [0, 1]], mass=1.0) | {"name": "plate"} | fields
    return json.dumps({"parts": [part]})


@pytest.mark.parametrize(
    ("fields", "words"),
    [
        ({"outline": [[0, 0], [1, 1], [1, 0], [0, 1]]}, ["plate", "outline", "crosses itself"]),
        ({"holes": [[[2, 2], [3, 2], [3, 3]]]}, ["holes[0]", "outside the outline"]),
        (
            {"holes": [[[0.1, 0.1], [0.5, 0.1], [0.5, 0.5]], [[0.3, 0.2], [0.6, 0.2], [0.6, 0.6]]]},
            ["holes[1]", "holes[0]"],
        ),
        (
            {
                "holes": [
                    [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9]],
                    [[0.3, 0.3], [0.6, 0.3], [0.6, 0.6]],
                ]
            },
            ["holes[1]", "inside holes[0]"],
        ),
        ({"holes": [[[0, 0], [0.5, 0.1], [0.5, 0.5]]]}, ["holes[0]", "touches the outline"]),
        ({"outline": [[0, 0], [1, 0], [2, 0]]}, ["outline: encloses no area (its vertices are on one line"]),
        (
            {"outline": [[0, 0], [2, 0], [1, 0], [3, 0]]},
            ["outline: encloses no area"],
        ),  # not "crosses itself"
        ({"holes": [[[0.1, 0.5], [0.2, 0.5], [0.3, 0.5]]]}, ["holes[0]: encloses no area"]),
        ({"outline": [[0, 0], [1e200, 0], [0, 1e200]]}, ["outline", "numbers too large"]),
        ({"outline": [[0, 0], [1e-200, 0], [0, 1e-200]]}, ["outline", "encloses no area"]),
        ({"outline": [[0, 0], [1, 0], [1, 0], [0, 1]]}, ["outline", "repeated"]),
        ({"outline": [[0, 0], [1, 0]]}, ["outline", "at least 3 vertices"]),
        ({"outline": [[0, 0], [1, 0], [1, 1, 1]]}, ["outline[2]", "[x, y]"]),
        ({"x_axis": [0, 0, -1]}, ["x_axis", "along the extrusion"]),
        ({"x_axis": [0, 0, 0]}, ["x_axis: must not be the zero vector"]),
        ({"outline": [0, 0]}, ["outline[0]: must be a point [x, y] (got 0)"]),
        ({"outline": "abc"}, ["outline: must be a list of points [[x, y], ...] (got 'abc')"]),
        ({"holes": 5}, ["holes: must be a list of polygons [[[x, y], ...], ...] (got 5)"]),
        ({"holes": [5]}, ["holes[0]: must be a list of points [[x, y], ...] (got 5)"]),
        ({"end": [0, 0, 0]}, ["start, end"]),
    ],
)
def test_bad_prisms_are_refused_naming_part_and_field(write_spec, fields, words):
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(spec_line(**fields))), "parts[0] (plate)", *words)


def test_nan_and_huge_outlines_are_refused_in_bounded_time(write_spec):
    nan = write_spec(
        "parts: [{name: plate, shape: prism, mass: 1, outline: [[.nan, 0], [1, 0], [0, 1]],"
        " start: [0, 0, 0], end: [0, 0, 1]}]\n"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", nan), "outline[0][0]", "finite")
    n = 100_000
    angles = 2 * np.pi * np.arange(n) / n
    started = time.process_time()
    big = write_spec(
        spec_line(outline=np.column_stack((np.cos(angles), np.sin(angles))).tolist()), "big.json"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", big), "outline", "at most 4096 vertices (got 100000)")
    assert time.process_time() - started < 10
