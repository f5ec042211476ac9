"""Issue 18 for the new door `rbi audit` (and the reading import and validate share): hostile
and careless robot files. Each case is exit 2 with one line, or a normal result; never a
traceback, a hang, a file read outside the robot's folder, or a broken fixed copy."""

from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from tests.conftest import one_line_exit_2, run_rbi_inprocess

BOX = (
    '<inertial><mass value="2"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
    '<collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision>'
)


def with_mesh(uri: str) -> str:
    box = '<box size="0.2 0.1 0.05"/>'
    return f'<robot name="r"><link name="a">{BOX.replace(box, f"<mesh filename={chr(34)}{uri}{chr(34)}/>")}</link></robot>'


def write(folder, name, text):
    path = folder / name
    path.write_text(text)
    return path


@pytest.mark.parametrize("target", ["loop.xml", "../outside.xml", "/etc/passwd"])
def test_mjcf_includes_that_loop_or_leave_the_folder_are_exit_2(tmp_path, target):
    inner = tmp_path / "robot"
    inner.mkdir()
    write(tmp_path, "outside.xml", "<mujoco/>")
    path = write(inner, "loop.xml", f'<mujoco><include file="{target}"/><worldbody/></mujoco>')
    proc = run_rbi_inprocess("audit", path)
    one_line_exit_2(proc, "include")
    assert "root:" not in proc.stderr


@pytest.mark.parametrize(
    "uri",
    [
        "package://pkg/../../secret.stl",
        "file:///etc/passwd",
        "../secret.stl",
        "package://pkg/meshes/../../../secret.stl",
    ],
)
def test_mesh_paths_do_not_leave_the_folders_they_are_given(tmp_path, uri):
    (tmp_path / "secret.stl").write_text("solid x\nendsolid x\n")
    package = tmp_path / "ws" / "pkg"
    (package / "meshes").mkdir(parents=True)
    robot_folder = tmp_path / "ws" / "robot"
    robot_folder.mkdir()
    path = write(robot_folder, "r.urdf", with_mesh(uri))
    proc = run_rbi_inprocess("audit", path, "--package-path", f"pkg={package}")
    one_line_exit_2(proc)
    assert "secret.stl" not in proc.stderr or "no such file" in proc.stderr or "leaves" in proc.stderr


def test_a_fifo_where_a_mesh_should_be_is_refused_at_once(tmp_path):
    os.mkfifo(tmp_path / "mesh.stl")
    one_line_exit_2(
        run_rbi_inprocess("audit", write(tmp_path, "r.urdf", with_mesh("mesh.stl"))), "not a regular file"
    )


@pytest.mark.parametrize("command", ["audit", "import"])
def test_a_fifo_given_as_the_robot_file_is_refused_in_plain_words(tmp_path, command):
    os.mkfifo(tmp_path / "r.urdf")
    proc = run_rbi_inprocess(command, str(tmp_path / "r.urdf"))
    one_line_exit_2(proc, "not a regular file but a FIFO (named pipe); give a robot file")
    assert "file file" not in proc.stderr


@pytest.mark.parametrize(
    "inertia, size",
    [("1e308", "0.2 0.1 0.05"), ("1", "1e200 1e200 1e200"), ("1e-300", "1e-120 1e-120 1e-120")],
)
def test_extreme_numbers_are_a_result_or_one_line(tmp_path, inertia, size):
    text = (
        f'<robot name="r"><link name="a"><inertial><mass value="2"/><inertia ixx="{inertia}" ixy="0" ixz="0" '
        f'iyy="{inertia}" iyz="0" izz="{inertia}"/></inertial><collision><geometry><box size="{size}"/>'
        "</geometry></collision></link></robot>"
    )
    proc = run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text), "--format", "json")
    assert (
        proc.returncode in (0, 1, 2)
        and "Traceback" not in proc.stderr
        and "internal error" not in proc.stderr
    )
    if proc.returncode == 2:
        assert len(proc.stderr.strip().splitlines()) == 1


def test_a_chain_of_450_bodies_is_read(tmp_path):
    depth = 450
    text = (
        "<mujoco><worldbody>"
        + '<body pos="0 0 0.1"><joint/><geom size="0.01"/>' * depth
        + "</body>" * depth
        + "</worldbody></mujoco>"
    )
    proc = run_rbi_inprocess("audit", write(tmp_path, "chain.xml", text), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert len(json.loads(proc.stdout)["links"]) == depth


names = (
    st.text(
        st.characters(blacklist_categories=("Cs",), blacklist_characters="\ufffe\uffff"),
        min_size=1,
        max_size=30,
    )
    .map(lambda s: "".join(c for c in s if c in "\t\n\r" or ord(c) >= 0x20))
    .filter(str.strip)
)


@given(st.lists(names, min_size=1, max_size=3, unique=True))
@example(["0\u2028"])  # found by hypothesis: the line separator was printed raw
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_any_link_names_give_a_fixed_copy_that_is_xml_and_a_safe_terminal(tmp_path, link_names):
    from xml.sax.saxutils import quoteattr

    def attr(n):
        return quoteattr(n, {chr(10): "&#10;", chr(13): "&#13;", chr(9): "&#9;"})

    links = "".join(f"<link name={attr(n)}>{BOX}</link>" for n in link_names)
    joints = "".join(  # one root link: each other link fixed to the first
        f'<joint name="j{i}" type="fixed"><parent link={attr(link_names[0])}/><child link={attr(n)}/></joint>'
        for i, n in enumerate(link_names[1:])
    )
    path = write(tmp_path, "r.urdf", f'<robot name="r">{links}{joints}</robot>')
    out = tmp_path / "fixed.urdf"
    if out.exists():
        out.unlink()
    proc = run_rbi_inprocess("audit", path, "--fix", "--out", out)
    assert proc.returncode == 0, proc.stderr
    root = ET.parse(out).getroot()  # still well-formed XML, comments and all
    assert [link.get("name") for link in root.iter("link")] == link_names
    for stream in (proc.stdout, proc.stderr):
        assert not any(ch in stream for ch in "\x1b\x9b\u202e\u2028")


@pytest.mark.parametrize("fmt", ["xml_urdf", "mjcf"])
def test_moments_whose_sum_overflows_are_one_spec_error_and_no_numpy_warning(tmp_path, fmt):
    """Three moments of 1e308 are each finite but add up past the largest double: rbi.audit
    raises SpecError naming the file, the link and the field, and numpy prints no
    RuntimeWarning on the way (warnings are errors here)."""
    import warnings

    import rbi

    if fmt == "mjcf":
        name, text = (
            "r.xml",
            '<mujoco><worldbody><body name="a"><joint type="hinge"/><inertial pos="0 0 0" mass="1" '
            'diaginertia="1e308 1e308 1e308"/></body></worldbody></mujoco>',
        )
    else:
        name, text = (
            "r.urdf",
            '<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="1e308" ixy="0" '
            'ixz="0" iyy="1e308" iyz="0" izz="1e308"/></inertial></link></robot>',
        )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rbi.SpecError, match=r"\(a\): inertia: numbers too large: .*1\.8e\+308"):
            rbi.audit(write(tmp_path, name, text))


def test_a_robot_whose_totals_overflow_is_told_which_numbers_are_too_large(tmp_path):
    """One moment of 1e308 kg·m² (the entries' sum is still a double) overflows the whole
    robot's inertia. The message names the moment as well as the distances (it once blamed a
    centre of mass '0 m from the root' and asked for lengths in metres), and numpy prints no
    RuntimeWarning on the way."""
    import warnings

    import rbi

    text = (
        '<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="1e308" ixy="0" '
        'ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial><collision><geometry><box size="1 1 1"/>'
        "</geometry></collision></link></robot>"
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rbi.SpecError, match=r"overflow a double .*moments up to 1e\+308 kg·m²"):
            rbi.audit(write(tmp_path, "r.urdf", text))


XACRO_READING_DATA = (
    '<?xml version="1.0"?>\n<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="x">\n'
    '  <xacro:property name="y" value="${{load_yaml(\'config.yaml\')}}"/>\n'
    '  <link name="${{{expression}}}"/>\n</robot>\n'
)


@pytest.mark.parametrize("expression", ["float(y['token'])", "int(y['token'])"])
@pytest.mark.parametrize("command", ["audit", "import", "validate"])
def test_a_xacro_error_never_prints_what_a_data_file_holds(tmp_path, expression, command):
    """A xacro that converts a value of a YAML file it loads printed the value: 'xacro could not
    expand it: could not convert string to float: 'sk-SECRET-...' when evaluating expression
    ...' (an error message never prints the content of a file other than the robot file). The
    value is now '...'; the expression, from the robot file itself, is kept."""
    pytest.importorskip("xacro")
    write(tmp_path, "config.yaml", "token: sk-SECRET-1234567890\nname: arm\n")
    robot = write(tmp_path, "robot.urdf.xacro", XACRO_READING_DATA.format(expression=expression))
    proc = run_rbi_inprocess(command, robot)
    assert proc.returncode == 2, proc.stderr
    text = proc.stderr + proc.stdout
    assert "SECRET" not in text and expression in text, text


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_a_sphere_whose_volume_overflows_is_one_line(tmp_path, fmt):
    """Found: a collision sphere of radius 1e110 m was an internal error (exit 1): Python's
    float power (r³) raises OverflowError where a box's product gives inf. Refused as the box
    is, naming the geometry."""
    text = (
        '<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" '
        'iyy="1" iyz="0" izz="1"/></inertial><collision><geometry><sphere radius="1e110"/>'
        "</geometry></collision></link></robot>"
    )
    proc = run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text), "--format", fmt)
    one_line_exit_2(proc, "sphere", "too large")


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
@pytest.mark.parametrize(
    "name, text",
    [
        ("r.urdf", f'<robot name="r"><link name="a">{BOX.replace("2", "1e308", 1)}</link></robot>'),
        (
            "r.sdf",
            '<sdf version="1.9"><model name="m"><link name="a"><inertial><mass>1e308</mass><inertia>'
            "<ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial><collision name='c'><geometry>"
            "<box><size>0.1 0.1 0.1</size></box></geometry></collision></link></model></sdf>",
        ),
    ],
)
def test_a_mass_whose_geometry_overflows_is_one_line(tmp_path, name, text, fmt):
    """Found: a declared mass of 1e308 kg on a 0.1 m box (URDF, SDF) was 'rbi: internal error:
    LinAlgError: Eigenvalues did not converge' (exit 1): the geometry's inertia at that mass
    overflows, and its principal moments were asked for before the overflow was refused. Now
    exit 2, one line naming the link and the overflow."""
    proc = run_rbi_inprocess("audit", write(tmp_path, name, text), "--format", fmt)
    one_line_exit_2(proc, name, "link[0] (a)", "overflows a double")
