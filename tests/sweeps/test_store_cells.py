"""The sweep's CSV rows file: every cell the store writes reads back (for --resume) to the value
written, typed as the sweep holds it, through the one CSV cell rule (rbi.text.csv_cell)."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rbi.sweeps import store


def _read_back(columns, row):
    line = store.csv_bytes([row])
    cells = store._csv_line(line, "rows", 2)
    return [store._cell(name, cell, text=True) for name, cell in zip(columns, cells)]


@given(
    run=st.integers(0, 10**9),
    value=st.floats(allow_nan=False, allow_infinity=False),
    steps=st.integers(0, 10**6),
)
def test_numbers_read_back_exactly(run, value, steps):
    columns = ["run", "spin", "steps", "status"]
    assert _read_back(columns, [run, value, steps, "ok"]) == [run, value, steps, "ok"]


@pytest.mark.parametrize(
    "status",
    ["ok", "failed: step budget of 1,000 steps reached", '=HYPERLINK("x")', "-not a number", "-0.5"],
)
def test_a_status_reads_back_as_written(status):
    assert _read_back(["run", "status"], [0, status]) == [0, status]


def test_an_undefined_value_is_an_empty_cell_and_reads_back_as_none():
    assert store.csv_bytes([[0, None, float("nan"), "ok"]]) == b"0,,,ok\n"
    assert _read_back(["run", "spin", "precession_rate_deg_s", "status"], [0, None, None, "ok"]) == [
        0,
        None,
        None,
        "ok",
    ]
