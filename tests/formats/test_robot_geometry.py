"""The mesh cache of robot geometry: the meshes integrated for an audit are kept, the last used
only, each entry a few numbers whatever the size of its mesh (a process that audits robot after
robot keeps bounded memory)."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from rbi.formats import robot_geometry
from rbi.formats.robot import Geom, Pose
from rbi.formats.robot_geometry import distribution

TETRAHEDRON = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 0), (1, 0, 0), (0, 0, 1)),
               ((0, 0, 0), (0, 0, 1), (0, 1, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]  # fmt: skip
"""The unit right tetrahedron, outward winding: volume 1/6, centroid (1/4, 1/4, 1/4)."""


def ascii_stl(path, triangles):
    lines = ["solid probe"]
    for triangle in triangles:
        lines += ["facet normal 0 0 0", "outer loop", *(f"vertex {x} {y} {z}" for x, y, z in triangle)]
        lines += ["endloop", "endfacet"]
    path.write_text("\n".join([*lines, "endsolid probe"]) + "\n")
    return path


def mesh_geom(path, scale: float) -> Geom:
    return Geom("mesh", (), Pose.identity(), "probe", mesh_file=path, mesh_scale=np.full(3, scale))


@pytest.fixture
def empty_cache(monkeypatch):
    monkeypatch.setattr(robot_geometry, "_MESHES", type(robot_geometry._MESHES)())
    return robot_geometry._MESHES


def test_the_cache_keeps_the_last_used_meshes_only(tmp_path, monkeypatch, empty_cache):
    monkeypatch.setattr(robot_geometry, "_MESH_ENTRIES", 3, raising=False)  # fails on a cache without it
    path = ascii_stl(tmp_path / "tetra.stl", TETRAHEDRON)
    for scale in (1.0, 2.0, 3.0, 4.0, 5.0, 6.0):
        unit = distribution(mesh_geom(path, scale)).unit
        assert unit.mass == pytest.approx(scale**3 / 6, rel=1e-12)  # volume, m³
        np.testing.assert_allclose(unit.center_of_mass, np.full(3, scale / 4), rtol=1e-12)
        distribution(mesh_geom(path, 4.0))  # used again: kept while newer ones come
    assert len(empty_cache) == 3
    assert sorted(key[3][0] for key in empty_cache) == [4.0, 5.0, 6.0]


def test_an_entry_holds_a_few_numbers_whatever_the_size_of_its_mesh(tmp_path, empty_cache):
    trimesh = pytest.importorskip("trimesh")
    sphere = trimesh.creation.icosphere(subdivisions=4)  # 5,120 triangles
    path = ascii_stl(tmp_path / "sphere.stl", sphere.vertices[sphere.faces].tolist())
    unit = distribution(mesh_geom(path, 1.0)).unit
    assert unit.mass == pytest.approx(4 / 3 * np.pi, rel=0.01)  # a unit sphere, nearly
    (entry,) = empty_cache.values()
    held = sum(sys.getsizeof(v) + getattr(v, "nbytes", 0) for v in entry)
    assert held < 2_000  # bytes: the mesh's 2,562 vertices (61 kB) are not kept
