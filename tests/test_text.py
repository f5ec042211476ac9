"""rbi.text: the one escaper, the one number formatter and the one CSV cell rule, checked against
what a spreadsheet and Python's own csv module read back (never against rbi's own output)."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rbi.text import FORMULA_STARTS, csv_cell, csv_lines, csv_text_read


@pytest.mark.parametrize(
    "value,cell",
    [
        (None, ""),
        (float("nan"), ""),
        (0.1, "0.1"),
        (-1.5, "-1.5"),
        (1e-300, "1e-300"),
        (np.float64(0.1), "0.1"),  # numpy's repr would be "np.float64(0.1)"
        (-0.0, "0.0"),  # zero as the CLI's tables and JSON write it
        (np.float64(-0.0), "0.0"),
        (7, 7),
        ("wheel", "wheel"),
        ("-0.5", "-0.5"),  # text that reads as a number is left alone
        ("a-b", "a-b"),
        ('=HYPERLINK("x")', '\'=HYPERLINK("x")'),
        ("+cmd", "'+cmd"),
        ("-2+3", "'-2+3"),
        ("@SUM(A1)", "'@SUM(A1)"),
        ("\tx", "'\\tx"),
        ("a\nb", "a\\nb"),  # one line: the rows file is read a line at a time
    ],
)
def test_csv_cell(value, cell):
    assert csv_cell(value) == cell


@given(st.floats(allow_nan=False))
def test_a_float_cell_reads_back_to_the_same_float(value):
    assert float(csv_cell(value)) == value


@given(
    st.text(st.characters(codec="utf-8", exclude_categories=("Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp", "Zs")))
)
def test_a_text_cell_reads_back_to_the_same_text(text):
    assert csv_text_read(csv_cell(text)) == text


@pytest.mark.parametrize("cell", ["=1+1", "+x", "@A1", "-x", "a\x1bb", "o\u202ek"])
def test_a_cell_csv_cell_never_writes_is_not_read_as_text(cell):
    assert csv_text_read(cell) is None


def test_no_written_text_cell_starts_a_formula_for_a_spreadsheet():
    for text in ["=A1", "+A1", "-A1", "@A1", "\t=A1", "\r=A1"]:
        assert not str(csv_cell(text)).startswith(FORMULA_STARTS)


def test_csv_lines_is_what_the_csv_module_reads_back():
    text = csv_lines([[0, 0.25, "ok"], [1, None, 'failed: "quoted", with a comma']], header=["run", "x", "s"])
    assert text.endswith("\n") and "\r" not in text
    rows = list(csv.reader(io.StringIO(text)))
    assert rows == [["run", "x", "s"], ["0", "0.25", "ok"], ["1", "", 'failed: "quoted", with a comma']]
    assert math.isclose(float(rows[1][1]), 0.25)


def test_the_cli_and_the_sweep_store_write_the_same_cells():
    """One rule for both: `rbi ... --format csv` (rbi.reprs.csv_text) and the sweep's rows file."""
    from rbi.reprs import csv_text as to_csv
    from rbi.sweeps.store import csv_bytes

    cells = {"run": 3, "spin": 1 / 3, "tilt": None, "status": "=bad"}
    cli = to_csv([cells]).splitlines()
    store = csv_bytes([list(cells)] + [list(cells.values())]).decode().splitlines()
    assert cli == store == ["run,spin,tilt,status", "3,0.3333333333333333,,'=bad"]


@pytest.mark.parametrize(
    "value, u, shown",
    [(1.0, 1e-320, "1 ± 1e-320"), (1e-300, 1e100, "1e-300 ± 1e+100"), (1e300, 1e-300, "1e+300 ± 1e-300")],
)
def test_plus_minus_where_value_over_u_leaves_a_double(value, u, shown):
    from rbi.text import plus_minus

    assert plus_minus(value, u) == shown


@given(st.floats(allow_nan=False, allow_infinity=False), st.floats(min_value=0, allow_infinity=False))
def test_plus_minus_never_fails(value, u):
    from rbi.text import plus_minus

    assert " ± " in plus_minus(value, u)
