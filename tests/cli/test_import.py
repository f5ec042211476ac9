"""`rbi import` and `rbi validate` on robot files (URDF, SDF, MJCF): round trips through
`rbi export`, hand-written files with values worked by hand, MuJoCo's own compiler as the
reference for MJCF, unphysical links with their margins, and hostile files."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rbi
from tests.conftest import BODIES, one_line_exit_2, run_rbi, run_rbi_inprocess


def ok(*args) -> str:
    proc = run_rbi_inprocess(*args)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def links_json(path) -> list[dict]:
    return json.loads(ok("import", path, "--format", "json"))["links"]


def write(tmp_path, name: str, text: str):
    path = tmp_path / name
    path.write_text(text)
    return path


# --- round trips through rbi export ----------------------------------------------------------

ROUND_TRIP_BODIES = ["robot_link.yaml", "top_bolted.yaml", "tbar.yaml", "flywheel.yaml"]


@pytest.mark.parametrize("body", ROUND_TRIP_BODIES)
@pytest.mark.parametrize("target", [["urdf"], ["sdf"], ["mjcf"], ["mjcf", "--diagonal"]])
def test_export_then_import_gives_back_the_mass_properties(tmp_path, body, target):
    spec = BODIES / body
    exported = ok("export", spec, "--to", *target, "--document")
    suffix = {"urdf": ".urdf", "sdf": ".sdf", "mjcf": ".xml"}[target[0]]
    robot = write(tmp_path, "robot" + suffix, exported)
    truth = json.loads(ok("inertia", spec, "--units", "SI", "--format", "json"))
    (link,) = links_json(robot)
    scale = max(abs(v) for row in truth["inertia"] for v in row)
    assert link["mass"] == pytest.approx(truth["mass"], rel=1e-15)
    assert link["center_of_mass"] == pytest.approx(truth["center_of_mass"], rel=1e-14, abs=1e-17)
    assert np.allclose(link["inertia"], truth["inertia"], rtol=0, atol=1e-13 * scale)
    # ... and the spec written by import gives the same numbers through rbi inertia
    out = tmp_path / "link.yaml"
    ok("import", robot, "--out", out)
    again = json.loads(ok("inertia", out, "--format", "json"))
    assert again["mass"] == pytest.approx(truth["mass"], rel=1e-15)
    assert again["center_of_mass"] == pytest.approx(truth["center_of_mass"], rel=1e-14, abs=1e-17)
    assert np.allclose(again["inertia"], truth["inertia"], rtol=0, atol=1e-13 * scale)


# --- hand-written files, values worked by hand -------------------------------------------------

# A box, 2 kg, 0.3 × 0.2 × 0.1 m, in its inertial frame: Ixx = m(b² + c²)/12 = 2·0.05/12,
# Iyy = m(a² + c²)/12 = 2·0.10/12, Izz = m(a² + b²)/12 = 2·0.13/12. Turned by yaw = 90° about z,
# its x axis lies along the link's y: in link axes Ixx and Iyy swap.
BOX = (2 * 0.05 / 12, 2 * 0.10 / 12, 2 * 0.13 / 12)

URDF = f"""<?xml version="1.0"?>
<robot name="hand">
  <link name="world"/>
  <link name="box">
    <inertial>
      <origin xyz="0.1 0.2 0.3" rpy="0 0 {math.pi / 2!r}"/>
      <mass value="2"/>
      <inertia ixx="{BOX[0]!r}" ixy="0" ixz="0" iyy="{BOX[1]!r}" iyz="0" izz="{BOX[2]!r}"/>
    </inertial>
  </link>
  <link name="plate">
    <inertial>
      <mass value="0.5"/>
      <inertia ixx="0.01" ixy="-0.002" ixz="0.001" iyy="0.02" iyz="0.003" izz="0.025"/>
    </inertial>
  </link>
  <joint name="box_on_world" type="fixed"><parent link="world"/><child link="box"/></joint>
  <joint name="plate_on_world" type="fixed"><parent link="world"/><child link="plate"/></joint>
</robot>
"""


def test_urdf_by_hand(tmp_path):
    box, plate = links_json(write(tmp_path, "hand.urdf", URDF))
    assert box["name"] == "box" and box["mass"] == 2.0 and box["center_of_mass"] == [0.1, 0.2, 0.3]
    assert np.allclose(box["inertia"], np.diag([BOX[1], BOX[0], BOX[2]]), rtol=0, atol=1e-16)
    assert box["inertial_quaternion"] == pytest.approx([math.sqrt(0.5), 0, 0, math.sqrt(0.5)])
    # no origin: the inertial frame is the link frame; ixy etc. are the matrix entries, copied as they are
    assert plate["center_of_mass"] == [0, 0, 0]
    assert plate["inertia"] == [[0.01, -0.002, 0.001], [-0.002, 0.02, 0.003], [0.001, 0.003, 0.025]]


def test_urdf_link_without_inertial_is_skipped_with_a_note(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    proc = run_rbi_inprocess("import", path)
    assert proc.returncode == 0
    assert "link[0] (world): skipped: no <inertial> element" in proc.stderr
    (robot,) = [d for d in yaml.safe_load_all(proc.stdout)]  # one spec: the whole robot
    assert [part["name"] for part in robot["parts"]] == ["box", "plate"]
    box = yaml.safe_load(ok("import", path, "--link", "box"))  # one link: in its own frame
    assert box["parts"][0]["rotation"] == {"euler_deg": [0.0, 0.0, 90.0], "sequence": "xyz"}
    assert json.loads(ok("import", path, "--format", "json"))["skipped"] == [
        {"link": "link[0] (world)", "reason": "no <inertial> element"}
    ]


def test_imported_spec_works_with_principal_and_check(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    out = tmp_path / "box.yaml"
    ok("import", path, "--link", "box", "--out", out)
    principal = json.loads(ok("principal", out, "--format", "json"))
    assert principal["moments"] == pytest.approx(sorted(BOX), rel=1e-14)
    assert principal["center_of_mass"] == pytest.approx([0.1, 0.2, 0.3])
    assert run_rbi_inprocess("validate", out).returncode == 0


SDF = """<?xml version="1.0"?>
<sdf version="1.9">
  <model name="m">
    <link name="turned">
      <inertial>
        <pose>1 2 3 0 0 90</pose>
        <mass>4</mass>
        <inertia><ixx>0.1</ixx><iyy>0.2</iyy><izz>0.3</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia>
      </inertial>
    </link>
    <link name="defaults">
      <inertial/>
    </link>
  </model>
</sdf>
"""


def test_sdf_by_hand_with_degrees_and_defaults(tmp_path):
    text = SDF.replace("<pose>", '<pose degrees="true">')
    turned, defaults = links_json(write(tmp_path, "m.sdf", text))
    assert turned["center_of_mass"] == [1, 2, 3] and turned["mass"] == 4
    assert np.allclose(turned["inertia"], np.diag([0.2, 0.1, 0.3]), rtol=0, atol=1e-15)
    # SDF's defaults: mass 1, ixx = iyy = izz = 1, products 0
    assert defaults["mass"] == 1.0 and defaults["inertia"] == np.eye(3).tolist()


def test_sdf_pose_angles_are_radians_by_default(tmp_path):
    text = SDF.replace("<pose>1 2 3 0 0 90</pose>", f"<pose>1 2 3 0 0 {math.pi / 2!r}</pose>")
    turned, _ = links_json(write(tmp_path, "m.sdf", text))
    assert np.allclose(turned["inertia"], np.diag([0.2, 0.1, 0.3]), rtol=0, atol=1e-15)


MJCF = """<mujoco model="hand">
  <worldbody>
    <body name="a" pos="0 0 1">
      <freejoint/>
      <inertial pos="0.1 0.2 0.3" quat="0.9 0.1 -0.3 0.2" mass="1.5" diaginertia="0.01 0.02 0.025"/>
      <body name="b" pos="0.5 0 0">
        <joint type="hinge" axis="0 0 1"/>
        <inertial pos="0 0 -0.1" mass="0.7" fullinertia="0.03 0.04 0.05 0.004 -0.002 0.001"/>
        <body name="c" pos="0.5 0 0">
          <joint type="hinge" axis="0 1 0"/>
          <geom type="sphere" size="0.05"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def test_mjcf_matches_mujoco_compiler(tmp_path):
    mujoco = pytest.importorskip("mujoco")
    path = write(tmp_path, "hand.xml", MJCF)
    links = links_json(path)
    model = mujoco.MjModel.from_xml_path(str(path))
    assert [link["name"] for link in links] == ["a", "b", "c"]  # c: mass from its sphere geom, as MuJoCo
    for link in links:
        body = model.body(link["name"]).id
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, model.body_iquat[body])
        R = R.reshape(3, 3)
        expected = R @ np.diag(model.body_inertia[body]) @ R.T  # MuJoCo's principal form, back in body axes
        assert link["mass"] == pytest.approx(model.body_mass[body], rel=1e-15)
        assert link["center_of_mass"] == pytest.approx(model.body_ipos[body], abs=1e-15)
        assert np.allclose(link["inertia"], expected, rtol=0, atol=1e-12 * np.trace(expected))


def test_mjcf_body_without_inertial_or_geoms_is_listed_as_skipped(tmp_path):
    text = MJCF.replace('<geom type="sphere" size="0.05"/>', '<site pos="0 0 0"/>')
    # moved by a joint, MuJoCo's compiler refuses it (exit 2); fixed to its parent, it is skipped
    assert (
        run_rbi_inprocess("import", write(tmp_path, "moving.xml", text), "--format", "json").returncode == 2
    )
    text = text.replace('<joint type="hinge" axis="0 1 0"/>', "")
    listing = json.loads(ok("import", write(tmp_path, "hand.xml", text), "--format", "json"))
    assert listing["format"] == "mjcf"
    assert listing["skipped"] == [
        {"link": "body[2] (c)", "reason": "no <inertial> element and no geoms with mass"}
    ]


def test_mjcf_quaternion_becomes_the_part_rotation(tmp_path):
    text = ok("import", write(tmp_path, "hand.xml", MJCF), "--link", "a")
    part = yaml.safe_load(text)["parts"][0]
    assert part["rotation"] == {"quaternion": [0.9, 0.1, -0.3, 0.2]}
    assert part["inertia"] == {"ixx": 0.01, "iyy": 0.02, "izz": 0.025, "ixy": 0.0, "ixz": 0.0, "iyz": 0.0}


# --- unphysical links: validate reports each with its margin -----------------------------------

CAD_URDF = """<robot name="cad-export">
  <link name="base">
    <inertial><mass value="3"/><inertia ixx="0.03" ixy="0" ixz="0" iyy="0.04" iyz="0" izz="0.05"/></inertial>
  </link>
  <link name="thin_plate">
    <inertial><mass value="0.4"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.003"/></inertial>
  </link>
  <link name="negative">
    <inertial><mass value="0.2"/><inertia ixx="-0.001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial>
  </link>
  <link name="massless">
    <inertial><mass value="0"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
  </link>
  <joint name="moves_the_massless_link" type="revolute">
    <parent link="base"/><child link="massless"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="plate_on_base" type="fixed"><parent link="base"/><child link="thin_plate"/></joint>
  <joint name="negative_on_base" type="fixed"><parent link="base"/><child link="negative"/></joint>
</robot>
"""


def test_validate_reports_every_unphysical_link_with_its_margin(tmp_path):
    path = write(tmp_path, "cad.urdf", CAD_URDF)
    proc = run_rbi_inprocess("validate", path)
    assert proc.returncode == 2
    lines = proc.stdout.strip().splitlines()
    assert len(lines) == 3, proc.stdout
    triangle, negative, massless = lines
    # I1 + I2 − I3 = 0.001 + 0.001 − 0.003 = −0.001, a third of I3
    assert "link[1] (thin_plate): inertia:" in triangle and "triangle inequality" in triangle
    assert "-0.001 kg·m²" in triangle and "-33.333% of I3" in triangle
    assert "link[2] (negative): inertia:" in negative and "-0.001 kg·m² below zero" in negative
    assert "link[3] (massless): inertia: mass 0 with non-zero moments" in massless
    assert all(line.startswith(str(path)) for line in lines)


def test_validate_json_lists_the_problems(tmp_path):
    path = write(tmp_path, "cad.urdf", CAD_URDF)
    proc = run_rbi_inprocess("validate", path, BODIES / "two_link_arm.urdf", "--format", "json")
    assert proc.returncode == 2
    files = json.loads(proc.stdout)["files"]
    assert [f["ok"] for f in files] == [False, True]
    assert len(files[0]["problems"]) == 3


def test_example_robot_file_is_valid_and_imports(tmp_path):
    assert run_rbi_inprocess("validate", BODIES / "two_link_arm.urdf").returncode == 0
    upper, forearm = links_json(BODIES / "two_link_arm.urdf")
    # upper arm: solid cylinder 1.2 kg, r = 0.03, L = 0.3 along the link's x axis
    m, r, L = 1.2, 0.03, 0.3
    assert np.allclose(
        upper["inertia"],
        np.diag([m * r**2 / 2, m * (3 * r**2 + L**2) / 12, m * (3 * r**2 + L**2) / 12]),
        rtol=1e-12,
        atol=1e-18,
    )
    # forearm: box 0.8 kg, 0.25 × 0.04 × 0.04
    assert forearm["inertia"][1][1] == pytest.approx(0.8 * (0.25**2 + 0.04**2) / 12, rel=1e-15)


def test_import_warns_about_unphysical_links_but_writes_them(tmp_path):
    path = write(tmp_path, "cad.urdf", CAD_URDF)
    proc = run_rbi_inprocess("import", path, "--out", str(tmp_path) + "/")
    assert proc.returncode == 0
    assert proc.stderr.count("rbi: warning:") == 3
    assert sorted(p.name for p in tmp_path.glob("*.yaml")) == [
        "base.yaml",
        "massless.yaml",
        "negative.yaml",
        "thin_plate.yaml",
    ]
    one_line_exit_2(run_rbi_inprocess("inertia", tmp_path / "thin_plate.yaml"), "triangle inequality")


# --- command-line behaviour ---------------------------------------------------------------------


def test_out_file_needs_a_single_link(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    one_line_exit_2(
        run_rbi_inprocess("import", path, "--out", tmp_path / "x.yaml"), "--out", "2 links", "--link"
    )
    assert not (tmp_path / "x.yaml").exists()


def test_unknown_link_is_refused_with_a_hint(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    one_line_exit_2(run_rbi_inprocess("import", path, "--link", "boxx"), "--link", "'boxx'", "'box'")


def test_out_refuses_other_extensions_and_the_input(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    one_line_exit_2(run_rbi_inprocess("import", path, "--link", "box", "--out", tmp_path / "x.json"), "--out")
    one_line_exit_2(run_rbi_inprocess("import", path, "--link", "box", "--out", path), "--out")
    assert path.read_text() == URDF


def test_out_folder_gets_safe_distinct_names(tmp_path):
    text = URDF.replace('"box"', '"../../evil box"').replace('"plate"', '"evil_box"')
    path = write(tmp_path, "hand.urdf", text)
    out = tmp_path / "specs"
    out.mkdir()
    printed = ok("import", path, "--out", str(out) + "/").split()
    assert sorted(p.name for p in out.iterdir()) == ["evil_box.yaml", "evil_box_2.yaml"]
    assert len(printed) == 2
    assert yaml.safe_load((out / "evil_box.yaml").read_text())["name"] == "../../evil box"


def test_missing_out_folder_is_refused(tmp_path):
    path = write(tmp_path, "hand.urdf", URDF)
    one_line_exit_2(run_rbi_inprocess("import", path, "--out", str(tmp_path / "nowhere") + "/"), "--out")


def test_csv_has_one_row_per_link(tmp_path):
    text = ok("import", write(tmp_path, "hand.urdf", URDF), "--format", "csv")
    header, *rows = text.strip().splitlines()
    assert len(rows) == 2 and "inertia_xx" in header and header.endswith(",ok")


# --- hostile and malformed files ----------------------------------------------------------------

BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
]>
<robot name="&lol3;"><link name="a"/></robot>
"""

EXTERNAL = """<?xml version="1.0"?>
<!DOCTYPE robot [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<robot name="x"><link name="&secret;"><inertial><mass value="1"/>
<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link></robot>
"""


@pytest.mark.parametrize("text", [BILLION_LAUGHS, EXTERNAL], ids=["entity-bomb", "external-entity"])
@pytest.mark.parametrize("command", ["import", "validate"])
def test_entities_are_refused(tmp_path, text, command):
    proc = run_rbi_inprocess(command, write(tmp_path, "evil.urdf", text))
    assert proc.returncode == 2
    output = proc.stdout + proc.stderr
    assert "entities" in output and "root:" not in output and "lollol" not in output
    if command == "import":
        one_line_exit_2(proc, "evil.urdf")


def test_deep_nesting_is_refused(tmp_path):
    depth = 5000
    text = "<mujoco><worldbody>" + "<body>" * depth + "</body>" * depth + "</worldbody></mujoco>"
    one_line_exit_2(
        run_rbi_inprocess("import", write(tmp_path, "deep.xml", text)), "deep.xml", "nested deeper"
    )


def test_huge_file_is_refused(tmp_path, monkeypatch):
    from rbi.formats import robot_xml

    monkeypatch.setattr(robot_xml, "MAX_FILE_BYTES", 200)
    one_line_exit_2(
        run_rbi_inprocess("import", write(tmp_path, "hand.urdf", URDF)),
        "hand.urdf",
        "too large for a robot file",
    )


@pytest.mark.parametrize(
    "value, words",
    [
        ("abc", ["ixy", "'abc'"]),
        ("nan", ["ixy", "'nan'"]),
        ("inf", ["ixy", "'inf'"]),
        ("1e400", ["ixy", "too large"]),
        ("1_000", ["ixy", "'1_000'"]),
        ("0x10", ["ixy", "'0x10'"]),
        ("", ["ixy", "expected 1"]),
    ],
)
def test_bad_numbers_name_file_link_and_attribute(tmp_path, value, words):
    text = URDF.replace('ixy="-0.002"', f'ixy="{value}"')
    proc = run_rbi_inprocess("import", write(tmp_path, "hand.urdf", text))
    one_line_exit_2(proc, "hand.urdf", "link[2] (plate)", "inertial/inertia", *words)


@pytest.mark.parametrize(
    "text, words",
    [
        (
            "<robot><link name='a'><inertial><mass value='1'/></inertial></link></robot>",
            ["link[0] (a)", "inertia: missing"],
        ),
        (
            "<robot><link name='a'><inertial><inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link></robot>",
            ["mass: missing"],
        ),
        (
            "<robot><link name='a'><inertial><origin xyz='1 2'/><mass value='1'/>"
            "<inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link></robot>",
            ["xyz", "expected 3"],
        ),
        ("<html><body/></html>", ["not a URDF, SDF or MJCF", "<html>"]),
        ("<robot><link name='a'>", ["not well-formed XML"]),
        ("", ["not well-formed XML"]),
    ],
)
def test_malformed_urdf_is_one_line(tmp_path, text, words):
    one_line_exit_2(run_rbi_inprocess("import", write(tmp_path, "bad.urdf", text)), "bad.urdf", *words)


@pytest.mark.parametrize(
    "inertial, words",
    [
        ('<inertial pos="0 0 0" mass="1" diaginertia="1 1 1" fullinertia="1 1 1 0 0 0"/>', ["exactly one"]),
        ('<inertial pos="0 0 0" mass="1"/>', ["exactly one"]),
        (
            '<inertial pos="0 0 0" mass="1" euler="0 0 90" fullinertia="1 1 1 0 0 0"/>',
            ["orientation", "fullinertia"],
        ),
        ('<inertial pos="0 0 0" mass="1" quat="0 0 0 0" diaginertia="1 1 1"/>', ["quat", "zero"]),
        ('<inertial mass="1" diaginertia="1 1 1"/>', ["pos", "expected 3"]),
        ('<inertial pos="0 0 0" mass="NaN" diaginertia="1 1 1"/>', ["mass", "'NaN'"]),
    ],
)
def test_malformed_mjcf_is_one_line(tmp_path, inertial, words):
    text = f'<mujoco><worldbody><body name="b">{inertial}</body></worldbody></mujoco>'
    one_line_exit_2(
        run_rbi_inprocess("import", write(tmp_path, "m.xml", text)), "m.xml", "body[0] (b)", *words
    )


def test_sdf_pose_relative_to_another_frame_is_refused(tmp_path):
    text = SDF.replace("<pose>", '<pose relative_to="other">')
    one_line_exit_2(run_rbi_inprocess("import", write(tmp_path, "m.sdf", text)), "relative_to")


def test_end_to_end_import_then_principal(tmp_path):
    out = tmp_path / "forearm.yaml"
    proc = run_rbi("import", BODIES / "two_link_arm.urdf", "--link", "forearm", "--out", out)
    assert proc.returncode == 0, proc.stderr
    principal = run_rbi("principal", out, "--format", "json", check=True)
    moments = json.loads(principal.stdout)["moments"]
    assert moments[0] == pytest.approx(0.8 * (0.04**2 + 0.04**2) / 12, rel=1e-15)


def test_sdf_pose_as_quaternion_xyzw(tmp_path):
    half = math.sqrt(0.5)  # a quarter turn about z: (x, y, z, w) = (0, 0, √½, √½)
    text = SDF.replace(
        "<pose>1 2 3 0 0 90</pose>", f'<pose rotation_format="quat_xyzw">1 2 3 0 0 {half!r} {half!r}</pose>'
    )
    turned, _ = links_json(write(tmp_path, "m.sdf", text))
    assert np.allclose(turned["inertia"], np.diag([0.2, 0.1, 0.3]), rtol=0, atol=1e-15)
    assert turned["inertial_quaternion"] == pytest.approx([half, 0, 0, half])


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    st.lists(
        st.tuples(st.floats(0.1, 5), st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1)),
        min_size=4,
        max_size=6,
    ),
    st.tuples(*[st.floats(-math.pi, math.pi)] * 3),
)
def test_urdf_rpy_turns_the_inertia_as_scipy_does(tmp_path, points, rpy):
    # any real mass distribution (point masses), its inertia written in a turned inertial frame
    from scipy.spatial.transform import Rotation

    masses = np.array([p[0] for p in points])
    r = np.array([p[1:] for p in points])
    r = r - masses @ r / masses.sum()
    second = (r * masses[:, None]).T @ r
    inertia = np.trace(second) * np.eye(3) - second
    names = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
    values = (inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2])
    attributes = " ".join(f'{k}="{float(v)!r}"' for k, v in zip(names, values))
    text = (
        f'<robot name="r"><link name="l"><inertial><origin xyz="0 0 0" rpy="{rpy[0]!r} {rpy[1]!r} {rpy[2]!r}"/>'
        f'<mass value="{float(masses.sum())!r}"/><inertia {attributes}/></inertial></link></robot>'
    )
    (link,) = links_json(write(tmp_path, "r.urdf", text))
    R = Rotation.from_euler("xyz", rpy).as_matrix()  # URDF: fixed-axis roll, pitch, yaw
    assert np.allclose(link["inertia"], R @ inertia @ R.T, rtol=0, atol=1e-13 * np.trace(inertia))


def test_notes_and_warnings_show_link_names_escaped(tmp_path):
    """XML 1.0 allows C1 control characters and bidi overrides in a name: the note about a
    skipped link must reach the terminal with them escaped, never raw."""
    name = "evil\u202e\u009b2J"
    path = write(
        tmp_path,
        "arm.urdf",
        f"""<robot name="r">
  <link name="{name}"/>
  <link name="ok"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="fixed"><parent link="{name}"/><child link="ok"/></joint>
</robot>""",
    )
    proc = run_rbi_inprocess("import", path, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert "skipped" in proc.stderr
    assert "\u202e" not in proc.stderr and "\u009b" not in proc.stderr
    assert "\\u202e" in proc.stderr and "\\x9b" in proc.stderr


def test_one_file_for_several_links_names_both_ways_out(tmp_path):
    """The refusal says how to write several links (a folder, --out DIR/) or pick one (--link NAME),
    as the CLI spells them; the API's message spells its own parameters."""
    out = tmp_path / "arm.yaml"
    proc = run_rbi_inprocess("import", BODIES / "two_link_arm.urdf", "--out", out)
    one_line_exit_2(proc)
    assert not out.exists()
    assert "name a folder (--out DIR/) or pick one with --link NAME" in proc.stderr
    with pytest.raises(rbi.ArgumentError, match=r"\(out=DIR/\) or pick one with links=NAME"):
        rbi.import_robot(BODIES / "two_link_arm.urdf", out=out)
