"""A small fast sample of the robot collections the test extra installs (the whole survey is
docs/scripts/audit_collections.py): each file audited as given in every output form (table,
JSON, CSV), never an internal error; totals and joint torques against Pinocchio (URDF) and
MuJoCo (MJCF)."""

from __future__ import annotations

import glob
import json
import os
import site

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess
from tests.robot.test_shipped_files import _pinocchio_totals, _relative_error


def _site(*parts: str) -> str | None:
    for entry in site.getsitepackages():
        candidate = os.path.join(entry, *parts)
        if os.path.exists(candidate):
            return candidate
    return None


ERD = _site("cmeel.prefix", "share", "example-robot-data", "robots")
ICUB = os.path.normpath(os.path.join(site.getsitepackages()[0], "..", "..", "..", "share", "iCub"))
GIM = _site("gym_ignition_models")
DMC = _site("dm_control")


def _sample():
    """(id, path, package paths) for a few files of each collection that is installed."""
    found = []
    if ERD:
        packages = [f"example-robot-data={os.path.dirname(ERD)}"]
        for relative in (
            "double_pendulum_description/urdf/double_pendulum.urdf",
            "ur_description/urdf/ur5_robot.urdf",  # Collada visual meshes, STL collision
            "solo_description/urdf/solo.urdf",
        ):
            found.append((f"erd:{os.path.basename(relative)}", os.path.join(ERD, relative), packages))
    if os.path.isdir(ICUB):
        path = os.path.join(ICUB, "robots", "iCubGazeboV2_5", "model.urdf")
        found.append(("icub:iCubGazeboV2_5", path, [f"iCub={ICUB}", "--geometry-none"]))
    if GIM:
        for relative in ("pendulum/pendulum.urdf", "ground_plane/ground_plane.sdf", "cartpole/cartpole.urdf"):
            name = relative.split("/")[0]
            found.append((f"gim:{relative}", os.path.join(GIM, relative), [f"{name}={GIM}/{name}"]))
    if DMC:
        for relative in ("suite/cartpole.xml", "suite/humanoid_CMU.xml", "suite/dog.xml"):
            found.append((f"dm_control:{relative}", os.path.join(DMC, relative), []))
    return [each for each in found if os.path.exists(each[1])]


SAMPLE = _sample()


@pytest.mark.skipif(not SAMPLE, reason="no robot collection installed (pip install '.[test]')")
@pytest.mark.parametrize("name, path, packages", SAMPLE, ids=[each[0] for each in SAMPLE])
def test_every_output_form_and_the_references(name, path, packages):
    options = [
        arg for package in packages if package != "--geometry-none" for arg in ("--package-path", package)
    ]
    if "--geometry-none" in packages:  # its 200 STL meshes take a minute: the declared inertials only
        options += ["--geometry", "none"]
    outputs = {}
    for form in ("json", "csv", "table"):
        proc = run_rbi_inprocess("audit", path, "--format", form, *options)
        assert proc.returncode in (0, 1), (form, proc.stderr)
        assert "internal error" not in proc.stderr.lower() and "Traceback" not in proc.stderr
        outputs[form] = proc.stdout
    result = json.loads(outputs["json"])
    assert len(outputs["csv"].strip().splitlines()) == len(result["links"]) + 1
    if path.endswith(".urdf"):
        _against_pinocchio(path, result)
    elif path.endswith(".xml"):
        _against_mujoco(path, result)


def _against_pinocchio(path, result):
    pin = pytest.importorskip("pinocchio")
    expected = _pinocchio_totals(path)
    if expected is not None and expected[0] > 0:
        assert result["total"]["mass"] == pytest.approx(expected[0], rel=1e-12)
        assert _relative_error(result["total"]["inertia_about_com"], expected[2]) < 1e-12
    model = pin.buildModelFromUrdf(path)
    g = pin.computeGeneralizedGravity(model, model.createData(), pin.neutral(model))
    ours = {each["name"]: each["torque"] for each in result["joints"]}
    scale = max(float(np.max(np.abs(g))) if len(g) else 0.0, 1e-9)
    for jid in range(1, model.njoints):
        if model.joints[jid].nv == 1:
            assert abs(ours[model.names[jid]] - g[model.joints[jid].idx_v]) <= 1e-12 * scale


def _against_mujoco(path, result):
    mujoco = pytest.importorskip("mujoco")
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert result["total"]["mass"] == pytest.approx(model.body_subtreemass[0], rel=1e-12)
    np.testing.assert_allclose(result["total"]["center_of_mass"], data.subtree_com[0], rtol=1e-10, atol=1e-12)
    ours = {each["name"]: each["torque"] for each in result["joints"]}
    scale = max(float(np.max(np.abs(data.qfrc_bias))), 1e-9)
    for j in range(model.njnt):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j)
        if model.jnt_type[j] in (2, 3) and name in ours:
            assert abs(ours[name] - data.qfrc_bias[model.jnt_dofadr[j]]) <= 1e-10 * scale


def test_the_sample_covers_each_kind_of_file():
    kinds = {os.path.splitext(path)[1] for _, path, _ in SAMPLE}
    if ERD and GIM and DMC:
        assert kinds >= {".urdf", ".sdf", ".xml"}
        meshes = glob.glob(os.path.join(ERD, "ur_description", "meshes", "**", "*.dae"), recursive=True)
        assert meshes  # the Collada meshes the UR5 sample reads
