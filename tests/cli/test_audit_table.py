"""`rbi audit`'s table output on an 80-column terminal: the robot's totals are short lines that
a terminal does not break inside a number."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import BODIES, run_rbi_inprocess


def test_the_totals_fit_an_80_column_terminal(monkeypatch):
    # `rbi audit pybullet_data/r2d2.urdf` printed 'total (root link base_link): mass 65.25 kg, centre
    # of mass [2.83996e-08, 0.00320153, -0.0960705] m' on one line of 98 characters, which an
    # 80-column terminal broke inside -0.0960705
    data = pytest.importorskip("pybullet_data")
    monkeypatch.setenv("COLUMNS", "80")
    proc = run_rbi_inprocess("audit", Path(data.getDataPath()) / "r2d2.urdf")
    lines = proc.stdout.splitlines()
    at = lines.index("total (root link base_link): mass 65.25 kg")  # 5 links of 10 kg, ... (the URDF's sum)
    block = lines[at : at + 3]
    assert block[1].startswith("  centre of mass [m]: [") and "0.00320153" in block[1], block
    assert block[2].startswith("  principal moments about it [kg·m²]: "), block
    assert all(len(line) <= 80 for line in block), block


def test_the_tables_principal_moments_of_the_robot_are_in_json():
    # the table printed the whole robot's principal moments, and --format json had no such key
    # (only the matrix). bodies/two_link_arm.urdf: a 1.2 kg cylinder (ixx 0.00054, iyy = izz
    # 0.00927 in link axes) with its centre at x = 0.15 and a 0.8 kg box (0.00021333,
    # 0.0042733) at x = 0.425, so the centre of mass is at x = 0.26 and, by the parallel axis
    # theorem, I_xx = 0.00054 + 0.00021333, I_yy = I_zz = 0.00927 + 1.2·0.11² + 0.0042733 + 0.8·0.165²
    proc = run_rbi_inprocess("audit", BODIES / "two_link_arm.urdf", "--format", "json")
    total = json.loads(proc.stdout)["total"]
    small = 0.00054 + 0.8 * (0.04**2 + 0.04**2) / 12
    large = 0.00927 + 1.2 * 0.11**2 + 0.8 * (0.25**2 + 0.04**2) / 12 + 0.8 * 0.165**2
    assert total["moments"] == pytest.approx([small, large, large], rel=1e-12)
    table = run_rbi_inprocess("audit", BODIES / "two_link_arm.urdf").stdout
    assert "  principal moments about it [kg·m²]: 0.000753333, 0.0498433, 0.0498433" in table.splitlines()


def test_a_link_name_is_shown_as_it_is_not_read_as_markup(tmp_path):
    # a link named '[bold]arm[/bold]x' was shown as 'armx' in the table: rich read the name as
    # markup (the joints table and the flag lines showed it as it is)
    robot = tmp_path / "r.urdf"
    robot.write_text(
        '<robot name="r"><link name="base"><inertial><mass value="2"/><inertia ixx="1" iyy="2" izz="3" '
        'ixy="0" ixz="0" iyz="0"/></inertial></link><link name="[bold]arm[/bold]x"/>'
        '<joint name="j" type="fixed"><parent link="base"/><child link="[bold]arm[/bold]x"/></joint></robot>'
    )
    proc = run_rbi_inprocess("audit", robot)
    rows = [line.split() for line in proc.stdout.splitlines()]
    assert ["[bold]arm[/bold]x", "-", "-", "-", "-", "ok"] in rows, proc.stdout
