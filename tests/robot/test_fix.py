"""`rbi audit --fix` loses nothing: every byte outside the replaced inertials is kept whatever
form the XML takes, the written file loads in MuJoCo / Pinocchio and re-audits clean, and no
file the robot reads (an include, a mesh, a .xacro) is ever written."""

from __future__ import annotations

import json

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess

PLACEHOLDER_MJCF = """<mujoco model="m">
  <compiler inertiafromgeom="auto"/>
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/><geom type="box" size="0.1 0.05 0.025"/>
      <body name="tip" pos="0.3 0 0"><joint type="hinge" axis="0 1 0"/><geom type="sphere" size="0.05"/></body>
    </body>
  </worldbody>
</mujoco>
"""

SELF_CLOSING_SDF = """<?xml version="1.0"?>
<sdf version="1.7">
  <model name="m">
    <link name="base">
      <inertial><mass>2</mass><inertia><ixx>0.0020833333333333333</ixx><iyy>0.007083333333333333</iyy><izz>0.008333333333333333</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.2 0.1 0.05</size></box></geometry></collision>
    </link>
    <link name="arm">
      <pose>0 0 0.5 0 0 0</pose>
      <inertial/><collision name="c"><geometry><box><size>0.2 0.1 0.05</size></box></geometry></collision>
    </link>
    <joint name="j" type="revolute"><parent>base</parent><child>arm</child><axis><xyz>0 1 0</xyz></axis></joint>
  </model>
</sdf>
"""


def _kept_outside(original: bytes, fixed: bytes, old: str) -> None:
    """``fixed`` is ``original`` with the one element ``old`` replaced: the bytes before it and
    after it are identical."""
    start = original.index(old.encode())
    end = start + len(old.encode())
    assert fixed[:start] == original[:start]
    assert fixed.endswith(original[end:])


def _fix(tmp_path, name: str, text: str, *extra: str):
    source = tmp_path / name
    source.write_text(text)
    out = tmp_path / ("fixed" + source.suffix)
    proc = run_rbi_inprocess("audit", str(source), "--fix", "--out", str(out), *extra)
    return source, out, proc


def test_self_closing_mjcf_inertial_keeps_the_next_geom_and_loads_in_mujoco(tmp_path):
    mujoco = pytest.importorskip("mujoco")
    source, out, proc = _fix(tmp_path, "arm.xml", PLACEHOLDER_MJCF)
    assert proc.returncode == 0, proc.stderr
    fixed = out.read_bytes()
    _kept_outside(source.read_bytes(), fixed, '<inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>')
    model = mujoco.MjModel.from_xml_path(str(out))
    arm = model.body("arm").id
    a, b, c = 0.2, 0.1, 0.05  # the box's full edges
    expected = 2.0 / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
    np.testing.assert_allclose(model.body_mass[arm], 2.0, rtol=1e-15)
    np.testing.assert_allclose(np.sort(model.body_inertia[arm]), np.sort(expected), rtol=1e-12)
    assert model.ngeom == 2  # the geom after the self-closing inertial survived
    again = run_rbi_inprocess("audit", str(out), "--format", "json")
    assert again.returncode == 0, again.stdout


def test_self_closing_sdf_inertial_keeps_the_collision(tmp_path):
    source, out, proc = _fix(tmp_path, "m.sdf", SELF_CLOSING_SDF)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    fixed = out.read_bytes()
    _kept_outside(source.read_bytes(), fixed, "<inertial/>")
    assert fixed.count(b'<collision name="c">') == 2
    for form in ("json", "csv", "table"):
        again = run_rbi_inprocess("audit", str(out), "--format", form)
        assert again.returncode == 0, (form, again.stdout, again.stderr)
    report = json.loads(run_rbi_inprocess("audit", str(out), "--format", "json").stdout)
    arm = next(link for link in report["links"] if link["name"] == "arm")
    # the box at SDFormat's default mass of 1 kg
    np.testing.assert_allclose(
        arm["declared"]["moments"], sorted([0.0125 / 12, 0.0425 / 12, 0.05 / 12]), rtol=1e-12
    )


def test_fixed_urdf_loads_in_pinocchio_and_every_other_byte_is_kept(tmp_path):
    pin = pytest.importorskip("pinocchio")
    text = """<?xml version="1.0"?>
<!-- a comment the fix keeps -->
<robot name="r">
  <link name="base"/>
  <link name="arm">
    <inertial><origin xyz="0 0 0"/><mass value="3"/><inertia ixx="-1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <collision><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit effort="10" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""
    old = '<inertial><origin xyz="0 0 0"/><mass value="3"/><inertia ixx="-1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
    source, out, proc = _fix(tmp_path, "r.urdf", text)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    _kept_outside(source.read_bytes(), out.read_bytes(), old)
    model = pin.buildModelFromUrdf(str(out))
    inertia = model.inertias[model.getJointId("j")]
    r, h, m = 0.05, 0.4, 3.0
    np.testing.assert_allclose(inertia.mass, m, rtol=1e-15)
    np.testing.assert_allclose(
        np.diag(inertia.inertia), [m * (3 * r * r + h * h) / 12] * 2 + [m * r * r / 2], rtol=1e-12
    )


def test_a_file_with_windows_line_ends_keeps_them_in_the_replaced_inertials(tmp_path):
    """CRLF everywhere before, CRLF everywhere after (the inserted lines were LF: mixed line
    ends); the bytes around the inertial kept; the fixed box's moments are m/12 (b² + c²), ..."""
    lines = [
        '<?xml version="1.0"?>',
        '<robot name="r">',
        '  <link name="a">',
        '    <inertial><mass value="6"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>',
        '    <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>',
        "  </link>",
        "</robot>",
    ]
    text = ("\r\n".join(lines) + "\r\n").encode()
    (tmp_path / "r.urdf").write_bytes(text)
    proc = run_rbi_inprocess("audit", str(tmp_path / "r.urdf"), "--fix", "--out", str(tmp_path / "f.urdf"))
    assert proc.returncode == 0, proc.stderr
    fixed = (tmp_path / "f.urdf").read_bytes()
    assert fixed.count(b"\n") == fixed.count(b"\r\n") > text.count(b"\r\n")
    start, end = text.index(b"<inertial>"), text.index(b"</inertial>") + len(b"</inertial>")
    assert fixed.startswith(text[:start].rstrip(b" ")) and fixed.endswith(text[end:])
    again = run_rbi_inprocess("audit", str(tmp_path / "f.urdf"), "--format", "json")
    assert again.returncode == 0, again.stderr
    declared = json.loads(again.stdout)["links"][0]["declared"]
    np.testing.assert_allclose(
        declared["moments"], np.sort(6 / 12 * np.array([0.04 + 0.09, 0.01 + 0.09, 0.01 + 0.04])), rtol=1e-12
    )


def test_out_naming_an_included_file_is_refused_and_the_file_kept(tmp_path):
    (tmp_path / "part.xml").write_text(
        '<mujoco><body name="tip" pos="0.3 0 0"><joint type="hinge"/><geom type="sphere" size="0.05"/></body></mujoco>'
    )
    main = tmp_path / "main.xml"
    main.write_text(
        PLACEHOLDER_MJCF.replace('<body name="tip"', '<include file="part.xml"/><body name="tip2"')
    )
    before = (tmp_path / "part.xml").read_bytes()
    proc = run_rbi_inprocess("audit", str(main), "--fix", "--out", str(tmp_path / "part.xml"))
    assert proc.returncode == 2
    assert "part.xml" in proc.stderr and "reads" in proc.stderr
    assert (tmp_path / "part.xml").read_bytes() == before


XACRO = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="m" value="2.0"/>
  <xacro:include filename="arm.xacro"/>
  <link name="base"/>
  <xacro:arm parent="base"/>
</robot>
"""

ARM_XACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="arm" params="parent">
    <link name="arm">
      <inertial><mass value="${m}"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
      <collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision>
    </link>
    <joint name="j" type="revolute"><parent link="${parent}"/><child link="arm"/><axis xyz="0 1 0"/>
      <limit effort="5" velocity="1" lower="-1" upper="1"/></joint>
  </xacro:macro>
</robot>
"""


@pytest.fixture
def xacro_robot(tmp_path):
    pytest.importorskip("xacro")
    (tmp_path / "arm.xacro").write_text(ARM_XACRO)
    path = tmp_path / "r.xacro"
    path.write_text(XACRO)
    return path


def test_fix_on_a_xacro_writes_only_a_urdf(xacro_robot, tmp_path):
    before = xacro_robot.read_bytes(), (tmp_path / "arm.xacro").read_bytes()
    for out in ("fixed.xacro", "arm.xacro", "r.xacro"):
        proc = run_rbi_inprocess("audit", str(xacro_robot), "--fix", "--out", str(tmp_path / out))
        assert proc.returncode == 2, (out, proc.stdout)
    proc = run_rbi_inprocess("audit", str(xacro_robot), "--fix", "--out", str(tmp_path / "fixed.urdf"))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert (xacro_robot.read_bytes(), (tmp_path / "arm.xacro").read_bytes()) == before
    again = run_rbi_inprocess("audit", str(tmp_path / "fixed.urdf"), "--format", "csv")
    assert again.returncode == 0, again.stdout
    pin = pytest.importorskip("pinocchio")
    model = pin.buildModelFromUrdf(str(tmp_path / "fixed.urdf"))
    np.testing.assert_allclose(
        np.diag(model.inertias[model.getJointId("j")].inertia),
        2.0 / 12 * np.array([0.0125, 0.0425, 0.05]),
        rtol=1e-12,
    )


# --- the xacro sandbox ----------------------------------------------------------------------------


def _xacro(tmp_path, body: str) -> str:
    path = tmp_path / "hostile.xacro"
    path.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}</robot>')
    return str(path)


def _refused(path, *extra):
    proc = run_rbi_inprocess("audit", path, "--format", "json", *extra)
    assert proc.returncode == 2, proc.stdout
    assert proc.stdout == ""
    assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr
    return proc.stderr


def test_xacro_sees_no_environment_variable(tmp_path, monkeypatch):
    pytest.importorskip("xacro")
    monkeypatch.setenv("RBI_SECRET_TOKEN", "s3cr3t-value")
    message = _refused(_xacro(tmp_path, '<link name="$(env RBI_SECRET_TOKEN)"/>'))
    assert "s3cr3t" not in message and "RBI_SECRET_TOKEN" in message


def test_xacro_reads_no_file_outside_the_folder(tmp_path):
    pytest.importorskip("xacro")
    secret = tmp_path.parent / f"{tmp_path.name}-secret.yaml"
    secret.write_text("token: s3cr3t-value\n")
    inner = tmp_path / "robot"
    inner.mkdir()
    body = f'<xacro:property name="y" value="${{xacro.load_yaml(\'{secret}\')}}"/><link name="${{y[\'token\']}}"/>'
    message = _refused(_xacro(inner, body))
    assert "s3cr3t" not in message and "outside" in message
    include = f'<xacro:include filename="{secret}"/><link name="a"/>'
    assert "s3cr3t" not in _refused(_xacro(inner, include))
    allowed = run_rbi_inprocess("audit", _xacro(inner, body), "--format", "json", "--allow-outside-paths")
    assert allowed.returncode == 0 and "s3cr3t-value" in allowed.stdout


def test_xacro_include_of_a_fifo_is_refused_at_once(tmp_path):
    pytest.importorskip("xacro")
    import os

    os.mkfifo(tmp_path / "pipe.xacro")
    assert "not a regular file" in _refused(_xacro(tmp_path, '<xacro:include filename="pipe.xacro"/>'))


def test_xacro_past_its_time_limit_is_refused(tmp_path, monkeypatch):
    pytest.importorskip("xacro")
    from rbi.formats import xacro_sandbox

    monkeypatch.setattr(xacro_sandbox, "TIME_LIMIT_S", 2.0)
    message = _refused(_xacro(tmp_path, '<link name="${10**10**8}"/>'))
    assert "2 s" in message or "memory" in message


@pytest.mark.parametrize(
    "body",
    [
        '<xacro:property name="s" value="${\'x\' * 2**31}"/><link name="${s}"/>',  # a 2 GiB string
        '<link name="${[0] * 2**28}"/>',  # a 2 GiB list, inside an attribute
    ],
)
def test_xacro_past_its_memory_limit_is_refused_saying_so(tmp_path, body):
    """xacro wraps the MemoryError in its own exception, whose text says only where it happened:
    the message names the limit the expansion ran out of (it was 'could not expand it: when
    evaluating expression ...')."""
    pytest.importorskip("xacro")
    message = _refused(_xacro(tmp_path, body))
    assert "ran out of its 1 GiB memory limit" in message and "could not expand" not in message
