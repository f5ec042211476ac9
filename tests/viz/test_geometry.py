"""Drawable geometry of each shape kind, checked against the spec as written and against
closed forms (areas of the drawn solids, the inertia of a stand-in box)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.spec.geometry import part_geometry
from rbi.spec.load import load_body
from rbi.viz.solids import part_quads


def _geometry(write_spec, parts: str, extra: str = "") -> list[dict]:
    return part_geometry(load_body(write_spec(f"name: t\n{extra}parts:\n{parts}")))


def _area(quads: np.ndarray) -> float:
    """Area of planar quads (two triangles each)."""
    a = np.cross(quads[:, 1] - quads[:, 0], quads[:, 2] - quads[:, 0])
    b = np.cross(quads[:, 2] - quads[:, 0], quads[:, 3] - quads[:, 0])
    return float(0.5 * (np.linalg.norm(a, axis=1) + np.linalg.norm(b, axis=1)).sum())


def test_cone_cylinder_tube_are_frusta_with_the_written_ends(write_spec):
    items = _geometry(
        write_spec,
        """\
  - {name: c, shape: cone, mass: 1, radius: 0.5, apex: [0, 0, 0], base: [0, 0, 2]}
  - {name: y, shape: cylinder, mass: 1, radius: 0.25, start: [1, 0, 0], end: [1, 0, 1]}
  - {name: t, shape: tube, mass: 1, outer_radius: 0.3, inner_radius: 0.2, start: [0, 1, 0], end: [0, 2, 0]}
""",
    )
    cone, cylinder, tube = items
    assert cone["kind"] == "frustum" and cone["start"] == [0, 0, 0] and cone["end"] == [0, 0, 2]
    assert (cone["start_radius"], cone["end_radius"]) == (0.0, 0.5)
    assert (cylinder["start_radius"], cylinder["end_radius"]) == (0.25, 0.25)
    assert tube["inner_radius"] == 0.2 and tube["start_radius"] == 0.3
    assert [i["name"] for i in items] == ["c", "y", "t"] and not any(i["hole"] for i in items)


def test_drawn_surface_areas_match_closed_forms(write_spec):
    box, sphere, cylinder, torus = _geometry(
        write_spec,
        """\
  - {shape: box, mass: 1, center: [0, 0, 0], size: [1, 2, 3]}
  - {shape: sphere, mass: 1, center: [0, 0, 0], radius: 1}
  - {shape: cylinder, mass: 1, radius: 1, start: [0, 0, 0], end: [0, 0, 2]}
  - {shape: torus, mass: 1, center: [0, 0, 0], axis: [0, 0, 1], major_radius: 3, minor_radius: 1}
""",
    )
    assert _area(part_quads(box, 1.0)[0]) == pytest.approx(2 * (1 * 2 + 2 * 3 + 1 * 3), rel=1e-12)
    # polygonal approximations of round solids: within 2 % of the exact areas
    assert _area(part_quads(sphere, 1.0)[0]) == pytest.approx(4 * math.pi, rel=0.02)
    assert _area(part_quads(cylinder, 1.0)[0]) == pytest.approx(2 * math.pi * 2 + 2 * math.pi, rel=0.02)
    assert _area(part_quads(torus, 1.0)[0]) == pytest.approx(4 * math.pi**2 * 3 * 1, rel=0.02)


def test_hemisphere_and_capsule_reach_where_the_spec_says(write_spec):
    hemisphere, capsule = _geometry(
        write_spec,
        """\
  - {shape: hemisphere, mass: 1, center: [0, 0, 1], axis: [0, 0, 2], radius: 0.5}
  - {shape: capsule, mass: 1, start: [0, 0, 0], end: [2, 0, 0], radius: 0.5}
""",
    )
    points = part_quads(hemisphere, 1.0)[0].reshape(-1, 3)
    assert points[:, 2].min() == pytest.approx(1.0) and points[:, 2].max() == pytest.approx(1.5)
    points = part_quads(capsule, 1.0)[0].reshape(-1, 3)
    assert points[:, 0].min() == pytest.approx(-0.5) and points[:, 0].max() == pytest.approx(2.5)
    assert np.abs(points[:, 1]).max() == pytest.approx(0.5, rel=1e-3)


def test_ellipsoid_and_box_rotations_are_part_to_body(write_spec):
    (box,) = _geometry(
        write_spec,
        """\
  - {shape: box, mass: 1, center: [1, 0, 0], size: [4, 0.2, 0.2], rotation: {axis: [0, 0, 1], angle_deg: 90}}
""",
    )
    points = part_quads(box, 1.0)[0].reshape(-1, 3)
    # the long edge, along part x, lies along body y after a quarter turn about z
    assert np.ptp(points[:, 1]) == pytest.approx(4.0) and np.ptp(points[:, 0]) == pytest.approx(0.2)


def test_point_mass_and_hole(write_spec):
    point, hole = _geometry(
        write_spec,
        """\
  - {name: p, shape: point, mass: 1, position: [1, 2, 3]}
  - {name: h, shape: sphere, mass: 0.1, center: [1, 2, 3], radius: 0.1, subtract: true}
  - {name: s, shape: sphere, mass: 10, center: [1, 2, 3], radius: 0.5}
""",
    )[:2]
    assert point == point | {"kind": "point", "position": [1.0, 2.0, 3.0], "hole": False}
    assert hole["hole"] is True and hole["kind"] == "ellipsoid"


def test_pattern_about_an_axis_gives_each_copy_in_place(write_spec):
    items = _geometry(
        write_spec,
        """\
  - {name: bolt, shape: point, mass: 0.5, position: [2, 0, 1], pattern: {count: 4, axis: [0, 0, 1], through: [1, 0, 0]}}
""",
    )
    assert len(items) == 4 and {i["part"] for i in items} == {0}
    positions = np.array([i["position"] for i in items])
    # quarter turns about the vertical line through (1, 0, 0)
    np.testing.assert_allclose(positions, [[2, 0, 1], [1, 1, 1], [0, 0, 1], [1, -1, 1]], atol=1e-12)
    assert sum(i["mass"] for i in items) == pytest.approx(2.0)


def test_pattern_in_a_row_moves_solids_and_turns_nothing(write_spec):
    items = _geometry(
        write_spec,
        """\
  - {shape: cylinder, mass: 1, radius: 0.1, start: [0, 0, 0], end: [0, 0, 1], pattern: {count: 3, step: [0.5, 0, 0]}}
""",
    )
    assert [i["start"] for i in items] == [[0, 0, 0], [0.5, 0, 0], [1.0, 0, 0]]
    assert [i["end"] for i in items] == [[0, 0, 1], [0.5, 0, 1], [1.0, 0, 1]]


def test_custom_part_stand_in_box_has_the_parts_mass_and_moments(write_spec):
    (item,) = _geometry(
        write_spec,
        """\
  - {shape: custom, mass: 2, center_of_mass: [1, 1, 0], inertia: [[0.5, 0, 0], [0, 0.3, 0], [0, 0, 0.4]]}
""",
    )
    assert item["kind"] == "box" and item["stand_in"] is True
    a, b, c = item["size"]
    m = 2.0
    # the uniform box's moments about its own axes, in the body axes it is turned to
    box = np.diag([m / 12 * (b * b + c * c), m / 12 * (a * a + c * c), m / 12 * (a * a + b * b)])
    R = np.array(item["rotation"])
    np.testing.assert_allclose(R @ box @ R.T, np.diag([0.5, 0.3, 0.4]), atol=1e-12)
    assert item["center"] == [1.0, 1.0, 0.0]


def test_mesh_part_is_drawn_from_its_triangles_placed_like_its_mass(write_spec, tmp_path):
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    lines = ["solid t"]
    for f in faces:
        lines += [
            "facet normal 0 0 0",
            "outer loop",
            *[f"vertex {x} {y} {z}" for x, y, z in vertices[list(f)]],
            "endloop",
            "endfacet",
        ]
    (tmp_path / "tet.stl").write_text("\n".join(lines + ["endsolid t"]) + "\n")
    (item,) = _geometry(
        write_spec,
        """\
  - {shape: mesh, file: tet.stl, mass: 1, scale: 2, position: [10, 0, 0], rotation: {axis: [0, 0, 1], angle_deg: 90}}
""",
    )
    assert item["kind"] == "mesh" and len(item["faces"]) == 4
    drawn = np.array(item["vertices"])
    expected = vertices * 2 @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]], dtype=float).T + [10, 0, 0]
    assert sorted(map(tuple, np.round(drawn, 12))) == sorted(map(tuple, np.round(expected, 12)))
    body = load_body(tmp_path / "body.yaml")
    centroid = np.mean(
        drawn[np.array(item["faces"])].reshape(-1, 3), axis=0
    )  # every vertex thrice: the tet's centroid
    np.testing.assert_allclose(body.props.center_of_mass, centroid, atol=1e-9)


@pytest.mark.parametrize(
    "name", sorted(p.name for p in __import__("tests.conftest", fromlist=["BODIES"]).BODIES.glob("*.yaml"))
)
def test_every_bundled_body_has_drawable_parts(name, bodies):
    body = load_body(bodies / name)
    items = part_geometry(body)
    assert {i["part"] for i in items} == set(range(len(body.elements)))
    for item in items:
        quads = part_quads(item, 1.0)[0] if item["kind"] != "point" else np.zeros((1, 4, 3))
        assert np.all(np.isfinite(quads))


def test_point_cloud_points_are_drawn_where_the_file_puts_them(write_spec, tmp_path):
    (tmp_path / "pts.csv").write_text("mass,x,y,z\n1,0,0,0\n2,1,0,0\n3,0,2,0\n")
    items = _geometry(
        write_spec,
        "  - {name: rod, shape: rod, mass: 1, start: [0, 0, 0], end: [0, 0, 1]}\n",
        extra="point_cloud: {file: pts.csv}\n",
    )
    cloud = items[-1]
    assert cloud["kind"] == "points" and cloud["shape"] == "point_cloud" and cloud["part"] == 1
    assert cloud["positions"] == [[0, 0, 0], [1, 0, 0], [0, 2, 0]]
    assert cloud["mass"] == pytest.approx(6.0)


def test_a_cloud_too_big_to_draw_point_by_point_gets_its_stand_in_box(write_spec, tmp_path, monkeypatch):
    import rbi.spec.geometry as geometry

    monkeypatch.setattr(geometry, "MAX_DRAWN_POINTS", 2)
    (tmp_path / "pts.csv").write_text("mass,x,y,z\n1,1,0,0\n1,-1,0,0\n1,0,1,0\n1,0,-1,0\n")
    (item,) = part_geometry(load_body(write_spec("point_cloud: {file: pts.csv}\n")))
    assert item["kind"] == "box" and item["stand_in"] is True
