"""rbi.sweep gives the rows `rbi sweep --format json` prints for the same sweep."""

from __future__ import annotations

import json

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as run_rbi


def cli_ok(*args):
    """`rbi ARGS` run in this process; its output when it succeeds."""
    proc = run_rbi(*args)
    assert proc.returncode == 0, proc.stderr
    return proc


@pytest.fixture(scope="module")
def bolted():
    return rbi.load(BODIES / "top_bolted.yaml")


def cli_runs(*args):
    proc = cli_ok("sweep", BODIES / "top_bolted.yaml", *args, "--format", "json", "--workers", "1")
    return json.loads(proc.stdout)["runs"]


def test_grid_rows_equal_the_cli(bolted):
    rows = rbi.sweep(bolted, spin=(150.0, 260.0, 3), tilt="0.01:1:2", duration=0.3, workers=1)
    assert rows == cli_runs("--spin", "150:260:3", "--tilt", "0.01:1:2", "--duration", "0.3")
    assert [r["spin"] for r in rows[::2]] == [150.0, 205.0, 260.0]
    assert all(r["status"] == "ok" for r in rows)


def test_a_sweep_row_is_the_single_run(bolted):
    # the same run through rbi.simulate: the largest and final tilt agree
    row = rbi.sweep(bolted, spin=200.0, tilt=0.5, duration=0.3, workers=1)[0]
    run = rbi.simulate(bolted, spin=200.0, tilt_deg=0.5, duration=0.3)
    assert row["max_tilt_deg"] == pytest.approx(float(np.max(run.tilt_deg)), rel=1e-9)
    assert row["final_tilt_deg"] == pytest.approx(float(run.tilt_deg[-1]), rel=1e-9)


def test_mass_property_draws_equal_the_cli(bolted):
    rows = rbi.sweep(
        bolted, mass_properties=True, vary={"parts.bolt.mass": "uniform(0.01,0.03)"}, runs=5, seed=3
    )
    assert rows == cli_runs(
        "--mass-properties", "--vary", "parts.bolt.mass=uniform(0.01,0.03)", "--runs", "5", "--seed", "3"
    )
    # mass = body without the bolt + the drawn bolt mass
    for r in rows:
        assert r["mass"] == pytest.approx(bolted.mass - 0.02 + r["parts.bolt.mass"], rel=1e-12)


def test_bad_variation_raises_the_cli_line(bolted):
    with pytest.raises(rbi.SpecError) as caught:
        rbi.sweep(bolted, vary=["parts.nope.mass=1:2:2"])
    proc = run_rbi("sweep", BODIES / "top_bolted.yaml", "--vary", "parts.nope.mass=1:2:2")
    assert proc.returncode == 2 and proc.stderr == f"rbi: {caught.value}\n"
