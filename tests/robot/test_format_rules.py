"""What each format's own readers do, rbi does: SDFormat's default and automatic inertials,
MuJoCo's compiler refusals (checked against mujoco itself), urdfdom/pybullet's URDF refusals."""

from __future__ import annotations

import json

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess

BOX = "<geometry><box><size>0.2 0.1 0.05</size></box></geometry>"


def sdf(*links: str) -> str:
    return f'<?xml version="1.0"?><sdf version="1.11"><model name="m">{"".join(links)}</model></sdf>'


def audit(tmp_path, name, text, *args):
    path = tmp_path / name
    path.write_text(text)
    proc = run_rbi_inprocess("audit", str(path), "--format", "json", *args)
    return proc, (json.loads(proc.stdout) if proc.stdout.strip() else None)


def box_moments(m, a=0.2, b=0.1, c=0.05):
    return m / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])


def test_sdf_link_without_inertial_has_sdformats_default_and_a_placeholder_warning(tmp_path):
    proc, result = audit(
        tmp_path, "m.sdf", sdf(f'<link name="a"><collision name="c">{BOX}</collision></link>')
    )
    assert proc.returncode == 0, proc.stderr
    link = result["links"][0]
    assert link["declared"]["mass"] == 1.0
    np.testing.assert_array_equal(link["declared"]["inertia_about_com"], np.eye(3))
    assert [(f["code"], f["level"]) for f in link["flags"]] == [("placeholder", "warning")]
    assert result["total"]["mass"] == 1.0


@pytest.mark.parametrize("mass", [None, 2.0])
def test_sdf_auto_inertial_from_collisions_and_their_density(tmp_path, mass):
    given = f"<mass>{mass}</mass>" if mass else ""
    link = (
        f'<link name="a"><inertial auto="true">{given}</inertial>'
        f'<collision name="c"><density>500</density>{BOX}</collision>'
        '<collision name="d"><pose>1 0 0 0 0 0</pose><geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link>'
    )
    proc, result = audit(tmp_path, "m.sdf", sdf(link), "--geometry", "none")
    assert proc.returncode == 0, proc.stderr
    box_mass, sphere_mass = 500 * 0.001, 1000 * 4 / 3 * np.pi * 0.1**3
    total = box_mass + sphere_mass
    declared = result["links"][0]["declared"]
    scale = (mass / total) if mass else 1.0
    assert declared["mass"] == pytest.approx(total * scale, rel=1e-14)
    np.testing.assert_allclose(declared["center_of_mass"], [sphere_mass / total, 0, 0], rtol=1e-14)
    d = np.array([1.0, 0, 0]) - declared["center_of_mass"]
    expected = (
        np.diag(box_moments(box_mass))
        + box_mass
        * (
            np.dot(declared["center_of_mass"], declared["center_of_mass"]) * np.eye(3)
            - np.outer(declared["center_of_mass"], declared["center_of_mass"])
        )
        + np.eye(3) * 0.4 * sphere_mass * 0.01
        + sphere_mass * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    )
    np.testing.assert_allclose(declared["inertia_about_com"], expected * scale, rtol=1e-12, atol=1e-18)


MJCF_CASES = {
    "no_mass_body_moves": '<body name="a"><joint type="hinge"/><body name="b" pos="1 0 0"><joint type="hinge"/><geom size="0.1"/></body></body>',
    "density_zero": '<body name="a"><joint type="hinge"/><geom size="0.1" density="0"/></body>',
    "density_negative": '<body name="a"><joint type="hinge"/><geom size="0.1" density="-5"/></body>',
    "density_negative_static": '<body name="a"><geom size="0.1" density="-5"/></body>',
    "inertial_mass_0": '<body name="a"><joint type="hinge"/><inertial pos="0 0 0" mass="0" diaginertia="1 1 1"/></body>',
    "inertial_mass_0_static": '<body name="a"><inertial pos="0 0 0" mass="0" diaginertia="0 0 0"/></body>',
    "geom_mass_negative": '<body name="a"><joint type="hinge"/><geom size="0.1" mass="-1"/></body>',
    "mass_wins_over_density": '<body name="a"><joint type="hinge"/><geom size="0.1" mass="1" density="-1"/></body>',
    "free_without_mass": '<body name="a"><freejoint/></body>',
    "ok": '<body name="a"><joint type="hinge"/><geom size="0.1"/></body>',
    "duplicate_joint_names": '<body name="a"><joint name="j" type="hinge"/><geom size="0.1"/>'
    '<body name="b" pos="1 0 0"><joint name="j" type="slide"/><geom size="0.1"/></body></body>',
    # a massless moving body carried by a child welded to it (no joint) with mass: MuJoCo accepts
    "welded_child_carries_mass": '<body name="a"><joint type="hinge"/><geom size="0.1" mass="0"/>'
    '<body name="b" pos="0.5 0 0"><geom size="0.1" mass="2"/></body></body>',
    "welded_grandchild_only": '<body name="a"><joint type="hinge"/><body name="b"><body name="c" pos="1 0 0">'
    '<geom size="0.1"/></body></body></body>',
    "welded_child_without_inertia": '<body name="a"><joint type="hinge"/><body name="b">'
    '<inertial pos="0 0 0" mass="1" diaginertia="1 1 0"/></body></body>',
    "welded_child_inertial": '<body name="a"><joint type="hinge"/><inertial pos="0 0 0" mass="0" '
    'diaginertia="1 1 1"/><body name="b"><inertial pos="1 0 0" mass="1" diaginertia="1 1 1"/></body></body>',
    # free joints: only at the top level (a <frame> is not a level), at most 6 degrees of freedom
    "free_below_top": '<body name="a"><geom size="0.1"/><body name="b"><freejoint/><geom size="0.1"/></body></body>',
    "free_type_below_top": '<body name="a"><geom size="0.1"/><body name="b"><joint type="free"/>'
    '<geom size="0.1"/></body></body>',
    "free_in_frame_at_top": '<frame pos="1 0 0"><body name="a"><freejoint/><geom size="0.1"/></body></frame>',
    "free_and_hinge": '<body name="a"><freejoint/><joint type="hinge"/><geom size="0.1"/></body>',
    "two_free": '<body name="a"><freejoint/><freejoint/><geom size="0.1"/></body>',
    "two_balls": '<body name="a"><joint type="ball"/><joint type="ball"/><geom size="0.1"/></body>',
    "hinge_then_ball": '<body name="a"><joint type="hinge"/><joint type="ball"/><geom size="0.1"/></body>',
    "ball_then_hinge": '<body name="a"><joint type="ball"/><joint type="hinge"/><geom size="0.1"/></body>',
    "ball_then_three_slides": '<body name="a"><joint type="ball"/><joint type="slide" axis="1 0 0"/>'
    '<joint type="slide" axis="0 1 0"/><joint type="slide"/><geom size="0.1"/></body>',
    "six_hinges": '<body name="a">'
    + "".join(f'<joint axis="{a}"/>' for a in ["1 0 0", "0 1 0", "0 0 1"] * 2)
    + '<geom size="0.1"/></body>',
    "seven_hinges": '<body name="a">'
    + "".join(f'<joint axis="{a}"/>' for a in ["1 0 0", "0 1 0", "0 0 1"] * 2)
    + '<joint/><geom size="0.1"/></body>',
    "ball_and_four_hinges": '<body name="a"><joint type="ball"/><joint axis="1 0 0"/><joint axis="0 1 0"/>'
    '<joint axis="0 0 1"/><joint axis="1 0 0"/><geom size="0.1"/></body>',
}


@pytest.mark.parametrize("case", sorted(MJCF_CASES))
def test_mjcf_refused_exactly_when_mujoco_refuses(tmp_path, case):
    mujoco = pytest.importorskip("mujoco")
    text = f"<mujoco><worldbody>{MJCF_CASES[case]}</worldbody></mujoco>"
    try:
        mujoco.MjModel.from_xml_string(text)
        refused = False
    except ValueError:
        refused = True
    proc, _ = audit(tmp_path, "m.xml", text)
    assert (proc.returncode == 2) is refused, proc.stderr
    if refused:
        assert len(proc.stderr.strip().splitlines()) == 1 and "m.xml" in proc.stderr


URDF_REFUSED = {
    "no link": ('<robot name="r"><joint name="j" type="fixed"/></robot>', "no <link>"),
    "unnamed link": ('<robot name="r"><link/></robot>', "name: missing"),
    "two roots": ('<robot name="r"><link name="a"/><link name="b"/></robot>', "2 root links"),
    "attribute default": (
        '<?xml version="1.0"?><!DOCTYPE robot [<!ATTLIST mass value CDATA "5">]><robot name="r"><link name="a">'
        '<inertial><mass/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>',
        "default",
    ),
    "closed chain": (
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j1" type="fixed"><parent link="a"/><child link="c"/></joint>'
        '<joint name="j2" type="fixed"><parent link="b"/><child link="c"/></joint></robot>',
        "loop",
    ),
    "duplicate joint name": (
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
        '<joint name="j" type="fixed"><parent link="a"/><child link="c"/></joint></robot>',
        "duplicate joint name 'j'",
    ),
    "unnamed joint": (
        '<robot name="r"><link name="a"/><link name="b"/>'
        '<joint type="fixed"><parent link="a"/><child link="b"/></joint></robot>',
        "name: missing",
    ),
}


@pytest.mark.parametrize("case", ["duplicate joint name", "unnamed joint"])
def test_urdfdom_refuses_the_joint_name_cases_too(tmp_path, case):
    """The refusals rbi adds for joints are urdfdom's (read through Pinocchio)."""
    pin = pytest.importorskip("pinocchio")
    path = tmp_path / "r.urdf"
    path.write_text(URDF_REFUSED[case][0])
    with pytest.raises(ValueError):
        pin.buildModelFromUrdf(str(path))


@pytest.mark.parametrize("case", sorted(URDF_REFUSED))
def test_urdf_refusals_of_urdfdom_and_pybullet(tmp_path, case):
    text, words = URDF_REFUSED[case]
    for command in (("audit",), ("import",), ("validate",)):
        path = tmp_path / "r.urdf"
        path.write_text(text)
        proc = run_rbi_inprocess(*command, str(path))
        assert proc.returncode == 2, (command, proc.stdout, proc.stderr)
        message = (proc.stderr + proc.stdout).strip()
        assert words in message and "r.urdf" in message and "Traceback" not in message


def test_import_and_validate_take_package_path(tmp_path):
    package = tmp_path / "pkgs" / "my_robot"
    (package / "meshes").mkdir(parents=True)
    (package / "meshes" / "box.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n"
    )
    robot = tmp_path / "robot" / "r.urdf"
    robot.parent.mkdir()
    robot.write_text(
        '<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="0.16" iyy="0.16" izz="0.16" '
        'ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry><mesh filename="package://my_robot/meshes/box.obj"/>'
        "</geometry></collision></link></robot>"
    )
    option = ("--package-path", f"my_robot={package}")
    for command in ("validate", "import"):
        without = run_rbi_inprocess(command, str(robot))
        assert without.returncode == 2 and "--package-path my_robot=DIR" in without.stderr + without.stdout
        assert (without.stderr + without.stdout).count("package://my_robot/meshes/box.obj") == 1
        assert run_rbi_inprocess(command, str(robot), *option).returncode == 0
    for form in ("json", "csv", "table"):
        assert run_rbi_inprocess("audit", str(robot), *option, "--format", form).returncode == 0


def test_centres_of_mass_whose_squares_overflow_are_refused_naming_the_file(tmp_path):
    link = '<link name="{}"><inertial><origin xyz="{} 0 0"/><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>'
    text = (
        f'<robot name="r">{link.format("a", "1e155")}{link.format("b", "0")}'
        '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>'
    )
    path = tmp_path / "far.urdf"
    path.write_text(text)
    for form in ("table", "json", "csv"):
        proc = run_rbi_inprocess("audit", str(path), "--format", form)
        assert proc.returncode == 2 and proc.stdout == ""
        assert "far.urdf" in proc.stderr and "overflow" in proc.stderr


L_PRISM = (
    "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0.5\nv 3 0 0.5\nv 3 1 0.5\nv 1 1 0.5\nv 1 2 0.5\nv 0 2 0.5\n"
    "f 1 3 2\nf 7 8 9\nf 1 4 3\nf 7 9 10\nf 1 5 4\nf 7 10 11\nf 1 6 5\nf 7 11 12\n"
    "f 1 2 8\nf 1 8 7\nf 2 3 9\nf 2 9 8\nf 3 4 10\nf 3 10 9\nf 4 5 11\nf 4 11 10\nf 5 6 12\nf 5 12 11\nf 6 1 7\nf 6 7 12\n"
)


@pytest.mark.parametrize("mode", [None, "legacy", "exact", "convex", "shell"])
def test_mjcf_mesh_inertia_modes_as_mujoco_computes_them(tmp_path, mode):
    """A non-convex L-shaped prism: legacy (MuJoCo's default) differs from exact by 4 % in mass."""
    mujoco = pytest.importorskip("mujoco")
    (tmp_path / "l.obj").write_text(L_PRISM)
    attribute = f' inertia="{mode}"' if mode else ""
    text = (
        f'<mujoco><asset><mesh name="m" file="l.obj"{attribute}/></asset><worldbody><body name="b">'
        '<freejoint/><geom type="mesh" mesh="m" pos="0.3 0 0"/></body></worldbody></mujoco>'
    )
    path = tmp_path / "m.xml"
    path.write_text(text)
    model = mujoco.MjModel.from_xml_path(str(path))
    _, result = audit(tmp_path, "m.xml", text)
    declared = result["links"][0]["declared"]
    assert declared["mass"] == pytest.approx(model.body_mass[1], rel=1e-12)
    np.testing.assert_allclose(declared["center_of_mass"], model.body_ipos[1], rtol=1e-12)
    np.testing.assert_allclose(declared["moments"], np.sort(model.body_inertia[1]), rtol=1e-12)


def _decimal_prism(drop: int) -> str:
    """L_PRISM with coordinates no float32 holds exactly (×0.1234567, seven decimals), less its
    last ``drop`` faces (an open mesh when ``drop`` > 0)."""
    lines = L_PRISM.splitlines()
    vertices = [
        "v " + " ".join(f"{float(x) * 0.1234567 + 0.0100001:.7f}" for x in line.split()[1:])
        for line in lines
        if line.startswith("v ")
    ]
    faces = [line for line in lines if line.startswith("f ")]
    return "\n".join(vertices + faces[: len(faces) - drop]) + "\n"


@pytest.mark.parametrize("drop", [0, 2])
@pytest.mark.parametrize("mode", ["legacy", "exact", "convex", "shell"])
def test_mjcf_mesh_bodies_as_mujoco_compiles_them_from_single_precision_vertices(tmp_path, mode, drop):
    """MuJoCo keeps a mesh's vertices as float32 and integrates an open mesh in every mode
    (``exact`` by signed volumes): the declared mass properties match its compiled body to 1e-12
    (a double reading of the file was 1e-8 off in inertia); the audit's own geometry of the open
    mesh in ``exact`` is its convex hull with a warning-level ``mesh`` flag, not a refusal."""
    mujoco = pytest.importorskip("mujoco")
    (tmp_path / "l.obj").write_text(_decimal_prism(drop))
    text = (
        f'<mujoco><asset><mesh name="m" file="l.obj" inertia="{mode}" scale="1 2 0.5"/></asset><worldbody>'
        '<body name="b"><joint type="hinge" axis="0 1 0"/><geom type="mesh" mesh="m" pos="0.3 0 0"/></body>'
        "</worldbody></mujoco>"
    )
    (tmp_path / "m.xml").write_text(text)
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "m.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    proc, result = audit(tmp_path, "m.xml", text)
    assert proc.returncode == 0, proc.stderr
    link = result["links"][0]
    declared = link["declared"]
    assert declared["mass"] == pytest.approx(model.body_mass[1], rel=1e-12)
    np.testing.assert_allclose(declared["center_of_mass"], model.body_ipos[1], rtol=1e-12)
    np.testing.assert_allclose(declared["moments"], np.sort(model.body_inertia[1]), rtol=1e-12)
    assert result["joints"][0]["torque"] == pytest.approx(data.qfrc_bias[0], rel=1e-12)
    codes = [(f["code"], f["level"]) for f in link["flags"]]
    assert (("mesh", "warning") in codes) is (drop > 0 and mode == "exact")
    for form in ("table", "csv"):
        assert run_rbi_inprocess("audit", str(tmp_path / "m.xml"), "--format", form).returncode == 0


FRAMED_SDF = """<?xml version="1.0"?><sdf version="1.9"><model name="m">
  <link name="base"><inertial><mass>2</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz>
    <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial></link>
  <frame name="f1" attached_to="base"><pose>0.3 0 0.2 0 0.4 0.3</pose></frame>
  <link name="arm"><pose relative_to="f1">0.1 0.05 0 0.2 0 0</pose>
    <inertial><pose>0.25 0.01 -0.02 0.1 0.2 0.3</pose><mass>1.5</mass><inertia><ixx>0.02</ixx><iyy>0.03</iyy>
      <izz>0.04</izz><ixy>0.001</ixy><ixz>0</ixz><iyz>0.002</iyz></inertia></inertial>
    <collision name="c"><pose relative_to="f1">0.2 0 0 0 0 0</pose><geometry><box><size>0.4 0.1 0.1</size></box>
      </geometry></collision></link>
  <link name="tip"><pose relative_to="j1">0.5 0 0 0 0.3 0</pose>
    <inertial><pose>0.05 0 0 0 0 0</pose><mass>0.7</mass><inertia><ixx>0.001</ixx><iyy>0.002</iyy><izz>0.002</izz>
      <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial></link>
  <joint name="weld" type="fixed"><parent>world</parent><child>base</child></joint>
  <joint name="j1" type="revolute"><pose relative_to="arm">0 0 0.05 0 0 0</pose><parent>base</parent><child>arm</child>
    <axis><xyz expressed_in="__model__">0 1 0.3</xyz><limit><effort>5</effort></limit></axis></joint>
  <joint name="j2" type="prismatic"><parent>arm</parent><child>tip</child>
    <axis><xyz expressed_in="f1">1 0 0.2</xyz><limit><lower>-1</lower><upper>1</upper></limit></axis></joint>
</model></sdf>"""


@pytest.mark.parametrize("effort, limit", [("-1", None), ("-5", None), ("0", 0.0), ("5", 5.0)])
def test_an_sdf_negative_effort_is_no_limit(tmp_path, effort, limit):
    """SDFormat's <limit><effort>: "Limit is not enforced if value is negative" (its default is
    -1); rbi read -1 as a limit of 1 N·m and flagged the holding torque against it."""
    text = (
        '<?xml version="1.0"?><sdf version="1.9"><model name="m"><link name="base"/>'
        '<link name="arm"><inertial><pose>0.5 0 0 0 0 0</pose><mass>2</mass></inertial></link>'
        '<joint name="j" type="revolute"><parent>base</parent><child>arm</child>'
        f"<axis><xyz>0 1 0</xyz><limit><effort>{effort}</effort></limit></axis></joint></model></sdf>"
    )
    proc, result = audit(tmp_path, "effort.sdf", text)
    assert proc.returncode == 0, proc.stderr
    (joint,) = result["joints"]
    assert joint["effort_limit"] == limit
    assert [flag["code"] for flag in joint["flags"]] == ([] if limit is None else ["effort"])


@pytest.mark.parametrize("values", [{"j1": 0.7, "j2": 0.15}, {"j1": -1.2, "j2": -0.3}])
def test_sdf_poses_relative_to_other_frames_agree_with_drake(tmp_path, values):
    """SDFormat's pose graph: a link placed relative_to a <frame>, another relative_to a joint, a
    joint's pose relative_to a link, a collision relative_to a frame, axes expressed_in the model
    and in a frame: joint torques, the total centre of mass and each link's inertial as Drake's
    MultibodyPlant reads the file (before, rbi refused the first relative_to, and read a joint's
    pose relative_to another frame as if in its child link's)."""
    pydrake = pytest.importorskip("pydrake.all")
    path = tmp_path / "framed.sdf"
    path.write_text(FRAMED_SDF)
    plant = pydrake.MultibodyPlant(0.0)
    pydrake.Parser(plant).AddModels(str(path))
    plant.Finalize()
    context = plant.CreateDefaultContext()
    plant.GetJointByName("j1").set_angle(context, values["j1"])
    plant.GetJointByName("j2").set_translation(context, values["j2"])
    gravity = plant.CalcGravityGeneralizedForces(
        context
    )  # the force gravity exerts: minus the holding effort
    args = [arg for name, value in values.items() for arg in ("--joints", f"{name}={value!r}")]
    proc, result = audit(tmp_path, "framed.sdf", FRAMED_SDF, *args)
    assert proc.returncode == 0, proc.stderr
    for joint in result["joints"]:
        expected = -gravity[plant.GetJointByName(joint["name"]).velocity_start()]
        assert joint["torque"] == pytest.approx(expected, rel=1e-12, abs=1e-14)
    np.testing.assert_allclose(
        result["total"]["center_of_mass"], plant.CalcCenterOfMassPositionInWorld(context), rtol=0, atol=1e-14
    )
    for link in result["links"]:
        inertia = plant.GetBodyByName(link["name"]).default_spatial_inertia()
        about_com = inertia.Shift(inertia.get_com()).CalcRotationalInertia().CopyToFullMatrix3()
        np.testing.assert_allclose(link["declared"]["center_of_mass"], inertia.get_com(), rtol=0, atol=1e-15)
        np.testing.assert_allclose(link["declared"]["inertia_about_com"], about_com, rtol=0, atol=1e-15)
    # the box collision, 0.2 m along f1's x from f1, seen from the arm link (placed 0.1, 0.05, 0, rolled 0.2 in f1)
    box = next(each for each in result["links"] if each["name"] == "arm")["geometry"]
    roll = np.array([[1, 0, 0], [0, np.cos(0.2), -np.sin(0.2)], [0, np.sin(0.2), np.cos(0.2)]])
    np.testing.assert_allclose(
        box["center_of_mass"], roll.T @ np.array([0.1, -0.05, 0.0]), rtol=0, atol=1e-15
    )
    for form in ("table", "csv"):
        assert run_rbi_inprocess("audit", str(path), "--format", form, *args).returncode == 0


@pytest.mark.parametrize(
    "frames, words",
    [
        ('<frame name="a" attached_to="b"/><frame name="b" attached_to="a"/>', "loop"),
        ('<frame name="a" attached_to="nowhere"/>', "no link, joint or frame named 'nowhere'"),
    ],
)
def test_sdf_frames_that_loop_or_name_nothing_are_one_line_errors(tmp_path, frames, words):
    text = sdf(f'<link name="l"><pose relative_to="a">1 0 0 0 0 0</pose></link>{frames}')
    proc, _ = audit(tmp_path, "m.sdf", text)
    assert proc.returncode == 2 and words in proc.stderr and len(proc.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("extra", ["", ' settotalmass="3"', ' boundinertia="0.003"'])
def test_mjcf_balanceinertia_evens_out_moments_as_mujoco_does(tmp_path, extra):
    """``<compiler balanceinertia="true">``: a body whose moments break the triangle inequality
    (0.0008, 0.0012, 0.005 kg·m²) gets their mean as all three, before settotalmass scales it and
    after boundinertia raises it; a body that satisfies it is left alone."""
    mujoco = pytest.importorskip("mujoco")
    text = (
        f'<mujoco><compiler balanceinertia="true"{extra}/><worldbody><body name="a"><joint type="hinge"/>'
        '<inertial pos="0.1 0 0" mass="0.1" fullinertia="0.001 0.001 0.005 0.0002 0 0"/></body>'
        '<body name="b" pos="1 0 0"><joint type="hinge"/><geom type="box" size="0.1 0.2 0.3" mass="0.2"/></body>'
        "</worldbody></mujoco>"
    )
    (tmp_path / "m.xml").write_text(text)
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "m.xml"))
    proc, result = audit(tmp_path, "m.xml", text)
    assert proc.returncode == 0, proc.stderr
    for body, link in enumerate(result["links"], start=1):
        assert link["declared"]["mass"] == pytest.approx(model.body_mass[body], rel=1e-12)
        np.testing.assert_allclose(link["declared"]["moments"], np.sort(model.body_inertia[body]), rtol=1e-12)
        assert "unphysical" not in [f["code"] for f in link["flags"]]


CUBE_OBJ = (
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n"
)


@pytest.mark.parametrize("where", ["geom", "mesh"])
def test_mesh_shell_inertia_only_through_the_mesh_asset_as_mujoco(tmp_path, where):
    """MuJoCo 4 refuses shellinertia on a mesh geom ('for mesh geoms, inertia should be specified
    in the mesh asset'); <mesh inertia="shell"> is the way, and gives the unit cube's surface,
    6 m², times the density as its mass."""
    mujoco = pytest.importorskip("mujoco")
    (tmp_path / "cube.obj").write_text(CUBE_OBJ)
    mesh = (
        '<mesh name="c" file="cube.obj" inertia="shell"/>'
        if where == "mesh"
        else '<mesh name="c" file="cube.obj"/>'
    )
    geom_shell = ' shellinertia="true"' if where == "geom" else ""
    text = (
        f'<mujoco><asset>{mesh}</asset><worldbody><body name="a"><joint type="hinge"/>'
        f'<geom type="mesh" mesh="c" density="2"{geom_shell}/></body></worldbody></mujoco>'
    )
    path = tmp_path / "m.xml"
    path.write_text(text)
    if where == "geom":
        with pytest.raises(ValueError, match="inertia should be specified in the mesh asset"):
            mujoco.MjModel.from_xml_path(str(path))
        for form in ("table", "json", "csv"):
            proc = run_rbi_inprocess("audit", str(path), "--format", form)
            assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
            assert "m.xml" in proc.stderr and "shellinertia" in proc.stderr
    else:
        model = mujoco.MjModel.from_xml_path(str(path))
        proc, result = audit(tmp_path, "m.xml", text)
        assert proc.returncode == 0, proc.stderr
        assert result["total"]["mass"] == pytest.approx(12.0, rel=1e-12)
        assert model.body_mass[1] == pytest.approx(12.0, rel=1e-6)


def _arm_model(name: str, rod_mass: float, x: float) -> str:
    """A base and a 1 m rod on a hinge about y at the base: the rod's centre 0.5 m out along x."""
    inertia = "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia>"
    return (
        f'<model name="{name}"><pose>{x} 0 0 0 0 0</pose>'
        f'<link name="base"><inertial><mass>1</mass>{inertia}</inertial></link>'
        f'<link name="rod"><pose>0.5 0 0 0 0 0</pose><inertial><mass>{rod_mass}</mass>{inertia}'
        "</inertial></link>"
        '<joint name="hinge" type="revolute"><parent>base</parent><child>rod</child>'
        "<pose>-0.5 0 0 0 0 0</pose><axis><xyz>0 1 0</xyz></axis></joint></model>"
    )


def test_sdf_models_of_one_name_are_refused_as_libsdformat_does(tmp_path):
    # Two models named alike gave links of one key: at --joints hinge=pi/2 the rods' torques
    # came out +m g l (turned twice) instead of 0 (pybullet's kuka_iiwa/model2.sdf: -2.8e6 N·m).
    world = '<sdf version="1.6"><world name="w">{}{}</world></sdf>'
    proc, _ = audit(tmp_path, "two.sdf", world.format(_arm_model("arm", 2, 0), _arm_model("arm", 5, 3)))
    assert proc.returncode == 2
    assert proc.stderr.strip().splitlines() == [
        f"rbi: {tmp_path / 'two.sdf'}: model arm: another model in this file has the same name, so "
        "their links and joints cannot be told apart (SDFormat: model names must be unique)"
    ]


def test_sdf_joints_of_several_models_are_named_model_colon_colon_joint(tmp_path):
    # As their links are: two models' joints "hinge" were one name, and --joints moved both.
    text = '<sdf version="1.6"><world name="w">{}{}</world></sdf>'.format(
        _arm_model("left", 2, 0), _arm_model("right", 5, 3)
    )
    held = [-2 * 9.81 * 0.5, -5 * 9.81 * 0.5]  # each rod level: -m g l/2
    for joints, expected in (
        ((), held),
        (("--joints", f"left::hinge={np.pi / 2!r}"), [0.0, held[1]]),  # the left rod hangs
        (("--joints", f"left::hinge={np.pi / 2!r}", "--joints", f"right::hinge={np.pi / 2!r}"), [0.0, 0.0]),
    ):
        proc, result = audit(tmp_path, "named.sdf", text, *joints)
        assert proc.returncode == 0, proc.stderr
        assert [joint["name"] for joint in result["joints"]] == ["left::hinge", "right::hinge"]
        np.testing.assert_allclose([joint["torque"] for joint in result["joints"]], expected, atol=1e-9)
    proc, _ = audit(tmp_path, "named.sdf", text, "--joints", "hinge=1")
    assert proc.returncode == 2 and "hinge" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1


def _meeting_names(other: str) -> str:
    """Model ``a``: a 1 kg base, a 2 kg rod ``b::c`` (centre 0.5 m along x) on a hinge about y
    at the base and a 4 kg link ``d`` (at x = 1 m) welded to the rod; model ``other`` 5 m up:
    one 3 kg link ``c``. With ``other`` = ``a::b`` two links are ``a::b::c``."""
    inertia = "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia>"

    def link(name, mass, pose="0 0 0"):
        return f'<link name="{name}"><pose>{pose} 0 0 0</pose><inertial><mass>{mass}</mass>{inertia}</inertial></link>'

    return (
        '<sdf version="1.6"><world name="w"><model name="a">'
        + link("base", 1)
        + link("b::c", 2, "0.5 0 0")
        + link("d", 4, "1 0 0")
        + '<joint name="hinge" type="revolute"><parent>base</parent><child>b::c</child>'
        "<pose>-0.5 0 0 0 0 0</pose><axis><xyz>0 1 0</xyz></axis></joint>"
        '<joint name="weld" type="fixed"><parent>b::c</parent><child>d</child></joint></model>'
        f'<model name="{other}"><pose>0 0 5 0 0 0</pose>' + link("c", 3) + "</model></world></sdf>"
    )


def test_sdf_links_whose_model_and_link_names_meet_are_refused(tmp_path):
    # Model "a" with link "b::c" and model "a::b" with link "c" gave two links the key a::b::c:
    # d, welded to a's rod, was placed on the other model's c (total centre of mass z = 3.5 m,
    # not 1.5; the hinge held -9.81 N·m, not -49.05), exit 0.
    proc, _ = audit(tmp_path, "meet.sdf", _meeting_names("a::b"))
    assert proc.returncode == 2
    assert proc.stderr.strip().splitlines() == [
        f"rbi: {tmp_path / 'meet.sdf'}: link[3] (a::b::c): duplicate link name 'a::b::c' "
        "(also link[1] (a::b::c)); every link needs its own name"
    ]
    validated = run_rbi_inprocess("validate", str(tmp_path / "meet.sdf"))
    assert validated.returncode == 2 and "duplicate link name 'a::b::c'" in validated.stdout
    proc, result = audit(tmp_path, "apart.sdf", _meeting_names("other"))
    assert proc.returncode == 0, proc.stderr
    assert result["total"]["mass"] == 10.0
    # x: (2·0.5 + 4·1)/10; z: 3·5/10. The hinge holds rod and d: -(2·0.5 + 4·1)·9.81
    np.testing.assert_allclose(result["total"]["center_of_mass"], [0.5, 0.0, 1.5], atol=1e-12)
    assert result["joints"][0]["torque"] == pytest.approx(-5 * 9.81, rel=1e-12)


def test_sdf_joints_that_form_a_loop_are_refused(tmp_path):
    # p's parent q, q's parent p: no root reaches them and their poses were never set (the
    # audit read uninitialised memory: centre of mass [0, 0.0033, 0.005] m, exit 0).
    inertia = "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia>"
    links = "".join(
        f'<link name="{name}"><pose>{x} 0 0 0 0 0</pose><inertial><mass>1</mass>{inertia}</inertial></link>'
        for name, x in (("base", 0), ("p", 1), ("q", 2))
    )
    joints = "".join(
        f'<joint name="{name}" type="revolute"><parent>{parent}</parent><child>{child}</child>'
        "<axis><xyz>0 1 0</xyz></axis></joint>"
        for name, parent, child in (("j1", "p", "q"), ("j2", "q", "p"))
    )
    proc, _ = audit(tmp_path, "loop.sdf", sdf(links + joints))
    assert proc.returncode == 2
    assert proc.stderr.strip().splitlines() == [
        f"rbi: {tmp_path / 'loop.sdf'}: link[1] (p): the joints form a loop through it; the links "
        "of a robot form a tree (each hangs from one parent, down from a root)"
    ]


def test_a_link_whose_parent_is_no_link_is_refused_by_the_tree():
    from rbi.errors import InputError
    from rbi.formats.robot import tree_rows

    assert tree_rows("r.urdf", "link", ["a", "b"], [None, "a"]) == ([2, 0], [0, 1])
    with pytest.raises(InputError) as refused:
        tree_rows("r.urdf", "link", ["a", "b"], [None, "x"])
    assert str(refused.value) == "r.urdf: link[1] (b): parent 'x': no link has that name"
