"""Every output form of ``rbi audit`` (table, ``--format json``, ``--format csv``) on robot files the
other tests read (pybullet_data's URDFs and SDFs, gymnasium's MJCF), and on a copy written by
``--fix``: no internal error, a JSON document with one object per link, a CSV with one row per
link. The files with a massless link that has geometry (cartpole, kuka_iiwa) once crashed the JSON
and CSV forms while the table printed."""

from __future__ import annotations

import csv
import io
import json
import os
import shutil

import pytest

from tests.conftest import run_rbi_inprocess

pybullet_data = pytest.importorskip("pybullet_data")
gymnasium = pytest.importorskip("gymnasium")

PYBULLET = pybullet_data.getDataPath()
GYM = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")

FILES = [  # (path, extra options); the kuka's link_0.stl is not closed, so it is read as its hull
    (os.path.join(PYBULLET, "cartpole.urdf"), ()),
    (os.path.join(PYBULLET, "kuka_iiwa", "model.urdf"), ("--mesh-inertia", "convex")),
    (os.path.join(PYBULLET, "r2d2.urdf"), ("--mesh-inertia", "convex")),
    (os.path.join(PYBULLET, "TwoJointRobot_w_fixedJoints.urdf"), ()),
    (os.path.join(PYBULLET, "pendulum5.urdf"), ()),
    (os.path.join(PYBULLET, "kuka_iiwa", "model.sdf"), ("--mesh-inertia", "convex")),
    (os.path.join(GYM, "hopper.xml"), ()),
    (os.path.join(GYM, "ant.xml"), ()),
    (os.path.join(GYM, "inverted_pendulum.xml"), ()),
]

CSV_COLUMNS = [
    "link",
    "mass",
    "geometry_volume",
    "implied_density",
    "ratio_1",
    "ratio_2",
    "ratio_3",
    "com_offset",
    "flags",
]


def _no_internal_error(proc) -> None:
    assert proc.returncode in (0, 1), proc.stderr
    assert "internal error" not in proc.stderr and "Traceback" not in proc.stderr, proc.stderr


def _three_forms(path: str, *options: str) -> int:
    """Audit ``path`` in each form, check each is well formed; the number of links."""
    table = run_rbi_inprocess("audit", path, *options)
    _no_internal_error(table)
    assert "total (" in table.stdout
    proc = run_rbi_inprocess("audit", path, *options, "--format", "json")
    _no_internal_error(proc)
    assert proc.returncode == table.returncode
    document = json.loads(proc.stdout)
    links = document["links"]
    assert links and all("name" in link and "flags" in link for link in links)
    for link in links:
        geometry = link["geometry"]
        if geometry is not None and geometry["mass"] is None:  # a shape with no mass: no moments
            assert geometry["inertia_about_com"] is None and geometry["moments"] is None
        if geometry is not None and geometry["mass"] is not None:
            assert len(geometry["moments"]) == 3
    assert document["total"]["mass"] >= 0
    proc = run_rbi_inprocess("audit", path, *options, "--format", "csv")
    _no_internal_error(proc)
    rows = list(csv.reader(io.StringIO(proc.stdout)))
    assert rows[0] == CSV_COLUMNS
    assert len(rows) == 1 + len(links) and all(len(row) == len(CSV_COLUMNS) for row in rows)
    for row, link in zip(rows[1:], links, strict=True):  # unnamed MJCF bodies show their label
        assert link["name"] is None or row[0] == link["name"]
    return len(links)


@pytest.mark.parametrize("path,options", FILES, ids=lambda value: os.path.basename(str(value)))
def test_every_form_of_audit(path, options):
    _three_forms(path, *options)


@pytest.mark.parametrize("path,options", FILES[:3], ids=lambda value: os.path.basename(str(value)))
def test_every_form_of_audit_on_the_fixed_copy(tmp_path, path, options):
    folder = os.path.dirname(path)
    for entry in os.listdir(folder):  # the meshes beside the copy, where the file names them
        if entry.endswith((".stl", "meshes")):
            copy = shutil.copytree if entry == "meshes" else shutil.copy
            copy(os.path.join(folder, entry), tmp_path / entry)
    fixed = tmp_path / os.path.basename(path)
    proc = run_rbi_inprocess("audit", path, *options, "--fix", "--out", fixed)
    _no_internal_error(proc)
    assert fixed.exists()
    assert _three_forms(str(fixed), *options) == _three_forms(path, *options)


def test_a_moment_the_geometry_cannot_give_is_null_in_json_and_empty_in_csv(tmp_path):
    """A 1 µm-radius, 1 m cylinder: its moment about its own axis (m r²/2 = 5e-13 kg·m² for 1 kg)
    is too small to divide by, so that ratio is '-' in the table. JSON and CSV once refused the
    whole result as 'not finite' (exit 2) where the table printed (exit 0)."""
    path = tmp_path / "thin.urdf"
    path.write_text(
        '<robot name="thin"><link name="base"><inertial><mass value="1"/>'
        '<inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>'
        '<collision><geometry><cylinder radius="1e-6" length="1"/></geometry></collision>'
        "</link></robot>"
    )
    table = run_rbi_inprocess("audit", str(path))
    assert table.returncode == 0, table.stderr
    assert "-, 1.2, 1.2 ×" in table.stdout
    proc = run_rbi_inprocess("audit", str(path), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    ratios = json.loads(proc.stdout)["links"][0]["moment_ratios"]
    # declared 0.1 about a transverse axis against the rod's m L²/12 = 1/12: 1.2
    assert ratios[0] is None and ratios[1:] == pytest.approx([1.2, 1.2], rel=1e-9)
    proc = run_rbi_inprocess("audit", str(path), "--format", "csv")
    assert proc.returncode == 0, proc.stderr
    row = next(csv.DictReader(io.StringIO(proc.stdout)))
    assert row["ratio_1"] == "" and float(row["ratio_2"]) == pytest.approx(1.2, rel=1e-9)


def test_a_moment_ratio_beyond_any_double_is_a_mismatch_in_every_form(tmp_path):
    """Declared moments of 2-4e306 kg·m² on a 1 kg link whose collision is a 1 cm cube (moments
    m a²/6 = 1.67e-5 kg·m²): each ratio is above 1e311, past the largest double. The link is a
    mismatch at error level (exit 1) in all three forms, its ratios printed as '>1.8e+308' in
    the table, null in JSON and empty in CSV. The table once printed '-' and no flag with
    exit 0, while JSON and CSV refused the result naming no file (exit 2)."""
    path = tmp_path / "heavy.urdf"
    path.write_text(
        '<robot name="heavy"><link name="a"><inertial><mass value="1"/>'
        '<inertia ixx="2e306" iyy="3e306" izz="4e306" ixy="0" ixz="0" iyz="0"/></inertial>'
        '<collision><geometry><box size="0.01 0.01 0.01"/></geometry></collision></link></robot>'
    )
    table = run_rbi_inprocess("audit", str(path))
    assert table.returncode == 1, table.stderr
    assert "mismatch" in table.stdout and ">1.8e+308" in table.stdout
    proc = run_rbi_inprocess("audit", str(path), "--format", "json")
    assert proc.returncode == 1, proc.stderr
    link = json.loads(proc.stdout)["links"][0]
    assert link["moment_ratios"] == [None, None, None]
    assert [(f["code"], f["level"]) for f in link["flags"] if f["code"] == "mismatch"] == [
        ("mismatch", "error")
    ]
    proc = run_rbi_inprocess("audit", str(path), "--format", "csv")
    assert proc.returncode == 1, proc.stderr
    row = next(csv.DictReader(io.StringIO(proc.stdout)))
    assert row["ratio_1"] == row["ratio_2"] == row["ratio_3"] == ""
