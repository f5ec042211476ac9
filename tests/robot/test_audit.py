"""`rbi audit` on small robot files made for the tests: each flag with its level, each refusal
with its one line, the totals against closed forms, and `--fix` keeping every other byte."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from rbi.errors import InputError
from tests.conftest import one_line_exit_2, run_rbi_inprocess


def write(tmp_path, name: str, text: str | bytes):
    path = tmp_path / name
    (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
    return path


def box_inertia(m, a, b, c):
    return np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])


def urdf_link(name, mass, I, size="0.2 0.1 0.05", xyz="0 0 0", extra=""):
    ixx, iyy, izz = I
    return (
        f'  <link name="{name}">\n    <inertial>\n      <origin xyz="{xyz}"/>\n      <mass value="{mass}"/>\n'
        f'      <inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/>\n    </inertial>\n'
        f'    <collision><geometry><box size="{size}"/></geometry></collision>{extra}\n  </link>\n'
    )


def joint(name, parent, child, kind="revolute", xyz="0 0 0", axis="0 0 1"):
    return (
        f'  <joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{xyz}"/><axis xyz="{axis}"/></joint>\n'
    )


GOOD = np.diag(box_inertia(2.0, 0.2, 0.1, 0.05))


def robot(*pieces):
    return (
        '<?xml version="1.0"?>\n<!-- made for the tests -->\n<robot name="r">\n'
        + "".join(pieces)
        + "</robot>\n"
    )


def audit_json(path, *args):
    proc = run_rbi_inprocess("audit", path, "--format", "json", *args)
    return proc, (json.loads(proc.stdout) if proc.stdout.strip() else None)


# --- flags ---------------------------------------------------------------------------------------


def test_a_link_that_matches_its_box_has_no_flag_and_exit_0(tmp_path):
    path = write(tmp_path, "r.urdf", robot(urdf_link("base", 2.0, GOOD)))
    proc, result = audit_json(path)
    assert proc.returncode == 0, proc.stderr
    (link,) = result["links"]
    assert link["flags"] == []
    assert link["geometry"]["volume"] == pytest.approx(0.2 * 0.1 * 0.05, rel=1e-15)
    assert link["geometry"]["implied_density"] == pytest.approx(2.0 / 0.001, rel=1e-12)
    assert np.allclose(
        link["geometry"]["inertia_about_com"], box_inertia(2.0, 0.2, 0.1, 0.05), rtol=1e-14, atol=0
    )
    assert set(result) >= {"file", "robot", "units", "links", "total"}
    assert set(link) >= {"name", "declared", "geometry", "flags"}
    assert set(link["declared"]) == {"mass", "center_of_mass", "inertia_about_com", "moments"}


@pytest.mark.parametrize(
    "I, code, level",
    [
        ((1, 1, 1), "placeholder", "error"),  # identity: 1 kg·m² on a 20 cm box of 2 kg
        ((0.001, 0.001, 0.001), "placeholder", "warning"),  # within 10× of the box, but three equal moments
        (tuple(20 * GOOD), "mismatch", "error"),  # 20× the geometry's
        (tuple(3 * GOOD), "mismatch", "warning"),  # 3×
        ((GOOD[0], GOOD[1], 3 * (GOOD[0] + GOOD[1])), "unphysical", "error"),  # triangle inequality
        ((-GOOD[0], GOOD[1], GOOD[2]), "unphysical", "error"),  # a negative moment
    ],
)
def test_each_flag_with_its_level(tmp_path, I, code, level):
    path = write(tmp_path, "r.urdf", robot(urdf_link("base", 2.0, I)))
    proc, result = audit_json(path)
    flags = result["links"][0]["flags"]
    assert (code, level) in [(f["code"], f["level"]) for f in flags], flags
    assert proc.returncode == (1 if any(f["level"] == "error" for f in flags) else 0)


@pytest.mark.parametrize(
    "I, margin",
    [
        ((GOOD[0], GOOD[1], 3 * (GOOD[0] + GOOD[1])), "; margin I1 + I2 − I3 = "),
        ((-GOOD[0], GOOD[1], GOOD[2]), " kg·m² below zero"),
    ],
)
def test_the_unphysical_flag_says_what_validate_says(tmp_path, I, margin):
    """One wording (rbi.formats.robot_files.inertia_problem_text): audit's flag is validate's
    line after 'inertia: ', margin included."""
    path = write(tmp_path, "r.urdf", robot(urdf_link("base", 2.0, I)))
    _, result = audit_json(path)
    (flag,) = [f for f in result["links"][0]["flags"] if f["code"] == "unphysical"]
    (line,) = run_rbi_inprocess("validate", path).stdout.splitlines()[:1]
    assert margin in flag["message"] and line.endswith(": link[0] (base): inertia: " + flag["message"])


def test_density_flag_for_a_unit_mistake(tmp_path):
    # the mass in grams: 2000 "kg" in a 1-litre box, moments scaled alike (so the shape agrees)
    path = write(tmp_path, "r.urdf", robot(urdf_link("base", 2000.0, tuple(1000 * GOOD))))
    _, result = audit_json(path)
    assert [(f["code"], f["level"]) for f in result["links"][0]["flags"]] == [("density", "warning")]
    assert result["links"][0]["geometry"]["implied_density"] == pytest.approx(2e6)


def test_com_outside_the_geometry_is_a_mismatch_warning(tmp_path):
    path = write(tmp_path, "r.urdf", robot(urdf_link("base", 2.0, GOOD, xyz="0.5 0 0")))
    _, result = audit_json(path)
    assert ("mismatch", "warning") in [(f["code"], f["level"]) for f in result["links"][0]["flags"]]


def test_massless_links_root_and_fixed_are_legal_moving_ones_are_flagged(tmp_path):
    text = robot(
        '  <link name="world"/>\n',
        '  <link name="bracket"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>\n',
        '  <link name="idler"/>\n',
        urdf_link("arm", 2.0, GOOD),
        '  <link name="tip"/>\n',
        joint("fix", "world", "bracket", "fixed"),
        joint("j1", "bracket", "idler"),
        joint("j2", "idler", "arm"),
        joint("j3", "arm", "tip"),
    )
    proc, result = audit_json(write(tmp_path, "r.urdf", text))
    flags = {link["name"]: [(f["code"], f["level"]) for f in link["flags"]] for link in result["links"]}
    assert flags["world"] == [] and flags["bracket"] == []
    assert flags["idler"] == [("massless", "warning")]  # carries the arm
    assert flags["tip"] == [("massless", "error")]  # carries nothing
    assert proc.returncode == 1
    assert result["total"]["mass"] == 2.0
    base = '  <link name="base"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>\n'
    assert run_rbi_inprocess("validate", write(tmp_path, "base.urdf", robot(base))).returncode == 0


def test_mass_0_with_moments_is_unphysical_even_on_a_static_base(tmp_path):
    base = '  <link name="base"><inertial><mass value="0"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>\n'
    path = write(tmp_path, "base.urdf", robot(base))
    proc, result = audit_json(path)
    assert proc.returncode == 1
    assert [(f["code"], f["level"]) for f in result["links"][0]["flags"]] == [("unphysical", "error")]
    assert run_rbi_inprocess("validate", path).returncode == 2  # validate: an invalid file


@pytest.mark.parametrize(
    "mass, ixx, flagged",
    [
        (0.53, "-5.4e-20", False),  # a CAD export's rounding noise: below 0.53 kg x (1 um)^2
        (0.53, "-1e-12", True),  # twice that: flagged
        (2.0, "-1e-12", False),  # below 2 kg x (1 um)^2 = 2e-12
    ],
)
def test_unphysical_ignores_rounding_noise(tmp_path, mass, ixx, flagged):
    link = f'  <link name="a"><inertial><mass value="{mass}"/><inertia ixx="{ixx}" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>\n'
    _, result = audit_json(write(tmp_path, "r.urdf", robot(link)))
    codes = [f["code"] for f in result["links"][0]["flags"]]
    assert ("unphysical" in codes) is flagged


def test_tiny_negative_products_from_cad_are_read_not_crashed_on(tmp_path):
    text = robot(urdf_link("base", 2.0, GOOD).replace('ixy="0"', 'ixy="-1.2e-19"'))
    proc, result = audit_json(write(tmp_path, "r.urdf", text))
    assert proc.returncode == 0 and result["links"][0]["flags"] == []


# --- totals ----------------------------------------------------------------------------------------


def test_totals_at_zero_and_at_a_joint_value(tmp_path):
    """Two 2 kg boxes, the second's centre 0.5 m along its link's x, on a hinge about z at the
    first's centre: at q = π/2 it sits at (0, 0.5, 0), and its box turns a quarter turn about z."""
    text = robot(
        urdf_link("a", 2.0, GOOD), urdf_link("b", 2.0, GOOD, xyz="0.5 0 0"), joint("hinge", "a", "b")
    )
    path = write(tmp_path, "r.urdf", text)
    _, zero = audit_json(path)
    assert zero["total"]["mass"] == 4.0
    assert np.allclose(zero["total"]["center_of_mass"], [0.25, 0, 0], atol=1e-15)
    _, turned = audit_json(path, "--joints", f"hinge={math.pi / 2}")
    assert np.allclose(turned["total"]["center_of_mass"], [0, 0.25, 0], atol=1e-15)
    I = box_inertia(2.0, 0.2, 0.1, 0.05)
    quarter = np.diag([I[1, 1], I[0, 0], I[2, 2]])
    d = np.array([0.0, 0.25, 0.0])  # each box's offset from the common CoM
    expected = I + quarter + 2 * 2.0 * (d @ d * np.eye(3) - np.outer(d, d))
    assert np.allclose(turned["total"]["inertia_about_com"], expected, rtol=0, atol=1e-15)


def test_unknown_joint_is_refused_with_a_hint(tmp_path):
    text = robot(urdf_link("a", 2.0, GOOD), urdf_link("b", 2.0, GOOD), joint("hinge", "a", "b"))
    one_line_exit_2(
        run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text), "--joints", "hinje=1"),
        "--joints",
        "hinje",
        "did you mean 'hinge'",
    )


# --- refusals -----------------------------------------------------------------------------------


@pytest.mark.parametrize("command", ["audit", "validate", "import"])
def test_duplicate_link_names_are_exit_2_naming_the_name(tmp_path, command):
    text = robot(urdf_link("arm", 2.0, GOOD), urdf_link("arm", 2.0, GOOD))
    proc = run_rbi_inprocess(command, write(tmp_path, "r.urdf", text))
    assert proc.returncode == 2
    assert "duplicate link name 'arm'" in proc.stdout + proc.stderr


def test_a_missing_mesh_is_exit_2_naming_it(tmp_path):
    text = robot(
        urdf_link("a", 2.0, GOOD).replace('<box size="0.2 0.1 0.05"/>', '<mesh filename="gone.stl"/>')
    )
    one_line_exit_2(run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text)), "gone.stl", "no such file")


def test_package_paths_resolve_through_the_option(tmp_path):
    mesh_folder = tmp_path / "pkg" / "meshes"
    mesh_folder.mkdir(parents=True)
    (mesh_folder / "box.obj").write_text(BOX_OBJ)
    text = robot(
        urdf_link("a", 2.0, GOOD).replace(
            '<box size="0.2 0.1 0.05"/>',
            '<mesh filename="package://my_robot/meshes/box.obj" scale="0.2 0.1 0.05"/>',
        )
    )
    robot_folder = tmp_path / "robot"
    robot_folder.mkdir()
    path = write(robot_folder, "r.urdf", text)
    one_line_exit_2(run_rbi_inprocess("audit", path), "package://my_robot", "--package-path my_robot=DIR")
    proc, result = audit_json(path, "--package-path", f"my_robot={tmp_path / 'pkg'}")
    assert proc.returncode == 0, proc.stderr
    assert result["links"][0]["geometry"]["volume"] == pytest.approx(0.001, rel=1e-14)
    assert result["links"][0]["flags"] == []


BOX_OBJ = """v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5
v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8
"""


def test_files_as_found_in_the_wild(tmp_path):
    """A BOM and blank lines before <?xml, NULs after the last element: read (pybullet and
    Pinocchio load them)."""
    text = b"\xef\xbb\xbf\n\n  " + robot(urdf_link("base", 2.0, GOOD)).encode() + b"\n\x00\x00\x00"
    path = write(tmp_path, "r.urdf", text)
    for command in ("audit", "validate", "import"):
        assert run_rbi_inprocess(command, path).returncode == 0


@pytest.mark.parametrize("encoding", ["shift_jis", "x-unknown", "utf-7"])
def test_unknown_encodings_are_exit_2(tmp_path, encoding):
    text = robot(urdf_link("base", 2.0, GOOD)).replace(
        '<?xml version="1.0"?>', f'<?xml version="1.0" encoding="{encoding}"?>'
    )
    one_line_exit_2(
        run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text)), "encoding", "save the file as UTF-8"
    )


def test_latin_1_is_read_and_kept_by_fix(tmp_path):
    text = robot(urdf_link("bras_é", 2.0, (1, 1, 1))).replace(
        '<?xml version="1.0"?>', '<?xml version="1.0" encoding="ISO-8859-1"?>'
    )
    path = write(tmp_path, "r.urdf", text.encode("latin-1"))
    out = tmp_path / "fixed.urdf"
    proc = run_rbi_inprocess("audit", path, "--fix", "--out", out)
    assert proc.returncode == 0, proc.stderr
    fixed = out.read_bytes().decode("latin-1")
    assert 'name="bras_é"' in fixed


def test_a_63_mib_token_is_refused_before_parsing(tmp_path):
    """Fed whole, expat still takes time that grows with the square of a token's length (a 60
    MiB link name: over a minute), so a block of 1 MiB without a delimiter is refused."""
    from rbi.formats.robot_files import read_robot

    path = tmp_path / "big.urdf"
    path.write_bytes(b'<robot name="' + b"a" * (63 * 2**20) + b'"><link name="x"/></robot>')
    with pytest.raises(InputError, match="1 MiB without a space, tag or quote"):
        read_robot(str(path))


def test_sdf_include_is_reported_as_not_checked(tmp_path):
    text = """<sdf version="1.6"><world name="w">
  <include><uri>model://other_robot</uri></include>
  <model name="m"><link name="l"><inertial><mass>2</mass><inertia><ixx>{}</ixx><iyy>{}</iyy><izz>{}</izz></inertia>
  </inertial><collision name="c"><geometry><box><size>0.2 0.1 0.05</size></box></geometry></collision></link></model>
</world></sdf>""".format(*tuple(GOOD))
    path = write(tmp_path, "w.sdf", text)
    proc = run_rbi_inprocess("validate", path)
    assert proc.returncode == 2 and "model://other_robot" in proc.stdout and "not checked" in proc.stdout
    proc = run_rbi_inprocess("audit", path)
    assert proc.returncode == 1 and "not checked" in proc.stderr


MJCF_MAIN = """<mujoco model="inc">
  <compiler angle="radian"/>
  <include file="parts.xml"/>
  <worldbody><body name="a"><joint type="hinge"/><geom type="box" size="0.1 0.05 0.025"/>
    <include file="child.xml"/></body></worldbody>
</mujoco>"""
MJCF_PARTS = """<mujoco><default><geom density="500"/></default></mujoco>"""
MJCF_CHILD = """<mujoco><body name="b" pos="0.3 0 0"><joint type="hinge"/><geom type="capsule" fromto="0 0 0 0.2 0 0" size="0.02"/></body></mujoco>"""


def test_mjcf_include_is_followed_as_mujoco_does(tmp_path):
    mujoco = pytest.importorskip("mujoco")
    path = write(tmp_path, "main.xml", MJCF_MAIN)
    write(tmp_path, "parts.xml", MJCF_PARTS)
    write(tmp_path, "child.xml", MJCF_CHILD)
    proc, result = audit_json(path)
    assert proc.returncode == 0, proc.stderr
    model = mujoco.MjModel.from_xml_path(str(path))
    assert [link["name"] for link in result["links"]] == ["a", "b"]
    for link in result["links"]:
        assert link["declared"]["mass"] == pytest.approx(
            model.body_mass[model.body(link["name"]).id], rel=1e-12
        )
    missing = tmp_path / "child.xml"
    missing.unlink()
    proc = run_rbi_inprocess("validate", path)
    assert proc.returncode == 2 and "child.xml: no such file" in proc.stdout


def test_mjcf_explicit_inertial_is_ignored_under_inertiafromgeom_true(tmp_path):
    """The hopper case: MuJoCo ignores <inertial> when inertiafromgeom="true"."""
    mujoco = pytest.importorskip("mujoco")
    text = """<mujoco><compiler inertiafromgeom="true"/><worldbody><body name="torso"><freejoint/>
      <inertial pos="0 0 0" mass="7" diaginertia="1 1 1"/><geom type="capsule" fromto="0 0 -0.2 0 0 0.2" size="0.05"/>
      </body></worldbody></mujoco>"""
    path = write(tmp_path, "h.xml", text)
    mass = mujoco.MjModel.from_xml_path(str(path)).body_mass[1]
    _, result = audit_json(path)
    assert result["links"][0]["declared"]["mass"] == pytest.approx(mass, rel=1e-14) and mass != 7
    listing = json.loads(run_rbi_inprocess("import", path, "--format", "json").stdout)
    assert listing["links"][0]["mass"] == pytest.approx(mass, rel=1e-14)


# --- --fix -----------------------------------------------------------------------------------------


def test_fix_replaces_only_the_flagged_inertial_and_keeps_every_other_byte(tmp_path):
    text = robot(
        urdf_link("good", 2.0, GOOD),
        "  <!-- a comment,   spaced   oddly -->\n",
        urdf_link("placeholder", 2.0, (1, 1, 1)),
        joint("j", "good", "placeholder"),
    )
    path = write(tmp_path, "r.urdf", text)
    dry = run_rbi_inprocess("audit", path, "--fix")
    assert dry.returncode == 1 and "would change" in dry.stdout and "+++" in dry.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.urdf"]  # a dry run writes nothing
    out = tmp_path / "fixed.urdf"
    proc = run_rbi_inprocess("audit", path, "--fix", "--out", out)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    fixed = out.read_text()
    original = path.read_text()
    start = original.index("<inertial>", original.index('name="placeholder"'))
    end = original.index("</inertial>", start) + len("</inertial>")
    assert fixed.startswith(original[:start]) and fixed.endswith(original[end:])
    assert "rbi audit fix: was principal moments 1, 1, 1" in fixed and "placeholder" in fixed
    again_proc, again = audit_json(out)
    assert again_proc.returncode == 0
    fixed_link = again["links"][1]
    assert fixed_link["flags"] == []
    assert np.allclose(
        fixed_link["declared"]["inertia_about_com"], box_inertia(2.0, 0.2, 0.1, 0.05), rtol=1e-15, atol=0
    )


def test_fix_of_a_link_without_geometry_exits_1_and_still_writes(tmp_path):
    text = robot(
        '  <link name="bare"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" '
        'izz="3"/></inertial></link>\n'
    )
    out = tmp_path / "fixed.urdf"
    proc = run_rbi_inprocess("audit", write(tmp_path, "r.urdf", text), "--fix", "--out", out)
    assert proc.returncode == 1 and out.exists() and "not fixed" in proc.stdout


def test_fix_of_an_mjcf_inertial(tmp_path):
    mujoco = pytest.importorskip("mujoco")
    text = """<mujoco>
  <worldbody>
    <body name="arm"><joint type="hinge"/>
      <inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>
      <geom type="box" size="0.1 0.05 0.025"/>
    </body>
  </worldbody>
</mujoco>
"""
    out = tmp_path / "fixed.xml"
    proc = run_rbi_inprocess("audit", write(tmp_path, "m.xml", text), "--fix", "--out", out)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    model = mujoco.MjModel.from_xml_path(str(out))
    assert np.allclose(
        np.sort(model.body_inertia[1]), np.sort(np.diag(box_inertia(2.0, 0.2, 0.1, 0.05))), rtol=1e-14
    )


def test_api_audit_returns_the_report(tmp_path):
    from rbi.robot import audit

    report = audit(write(tmp_path, "r.urdf", robot(urdf_link("base", 2.0, (1, 1, 1)))), fix=True)
    assert report.exit_code == 1 and report.links[0].flags[0].code == "placeholder"
    assert report.fix.changes and b"rbi audit fix" in report.fix.content
    with pytest.raises(ValueError, match="^density and material: give one of them"):
        audit(tmp_path / "r.urdf", density=1000, material="steel")


def test_xacro_files_are_expanded(tmp_path):
    pytest.importorskip("xacro")
    text = (
        '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:property name="m" value="2.0"/>\n'
        '  <xacro:macro name="boxlink" params="name">\n'
        + urdf_link("${name}", "${m}", GOOD)
        + '  </xacro:macro>\n  <xacro:boxlink name="a"/>\n  <xacro:boxlink name="b"/>\n'
        + joint("j", "a", "b")
        + "</robot>\n"
    )
    proc, result = audit_json(write(tmp_path, "r.urdf.xacro", text))
    assert proc.returncode == 0, proc.stderr
    assert [link["name"] for link in result["links"]] == ["a", "b"] and result["total"]["mass"] == 4.0


def test_import_without_out_prints_one_spec_that_rbi_reads_back_with_the_audit_totals(tmp_path):
    from tests.conftest import BODIES

    robot_file = BODIES / "two_link_arm.urdf"
    proc = run_rbi_inprocess("import", robot_file)
    assert proc.returncode == 0, proc.stderr
    spec = write(tmp_path, "arm.yaml", proc.stdout)
    inertia = json.loads(run_rbi_inprocess("inertia", spec, "--format", "json").stdout)
    _, audited = audit_json(robot_file)
    assert inertia["mass"] == pytest.approx(audited["total"]["mass"], rel=1e-15)
    assert np.allclose(inertia["center_of_mass"], audited["total"]["center_of_mass"], rtol=1e-15, atol=1e-17)
    assert np.allclose(inertia["inertia"], audited["total"]["inertia_about_com"], rtol=1e-14, atol=1e-18)


FEATURES = """<mujoco model="features">
  <compiler angle="radian" eulerseq="zyx" meshdir="meshes" inertiagrouprange="0 3"/>
  <asset><mesh name="block" file="box.obj" scale="0.2 0.1 0.05"/></asset>
  <default>
    <geom density="800"/>
    <default class="heavy"><geom density="7800" type="box" size="0.02 0.03 0.04"/></default>
    <default class="light"><geom density="300"/></default>
  </default>
  <worldbody>
    <geom type="plane" size="1 1 0.1"/>
    <body name="a" euler="0.3 0.2 0.1">
      <joint type="hinge" axis="1 0 0"/>
      <geom class="heavy" pos="0.1 0 0" euler="0.5 -0.2 0.3"/>
      <geom type="ellipsoid" size="0.03 0.04 0.05" xyaxes="0 1 0 -1 0 0" mass="0.7"/>
      <geom type="box" fromto="0 0 0 0.1 0.2 0.3" size="0.01 0.02"/>
      <geom type="sphere" size="0.5" group="4"/>
      <body name="b" pos="0.3 0 0" axisangle="0 0 1 0.7" childclass="light">
        <joint type="slide" axis="0 1 0"/>
        <geom type="cylinder" fromto="0 0 -0.1 0 0.05 0.1" size="0.02"/>
        <geom type="capsule" zaxis="1 1 0" size="0.01 0.05" pos="0 0.1 0"/>
        <frame pos="0 0 0.2" quat="0.9 0.1 0.2 0.3">
          <geom type="mesh" mesh="block"/>
        </frame>
      </body>
      <body name="c" pos="0 0.4 0">
        <joint type="ball"/>
        <geom type="sphere" size="0.05" shellinertia="true" density="2"/>
        <geom type="box" size="0.05 0.04 0.03" shellinertia="true" density="3" pos="0.1 0 0"/>
        <geom type="cylinder" size="0.03 0.06" shellinertia="true" density="4" pos="0 0.1 0"/>
        <geom type="capsule" size="0.03 0.06" shellinertia="true" density="5" pos="0 -0.1 0"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.mark.parametrize("settotalmass", [None, 12.5])
def test_mjcf_compiler_features_agree_with_mujoco(tmp_path, settotalmass):
    """Default classes and childclass, every orientation form with eulerseq, fromto boxes,
    frames, mesh assets with meshdir and scale, geom groups outside inertiagrouprange, shell
    inertia of primitives, settotalmass: each body as MuJoCo compiles it."""
    mujoco = pytest.importorskip("mujoco")
    text = (
        FEATURES
        if settotalmass is None
        else FEATURES.replace(
            'inertiagrouprange="0 3"', f'inertiagrouprange="0 3" settotalmass="{settotalmass}"'
        )
    )
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "box.obj").write_text(BOX_OBJ)
    path = write(tmp_path, "features.xml", text)
    proc, result = audit_json(path)
    assert proc.returncode == 0, proc.stderr
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for link in result["links"]:
        body = model.body(link["name"]).id
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, model.body_iquat[body])
        R = R.reshape(3, 3)
        expected = R @ np.diag(model.body_inertia[body]) @ R.T
        declared = link["declared"]
        assert declared["mass"] == pytest.approx(model.body_mass[body], rel=1e-12), link["name"]
        assert np.allclose(declared["center_of_mass"], model.body_ipos[body], rtol=0, atol=1e-14), link[
            "name"
        ]
        assert np.allclose(
            declared["inertia_about_com"], expected, rtol=0, atol=1e-12 * np.max(np.abs(expected))
        ), link["name"]
    assert result["total"]["mass"] == pytest.approx(model.body_subtreemass[0], rel=1e-12)
    assert np.allclose(result["total"]["center_of_mass"], data.subtree_com[0], rtol=0, atol=1e-13)


def test_mesh_repair_closes_a_small_hole_and_says_so(tmp_path):
    (tmp_path / "open.obj").write_text(
        BOX_OBJ.replace("f 5 6 7\n", "")
    )  # one triangle missing: a 3-edge hole
    text = robot(
        urdf_link("a", 2.0, GOOD).replace(
            '<box size="0.2 0.1 0.05"/>', '<mesh filename="open.obj" scale="0.2 0.1 0.05"/>'
        )
    )
    path = write(tmp_path, "r.urdf", text)
    one_line_exit_2(
        run_rbi_inprocess("audit", path, "--mesh-inertia", "exact"),
        "open.obj",
        "not closed",
        "--mesh-repair",
        "--mesh-inertia convex",
    )
    proc, result = audit_json(path)  # auto: the hull of the open box is the box, with a warning
    assert proc.returncode == 0, proc.stderr
    assert result["links"][0]["geometry"]["volume"] == pytest.approx(0.001, rel=1e-14)
    (flag,) = [f for f in result["links"][0]["flags"] if f["code"] == "mesh"]
    assert flag["level"] == "warning" and "open.obj" in flag["message"] and "convex hull" in flag["message"]
    proc, result = audit_json(path, "--mesh-repair", "--mesh-inertia", "exact")
    assert proc.returncode == 0, proc.stderr
    assert result["links"][0]["geometry"]["volume"] == pytest.approx(0.001, rel=1e-14)
    assert any("--mesh-repair closed holes with 1 triangle(s), 0.01 m²" in note for note in result["notes"])


def test_mjcf_totals_at_joint_values_agree_with_mujoco(tmp_path):
    """Hinge and slide coordinates (MuJoCo's qpos, radians and metres), with a ref, against
    mj_forward's subtree mass and centre of mass."""
    mujoco = pytest.importorskip("mujoco")
    text = """<mujoco><compiler angle="degree"/><worldbody>
      <body name="a" pos="0.1 0.2 0.3" euler="10 20 30"><joint name="h1" type="hinge" axis="0 1 1" pos="0 0 0.1" ref="15"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03"/>
        <body name="b" pos="0.3 0 0"><joint name="s1" type="slide" axis="1 0 0"/><joint name="h2" type="hinge" axis="0 0 1"/>
          <geom type="box" size="0.1 0.02 0.03" pos="0.1 0 0"/></body></body></worldbody></mujoco>"""
    path = write(tmp_path, "m.xml", text)
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    values = {"h1": 0.7, "s1": 0.05, "h2": -1.1}
    for name, value in values.items():
        data.qpos[model.jnt_qposadr[model.joint(name).id]] = value
    mujoco.mj_forward(model, data)
    _, result = audit_json(
        path, *[arg for name, value in values.items() for arg in ("--joints", f"{name}={value}")]
    )
    assert result["total"]["mass"] == pytest.approx(model.body_subtreemass[0], rel=1e-14)
    assert np.allclose(result["total"]["center_of_mass"], data.subtree_com[0], rtol=0, atol=1e-14)


SDF_ROBOT = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="m">
    <link name="base">
      <inertial><mass>2</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.2 0.1 0.05</size></box></geometry></collision>
    </link>
    <link name="arm">
      <pose>0.5 0 0 0 0 0</pose>
      <inertial><pose>0.1 0 0 0 0 0</pose><mass>1</mass>
        <inertia><ixx>0.0001</ixx><iyy>0.0034</iyy><izz>0.0034</izz></inertia></inertial>
      <collision name="c"><pose>0.1 0 0 0 0 0</pose><geometry><cylinder><radius>0.02</radius><length>0.2</length></cylinder></geometry></collision>
    </link>
    <joint name="j" type="revolute"><parent>base</parent><child>arm</child><axis><xyz>0 0 1</xyz></axis></joint>
  </model>
</sdf>
"""


def test_sdf_fix_and_joint_totals(tmp_path):
    path = write(tmp_path, "m.sdf", SDF_ROBOT)
    proc, result = audit_json(path)
    assert proc.returncode == 1
    assert [f["code"] for f in result["links"][0]["flags"]] == ["placeholder"]
    assert np.allclose(result["total"]["center_of_mass"], [0.6 / 3, 0, 0], atol=1e-15)
    _, turned = audit_json(path, "--joints", f"j={math.pi / 2}")  # the arm's CoM swings to (0.5, 0.1, 0)
    assert np.allclose(turned["total"]["center_of_mass"], [0.5 / 3, 0.1 / 3, 0], atol=1e-15)
    out = tmp_path / "fixed.sdf"
    assert run_rbi_inprocess("audit", path, "--fix", "--out", out).returncode == 0
    again_proc, again = audit_json(out)
    assert again_proc.returncode == 0, again_proc.stdout
    assert np.allclose(
        again["links"][0]["declared"]["inertia_about_com"],
        box_inertia(2.0, 0.2, 0.1, 0.05),
        rtol=1e-15,
        atol=0,
    )
    assert out.read_text().count("<link") == 2 and "rbi audit fix" in out.read_text()
