"""The mesh cache of robot geometry: the meshes integrated for an audit are kept, the last used
only, each entry a few numbers whatever the size of its mesh (a process that audits robot after
robot keeps bounded memory); geometry whose mass overflows is refused in one line."""

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


@pytest.mark.parametrize(
    "command", [("audit",), ("audit", "--format", "json"), ("import", "--format", "json"), ("validate",)]
)
def test_a_geom_mass_that_overflows_is_one_line_naming_the_geom(tmp_path, command):
    """Found: an MJCF geom of mass 1e308 kg (a 0.2 m box: density 1.25e310 kg/m³, past the
    largest double) was 'rbi: internal error: LinAlgError: Eigenvalues did not converge' (exit 1)
    in audit, import and validate alike: the compiled inertia was inf and NaN. Now the sum of a
    body's geoms (:func:`robot_geometry.geoms_sum`) refuses it: exit 2, one line naming the geom."""
    from tests.conftest import one_line_exit_2, run_rbi_inprocess

    path = tmp_path / "heavy.xml"
    path.write_text(
        '<mujoco><worldbody><body name="a"><freejoint/><geom mass="1e308" type="box" size="0.1 0.1 0.1"/>'
        "</body></worldbody></mujoco>"
    )
    proc = run_rbi_inprocess(command[0], path, *command[1:])
    assert proc.returncode == 2, proc.stderr
    assert (
        "heavy.xml: body[0] (a): geom[0]: its mass or inertia overflows a double" in proc.stderr + proc.stdout
    )
    if command[0] != "validate":  # (validate adds its summary line)
        one_line_exit_2(proc)
