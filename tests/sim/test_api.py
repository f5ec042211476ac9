"""The integrators against the reference final state, the conservation laws, the closed forms
and the hard cases of issue 3."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.sim import exact
from rbi.sim.api import METHODS, SimulationError, sample_times, simulate
from rbi.sim.diagnostics import (
    conserved_quantities,
    orientation_error_deg,
    sleeping_threshold,
    stability,
    tilt_deg,
)
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.spec.load import load_body
from rbi.spec.units import gravity_in

EXPECTED = (
    json.loads(Path("/work/shared/cases/expected.json").read_text())
    if Path("/work/shared/cases/expected.json").exists()
    else None
)
# The same reference (DOP853 at rtol 1e-13, from shared/cases/expected.json), kept here so the
# test also runs where the shared folder is absent.
BOLTED_FINAL_Q = [-0.8115423374746441, -0.0004863881802677963, 0.4154746034509781, 0.4108280075651523]
BOLTED_FINAL_OMEGA = [17.837792494482816, 4.26069065811585, 199.41803075686732]


def test_reference_constants_are_those_of_the_shared_cases():
    if EXPECTED is None:
        pytest.skip("shared/cases not present")
    final = EXPECTED["top_bolted"]["simulate --spin 200 --format json"]["final"]
    assert final["q"] == BOLTED_FINAL_Q and final["omega"] == BOLTED_FINAL_OMEGA


def test_bolted_top_default_run_meets_the_accuracy_targets(bolted_scene):
    """Issue 3: final orientation within 1e-5 deg, ω within 1e-5 rad/s of the converged
    reference; energy and vertical angular momentum drift below 1e-9; |q| = 1."""
    run = simulate(bolted_scene, *initial_state(0.0, [0, 0, 200.0]), 4.0, 481)
    assert run.t[0] == 0.0 and run.t[-1] == 4.0 and run.t.size == 481
    assert orientation_error_deg(run.q[-1], BOLTED_FINAL_Q) < 1e-5
    assert np.max(np.abs(run.omega[-1] - BOLTED_FINAL_OMEGA)) < 1e-5
    drifts = conserved_quantities(bolted_scene, run.q, run.omega)
    assert set(drifts) == {"energy", "h_vertical"}
    assert max(d["drift"] for d in drifts.values()) < 1e-9
    assert np.max(np.abs(np.linalg.norm(run.q, axis=1) - 1.0)) <= 4e-16


def test_the_chapter_set_up_is_what_the_issue_says(bolted_scene):
    """rk45 reproduces the chapter: about 1e-3 degrees off after 4 s (checked on 0.5 s here to
    keep the test fast: the error there is already far above the default's)."""
    q0, w0 = initial_state(0.0, [0, 0, 200.0])
    chapter = simulate(bolted_scene, q0, w0, 0.5, 11, method="rk45")
    reference = simulate(bolted_scene, q0, w0, 0.5, 11, rtol=1e-14)
    fast = simulate(bolted_scene, q0, w0, 0.5, 11)
    chapter_error = np.max(orientation_error_deg(chapter.q, reference.q))
    assert 1e-6 < chapter_error < 1e-2
    assert np.max(orientation_error_deg(fast.q, reference.q)) < chapter_error / 100
    assert chapter.rtol == 1e-8 and chapter.quaternion_norm_error > 0.0
    dop = simulate(bolted_scene, q0, w0, 0.5, 11, method="dop853", rtol=1e-11)
    assert np.max(orientation_error_deg(dop.q, reference.q)) < 1e-6


def test_progress_chunks_do_not_change_the_result(bolted_scene, monkeypatch):
    from rbi.sim import api

    q0, w0 = initial_state(5.0, [0, 0, 200.0])
    whole = simulate(bolted_scene, q0, w0, 2.0, 21)
    seen = []
    monkeypatch.setattr(api, "CHUNK_STEPS", 50)
    chunked = simulate(bolted_scene, q0, w0, 2.0, 21, progress=seen.append)
    np.testing.assert_array_equal(whole.q, chunked.q)
    assert len(seen) > 5 and seen[-1] == 1.0 and all(a <= b for a, b in zip(seen, seen[1:]))


def test_quaternion_stays_unit_over_1000_seconds(bolted_scene):
    run = simulate(bolted_scene, *initial_state(0.0, [0, 0, 200.0]), 1000.0, 1001)
    assert np.max(np.abs(np.linalg.norm(run.q, axis=1) - 1.0)) <= 4e-16
    drifts = conserved_quantities(bolted_scene, run.q, run.omega)
    assert max(d["drift"] for d in drifts.values()) < 1e-7


@pytest.mark.parametrize("spin", [2000.0, 1e4])
def test_very_fast_spin_against_the_lagrange_top(top_scene, spin):
    q0, w0 = initial_state(10.0, [0, 0, spin])
    run = simulate(top_scene, q0, w0, 1.0, 101)
    closed = exact.solve(top_scene, q0, w0).state_at(run.t)
    assert np.max(orientation_error_deg(run.q, closed[0])) < 1e-6
    assert np.max(np.abs(run.omega - closed[1])) < 1e-11 * spin


def test_sleeping_top_stays_exactly_upright(top_scene):
    threshold = sleeping_threshold(top_scene)["omega3"]
    for spin in (0.5 * threshold, 2.0 * threshold):
        run = simulate(top_scene, *initial_state(0.0, [0, 0, spin]), 4.0, 41)
        assert np.max(tilt_deg(run.q)) == 0.0


def test_sleeping_threshold_matches_the_issue_and_decides_the_fate(top_scene):
    threshold = sleeping_threshold(top_scene)
    m, g, l = top_scene.mass, top_scene.gravity, top_scene.com_from_pivot[2]
    I1, I3 = top_scene.inertia[0, 0], top_scene.inertia[2, 2]
    assert threshold["omega3"] == pytest.approx(np.sqrt(4 * m * g * l * I1) / I3, rel=1e-14)
    assert threshold["omega3"] == pytest.approx(208.0, abs=0.1)  # the issue's "about 208 rad/s"
    verdict = stability(top_scene, *initial_state(0.01, [0, 0, 200.0]))
    assert verdict["above_threshold"] is False and "unstable" in verdict["verdict"]
    # a 0.01 degree tilt: just below the threshold the top falls, just above it stays up
    below = simulate(top_scene, *initial_state(0.01, [0, 0, 0.98 * threshold["omega3"]]), 4.0, 2001)
    above = simulate(top_scene, *initial_state(0.01, [0, 0, 1.02 * threshold["omega3"]]), 4.0, 2001)
    assert np.max(tilt_deg(below.q)) > 10.0
    assert np.max(tilt_deg(above.q)) < 0.1
    assert (
        "stable" in stability(top_scene, *initial_state(0.01, [0, 0, 1.02 * threshold["omega3"]]))["verdict"]
    )


def test_dzhanibekov_verdict(free_scene):
    near_middle = free_scene.principal_axes[1] * 3.0 + free_scene.principal_axes[0] * 0.01
    assert "Dzhanibekov" in stability(free_scene, *initial_state(0, near_middle))["verdict"]
    near_major = free_scene.principal_axes[2] * 3.0 + free_scene.principal_axes[1] * 0.3
    assert stability(free_scene, *initial_state(0, near_major))["intermediate_axis"] is False


def test_duration_zero_and_single_sample(bolted_scene):
    q0, w0 = initial_state(5.0, [0, 0, 200.0])
    still = simulate(bolted_scene, q0, w0, 0.0, 481)
    assert still.t.tolist() == [0.0] and still.steps == 0
    np.testing.assert_array_equal(still.q[0], q0)
    np.testing.assert_array_equal(still.omega[0], w0)
    one = simulate(bolted_scene, q0, w0, 2.0, 1)
    full = simulate(bolted_scene, q0, w0, 2.0, 481)
    assert one.t.tolist() == [2.0]
    assert orientation_error_deg(one.q[0], full.q[-1]) < 1e-7
    for method in ("rk45", "dop853", "exact"):
        if method == "exact":
            continue  # the bolted top has no closed form
        assert simulate(bolted_scene, q0, w0, 0.0, 5, method=method).t.tolist() == [0.0]
    assert sample_times(1.0, 3).tolist() == [0.0, 0.5, 1.0]


def test_bad_runs_are_refused(bolted_scene):
    q0, w0 = initial_state(0.0, [0, 0, 200.0])
    for duration, samples, rtol, method, words in (
        (-1.0, 10, None, "default", "duration: must be a finite number of seconds >= 0 (got -1.0)"),
        (float("nan"), 10, None, "default", "duration: must be a finite number of seconds >= 0"),
        (1.0, 0, None, "default", "samples: must be a whole number between 1 and 1,000,000 (got 0)"),
        (1.0, 2.5, None, "default", "samples: must be a whole number between 1 and 1,000,000 (got 2.5)"),
        (
            1.0,
            10**6 + 1,
            None,
            "default",
            "samples: must be a whole number between 1 and 1,000,000 (got 1000001)",
        ),
        (1.0, 10, 0.5, "default", "rtol: must be between 1e-15 and 0.01 (got 0.5)"),
        (1.0, 10, None, "euler", "method: must be one of default, rk45, dop853, exact (got 'euler')"),
    ):
        with pytest.raises(ValueError) as refused:
            simulate(bolted_scene, q0, w0, duration, samples, rtol=rtol, method=method)
        assert str(refused.value).startswith(words)
    with pytest.raises(SimulationError, match="exact"):
        simulate(bolted_scene, q0, w0, 1.0, 10, method="exact")
    assert simulate(bolted_scene, q0, w0, 1.0, 3.0).t.tolist() == [0.0, 0.5, 1.0]  # 3.0 is 3
    assert set(METHODS) >= {"default", "rk45", "dop853", "exact"}


def test_singular_inertia_about_the_pivot_is_refused():
    # two point masses on the z axis, pivot on the axis: no inertia about z
    props = MassProperties(2.0, np.array([0.0, 0.0, 1.5]), np.diag([0.5, 0.5, 0.0]))
    with pytest.raises(ValueError, match="singular"):
        scene_from_properties(props, np.zeros(3), 9.81)


def _scaled_top(write_spec, factor: float, unit: str = "m"):
    text = f"""
units: {{length: {unit}, mass: kg}}
pivot: [0, 0, 0]
parts:
  - {{shape: cone, mass: 0.4, radius: {0.04 * factor}, apex: [0, 0, 0], base: [0, 0, {0.06 * factor}]}}
  - {{shape: cylinder, mass: 0.1, radius: {0.008 * factor}, start: [0, 0, {0.06 * factor}], end: [0, 0, {0.10 * factor}]}}
"""
    body = load_body(write_spec(text, f"top_{factor}_{unit}.yaml"))
    return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit))


@pytest.mark.parametrize("factor", [1e-3, 1e3])
def test_mm_and_km_scale_tops_against_the_closed_form(write_spec, factor):
    """A top 1000 times smaller or larger: gravity's time scale √(l/g) changes by √1000, so
    spin and duration scale with it; the integrator must stay as accurate as for the
    chapter's top (its error control does not depend on lengths)."""
    scene = _scaled_top(write_spec, factor)
    rate = 1.0 / np.sqrt(factor)
    q0, w0 = initial_state(10.0, [0, 0, 200.0 * rate])
    run = simulate(scene, q0, w0, 4.0 / rate, 101)
    closed = exact.solve(scene, q0, w0).state_at(run.t)
    assert np.max(orientation_error_deg(run.q, closed[0])) < 1e-5
    drifts = conserved_quantities(scene, run.q, run.omega)
    assert max(d["drift"] for d in drifts.values()) < 1e-9


def test_a_spec_in_millimetres_moves_like_the_one_in_metres(write_spec):
    metres = _scaled_top(write_spec, 1.0)
    millimetres = _scaled_top(write_spec, 1000.0, unit="mm")
    q0, w0 = initial_state(10.0, [0, 0, 200.0])
    a = simulate(metres, q0, w0, 2.0, 21)
    b = simulate(millimetres, q0, w0, 2.0, 21)
    assert np.max(orientation_error_deg(a.q, b.q)) < 1e-7


@pytest.mark.parametrize("degrees", [1e-7, 0.01, 30.0, 90.0, 179.0])
def test_orientation_error_is_the_angle_of_the_turn_between_by_cores_product(degrees, monkeypatch):
    """q and q ⊗ (a turn of θ about an axis): the error is θ, whichever sign either quaternion
    has, for a stack too; the product is rbi.core.rotation's (no second one in rbi.sim)."""
    from rbi.core import rotation
    from rbi.sim import diagnostics

    rng = np.random.default_rng(7)
    q = rng.normal(size=(4, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    axis = np.array([1.0, -2.0, 0.5]) / np.sqrt(5.25)
    half = np.radians(degrees) / 2
    turn = np.concatenate(([np.cos(half)], np.sin(half) * axis))
    r = np.array([rotation.quaternion_multiply(each, turn) for each in q])
    for sign in (1.0, -1.0):
        np.testing.assert_allclose(orientation_error_deg(sign * q, r), degrees, rtol=1e-9, atol=1e-13)
    calls = []

    def product(a, b):
        calls.append(1)
        return rotation.quaternion_multiply(a, b)

    monkeypatch.setattr(diagnostics, "quaternion_multiply", product)
    assert orientation_error_deg(q[0], r[0]) == pytest.approx(degrees, rel=1e-9, abs=1e-13) and calls
