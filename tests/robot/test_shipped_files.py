"""Every robot file the test dependencies ship, read once each by `rbi audit`'s reader and
compared with an independent reader: MuJoCo's compiler (body mass, CoM, inertia; subtree mass
and CoM after mj_forward) for gymnasium's MJCF assets, Pinocchio (total mass, CoM, centroidal
inertia) for pybullet_data's URDFs. The files that are refused are refused for a defect of the
file itself, named here with the reason."""

from __future__ import annotations

import glob
import json
import os
import time

import numpy as np
import pytest

from rbi.errors import InputError
from tests.conftest import run_rbi_inprocess

pybullet_data = pytest.importorskip("pybullet_data")
gymnasium = pytest.importorskip("gymnasium")

PYBULLET = pybullet_data.getDataPath()
GYM = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")

_ALL_URDFS = sorted(glob.glob(os.path.join(PYBULLET, "**", "*.urdf"), recursive=True))
_RANDOM = [f for f in _ALL_URDFS if f"{os.sep}random_urdfs{os.sep}" in f]
# the 1000 generated blobs are alike (one mesh, one placeholder inertia): every 20th is audited here
URDFS = [f for f in _ALL_URDFS if f not in _RANDOM] + _RANDOM[::20]
MJCFS = sorted(glob.glob(os.path.join(GYM, "*.xml")))
SDFS = sorted(glob.glob(os.path.join(PYBULLET, "**", "*.sdf"), recursive=True))

REFUSED = {  # file (relative to pybullet_data) → words of the one-line reason; defects of the files
    "bicycle/bike.urdf": "'0.07,'",  # a comma inside xyz
    "husky/husky.urdf": "$(optenv",  # an unexpanded xacro expression
    "quadruped/microtaur/microtaur.urdf": "got 4",  # four numbers in an rpy
    "racecar/racecar_differential.urdf": "scale: expected 1 or 3",  # scale="1 1 1 1"
    "differential/diff_ring.urdf": "no such file",  # mesh path relative to the wrong folder
    "kuka_iiwa/model_for_sdf.urdf": "no such file",  # names meshes/coarse/, not shipped
    "kuka_iiwa/model2.sdf": "no such file",  # meshes/coarse/ again
    "kuka_iiwa/kuka_world.sdf": "no such file",
    "kuka_iiwa/kuka_with_gripper.sdf": "leaves the robot file's folder",  # an absolute /meshes/link_0.stl
    "kuka_iiwa/kuka_with_gripper2.sdf": "leaves the robot file's folder",
    "torus_deform.urdf": "no <link>",  # a deformable body: pybullet's loadSoftBody, not a robot
}

TIMES: dict[str, float] = {}


def _every_form_agrees(path: str, report) -> None:
    """The command's table, JSON and CSV of ``path`` are well formed and hold the API's report:
    the same links, totals and exit code (each form once had a model of its own)."""
    from tests.robot.test_output_forms import _three_forms

    assert _three_forms(path) == len(report.links)
    proc = run_rbi_inprocess("audit", path, "--format", "json")
    assert proc.returncode == report.exit_code
    document = json.loads(proc.stdout)
    assert document["total"]["mass"] == report.total.mass
    assert document["total"]["center_of_mass"] == list(report.total.center_of_mass)


def _refused_in_every_form(path: str, words: str) -> None:
    for form in ("table", "json", "csv"):
        proc = run_rbi_inprocess("audit", path, "--format", form)
        assert proc.returncode == 2 and words in proc.stderr and proc.stdout == "", proc.stderr
        assert len(proc.stderr.strip().splitlines()) == 1


def _relative(path: str) -> str:
    return os.path.relpath(path, PYBULLET).replace(os.sep, "/")


def _audit(path: str):
    """Audit with the default mesh inertia, auto: exact where a mesh is closed, its convex hull
    (flagged ``mesh``) where not; a flat mesh (stadium.sdf's) is left out, flagged."""
    from rbi.robot import audit

    report = audit(path)
    return report, "convex" if any(f.code == "mesh" for each in report.links for f in each.flags) else "exact"


def _relative_error(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = float(np.max(np.abs(b)))
    return float(np.max(np.abs(a - b))) / scale if scale > 0 else float(np.max(np.abs(a)))


def _pinocchio_totals(path: str):
    """Pinocchio's total mass, CoM and centroidal inertia with a free-flyer root at its neutral
    pose (so the root link's frame is the world). Links whose mass is 0 get a zero inertia first:
    Pinocchio would add their rotational inertia, and the contract says a massless link adds
    nothing."""
    import xml.etree.ElementTree as ET

    pin = pytest.importorskip("pinocchio")
    text = open(path, "rb").read().lstrip().rstrip(b"\x00 \n\r\t")
    root = ET.fromstring(text)
    for inertial in root.iter("inertial"):
        mass = inertial.find("mass")
        if mass is not None and float(mass.get("value", "1")) == 0.0:
            block = inertial.find("inertia")
            if block is not None:
                for key in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz"):
                    block.set(key, "0")
    try:
        model = pin.buildModelFromXML(ET.tostring(root, encoding="unicode"), pin.JointModelFreeFlyer())
    except (RuntimeError, ValueError):
        return None
    data = model.createData()
    q = pin.neutral(model)
    pin.centerOfMass(model, data, q)
    pin.ccrba(model, data, q, np.zeros(model.nv))
    return float(data.mass[0]), np.array(data.com[0]), np.array(data.Ig.inertia)


@pytest.mark.parametrize("path", URDFS, ids=_relative)
def test_pybullet_urdf(path, record_property):
    from rbi.formats.robot_files import read_robot
    from rbi.robot.tree import totals

    start = time.perf_counter()
    relative = _relative(path)
    if relative in REFUSED:
        with pytest.raises(InputError) as caught:
            _audit(path)
        message = str(caught.value)
        assert REFUSED[relative] in message and len(message.splitlines()) == 1
        _refused_in_every_form(path, REFUSED[relative])
        TIMES[relative] = time.perf_counter() - start
        return
    if relative == "random_urdfs/168/168.urdf":
        with pytest.raises(InputError, match="coordinates must be finite"):
            _audit(path)
        return
    report, mode = _audit(path)
    _every_form_agrees(path, report)
    expected = _pinocchio_totals(path)
    if expected is not None:
        mass, com, inertia = expected
        total = totals(read_robot(path, geometry=False))
        assert total.mass == pytest.approx(mass, rel=1e-12, abs=0)
        if mass > 0:
            assert (
                _relative_error(total.center_of_mass, com) < 1e-12
                or np.max(np.abs(total.center_of_mass - com)) < 1e-15
            )
            assert _relative_error(total.inertia_about_com, inertia) < 1e-12
        assert report.total.mass == total.mass
    TIMES[relative] = time.perf_counter() - start
    record_property("seconds", TIMES[relative])


@pytest.mark.parametrize("path", MJCFS, ids=os.path.basename)
def test_gymnasium_mjcf_agrees_with_mujoco(path):
    """Every body: mass, CoM and inertia (MuJoCo's principal form turned back into body axes) to
    1e-9 relative; the totals against mj_forward's subtree mass and CoM of the world body."""
    mujoco = pytest.importorskip("mujoco")
    from rbi.robot import audit

    report = audit(path)
    _every_form_agrees(path, report)
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert len(report.links) == model.nbody - 1
    for each in report.links:
        body = model.body(each.link.name).id if each.link.name else each.link.index + 1
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, model.body_iquat[body])
        R = R.reshape(3, 3)
        reference = R @ np.diag(model.body_inertia[body]) @ R.T
        declared = each.declared
        assert declared.mass == pytest.approx(model.body_mass[body], rel=1e-9)
        scale = max(float(np.max(np.abs(model.body_ipos[body]))), 1e-300)
        assert np.max(np.abs(declared.center_of_mass - model.body_ipos[body])) <= 1e-9 * scale
        assert _relative_error(declared.inertia_about_com, reference) < 1e-9
        assert not each.has_error, each.flags  # MuJoCo compiled these: nothing unphysical
    assert report.total.mass == pytest.approx(model.body_subtreemass[0], rel=1e-9)
    assert _relative_error(report.total.center_of_mass, data.subtree_com[0]) < 1e-9


@pytest.mark.parametrize("path", SDFS, ids=_relative)
def test_pybullet_sdf(path):
    """Read, or refused for a defect of the file; the totals are the sum of the links' masses."""
    relative = _relative(path)
    if relative in REFUSED:
        with pytest.raises(InputError) as caught:
            _audit(path)
        assert REFUSED[relative] in str(caught.value)
        _refused_in_every_form(path, REFUSED[relative])
        return
    report, _ = _audit(path)
    _every_form_agrees(path, report)
    masses = [each.declared.mass for each in report.links if each.declared is not None]
    assert report.total.mass == pytest.approx(sum(masses), rel=1e-12)
