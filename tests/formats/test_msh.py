"""MuJoCo's binary MSH meshes (robosuite's objects ship them): read wherever a mesh is, the
same bodies MuJoCo compiles (its masses, centres of mass and moments), a file of bare vertices
taken as their convex hull as MuJoCo takes it, and damaged files refused in one line."""

from __future__ import annotations

import json
import struct

import numpy as np
import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess
from tests.mesh_builders import box_mesh, write_msh

mujoco = pytest.importorskip("mujoco")

MJCF = """<mujoco>
  <asset>
    <mesh name="box" file="box.msh"/>
    <mesh name="points" file="points.msh"/>
  </asset>
  <worldbody>
    <body name="block" pos="0 0 1">
      <freejoint/>
      <geom type="mesh" mesh="box" density="2700"/>
    </body>
    <body name="cloud" pos="1 0 0">
      <freejoint/>
      <geom type="mesh" mesh="points" density="500"/>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.fixture
def robot(tmp_path):
    vertices, faces = box_mesh((0.2, 0.3, 0.5), (0.1, 0.0, 0.25))
    write_msh(tmp_path / "box.msh", vertices, faces, normals=len(vertices), texcoords=len(vertices))
    corners, _ = box_mesh((0.4, 0.1, 0.2), (0.0, 0.05, 0.0))
    inside = np.array([[0.0, 0.05, 0.0], [0.1, 0.06, 0.05]])  # points within the hull add nothing
    write_msh(tmp_path / "points.msh", np.vstack([corners, inside]), np.zeros((0, 3), int))
    path = tmp_path / "objects.xml"
    path.write_text(MJCF)
    return path


def test_msh_bodies_are_the_ones_mujoco_compiles(robot):
    model = mujoco.MjModel.from_xml_path(str(robot))
    proc = run_rbi_inprocess("audit", robot, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    links = json.loads(proc.stdout)["links"]
    assert [link["name"] for link in links] == ["block", "cloud"]
    for body, link in enumerate(links, start=1):
        declared = link["declared"]
        assert declared["mass"] == pytest.approx(model.body_mass[body], rel=1e-12)
        np.testing.assert_allclose(declared["center_of_mass"], model.body_ipos[body], rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(declared["moments"], np.sort(model.body_inertia[body]), rtol=1e-12)
    # and the closed forms: a 0.2 × 0.3 × 0.5 m aluminium box, a 0.4 × 0.1 × 0.2 m hull at 500 kg/m³
    assert links[0]["declared"]["mass"] == pytest.approx(2700 * 0.03, rel=1e-6)
    assert links[1]["declared"]["mass"] == pytest.approx(500 * 0.008, rel=1e-6)


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_every_output_form_audits_the_msh_robot(robot, form):
    proc = run_rbi_inprocess("audit", robot, "--format", form)
    assert proc.returncode == 0, proc.stderr
    assert "cloud" in proc.stdout and "Traceback" not in proc.stderr


def _header(n_vertices, n_normals, n_texcoords, n_faces) -> bytes:
    return struct.pack("<4i", n_vertices, n_normals, n_texcoords, n_faces)


DAMAGED = {
    "shorter than its header": (b"\x01\x00", "no header"),
    "a negative count": (_header(-1, 0, 0, 0) + b"\0" * 12, "no header"),
    "counts promising more than the file": (_header(2**31 - 1, 0, 0, 2**31 - 1) + b"\0" * 64, "promises"),
    "one byte too many": (_header(0, 0, 0, 0) + b"\0", "promises"),
    "a face past the last vertex": (
        _header(3, 0, 0, 1) + np.eye(3, dtype="<f4").tobytes() + np.array([0, 1, 7], "<i4").tobytes(),
        "names a vertex that does not exist",
    ),
    "bare points in one plane": (
        _header(4, 0, 0, 0) + np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], "<f4").tobytes(),
        "flat",
    ),
    "a bare point that is not a number": (
        _header(4, 0, 0, 0) + np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, np.nan]], "<f4").tobytes(),
        "finite",
    ),
}


@pytest.mark.parametrize("case", sorted(DAMAGED))
@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_damaged_msh_is_refused_in_one_line(tmp_path, case, form):
    data, words = DAMAGED[case]
    (tmp_path / "part.msh").write_bytes(data)
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {name: piece, shape: mesh, file: part.msh, mass: 1}\n")
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec, "--format", form), "parts[0] (piece)", "part.msh", words
    )
    robot = tmp_path / "robot.xml"
    robot.write_text(MJCF.replace("box.msh", "part.msh").replace("points.msh", "part.msh"))
    one_line_exit_2(run_rbi_inprocess("audit", robot, "--format", form), "part.msh", words)
