"""The CSV of `rbi import ROBOT` and `rbi audit`: every text cell goes through the one CSV cell rule
(rbi.text.csv_cell) once, so a name that starts with a tab or a carriage return gets the leading
``'`` that keeps a spreadsheet from reading it as a formula, and shows the character escaped."""

from __future__ import annotations

import csv
import io

import pytest

from rbi.text import csv_cell
from tests.cli.test_import_output import urdf
from tests.conftest import run_rbi_inprocess

LEADING = ["\tlead", "\rlead"]
"""Names the cells got wrong: escaped first (``\\tlead``), the CSV rule no longer saw the tab,
and the cell had no ``'``."""


def _first_column(text: str) -> list[str]:
    return [row[0] for row in csv.reader(io.StringIO(text))][1:]


@pytest.mark.parametrize("command", ["import", "audit"])
def test_a_name_starting_with_a_tab_or_cr_is_escaped_once(tmp_path, command):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf([*LEADING, "plain", "=cmd", "a\tb"]))
    proc = run_rbi_inprocess(command, path, "--format", "csv")
    assert proc.returncode == 0, proc.stderr
    cells = ["'\\tlead", "'\\rlead", "plain", "'=cmd", "a\\tb"]
    assert [csv_cell(name) for name in [*LEADING, "plain", "=cmd", "a\tb"]] == cells
    assert _first_column(proc.stdout) == cells
