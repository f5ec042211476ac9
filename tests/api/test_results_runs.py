"""A Trajectory and a SweepTable present themselves as the commands do (issue 36, step 2): the
Trajectory's typed summary's ``to_dict()`` is ``rbi simulate --format json``'s object (timings
aside), ``to_pandas()`` the CSV's columns, ``print()`` the tables ``rbi simulate`` prints, from
one set of rows; and ``SweepTable.to_dict()`` is ``rbi sweep --format json``'s object."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES, run_rbi_inprocess

TIMINGS = ("wall_seconds", "load_seconds")


def _cli_json(*args):
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def _without(result: dict, keys=TIMINGS) -> dict:
    return {k: v for k, v in result.items() if k not in keys}


@pytest.mark.parametrize(
    ("spec", "settings", "args"),
    [
        (
            "top_bolted.yaml",
            {"spin": 200.0, "tilt_deg": 0.01, "duration": 0.3},
            ["--spin", "200", "--tilt", "0.01"],
        ),
        ("tbar.yaml", {"omega": [0.01, 8.0, 0.01], "duration": 0.3}, ["--omega", "0.01,8,0.01"]),
        (  # a file written: the JSON is the summary still (it said "out" too)
            "top_bolted_toleranced.yaml",
            {"spin": 200.0, "duration": 0.3, "draws": 4, "seed": 1, "out": "OUT"},
            ["--spin", "200", "--draws", "4", "--seed", "1", "--out", "OUT"],
        ),
    ],
)
def test_to_dict_is_what_simulate_prints_as_json(spec, settings, args, tmp_path):
    places = {"OUT": str(tmp_path / "run.csv")}
    settings = {k: places.get(v, v) if isinstance(v, str) else v for k, v in settings.items()}
    args = [places.get(a, a) for a in args]
    run = rbi.simulate(rbi.load(BODIES / spec), samples=31, **settings)
    printed = _cli_json("simulate", BODIES / spec, *args, "--duration", "0.3", "--samples", "31")
    mine = run.to_dict()
    assert json.loads(json.dumps(mine)) == mine  # JSON-ready as it is
    assert list(mine) == list(printed)
    assert _without(mine) == _without(printed)
    assert (
        run.summary.steps == printed["steps"]
        and run.summary.final["tilt_deg"] == printed["final"]["tilt_deg"]
    )


def test_to_pandas_is_the_trajectory_csv():
    pytest.importorskip("pandas")
    run = rbi.simulate(rbi.load(BODIES / "top.yaml"), spin=150.0, tilt_deg=5.0, duration=0.2, samples=11)
    frame = run.to_pandas()
    rows = list(csv.DictReader(io.StringIO(run.to_csv())))
    assert list(frame.columns) == list(rows[0])
    assert len(frame) == 11
    for name in frame.columns:
        np.testing.assert_array_equal(frame[name].to_numpy(), [float(r[name] or "nan") for r in rows])


def test_print_shows_the_tables_simulate_prints():
    run = rbi.simulate(rbi.load(BODIES / "top.yaml"), spin=150.0, tilt_deg=5.0, duration=0.2, samples=11)
    table = run_rbi_inprocess(
        "simulate",
        BODIES / "top.yaml",
        "--spin",
        "150",
        "--tilt",
        "5",
        "--duration",
        "0.2",
        "--samples",
        "11",
    ).stdout
    text, html = str(run), run._repr_html_()
    for rows in run.rows():
        assert rows.title in text and rows.title in table
        for quantity, _, value in rows.cells:
            if quantity not in ("integration wall time", "loading the compiled kernel"):
                assert value in table, quantity  # the CLI's rows are these rows
                assert quantity in html
    assert "Accuracy and cost" in text and "spin axis (body axes)" in text


def test_a_trajectory_made_by_hand_prints_its_samples():
    t = np.linspace(0.0, 1.0, 3)
    hand = rbi.Trajectory(t, np.tile([1.0, 0, 0, 0], (3, 1)), np.zeros((3, 3)), t, t, t)
    assert "samples" in str(hand) and "3" in str(hand)
    with pytest.raises(ValueError, match="summary"):
        hand.to_dict()


def test_sweep_table_to_dict_is_what_sweep_prints_as_json():
    args = ("--spin", "150:250:2", "--tilt", "0.5", "--duration", "0.1", "--samples", "11", "--workers", "1")
    printed = _cli_json("sweep", BODIES / "top.yaml", *args)
    table = rbi.sweep(
        BODIES / "top.yaml", spin=rbi.Grid(150, 250, 2), tilt_deg=0.5, duration=0.1, samples=11, workers=1
    )
    assert table.to_dict() == printed
    proc = run_rbi_inprocess("sweep", BODIES / "top.yaml", *args, "--format", "csv")
    assert table.to_csv() == proc.stdout
