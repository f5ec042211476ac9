"""`rbi export --to urdf|mjcf|sdf`: the XML parses, carries the body's numbers exactly, in SI
whatever the spec's units, in each format's own convention."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from tests.conftest import BODIES, run_rbi, run_rbi_inprocess

# A body written in mm and g whose SI answer is worked by hand: a 300 g point at
# (100, 0, 0) mm and a 100 g point at (-100, 200, 0) mm.
#   mass 0.4 kg; CoM = (0.3·0.1 − 0.1·0.1, 0.1·0.2, 0)/0.4 = (0.05, 0.05, 0) m
#   offsets from the CoM: a = (0.05, −0.05, 0), b = (−0.15, 0.15, 0)
#   Σ m x² = 0.3·0.0025 + 0.1·0.0225 = 0.003, Σ m y² = 0.003, Σ m x y = −0.003
#   Ixx = Σ m y² = 0.003, Iyy = 0.003, Izz = 0.006, Ixy = −Σ m x y = +0.003
MM_G = """
name: two-points
units: {length: mm, mass: g}
parts:
  - {shape: point, mass: 300, position: [100, 0, 0]}
  - {shape: point, mass: 100, position: [-100, 200, 0]}
"""
SI_MASS, SI_COM = 0.4, [0.05, 0.05, 0.0]
SI_INERTIA = np.array([[0.003, 0.003, 0.0], [0.003, 0.003, 0.0], [0.0, 0.0, 0.006]])


def export(path, *args) -> str:
    proc = run_rbi_inprocess("export", path, *args)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def floats(text: str) -> list[float]:
    return [float(x) for x in text.split()]


def test_urdf_is_si_and_carries_matrix_entries(write_spec):
    root = ET.fromstring(export(write_spec(MM_G), "--to", "urdf"))
    assert root.tag == "inertial"
    assert float(root.find("mass").get("value")) == pytest.approx(SI_MASS, rel=1e-15)
    assert floats(root.find("origin").get("xyz")) == pytest.approx(SI_COM, rel=1e-14)
    assert floats(root.find("origin").get("rpy")) == [0, 0, 0]
    inertia = root.find("inertia")
    got = {k: float(inertia.get(k)) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    want = {"ixx": 0.003, "ixy": 0.003, "ixz": 0.0, "iyy": 0.003, "iyz": 0.0, "izz": 0.006}
    assert got == pytest.approx(want, rel=1e-12, abs=1e-18)


def test_sdf_pose_mass_and_inertia_children(write_spec):
    root = ET.fromstring(export(write_spec(MM_G), "--to", "sdf"))
    assert floats(root.find("pose").text) == pytest.approx(SI_COM + [0, 0, 0], rel=1e-14)
    assert float(root.find("mass").text) == pytest.approx(SI_MASS, rel=1e-15)
    block = root.find("inertia")
    assert float(block.find("ixy").text) == pytest.approx(0.003, rel=1e-12)
    assert float(block.find("izz").text) == pytest.approx(0.006, rel=1e-12)


def test_mjcf_fullinertia_order_is_xx_yy_zz_xy_xz_yz(write_spec):
    root = ET.fromstring(export(write_spec(MM_G), "--to", "mjcf"))
    assert float(root.get("mass")) == pytest.approx(SI_MASS, rel=1e-15)
    assert floats(root.get("pos")) == pytest.approx(SI_COM, rel=1e-14)
    assert floats(root.get("fullinertia")) == pytest.approx(
        [0.003, 0.003, 0.006, 0.003, 0.0, 0.0], rel=1e-12, abs=1e-18
    )


def test_numbers_round_trip_exactly_against_rbi_inertia():
    """Full precision: the XML holds the very doubles `rbi inertia --units SI` prints."""
    path = BODIES / "flywheel.yaml"
    inertia = json.loads(run_rbi_inprocess("inertia", path, "--units", "SI", "-f", "json").stdout)
    I = inertia["inertia"]
    root = ET.fromstring(export(path, "--to", "mjcf"))
    assert floats(root.get("fullinertia")) == [I[0][0], I[1][1], I[2][2], I[0][1], I[0][2], I[1][2]]
    assert float(root.get("mass")) == inertia["mass"]
    assert floats(root.get("pos")) == inertia["center_of_mass"]


def test_mjcf_diagonal_form_rebuilds_the_matrix(bodies):
    out = json.loads(run_rbi_inprocess("inertia", bodies / "tbar.yaml", "-f", "json").stdout)
    root = ET.fromstring(export(bodies / "tbar.yaml", "--to", "mjcf", "--diagonal"))
    w, x, y, z = floats(root.get("quat"))
    R = Rotation.from_quat([x, y, z, w]).as_matrix()  # principal frame -> body frame
    rebuilt = R @ np.diag(floats(root.get("diaginertia"))) @ R.T
    np.testing.assert_allclose(rebuilt, out["inertia"], rtol=1e-12, atol=1e-12 * np.abs(out["inertia"]).max())
    assert floats(root.get("diaginertia")) == sorted(floats(root.get("diaginertia")))


@pytest.mark.parametrize(
    "to, root_tag, path",
    [
        ("urdf", "robot", "link/inertial"),
        ("sdf", "sdf", "model/link/inertial"),
        ("mjcf", "mujoco", "worldbody/body/inertial"),
    ],
)
def test_document_wraps_the_element(to, root_tag, path):
    root = ET.fromstring(export(BODIES / "top.yaml", "--to", to, "--document"))
    assert root.tag == root_tag and root.find(path) is not None


def test_json_format_holds_numbers_and_xml():
    out = json.loads(run_rbi_inprocess("export", BODIES / "top.yaml", "--to", "urdf", "-f", "json").stdout)
    assert out["units"] == {"length": "m", "mass": "kg"} and out["mass"] == 0.5
    assert ET.fromstring(out["xml"]).tag == "inertial"


def test_bad_requests_exit_2():
    proc = run_rbi_inprocess("export", BODIES / "top.yaml", "--to", "sdf", "--diagonal")
    assert proc.returncode == 2 and "--diagonal" in proc.stderr
    assert run_rbi_inprocess("export", BODIES / "top.yaml", "--to", "step").returncode == 2


def test_installed_command_prints_parseable_xml():
    proc = run_rbi("export", BODIES / "top.yaml", "--to", "urdf", check=True)
    assert float(ET.fromstring(proc.stdout).find("mass").get("value")) == 0.5


@pytest.mark.parametrize("to", ["urdf", "sdf", "mjcf"])
def test_names_with_control_characters_give_well_formed_xml_and_reach_the_terminal_escaped(tmp_path, to):
    """XML 1.0 cannot hold ESC or BEL, and printed raw they would drive the terminal; a comment
    cannot hold '--' (here from the file's name)."""
    spec = tmp_path / "a---b.yaml"
    spec.write_text(
        'name: "arm\\e]0;title\\a"\nparts:\n  - {shape: sphere, mass: 1, radius: 0.1, center: [0, 0, 0]}\n'
    )
    proc = run_rbi_inprocess("export", spec, "--to", to, "--document")
    assert proc.returncode == 0, proc.stderr
    assert not any(ord(c) < 32 and c not in "\n\t" for c in proc.stdout)
    root = ET.fromstring(proc.stdout)  # well formed, the leading comment included
    assert "arm\\x1b]0;title\\x07" in ET.tostring(root, encoding="unicode")


POINT_MASS = (
    "units: {length: m, mass: kg}\nparts:\n  - {name: p, shape: point, mass: 1, position: [0, 0, 0]}\n"
)
ZERO_MOMENT = (
    "the inertia has a zero principal moment (a point mass or thin rod); "
    "simulators such as MuJoCo refuse a moving body without rotational inertia"
)


@pytest.mark.parametrize("to", ["urdf", "mjcf", "sdf"])
def test_the_zero_moment_warning_is_in_json_as_table_output_prints_it(write_spec, to):
    """One warning path: JSON's "warnings" holds the lines table and CSV output print on stderr
    (the zero-moment line was printed on stderr only, naming no file, and JSON said [])."""
    path = write_spec(POINT_MASS, "pt.yaml")
    as_json = run_rbi_inprocess("export", path, "--to", to, "--format", "json")
    assert as_json.returncode == 0, as_json.stderr
    warnings = json.loads(as_json.stdout)["warnings"]
    assert warnings == [f"{path}: {ZERO_MOMENT}"]
    assert as_json.stderr == ""
    for form in ("table", "csv"):
        proc = run_rbi_inprocess("export", path, "--to", to, "--format", form)
        assert proc.returncode == 0, proc.stderr
        assert proc.stderr.splitlines() == [f"rbi: warning: {w}" for w in warnings]


def test_a_body_with_three_moments_has_no_export_warning():
    proc = run_rbi_inprocess("export", BODIES / "top.yaml", "--to", "mjcf", "--format", "json")
    assert json.loads(proc.stdout)["warnings"] == [] and proc.stderr == ""
