"""`pattern:` on a part: rings of copies about an axis line and rows of copies, against closed
forms (a ring of point masses, a wheel with a ring of holes) and against the same copies
written out one by one with scipy's rotations; on holes and meshes; in `rbi parts`; refusals."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from tests.conftest import BODIES, one_line_exit_2, run_rbi_inprocess
from tests.mesh_builders import box_mesh, write_obj


def run_json(*args) -> dict:
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


@pytest.mark.parametrize("count", [3, 4, 7, 12])
def test_ring_of_point_masses(write_spec, count):
    m, rho = 0.25, 0.4
    through = [1.0, -2.0, 0.5]
    spec = write_spec(
        f"parts:\n  - {{name: bolts, shape: point, mass: {m}, position: [{1.0 + rho}, -2.0, 0.5],\n"
        f"     pattern: {{count: {count}, axis: [0, 0, 1], through: {through}}}}}\n"
    )
    out = run_json("inertia", spec)
    assert out["mass"] == pytest.approx(count * m, rel=1e-15)
    np.testing.assert_allclose(out["center_of_mass"], through, rtol=0, atol=1e-15)
    # N ≥ 3 equal masses evenly on a circle: Σ cos² = Σ sin² = N/2, Σ cos·sin = 0
    ring = count * m * rho * rho
    np.testing.assert_allclose(
        out["inertia"], np.diag([ring / 2, ring / 2, ring]), rtol=1e-14, atol=1e-15 * ring
    )


def test_wheel_with_a_ring_of_holes_matches_the_closed_form(write_spec):
    M, R, t = 2.0, 0.1, 0.01  # disc
    n, r, rho, density = 6, 0.012, 0.06, 2700.0  # holes through the disc
    spec = write_spec(
        "parts:\n"
        f"  - {{name: disc, shape: cylinder, mass: {M}, radius: {R}, start: [0, 0, 0], end: [0, 0, {t}]}}\n"
        f"  - {{name: holes, shape: cylinder, density: {density}, radius: {r}, start: [{rho}, 0, 0], end: [{rho}, 0, {t}],\n"
        f"     subtract: true, pattern: {{count: {n}, axis: [0, 0, 1], through: [0, 0, 0]}}}}\n"
    )
    out = run_json("inertia", spec)
    m_hole = density * math.pi * r * r * t
    assert out["mass"] == pytest.approx(M - n * m_hole, rel=1e-14)
    np.testing.assert_allclose(out["center_of_mass"], [0, 0, t / 2], rtol=1e-14, atol=1e-16)
    axial = M * R * R / 2 - n * m_hole * (r * r / 2 + rho * rho)
    transverse = M * (3 * R * R + t * t) / 12 - n * m_hole * ((3 * r * r + t * t) / 12 + rho * rho / 2)
    np.testing.assert_allclose(
        out["inertia"], np.diag([transverse, transverse, axial]), rtol=1e-13, atol=1e-16
    )


def test_pattern_about_a_slanted_axis_equals_the_copies_written_out(write_spec):
    axis, through, count = np.array([1.0, 2.0, -0.5]), np.array([0.3, -0.1, 0.2]), 5
    part = dict(
        shape="box",
        density=1200.0,
        center=[0.8, 0.1, -0.3],
        size=[0.1, 0.2, 0.05],
        rotation={"axis": [0, 1, 0], "angle_deg": 20},
    )
    patterned = write_spec(
        json.dumps(
            {
                "parts": [
                    dict(part, pattern={"count": count, "axis": axis.tolist(), "through": through.tolist()})
                ]
            }
        ),
        "a.yaml",
    )
    copies = []
    base_turn = Rotation.from_rotvec(np.radians(20) * np.array([0, 1, 0]))
    for k in range(count):
        turn = Rotation.from_rotvec(2 * math.pi * k / count * axis / np.linalg.norm(axis))
        center = through + turn.apply(np.array(part["center"]) - through)
        q = (turn * base_turn).as_quat(scalar_first=True)
        copies.append(dict(part, center=center.tolist(), rotation={"quaternion": q.tolist()}))
    written = write_spec(json.dumps({"parts": copies}), "b.yaml")
    a, b = run_json("inertia", patterned), run_json("inertia", written)
    assert a["mass"] == pytest.approx(b["mass"], rel=1e-14)
    np.testing.assert_allclose(a["center_of_mass"], b["center_of_mass"], rtol=0, atol=1e-15)
    np.testing.assert_allclose(a["inertia"], b["inertia"], rtol=0, atol=1e-13 * np.max(np.abs(b["inertia"])))


def test_row_of_copies(write_spec):
    m, size, step, count = 0.5, [0.02, 0.03, 0.04], [0.1, 0.0, 0.0], 5
    spec = write_spec(
        f"parts:\n  - {{name: fins, shape: box, mass: {m}, center: [0, 1, 2], size: {size},\n"
        f"     pattern: {{count: {count}, step: {step}}}}}\n"
    )
    out = run_json("inertia", spec)
    assert out["mass"] == pytest.approx(count * m, rel=1e-15)
    np.testing.assert_allclose(out["center_of_mass"], [0.2, 1, 2], rtol=1e-15)
    a, b, c = size
    own = m / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
    spread = m * sum((k * 0.1 - 0.2) ** 2 for k in range(count))  # Σ m x_k² about the middle
    np.testing.assert_allclose(
        out["inertia"], np.diag(count * own + np.array([0, spread, spread])), rtol=1e-13, atol=1e-18
    )


def test_count_one_is_the_part_itself(write_spec):
    part = "{name: p, shape: capsule, mass: 2, start: [0, 0, 0], end: [0.3, 0.1, 0], radius: 0.05"
    plain = write_spec(f"parts:\n  - {part}}}\n", "a.yaml")
    once = write_spec(f"parts:\n  - {part}, pattern: {{count: 1, step: [9, 9, 9]}}}}\n", "b.yaml")
    assert run_json("inertia", plain) == run_json("inertia", once)


def test_pattern_on_a_mesh(tmp_path):
    write_obj(tmp_path / "block.obj", *box_mesh((0.1, 0.1, 0.1), (0.5, 0, 0)))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: blocks, shape: mesh, file: block.obj, mass: 1,\n"
        "     pattern: {count: 4, axis: [0, 0, 1], through: [0, 0, 0]}}\n"
    )
    out = run_json("inertia", spec)
    assert out["mass"] == pytest.approx(4.0)
    own = 1 / 12 * 0.02  # m (a² + b²)/12 for a 0.1 cube
    np.testing.assert_allclose(
        out["inertia"],
        np.diag([4 * own + 2 * 0.25, 4 * own + 2 * 0.25, 4 * own + 4 * 0.25]),
        rtol=1e-13,
        atol=1e-16,
    )


def test_parts_shows_one_row_per_written_part_with_all_copies(write_spec):
    spec = write_spec(
        "parts:\n"
        "  - {name: plate, shape: box, density: 1000, center: [0, 0, 0], size: [1, 1, 0.1]}\n"
        "  - {name: holes, shape: cylinder, density: 1000, radius: 0.05, start: [0.3, 0, -0.05], end: [0.3, 0, 0.05],\n"
        "     subtract: true, pattern: {count: 8, axis: [0, 0, 1], through: [0, 0, 0]}}\n"
    )
    out = run_json("parts", spec)
    plate, holes = out["parts"]
    hole_volume = 8 * math.pi * 0.05**2 * 0.1
    assert holes["mass"] == pytest.approx(-1000 * hole_volume, rel=1e-14)
    assert holes["volume"] == pytest.approx(-hole_volume, rel=1e-14)  # negative, as the mass
    assert holes["implied_density"] == pytest.approx(1000, rel=1e-14)
    assert plate["mass"] + holes["mass"] == pytest.approx(out["mass"], rel=1e-14)
    np.testing.assert_allclose(holes["center_of_mass"], 0, atol=1e-15)


def test_bundled_wheel_pattern_equals_the_wheel_with_holes_written_out():
    """wheel_pattern.yaml is wheel_with_holes.yaml (six holes written out, centres rounded to
    1e-6 mm) with the holes as one pattern, plus four 5 g point weights in a row."""
    pattern = run_json("inertia", BODIES / "wheel_pattern.yaml", "--about", "origin")
    written = run_json("inertia", BODIES / "wheel_with_holes.yaml", "--about", "origin")
    weights = [np.array([-7.5 + 5 * k, 92.0, 10.0]) for k in range(4)]
    weights_inertia = sum(5.0 * (p @ p * np.eye(3) - np.outer(p, p)) for p in weights)
    assert pattern["mass"] == pytest.approx(written["mass"] + 20.0, rel=1e-9)
    expected = np.array(written["inertia"]) + weights_inertia
    np.testing.assert_allclose(pattern["inertia"], expected, rtol=0, atol=1e-8 * np.max(expected))
    for command in ("principal", "parts", "check", "validate"):
        assert run_rbi_inprocess(command, BODIES / "wheel_pattern.yaml").returncode == 0, command


@pytest.mark.parametrize(
    "pattern, words",
    [
        ("{count: 3}", "got neither axis nor step"),
        ("{count: 3, axis: [0, 0, 1], step: [1, 0, 0]}", "got both"),
        ("{count: 3, through: [0, 0, 0]}", "axis: missing required field"),
        ("{count: 3, axis: [0, 0, 0]}", "axis: must not be the zero vector"),
        ("{count: 0, step: [1, 0, 0]}", "count"),
        ("{count: 2.5, step: [1, 0, 0]}", "count"),
        ("{count: 3, step: [1, 0]}", "step"),
        ("{count: 3, step: [1, 0, 0], spacing: 2}", "unknown field"),
        ("6", "pattern"),
    ],
)
def test_bad_patterns_name_the_part_and_field(write_spec, pattern, words):
    spec = write_spec(
        f"parts:\n  - {{name: ring, shape: sphere, mass: 1, center: [1, 0, 0], radius: 0.1, pattern: {pattern}}}\n"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[0] (ring)", "pattern", words)


def test_a_pattern_of_holes_that_removes_too_much_names_the_hole(write_spec):
    spec = write_spec(
        "parts:\n"
        "  - {name: disc, shape: cylinder, density: 1000, radius: 0.1, start: [0, 0, 0], end: [0, 0, 0.01]}\n"
        "  - {name: holes, shape: cylinder, density: 1000, radius: 0.05, start: [0.05, 0, 0], end: [0.05, 0, 0.01],\n"
        "     subtract: true, pattern: {count: 12, axis: [0, 0, 1], through: [0, 0, 0]}}\n"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[1] (holes)", "subtract")


@settings(max_examples=60, deadline=None)
@given(
    count=st.integers(3, 40),
    axis=st.tuples(*[st.floats(-1, 1) for _ in range(3)]).filter(lambda v: np.linalg.norm(v) > 0.1),
    through=st.tuples(*[st.floats(-2, 2) for _ in range(3)]),
    size=st.tuples(*[st.floats(0.01, 1) for _ in range(3)]),
    center=st.tuples(*[st.floats(-2, 2) for _ in range(3)]),
)
def test_three_or_more_copies_about_an_axis_are_symmetric_about_it(count, axis, through, size, center):
    """N ≥ 3 equal copies turned evenly about a line have the line's symmetry: the centre of
    mass lies on it and the inertia is axial·uuᵀ + transverse·(E − uuᵀ), whatever the part."""
    from types import SimpleNamespace

    from rbi.spec.pattern import patterned
    from tests.core.built import box

    R = Rotation.from_rotvec([0.3, -0.2, 0.5]).as_matrix()
    element = patterned(
        box(1.0, np.array(size), np.array(center), R),
        SimpleNamespace(count=count, axis=list(axis), through=list(through), step=None),
    )
    u = np.array(axis) / np.linalg.norm(axis)
    offset = element.center_of_mass - np.array(through)
    scale = 1.0 + float(np.linalg.norm(center)) + float(np.linalg.norm(through))
    np.testing.assert_allclose(offset - (offset @ u) * u, 0, atol=1e-12 * scale)
    I = element.inertia_about_com
    axial = u @ I @ u
    transverse = 0.5 * (np.trace(I) - axial)
    expected = axial * np.outer(u, u) + transverse * (np.eye(3) - np.outer(u, u))
    np.testing.assert_allclose(I, expected, rtol=0, atol=1e-11 * np.trace(I))
