"""`rbi simulate --draws` / `rbi.simulate(draws=...)`: the motion's spread from the inputs
written with ±, against the same draws run one by one through the single-run path."""

from __future__ import annotations

import json
import tracemalloc

import numpy as np
import pytest

import rbi
from rbi.api import input_uncertainty
from rbi.sim import compiled
from tests.conftest import BODIES, one_line_exit_2, run_rbi_inprocess

TOLERANCED = BODIES / "top_bolted_toleranced.yaml"
RUN = dict(spin=200.0, tilt_deg=10.0, duration=0.5, samples=101)


def test_spread_equals_the_draws_run_one_by_one():
    n, seed = 6, 11
    batch = input_uncertainty(rbi.load(TOLERANCED), draws=n, seed=seed, **RUN)
    rng = np.random.default_rng(seed)  # the inputs in file order, each drawn n times
    radius, mass, x, z = (
        rng.normal(v, u, n).tolist() for v, u in [(0.04, 5e-4), (0.02, 1e-3), (0.04, 5e-4), (0.06, 5e-4)]
    )
    figures = []
    for k in range(n):
        text = (BODIES / "top_bolted.yaml").read_text()
        text = text.replace("radius: 0.04", f"radius: {radius[k]!r}").replace(
            "mass: 0.02", f"mass: {mass[k]!r}"
        )
        text = text.replace("position: [0.04, 0, 0.06]", f"position: [{x[k]!r}, 0, {z[k]!r}]")
        s = rbi.simulate(rbi.loads(text), error_estimate=False, **RUN).summary
        figures.append([s.tilt_max_deg, s.final["tilt_deg"], s.mean_precession_rate_deg_s, *s.final["omega"]])
    sd = np.std(np.array(figures), axis=0, ddof=1)
    got = [
        batch["tilt_max_deg"],
        batch["final_tilt_deg"],
        batch["mean_precession_rate_deg_s"],
        *batch["final_omega"],
    ]
    assert got == pytest.approx(sd, rel=1e-6, abs=1e-9)
    assert batch["draws"] == n and batch["failed"] == 0


def test_zero_uncertainty_gives_zero_spread(write_spec):
    text = (BODIES / "top_bolted.yaml").read_text().replace("mass: 0.02", "mass: 0.02 ± 0")
    spread = input_uncertainty(rbi.load(write_spec(text)), draws=4, seed=1, **RUN)
    assert spread["tilt_max_deg"] == 0.0 and spread["final_omega"] == [0.0, 0.0, 0.0]


def test_cli_json_beside_the_error_estimate():
    args = ("simulate", TOLERANCED, "--spin", "200", "--tilt", "10", "--duration", "0.5", "-f", "json")
    out = json.loads(run_rbi_inprocess(*args, "--draws", "20", "--seed", "3").stdout)
    keys = list(out)
    assert keys.index("input_uncertainty") == keys.index("error_estimate") + 1
    assert set(out["input_uncertainty"]) >= {
        "tilt_min_deg",
        "tilt_max_deg",
        "final_tilt_deg",
        "mean_precession_rate_deg_s",
        "final_omega",
    }
    assert (
        out["input_uncertainty"]["mean_precession_rate_deg_s"]
        > 1e3 * out["error_estimate"]["orientation_deg"]
    )
    assert "input_uncertainty" not in json.loads(run_rbi_inprocess(*args).stdout)
    one_line_exit_2(run_rbi_inprocess(*args, "--draws", "0"), "--draws")


def test_a_figure_the_run_does_not_define_has_no_spread(tmp_path):
    # an untilted free sphere spins steadily: no precession (null in the summary), so no spread
    # of it either; ω stays (0, 0, 50) whatever the drawn radius and mass
    spec = tmp_path / "ball.yaml"
    spec.write_text(
        'parts: [{name: ball, shape: sphere, radius: "0.1 ± 0.001", mass: "2 ± 1%", center: [0, 0, 0]}]\n'
    )
    proc = run_rbi_inprocess(
        "simulate",
        str(spec),
        "--spin",
        "50",
        "--duration",
        "0.5",
        "--draws",
        "8",
        "--seed",
        "1",
        "-f",
        "json",
    )
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["mean_precession_rate_deg_s"] is None
    spread = out["input_uncertainty"]
    assert spread["mean_precession_rate_deg_s"] is None
    assert spread["draws"] == 8 and spread["failed"] == 0
    assert spread["final_omega"] == pytest.approx([0.0, 0.0, 0.0], abs=1e-9)
    assert "error_estimate" in out
    table = run_rbi_inprocess("simulate", str(spec), "--spin", "50", "--duration", "0.5", "--draws", "8")
    assert table.returncode == 0, table.stderr


def test_draws_of_a_spec_without_plus_minus_are_refused():
    """Without ± every spread would be 0, which would read as certainty: --draws is refused in
    one line naming the file (the contract defines --draws on a spec with ±)."""
    proc = run_rbi_inprocess("simulate", str(BODIES / "top.yaml"), "--spin", "200", "--draws", "20")
    one_line_exit_2(proc, "--draws")
    assert "top.yaml has none" in proc.stderr
    with pytest.raises(rbi.ArgumentError, match="draws: needs a spec that writes numbers with ±"):
        input_uncertainty(rbi.load(BODIES / "top.yaml"), draws=4, seed=1, **RUN)


def test_drawn_runs_past_the_batch_budget_are_refused_before_they_start(monkeypatch):
    """Each run is within its own step budget (3 steps per radian × 2 headroom × 200 rad/s ×
    1000 s = 1.2e6 < 1e7), but 100,000 of them, 1.2e11 steps (days of CPU), are refused in one
    line, as a sweep past the same budget is; check_budget=False (--yes) lets them run."""
    args = ("simulate", str(TOLERANCED), "--spin", "200", "--duration", "1000", "--draws", "100000")
    proc = run_rbi_inprocess(*args)
    one_line_exit_2(proc, "100,000 drawn runs", "1.2e+11 integration steps", "--draws", "--yes")
    # 4 runs of 50 rad/s for 0.5 s: 4 × 150 steps, past a budget of 100
    monkeypatch.setattr("rbi.sim.budget.BATCH_STEP_BUDGET", 100.0)
    small = dict(RUN, spin=50.0, duration=0.5)
    with pytest.raises(rbi.ArgumentError, match="4 drawn runs are estimated to need about 6e\\+02"):
        input_uncertainty(rbi.load(TOLERANCED), draws=4, seed=1, **small)
    spread = input_uncertainty(rbi.load(TOLERANCED), draws=4, seed=1, check_budget=False, **small)
    assert spread["draws"] == 4 and spread["failed"] == 0


def test_runs_in_chunks_of_bounded_memory_give_the_numbers_of_one_call(monkeypatch):
    """The drawn runs are integrated and summarised in chunks of at most OUT_BYTES_PER_CHUNK of
    sampled states: 100 draws of 5,000 samples (28 MB of states in one call) in chunks of 7 runs
    take a few MB at their peak and give the one call's spread bit for bit."""
    run = dict(spin=100.0, tilt_deg=10.0, duration=0.1, samples=5000)
    body = rbi.load(TOLERANCED)
    whole = input_uncertainty(body, draws=100, seed=2, **run)
    monkeypatch.setattr(compiled, "OUT_BYTES_PER_CHUNK", 7 * 5000 * 7 * 8)
    tracemalloc.start()
    try:
        chunked = input_uncertainty(body, draws=100, seed=2, **run)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert chunked == whole and whole["failed"] == 0
    assert peak < 12e6, peak


def test_a_drawn_body_no_run_starts_from_is_a_failed_run_not_a_crash():
    """A mass drawn at or below 0 (0.4 ± 0.3: 9% of its normal distribution) gives a body whose
    inertia about the pivot is not positive: that run fails, the others are summarised."""
    spec = {"pivot": [0, 0, 0], "parts": [{"shape": "cone", "mass": "0.4 ± 0.3", "radius": 0.04}]}
    spec["parts"][0] |= {"apex": [0, 0, 0], "base": [0, 0, 0.06]}
    n, seed = 200, 5
    spread = input_uncertainty(rbi.load(spec), draws=n, seed=seed, spin=100.0, duration=0.05, samples=11)
    drawn_mass = np.random.default_rng(seed).normal(0.4, 0.3, n)
    assert spread["failed"] == np.sum(drawn_mass <= 0) > 0
    assert spread["final_omega"][2] is not None and spread["warnings"] == []
