"""Monte Carlo in bounded memory (rbi.spec.uncertain.monte_carlo): the draws' bodies are built
chunk by chunk, giving the numbers one stack of all draws gives bit for bit, so memory no longer
grows with draws × parts; what must be kept, the draws (n × k inputs) and their 16 quantities,
is bounded before any draw is made, in one line naming --samples (exit 2) and in the API."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

import rbi
from rbi.spec import uncertain
from rbi.spec.load import body_from_raw
from tests.conftest import one_line_exit_2, run_rbi_inprocess

POINTS = "".join(f'  - {{shape: point, mass: "1 ± 0.01", position: [{i}, 0, 0]}}\n' for i in range(20))


def test_more_draws_than_the_memory_bound_holds_are_refused_in_one_line(write_spec):
    # 20 inputs and 16 quantities: 36 numbers of 8 bytes a draw, and 2 GiB / 288 B = 7,456,540
    spec = write_spec("parts:\n" + POINTS)
    proc = run_rbi_inprocess("uncertainty", spec, "--method", "monte-carlo", "--samples", "10000000")
    one_line_exit_2(proc, "--samples", "at most 7,456,540", "20 inputs", "2 GiB")
    with pytest.raises(rbi.ArgumentError, match=r"^samples: must be at most 7,456,540 for this body"):
        rbi.load(spec).uncertainty(method="monte-carlo", samples=7_456_541)


def test_the_bound_is_exact_and_the_draws_within_it_run(write_spec, monkeypatch):
    spec = rbi.load(write_spec("parts:\n" + POINTS))
    monkeypatch.setattr(uncertain, "MONTE_CARLO_BYTES", 1000 * 36 * 8)  # room for 1,000 draws
    with pytest.raises(rbi.ArgumentError, match="at most 1,000 for this body"):
        spec.uncertainty(method="monte-carlo", samples=1001)
    mass = spec.uncertainty(of="mass", method="monte-carlo", samples=1000, seed=2).to_dict()["quantities"][0]
    # 20 independent masses 1 ± 0.01: 20 ± 0.01·√20 = 0.0447; 1,000 draws hit it within 10 %
    assert mass["value"] == pytest.approx(20.0, abs=0.005)
    assert mass["u"] == pytest.approx(0.01 * np.sqrt(20), rel=0.1)


MIX = {
    "parts": [
        {
            "shape": "box",
            "mass": "2 ± 0.02",
            "size": ["0.1 ± 0.001", 0.2, 0.3],
            "center": [0.1, "0 ± 0.01", 0.2],
        }
        | {"rotation": {"axis": [1, "2 ± 0.1", 3], "angle_deg": "30 ± 0.5"}},
        {"shape": "cylinder", "density": "1000 ± 5", "radius": "0.05 ± 0.001", "start": ["0.3 ± 0.01", 0, 0]}
        | {"end": [0.3, 0, 0.2], "pattern": {"count": 3, "axis": [0, 0, 1], "through": [0.1, 0, 0]}},
        {
            "shape": "point",
            "mass": "1 ± 0.1",
            "position": [0.1, 0, 0],
            "pattern": {"count": 4, "step": ["0.1 ± 0.01", 0, 0]},
        },
        {"shape": "sphere", "density": 1000, "radius": "0.01 ± 0.001", "center": [0, 0, 0], "subtract": True},
        {"shape": "prism", "density": "2700 ± 1%", "outline": [[0, 0], [0.1, 0], ["0 ± 0.001", 0.1]]}
        | {"start": [0, 0, 0], "end": [0, 0, 0.01]},
        {"shape": "cylinder", "mass": 0.5, "radius": 0.01, "start": [0, 0, 0], "end": [0, 0, 0.1]},
    ]
}


@pytest.mark.parametrize("rows", [1, 7, 250])
def test_chunks_give_one_stacks_numbers_bit_for_bit(monkeypatch, rows):
    """Turned, patterned (a pattern's copies are summed about the first draw's), holed, built
    part by part (a prism) and fixed parts: chunks of 1, 7 and 250 draws against main's one
    stack of all 1,000 draws, from the same draws of the same generator."""
    loaded = body_from_raw(MIX, "mix.yaml")
    n, parts = 1000, 10  # parts once the patterns are copied: 1 + 3 + 4 + 1 + 1 + 1
    rng = uncertain.generator(5)
    draws = np.stack([each.draws(rng, n) for each in loaded.spec._uncertain], axis=1)
    with np.errstate(all="ignore"):
        one = uncertain.MassProperties(
            *uncertain.body_stack(*uncertain.rows_at(loaded, draws), loaded.props.center_of_mass)
        )
    moments = np.linalg.eigvalsh(one.inertia_about_com)
    monkeypatch.setattr(uncertain, "CHUNK_PARTS", rows * parts)
    samples = uncertain.monte_carlo(loaded, n, 5)
    assert np.array_equal(samples[:, 0], one.mass) and np.array_equal(samples[:, 1:4], one.center_of_mass)
    assert np.array_equal(samples[:, 4:13], one.inertia_about_com.reshape(n, 9))
    assert np.array_equal(samples[:, 13:], moments)


def test_memory_does_not_grow_with_draws_times_parts(monkeypatch):
    """60 cylinders, each radius ± 1 %, 4,000 draws, chunks of 2**12 parts: the peak of numpy's
    allocations stays near what is kept (draws 4,000 × 60 and samples 4,000 × 16, 2.4 MB), where
    one stack of all draws' parts takes some 90 MB."""
    cylinders = [
        {"shape": "cylinder", "density": 1000, "radius": "0.01 ± 1%", "start": [i, 0, 0], "end": [i, 0, 0.1]}
        for i in range(60)
    ]
    loaded = body_from_raw({"parts": cylinders}, "many.yaml")
    monkeypatch.setattr(uncertain, "CHUNK_PARTS", 2**12, raising=False)
    tracemalloc.start()
    try:
        samples = uncertain.monte_carlo(loaded, 4000, 1)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 8e6, peak
    # mass of each: 1000 π r² 0.1 = 0.0314159 kg; its u: 2 % of it; 60 of them: √60 times that
    assert np.mean(samples[:, 0]) == pytest.approx(60 * 0.0314159, rel=1e-3)
    assert np.std(samples[:, 0], ddof=1) == pytest.approx(0.02 * 0.0314159 * np.sqrt(60), rel=0.1)
