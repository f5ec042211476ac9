"""MJCF bodies may be unnamed: a child of an unnamed body still sits in its parent's frame
(the tree used to join bodies by name, so such a child lost its parent's pose)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess

mujoco = pytest.importorskip("mujoco")

NESTED = """<mujoco><worldbody>
  <body pos="1 0 0"><geom type="box" size=".1 .1 .1" mass="1"/>
    <body pos="0 0.5 0"><geom type="box" size=".1 .2 .1" mass="3"/>
      <body name="child" pos="0 0 1" euler="0 90 0">
        <joint name="hinge" type="hinge" axis="0 1 0"/>
        <geom type="capsule" fromto="0 0 0 0.4 0 0" size=".05" mass="2"/>
      </body>
    </body>
  </body>
</worldbody></mujoco>"""


def test_children_of_unnamed_bodies_keep_their_parents_pose(tmp_path):
    path = tmp_path / "nested.xml"
    path.write_text(NESTED)
    proc = run_rbi_inprocess("audit", path, "--format", "json")
    assert proc.returncode in (0, 1), proc.stderr
    total = json.loads(proc.stdout)["total"]
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert total["mass"] == pytest.approx(model.body_subtreemass[0], rel=1e-12)
    np.testing.assert_allclose(total["center_of_mass"], data.subtree_com[0], rtol=0, atol=1e-12)
    joints = {j["name"]: j for j in json.loads(proc.stdout)["joints"]}
    # the capsule's weight about the hinge: MuJoCo's gravity bias force at rest
    assert joints["hinge"]["torque"] == pytest.approx(data.qfrc_bias[0], abs=1e-12)
