"""Joint holding torques: each joint's generalised gravity force, against a closed form, against
Pinocchio's computeGeneralizedGravity (URDF) and MuJoCo's qfrc_bias at zero velocity (MJCF), in
every output form; the `effort` warning when the torque exceeds the declared limit."""

from __future__ import annotations

import json
import math
import os

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES, run_rbi_inprocess

ARM = """<robot name="arm">
  <link name="base"/>
  <link name="upper"><inertial><origin xyz="0.25 0 0"/><mass value="2"/>
    <inertia ixx="0.001" iyy="0.04" izz="0.04" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="fore"><inertial><origin xyz="0.2 0 0"/><mass value="1"/>
    <inertia ixx="0.001" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="slider"><inertial><mass value="0.5"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit effort="LIMIT" velocity="1" lower="-3" upper="3"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/><origin xyz="0.5 0 0"/>
    <axis xyz="0 1 0"/><limit effort="50" velocity="1" lower="-3" upper="3"/></joint>
  <joint name="lift" type="prismatic"><parent link="fore"/><child link="slider"/><origin xyz="0.4 0 0"/>
    <axis xyz="0 0 1"/><limit effort="100" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""


def _audit(path, *args, form="json"):
    proc = run_rbi_inprocess("audit", str(path), "--format", form, *args)
    return proc, (json.loads(proc.stdout) if form == "json" and proc.stdout.strip() else None)


def test_closed_form_arm_and_the_effort_flag(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM.replace("LIMIT", "10"))
    g = 9.81
    for angle in (0.0, 0.7):
        proc, result = _audit(path, "--joints", f"shoulder={angle}")
        joints = {j["name"]: j for j in result["joints"]}
        assert set(joints) == {"shoulder", "elbow", "lift"}
        # turning +angle about +y tips the arm's x axis down (z = -x sin(angle)): V = m g z falls as
        # the angle grows, so dV/dq (the effort that holds the arm) is negative
        c = math.cos(angle)
        shoulder = -g * c * (2 * 0.25 + 1 * (0.5 + 0.2) + 0.5 * (0.5 + 0.4))
        elbow = -g * c * (1 * 0.2 + 0.5 * 0.4)
        assert joints["shoulder"]["torque"] == pytest.approx(shoulder, rel=1e-14)
        assert joints["elbow"]["torque"] == pytest.approx(elbow, rel=1e-14)
        assert joints["lift"]["torque"] == pytest.approx(0.5 * g * c, rel=1e-14)  # lift's axis turns too
        assert joints["shoulder"]["effort_limit"] == 10.0 and joints["shoulder"]["type"] == "revolute"
        assert [(f["code"], f["level"]) for f in joints["shoulder"]["flags"]] == [("effort", "warning")]
        assert joints["elbow"]["flags"] == [] and joints["lift"]["type"] == "prismatic"
        assert proc.returncode == 0  # a warning does not fail the audit
    table = run_rbi_inprocess("audit", str(path), "--format", "table")
    assert "shoulder" in table.stdout and "margin" in table.stdout and "effort" in table.stdout
    assert run_rbi_inprocess("audit", str(path), "--format", "csv").returncode == 0


def _pybullet(name):
    data = pytest.importorskip("pybullet_data")
    return os.path.join(data.getDataPath(), name)


@pytest.mark.parametrize(
    "name", ["kuka_iiwa/model.urdf", "franka_panda/panda.urdf", "r2d2.urdf", "quadruped/minitaur.urdf"]
)
def test_agree_with_pinocchio_generalized_gravity(name):
    pin = pytest.importorskip("pinocchio")
    from rbi.robot import audit

    path = _pybullet(name)
    model = pin.buildModelFromUrdf(path)
    data = model.createData()
    rng = np.random.default_rng(7)
    q = pin.neutral(model)
    values = {}
    for jid in range(1, model.njoints):
        joint, jname = model.joints[jid], model.names[jid]
        angle = float(rng.uniform(-1, 1))
        if joint.nq == 1:
            q[joint.idx_q] = angle
        elif joint.nq == 2:  # continuous: cos, sin
            q[joint.idx_q : joint.idx_q + 2] = [math.cos(angle), math.sin(angle)]
        else:
            continue
        values[jname] = angle
    expected = pin.computeGeneralizedGravity(model, data, q)
    report = audit(path, geometry="none", joints=values)
    ours = {each.name: each.torque for each in report.joints}
    scale = report.total.mass * 9.81 * 1.0  # N·m per metre of reach
    for jid in range(1, model.njoints):
        if model.joints[jid].nv == 1:
            assert ours[model.names[jid]] == pytest.approx(
                expected[model.joints[jid].idx_v], rel=1e-12, abs=1e-14 * scale
            )


@pytest.mark.parametrize("name", ["ant.xml", "humanoid.xml", "walker2d.xml", "inverted_double_pendulum.xml"])
def test_agree_with_mujoco_bias_force_at_zero_velocity(name):
    mujoco = pytest.importorskip("mujoco")
    gymnasium = pytest.importorskip("gymnasium")
    from rbi.robot import audit

    path = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets", name)
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    rng = np.random.default_rng(3)
    values = {}
    for j in range(model.njnt):
        if model.jnt_type[j] in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
            value = float(rng.uniform(-0.5, 0.5))
            data.qpos[model.jnt_qposadr[j]] = value
            values[mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j)] = value
    mujoco.mj_forward(model, data)
    report = audit(path, geometry="none", joints=values)
    ours = {each.name: each.torque for each in report.joints}
    scale = float(np.max(np.abs(data.qfrc_bias)))
    for name_ in values:
        dof = model.jnt_dofadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name_)]
        assert ours[name_] == pytest.approx(data.qfrc_bias[dof], rel=1e-12, abs=1e-14 * scale)


def test_mjcf_effort_limit_from_actuators_and_gravity_option(tmp_path):
    text = """<mujoco><option gravity="0 0 -3"/><worldbody>
      <body name="a"><joint name="h" type="hinge" axis="0 1 0"/><geom type="sphere" size="0.1" pos="1 0 0" mass="2"/></body>
      <body name="b" pos="0 2 0"><joint name="k" type="hinge" axis="0 1 0" actuatorfrcrange="-1 4"/>
        <geom type="sphere" size="0.1" pos="1 0 0" mass="2"/></body>
    </worldbody><actuator><motor joint="h" gear="5" forcerange="-2 2"/></actuator></mujoco>"""
    path = tmp_path / "m.xml"
    path.write_text(text)
    _, result = _audit(path)
    joints = {j["name"]: j for j in result["joints"]}
    assert joints["h"]["torque"] == pytest.approx(-6.0, rel=1e-14)  # 2 kg × 3 m/s² × 1 m
    assert joints["h"]["effort_limit"] == 10.0 and joints["h"]["flags"] == []
    assert joints["k"]["effort_limit"] == 4.0
    assert [f["code"] for f in joints["k"]["flags"]] == ["effort"]


def test_the_joints_table_shows_names_as_text(tmp_path):
    # a joint name is data: rich markup in it is shown, not applied, and a bidirectional override
    # is escaped; the lift joint's axis is vertical at angle 0, so its torque is 0.5 kg × g
    arm = ARM.replace("LIMIT", "10").replace('name="elbow"', 'name="[red]elbow\u202e"')
    path = tmp_path / "arm.urdf"
    path.write_text(arm, encoding="utf-8")
    proc = run_rbi_inprocess("audit", str(path), "--format", "table")
    assert proc.returncode == 0, proc.stderr
    assert "[red]elbow\\u202e" in proc.stdout and "\u202e" not in proc.stdout
    assert " 4.905 " in proc.stdout


@pytest.mark.parametrize("value", ["1e200", "-1e200", "2e7"])
def test_a_joint_angle_rounding_would_lose_is_refused_naming_the_file_and_joint(value):
    """A revolute joint at 1e200 rad is some angle, not the one meant (doubles there are far more
    than a turn apart): refused like `--tilt 1e300` (at most 1e9 degrees, 1.745e7 rad)."""
    arm = str(BODIES / "two_link_arm.urdf")
    for form in ("table", "json", "csv"):
        proc = run_rbi_inprocess("audit", arm, "--joints", f"shoulder={value}", "--format", form)
        assert proc.returncode == 2 and proc.stdout == "", proc.stderr
        assert len(proc.stderr.strip().splitlines()) == 1
        assert (
            "two_link_arm.urdf" in proc.stderr and "'shoulder'" in proc.stderr and "too large" in proc.stderr
        )
    with pytest.raises(ValueError, match="joints: .*'shoulder'"):
        rbi.audit(arm, joints={"shoulder": float(value)})
    # 1.7e7 rad is still a turn rounding keeps: accepted
    assert rbi.audit(arm, joints={"shoulder": 1.7e7}).exit_code in (0, 1)


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_torque_that_overflows_is_one_line_naming_the_joint(tmp_path, form):
    """Found: a body placed 1e308 m up (MJCF) gave the hinge below it a torque of NaN: the table
    printed 'nan' and --format json was 'rbi: internal error: ValueError: Out of range float
    values are not JSON compliant' (exit 1). Now exit 2, one line naming the joint, and numpy
    prints no RuntimeWarning on the way."""
    import warnings

    text = (
        '<mujoco><worldbody><body name="a" pos="0 0 1e308"><freejoint/><geom type="box" size="0.1 0.1 0.1"/>'
        '<body name="b" pos="0 0 0.2"><joint name="h" axis="0 1 0"/><geom size="0.05" pos="0.1 0 0" mass="2"/></body></body>'
        "</worldbody></mujoco>"
    )
    path, message = _refused_in_one_line(tmp_path / "far.xml", text, form)
    assert "far.xml: body[1] (b): joint 'h': the torque that holds the pose overflows" in message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rbi.SpecError, match="joint 'h'"):
            rbi.audit(path)


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_an_actuator_force_limit_that_overflows_is_one_line(tmp_path, form):
    """Found: a motor with forcerange ±1e155 and gear 1e155 gave its joint an effort limit of
    inf: --format json was 'rbi: internal error: ValueError: Out of range float values are not
    JSON compliant' (exit 1). Now exit 2, one line naming the actuator."""
    text = (
        '<mujoco><worldbody><body name="a"><joint name="h" axis="0 1 0"/><geom size="0.05" pos="0.1 0 0"/>'
        '</body></worldbody><actuator><motor joint="h" gear="1e155" forcerange="-1e155 1e155" '
        'forcelimited="true"/></actuator></mujoco>'
    )
    _, message = _refused_in_one_line(tmp_path / "geared.xml", text, form)
    assert (
        "geared.xml: actuator 'h': forcerange times gear 1e+155: the joint's force limit overflows" in message
    )


def _refused_in_one_line(path, text, form):
    """``text`` written to ``path`` and audited in ``form``: exit 2 with one line on stderr.
    Returns the path and that line."""
    path.write_text(text)
    proc = run_rbi_inprocess("audit", str(path), "--format", form)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    return path, proc.stderr
