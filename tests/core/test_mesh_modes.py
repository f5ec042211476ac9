"""Meshes as CAD and convex decomposition write them, and the inertia modes MuJoCo names
(exact, convex, shell) plus opt-in repair, against independent answers: closed forms of
boxes, thin plates and prisms, sympy integrals, and MuJoCo's compiled inertia."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.core.mesh import (
    MeshError,
    closed_mesh_check,
    convex_hull_mesh,
    mesh_defects,
    repair_mesh,
    weld_vertices,
)
from tests.mesh_builders import box_mesh, mesh_mass_properties, sphere_mesh, tetrahedron_mesh


def box_inertia(mass, size):
    a, b, c = size
    return mass / 12.0 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])


def shifted(inertia, mass, offset):
    """Parallel axis theorem: inertia about a point ``offset`` away from the centre of mass."""
    d = np.asarray(offset, float)
    return inertia + mass * (d @ d * np.eye(3) - np.outer(d, d))


def combined(pieces):
    """Mass, centre of mass and inertia about it of (mass, com, inertia about own com) pieces."""
    mass = sum(m for m, _, _ in pieces)
    com = sum(m * np.asarray(c, float) for m, c, _ in pieces) / mass
    inertia = sum(shifted(i, m, np.asarray(c, float) - com) for m, c, i in pieces)
    return mass, com, inertia


def joined(*meshes):
    vertices, faces, offset = [], [], 0
    for v, f in meshes:
        vertices.append(np.asarray(v, float))
        faces.append(np.asarray(f) + offset)
        offset += len(v)
    return weld_vertices(np.vstack(vertices), np.vstack(faces))


# --- several closed pieces in one file --------------------------------------------------------


@pytest.mark.parametrize(
    "second_center, shares",
    [
        ((1.5, 1.5, 0.5), "an edge"),
        ((1.5, 1.5, 1.5), "a vertex"),
        ((1.5, 0.5, 0.5), "a face"),
    ],
)
def test_two_cubes_touching_are_twice_the_cube(second_center, shares):
    vertices, faces = joined(box_mesh(center=(0.5, 0.5, 0.5)), box_mesh(center=second_center))
    assert len(vertices) == {"an edge": 14, "a vertex": 15, "a face": 12}[shares]
    assert closed_mesh_check(vertices, faces)[0] is None, shares
    props = mesh_mass_properties(vertices, faces, "exact", density=1.0)
    mass, com, inertia = combined(
        [
            (1.0, (0.5, 0.5, 0.5), box_inertia(1.0, (1, 1, 1))),
            (1.0, second_center, box_inertia(1.0, (1, 1, 1))),
        ]
    )
    assert props.volume == pytest.approx(2.0, rel=1e-15)
    assert props.properties.mass == pytest.approx(mass, rel=1e-15)
    np.testing.assert_allclose(props.properties.center_of_mass, com, rtol=1e-15)
    np.testing.assert_allclose(props.properties.inertia_about_com, inertia, rtol=1e-14, atol=1e-15)


def test_an_edge_used_four_times_balanced_is_counted_as_shared_not_as_a_defect():
    vertices, faces = joined(box_mesh(center=(0.5, 0.5, 0.5)), box_mesh(center=(1.5, 1.5, 0.5)))
    defects = mesh_defects(faces)
    assert (defects.boundary_edges, defects.overshared_edges, defects.misoriented_edges) == (0, 0, 0)
    assert defects.shared_edges == 1


def test_two_tetrahedra_on_one_edge_are_their_sum():
    v1, f1 = tetrahedron_mesh([[0, 0, 0], [0, 0, 1], [1, 0, 0], [0, 1, 0]])
    v2, f2 = tetrahedron_mesh([[0, 0, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0]])
    vertices, faces = joined((v1, f1), (v2, f2))
    props = mesh_mass_properties(vertices, faces, "exact", density=6.0)
    assert props.properties.mass == pytest.approx(2.0, rel=1e-15)
    np.testing.assert_allclose(props.properties.center_of_mass, [0, 0, 0.25], atol=1e-16)


def test_an_edge_whose_uses_do_not_balance_is_still_refused():
    # a cube plus one extra triangle hanging on an edge: three uses of that edge, two one way
    vertices, faces = box_mesh()
    vertices = np.vstack([vertices, [[-1.0, -1.0, 0.0]]])
    faces = np.vstack([faces, [[0, 1, 8]]])
    defects = mesh_defects(faces)
    assert (defects.overshared_edges, defects.boundary_edges) == (1, 2)
    assert closed_mesh_check(vertices, faces)[0].startswith("not closed: 2 boundary edges")
    # two cubes on one edge, one face beside that edge turned over: four uses, three one way
    vertices, faces = joined(box_mesh(center=(0.5, 0.5, 0.5)), box_mesh(center=(1.5, 1.5, 0.5)))
    shared = {tuple(np.flatnonzero(np.all(vertices == p, axis=1))) for p in ([1, 1, 0], [1, 1, 1])}
    beside = [i for i, f in enumerate(faces) if {int(a) for (a,) in shared} <= set(f.tolist())]
    faces = faces.copy()
    faces[beside[0]] = faces[beside[0], ::-1]
    assert mesh_defects(faces).overshared_edges == 1
    problem = closed_mesh_check(vertices, faces)[0]
    assert "used by more than two triangles, not as many each way" in problem


def test_a_hollow_box_is_a_solid_with_a_cavity():
    outer, outer_faces = box_mesh((4, 4, 4))
    inner, inner_faces = box_mesh((2, 2, 2))
    vertices, faces = joined((outer, outer_faces), (inner, inner_faces[:, ::-1]))
    props = mesh_mass_properties(vertices, faces, "exact", density=1.0)
    assert props.volume == pytest.approx(56.0, rel=1e-15)
    np.testing.assert_allclose(
        props.properties.inertia_about_com,
        box_inertia(64, (4, 4, 4)) - box_inertia(8, (2, 2, 2)),
        rtol=1e-14,
        atol=1e-13,
    )


def test_a_piece_wound_inside_out_beside_a_good_one_is_refused():
    # total volume positive (8 - 1), but the small cube is no cavity: it lies outside the big one
    vertices, faces = joined(box_mesh((2, 2, 2)), (box_mesh(center=(5, 0, 0))[0], box_mesh()[1][:, ::-1]))
    problem = closed_mesh_check(vertices, faces)[0]
    assert problem is not None and "inside out" in problem


def test_overlapping_pieces_count_their_shared_space_twice_with_a_note():
    # as MuJoCo sums them: two 2-cubes overlapping by half are 16, not the union's 12
    vertices, faces = joined(box_mesh((2, 2, 2)), box_mesh((2, 2, 2), center=(1, 0, 0)))
    props = mesh_mass_properties(vertices, faces, "exact", density=1.0)
    assert props.volume == pytest.approx(16.0, rel=1e-15)
    assert len(props.notes) == 1 and "overlap" in props.notes[0]
    assert mesh_mass_properties(*box_mesh(), "exact", density=1.0).notes == ()


# --- welding ----------------------------------------------------------------------------------


def test_corners_one_ulp_apart_across_a_grid_boundary_are_one_vertex():
    # the old weld rounded positions to a grid of 1e-9 of the diagonal: put the L's inner
    # corner (not an extreme, so the diagonal stays put) on a half-way point of that grid and
    # give every other copy of it the next float up
    diagonal = float(np.linalg.norm([2.0, 2.0, 0.5]))
    step = 1e-9 * diagonal
    x = (round(0.7 / step) + 0.5) * step - 8 * np.spacing(0.7)
    while np.round(x / step) == np.round(np.nextafter(x, 2.0) / step):
        x = np.nextafter(x, 2.0)
    vertices, faces = extruded([(0, 0), (2, 0), (2, x), (x, x), (x, 2), (0, 2)], 0.5)
    soup = vertices[faces].reshape(-1, 3)
    copies = np.flatnonzero(soup[:, 0] == x)
    soup[copies[::2], 0] = np.nextafter(x, 2.0)
    welded, welded_faces = weld_vertices(soup, np.arange(len(soup)).reshape(-1, 3))
    assert len(welded) == 12
    assert closed_mesh_check(welded, welded_faces)[0] is None
    assert mesh_mass_properties(welded, welded_faces, density=1.0).volume == pytest.approx(
        0.5 * (4 - (2 - x) ** 2), rel=1e-12
    )


def test_welding_merges_chains_within_tolerance_but_not_distinct_corners():
    vertices = np.array([[0, 0, 0], [1e-12, 0, 0], [1, 0, 0], [1, 1e-3, 0], [0, 0, 1.0]])
    welded, faces = weld_vertices(vertices, np.array([[0, 2, 3], [1, 3, 4]]))
    assert len(welded) == 4
    assert faces[0, 0] == faces[1, 0]


# --- inertia modes ----------------------------------------------------------------------------


def test_exact_mode_refuses_an_open_mesh_with_a_hint_naming_the_other_modes():
    vertices, faces = box_mesh()
    with pytest.raises(MeshError) as caught:
        mesh_mass_properties(vertices, faces[1:], "exact", mass=1.0)
    message = str(caught.value)
    assert "not closed: 3 boundary edges" in message
    for option in ("convex", "shell", "repair"):
        assert option in message


def test_shell_of_a_cube_is_six_plates():
    a, m = 2.0, 3.0
    vertices, faces = box_mesh((a, a, a), (1, 2, 3))
    props = mesh_mass_properties(vertices, faces, "shell", mass=m)
    assert props.area == pytest.approx(6 * a * a, rel=1e-15)
    np.testing.assert_allclose(props.properties.center_of_mass, [1, 2, 3], rtol=1e-15)
    # each face a square plate of mass m/6: about its own normal (m/6)a²/6; about an in-plane
    # axis (m/6)a²/12, moved a/2 away from the cube's centre
    plates = 2 * (m / 6) * a * a / 6 + 4 * (m / 6) * (a * a / 12 + a * a / 4)
    np.testing.assert_allclose(props.properties.inertia_about_com, plates * np.eye(3), rtol=1e-14, atol=1e-15)
    assert plates == pytest.approx(5 / 18 * m * a * a, rel=1e-15)


def test_a_flat_mesh_in_exact_mode_is_pointed_to_shell():
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0.0]])
    sheet = np.array([[0, 1, 2], [0, 2, 3], [0, 2, 1], [0, 3, 2]])  # both sides: closed, but flat
    with pytest.raises(MeshError, match="encloses no volume.*choose inertia: shell"):
        mesh_mass_properties(square, sheet, "exact", mass=1.0)


def test_shell_density_is_per_area_as_in_mujoco():
    vertices, faces = box_mesh((1, 2, 3))
    props = mesh_mass_properties(vertices, faces, "shell", density=0.5)
    assert props.properties.mass == pytest.approx(0.5 * 2 * (2 + 3 + 6), rel=1e-15)


def test_shell_of_a_fine_sphere_approaches_the_thin_spherical_shell():
    r, m = 0.7, 2.0
    for n, tol in ((40, 3e-3), (160, 2e-4)):
        props = mesh_mass_properties(*sphere_mesh(r, n, 2 * n), "shell", mass=m)
        np.testing.assert_allclose(np.diag(props.properties.inertia_about_com), 2 / 3 * m * r * r, rtol=tol)


def test_shell_takes_an_open_or_flat_surface():
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0.0]])
    props = mesh_mass_properties(square, np.array([[0, 1, 2], [0, 2, 3]]), "shell", mass=6.0)
    np.testing.assert_allclose(
        props.properties.inertia_about_com, box_inertia(6.0, (2, 1, 0)), rtol=1e-15, atol=1e-15
    )
    assert props.volume is None


def test_convex_mode_of_an_l_shaped_prism_is_the_hull():
    import sympy as sp

    # L: the square [0,2]² without [1,2]×[1,2], extruded to z in [0, h]; hull: x + y <= 3
    h = 0.5
    outline = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    vertices, faces = extruded(outline, h)
    exact = mesh_mass_properties(vertices, faces, "exact", density=1.0)
    assert exact.volume == pytest.approx(3 * h, rel=1e-15)
    hull = mesh_mass_properties(vertices, faces, "convex", density=1.0)

    x, y, z = sp.symbols("x y z")

    def integral(f):
        return float(
            sp.integrate(f, (z, 0, h), (y, 0, 2), (x, 0, 1))
            + sp.integrate(f, (z, 0, h), (y, 0, 3 - x), (x, 1, 2))
        )

    volume = integral(1)
    com = np.array([integral(x), integral(y), integral(z)]) / volume
    second = np.array([[integral(p * q) for q in (x, y, z)] for p in (x, y, z)]) - volume * np.outer(com, com)
    inertia = np.trace(second) * np.eye(3) - second
    assert hull.volume == pytest.approx(volume, rel=1e-14) and volume == pytest.approx(3.5 * h)
    np.testing.assert_allclose(hull.properties.center_of_mass, com, rtol=1e-14)
    np.testing.assert_allclose(hull.properties.inertia_about_com, inertia, rtol=1e-13, atol=1e-15)


def extruded(outline, height):
    """A prism on a simple counter-clockwise polygon (fan-triangulated from a point that sees
    every edge: the L's first vertex does), z from 0 to ``height``."""
    n = len(outline)
    bottom = np.array([[x, y, 0.0] for x, y in outline])
    vertices = np.vstack([bottom, bottom + [0, 0, height]])
    faces = []
    for i in range(n):
        j = (i + 1) % n
        faces += [[i, j, n + j], [i, n + j, n + i]]
    for i in range(1, n - 1):
        faces += [[0, i + 1, i], [n, n + i, n + i + 1]]
    return vertices, np.array(faces)


def test_convex_hull_mesh_is_closed_and_outward():
    vertices, faces = extruded([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], 1.0)
    hull_vertices, hull_faces = convex_hull_mesh(vertices)
    assert closed_mesh_check(hull_vertices, hull_faces)[0] is None


def test_convex_mode_refuses_a_flat_point_set():
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0.0]])
    with pytest.raises(MeshError, match="flat"):
        mesh_mass_properties(square, np.array([[0, 1, 2], [0, 2, 3]]), "convex", mass=1.0)


def test_unknown_mode_is_refused():
    vertices, faces = box_mesh()
    with pytest.raises(MeshError, match="exact, convex or shell"):
        mesh_mass_properties(vertices, faces, "legacy", mass=1.0)


# --- repair -----------------------------------------------------------------------------------


def test_repair_closes_a_missing_triangle_and_reports_its_area():
    a = 2.0
    vertices, faces = box_mesh((a, a, a))
    repaired = repair_mesh(vertices, faces[1:])
    assert repaired.added_area == pytest.approx(a * a / 2, rel=1e-15)
    assert repaired.added_faces == 1
    props = mesh_mass_properties(repaired.vertices, repaired.faces, "exact", mass=8.0)
    assert props.volume == pytest.approx(a**3, rel=1e-15)
    np.testing.assert_allclose(
        props.properties.inertia_about_com, box_inertia(8.0, (a, a, a)), rtol=1e-14, atol=1e-15
    )


def test_repair_of_a_closed_mesh_changes_nothing():
    vertices, faces = box_mesh()
    repaired = repair_mesh(vertices, faces)
    assert repaired.added_area == 0.0 and repaired.added_faces == 0
    np.testing.assert_array_equal(repaired.faces, faces)


def test_repair_leaves_a_large_hole_and_says_so():
    vertices, faces = sphere_mesh(1.0, 12, 24)
    opened = faces[24:]  # the whole cap around the north pole: a 24-edge hole
    repaired = repair_mesh(vertices, opened)
    assert mesh_defects(repaired.faces).boundary_edges > 0
    with pytest.raises(MeshError, match="not closed"):
        mesh_mass_properties(repaired.vertices, repaired.faces, "exact", mass=1.0)


# --- MuJoCo's compiled mesh inertia -----------------------------------------------------------


def mujoco_inertia(vertices, faces, mode, mass=1.0):
    mujoco = pytest.importorskip("mujoco")
    v = " ".join(repr(float(c)) for c in np.asarray(vertices).ravel())
    f = " ".join(str(int(i)) for i in np.asarray(faces).ravel())
    xml = (
        f'<mujoco><asset><mesh name="m" inertia="{mode}" vertex="{v}" face="{f}"/></asset>'
        f'<worldbody><body><freejoint/><geom type="mesh" mesh="m" mass="{mass!r}"/></body></worldbody></mujoco>'
    )
    model = mujoco.MjModel.from_xml_string(xml)
    return model.body_ipos[1].copy(), np.sort(model.body_inertia[1].copy())


@pytest.mark.parametrize("mode", ["exact", "shell", "convex"])
@pytest.mark.parametrize("shape", ["box", "sphere", "l_prism"])
def test_principal_moments_agree_with_mujoco(mode, shape):
    vertices, faces = {
        "box": lambda: box_mesh((0.3, 0.5, 0.9), (0.1, 0.2, 0.3)),
        "sphere": lambda: sphere_mesh(0.4, 10, 20),
        "l_prism": lambda: extruded([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], 0.5),
    }[shape]()
    vertices = vertices.astype(np.float32).astype(float)  # MuJoCo keeps mesh vertices in single precision
    com, moments = mujoco_inertia(vertices, faces, mode, mass=2.5)
    props = mesh_mass_properties(vertices, faces, mode, mass=2.5)
    np.testing.assert_allclose(props.properties.center_of_mass, com, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(np.linalg.eigvalsh(props.properties.inertia_about_com), moments, rtol=1e-12)
