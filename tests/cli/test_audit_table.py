"""`rbi audit`'s table output on an 80-column terminal: the robot's totals are short lines that
a terminal does not break inside a number."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import run_rbi_inprocess


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
