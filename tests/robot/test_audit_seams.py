"""Issue 38's robot items: the totals say which declared moments they leave out; `--fix` writes
only characters the file's declared encoding holds and agrees with MuJoCo's compiler bounds; a
centre of mass whose distance overflows is one refusal in every form; `--joints a=1 b=2`."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess

FORMS = ("table", "json", "csv")
ROOT = Path(__file__).resolve().parents[2]


def _link(name: str, mass: str, moments: str, xyz: str = "0 0 0", geometry: str = "") -> str:
    ixx, iyy, izz = moments.split()
    return (
        f'<link name="{name}"><inertial><origin xyz="{xyz}"/><mass value="{mass}"/>'
        f'<inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="0" ixz="0" iyz="0"/></inertial>{geometry}</link>'
    )


def _fixed(name: str, parent: str, child: str) -> str:
    return f'<joint name="{name}" type="fixed"><parent link="{parent}"/><child link="{child}"/></joint>'


def test_total_names_the_mass_0_links_whose_moments_it_leaves_out(tmp_path):
    """Two links of 1 kg at x = ±1 and a mass-0 link declaring 5 kg·m² moments: the total is
    the two masses' (Iyy = Izz = 2 kg·m² about the centre, Ixx 0.2), not 5 more; it says so."""
    text = (
        '<robot name="r">'
        + _link("a", "1", "0.1 0.1 0.1", "1 0 0")
        + _link("ghost", "0", "5 5 5")
        + _link("b", "1", "0.1 0.1 0.1", "-1 0 0")
        + _fixed("j1", "a", "ghost")
        + _fixed("j2", "a", "b")
        + "</robot>"
    )
    path = tmp_path / "r.urdf"
    path.write_text(text)
    proc = run_rbi_inprocess("audit", str(path), "--format", "json")
    total = json.loads(proc.stdout)["total"]
    np.testing.assert_allclose(total["moments"], [0.2, 2.2, 2.2], rtol=1e-12)
    assert total["left_out"] == ["ghost"]
    table = run_rbi_inprocess("audit", str(path))
    lines = table.stdout.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("total"))
    under = "\n".join(lines[at : at + 5])
    assert "ghost" in under and "left out" in under
    clean = tmp_path / "c.urdf"
    clean.write_text('<robot name="c">' + _link("a", "1", "0.1 0.1 0.1") + "</robot>")
    proc = run_rbi_inprocess("audit", str(clean), "--format", "json")
    assert json.loads(proc.stdout)["total"]["left_out"] == []
    assert "left out" not in run_rbi_inprocess("audit", str(clean)).stdout


@pytest.mark.parametrize("name", ["franka_panda/panda.urdf", "kuka_iiwa/model.urdf"])
def test_the_left_out_links_explain_the_difference_from_pinocchio(name):
    """pybullet's panda and kuka_iiwa, rooted on a free flyer in Pinocchio (so its root link
    counts): Pinocchio adds the moments of the mass-0 links (centroidal inertia 7.3 % and 2.8 %
    off by Frobenius norm); rbi's total with the moments of ``left_out`` added back, each turned
    into the root frame, is Pinocchio's to 1e-12."""
    pin = pytest.importorskip("pinocchio")
    pybullet_data = pytest.importorskip("pybullet_data")
    import rbi
    from rbi.robot.tree import placement

    path = f"{pybullet_data.getDataPath()}/{name}"
    report = rbi.audit(path, geometry="none")
    left_out = report.as_dict()["total"]["left_out"]
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    data = model.createData()
    pin.ccrba(model, data, pin.neutral(model), np.zeros(model.nv))
    theirs, ours = data.Ig.inertia, report.total.inertia_about_com
    assert data.Ig.mass == pytest.approx(report.total.mass, rel=1e-12)
    assert np.linalg.norm(ours - theirs) > 0.02 * np.linalg.norm(theirs)
    at, names = placement(report.model), [link.name for link in report.model.links]
    added = ours.copy()
    for row in map(names.index, left_out):
        R = at.placed_rotations[row]
        added += R @ report.links[row].declared.inertia_about_com @ R.T
    np.testing.assert_allclose(added, theirs, rtol=0, atol=1e-12 * np.abs(theirs).max())


ASCII_URDF = (
    '<?xml version="1.0" encoding="{encoding}"?>\n<robot name="a">\n  <link name="base">\n'
    '    <inertial><mass value="1"/><inertia ixx="10" iyy="10" izz="10" ixy="0" ixz="0" iyz="0"/></inertial>\n'
    '    <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>\n  </link>\n</robot>\n'
)


@pytest.mark.parametrize("encoding", ["US-ASCII", "ascii", "ISO-8859-1"])
@pytest.mark.parametrize("out", [False, True])
def test_fix_writes_only_characters_the_declared_encoding_holds(tmp_path, encoding, out):
    path = tmp_path / "a.urdf"
    path.write_text(ASCII_URDF.format(encoding=encoding), encoding="ascii")
    extra = ("--out", str(tmp_path / "fixed.urdf")) if out else ()
    proc = run_rbi_inprocess("audit", str(path), "--fix", *extra)
    assert "internal error" not in proc.stderr
    assert proc.returncode == (0 if out else 1), proc.stderr
    if out:
        data = (tmp_path / "fixed.urdf").read_bytes()
        data.decode(encoding.lower().replace("us-ascii", "ascii"))
        if "ASCII" in encoding.upper():
            assert max(data) < 128
        assert b"rbi audit fix" in data
        again = run_rbi_inprocess("audit", str(tmp_path / "fixed.urdf"))
        assert again.returncode == 0, again.stdout


def test_a_centre_of_mass_whose_distance_overflows_is_one_refusal_in_every_form(tmp_path):
    """A CoM 1e155 m from a 0.1 m box: its offset over the box's size squares past a double.
    Every form: exit 2, one line naming the file and the link, nothing on stdout; the API too."""
    geometry = '<collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>'
    path = tmp_path / "far.urdf"
    path.write_text(
        '<robot name="far">' + _link("base", "1", "0.1 0.2 0.3", "1e155 0 0", geometry) + "</robot>"
    )
    for form in FORMS:
        proc = run_rbi_inprocess("audit", str(path), "--format", form)
        assert proc.returncode == 2 and proc.stdout == "", (form, proc.stdout)
        assert len(proc.stderr.strip().splitlines()) == 1
        assert "far.urdf" in proc.stderr and "base" in proc.stderr and "overflow" in proc.stderr
    import rbi

    with pytest.raises(rbi.SpecError, match="far.urdf.*base"):
        rbi.audit(path)


def test_mujoco_boundinertia_fix_agrees_with_the_audit_of_the_written_file(tmp_path):
    """boundinertia 0.1 kg·m² over a 5 cm cube of 1 kg (0.0017 kg·m²): MuJoCo raises whatever
    is written to 0.1, 60 × the geometry's; --fix --out cannot fix it, and says so (exit 1, as
    the audit of the written file)."""
    mujoco = pytest.importorskip("mujoco")
    text = (
        '<mujoco><compiler boundinertia="{b}"/><worldbody><body name="a"><joint type="hinge"/>'
        '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
        '<geom type="box" size="0.05 0.05 0.05" mass="1"/></body></worldbody></mujoco>'
    )
    for bound, fixable in (("0.1", False), ("0.002", True)):
        path = tmp_path / "b.xml"
        path.write_text(text.format(b=bound))
        out = tmp_path / "fixed.xml"
        out.unlink(missing_ok=True)
        proc = run_rbi_inprocess("audit", str(path), "--fix", "--out", str(out), "--format", "json")
        again = run_rbi_inprocess("audit", str(out if out.exists() else path))
        assert proc.returncode == again.returncode == (0 if fixable else 1), (bound, proc.stderr)
        result = json.loads(proc.stdout)["fix"]
        if not fixable:
            assert [each["link"] for each in result["unfixable"]] == ["body[0] (a)"]
            assert "boundinertia" in result["unfixable"][0]["reason"]
        mujoco.MjModel.from_xml_path(str(out if out.exists() else path))


def test_joints_take_several_values_after_one_option(tmp_path):
    """`--joints a=1 b=2` as the synopsis `[--joints NAME=VALUE ...]` reads: the same as
    `--joints a=1 --joints b=2`."""
    text = (
        '<robot name="r">'
        + _link("base", "1", "0.1 0.1 0.1")
        + _link("l1", "1", "0.1 0.1 0.1", "1 0 0")
        + _link("l2", "1", "0.1 0.1 0.1", "1 0 0")
        + '<joint name="a" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/></joint>'
        + '<joint name="b" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="1 0 0"/>'
        + '<axis xyz="0 0 1"/></joint></robot>'
    )
    path = tmp_path / "r.urdf"
    path.write_text(text)
    repeated = run_rbi_inprocess("audit", str(path), "--joints", "a=1", "--joints", "b=2", "-f", "json")
    for args in (
        ("--joints", "a=1", "b=2", str(path)),
        (str(path), "--joints", "a=1", "b=2"),
        (str(path), "--joints", "a=1", "b=2", "--format", "json"),
    ):
        proc = run_rbi_inprocess("audit", *args, "-f", "json")
        assert proc.returncode == 0, proc.stderr
        assert json.loads(proc.stdout)["total"] == json.loads(repeated.stdout)["total"]
    one = json.loads(run_rbi_inprocess("audit", str(path), "--joints", "a=1", "-f", "json").stdout)
    assert one["total"] != json.loads(repeated.stdout)["total"]


@pytest.mark.parametrize("options", [(), ("--fix",), ("--joints", "shoulder=0.5")])
def test_audit_json_is_the_reports_to_dict_with_the_file(options, monkeypatch):
    """`rbi audit --format json` = `rbi.audit(...).to_dict()` with "file" first; the report also
    has to_pandas (one row a link), a table for print() and an HTML repr from the same rows."""
    import rbi

    monkeypatch.chdir(ROOT)
    path = "bodies/two_link_arm.urdf"
    proc = run_rbi_inprocess("audit", path, *options, "--format", "json")
    kwargs = {"fix": True} if "--fix" in options else {}
    if "--joints" in options:
        kwargs["joints"] = {"shoulder": 0.5}
    report = rbi.audit(path, **kwargs)
    assert json.loads(proc.stdout) == {"file": path, **report.to_dict()}
    assert list(json.loads(proc.stdout))[0] == "file"
    frame = report.to_pandas()
    assert list(frame["link"]) == ["base_link", "upper_arm", "forearm"]
    text = str(report)
    assert "upper_arm" in text and "total" in text and "shoulder" in text
    html = report._repr_html_()
    assert html.count("<table>") == 3 and "forearm" in html


def test_import_json_is_the_results_to_dict_with_the_file(monkeypatch):
    import rbi

    monkeypatch.chdir(ROOT)
    path = "bodies/two_link_arm.urdf"
    proc = run_rbi_inprocess("import", path, "--format", "json")
    result = rbi.import_robot(path)
    assert json.loads(proc.stdout) == {"file": path, **result.to_dict()}
    frame = result.to_pandas()
    assert list(frame["name"]) == ["upper_arm", "forearm"] and frame["mass"].tolist() == [1.2, 0.8]
    assert "forearm" in str(result) and "<table>" in result._repr_html_()
    csv_text = run_rbi_inprocess("import", path, "--format", "csv").stdout
    assert csv_text == result.to_csv()


def test_dm_control_dog_bodies_are_mujocos_to_1e9():
    """dog.xml's 62 bodies, 162 STL meshes in MuJoCo's default (legacy) inertia mode: MuJoCo
    keeps each mesh's inertia on the principal axes its Jacobi iteration finds (to 1e-7
    relative), which moved 22 bodies' inertias by up to 1.2e-8 from the exact integral. Each
    body's mass, centre of mass and inertia (MuJoCo's body_inertia turned by body_iquat) to
    1e-9 of its largest moment."""
    mujoco = pytest.importorskip("mujoco")
    dm_control = pytest.importorskip("dm_control")
    import os

    import rbi

    path = os.path.join(os.path.dirname(dm_control.__file__), "suite", "dog.xml")
    model = mujoco.MjModel.from_xml_path(path)
    report = rbi.audit(path, geometry="none")
    assert len(report.links) == model.nbody - 1 == 62
    for body, link in enumerate(report.links, start=1):
        declared = link.declared
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, model.body_iquat[body])
        R = R.reshape(3, 3)
        theirs = R @ np.diag(model.body_inertia[body]) @ R.T
        scale = np.max(model.body_inertia[body])
        assert declared.mass == pytest.approx(model.body_mass[body], rel=1e-12)
        np.testing.assert_allclose(declared.center_of_mass, model.body_ipos[body], rtol=0, atol=1e-12)
        assert np.max(np.abs(declared.inertia_about_com - theirs)) <= 1e-9 * scale, link.name
        moments = np.sort(np.linalg.eigvalsh(declared.inertia_about_com))
        assert np.max(np.abs(moments - np.sort(model.body_inertia[body]))) <= 1e-9 * scale, link.name
