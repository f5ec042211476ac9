"""`--omega` without `--spin-axis` spins about ω's own direction, and a free body's summary gives
the angle between that axis and the conserved angular momentum h (contract, fifth round,
"Seams"). Issue 38: `rbi simulate bodies/tbar.yaml --omega 0.01,8,0.01`, a stable spin about
the largest axis, reported "spin axis [0, 0, 1]" and a tilt of 0 … 179.6°, which reads as a
flip. Reference values: the T-handle's moments worked out by hand (tests/sim/test_hard_cases),
a cylinder's closed-form moments and its torque-free precession, and the Euler–Poinsot closed
form (rbi.sim.exact)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rbi
from rbi.sim import exact
from rbi.sim.diagnostics import angular_momentum_body
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.spec.load import load_body
from tests.conftest import BODIES, run_rbi, run_rbi_inprocess
from tests.sim.test_hard_cases import t_handle_moments

OMEGA = np.array([0.01, 8.0, 0.01])


def _angle_deg(a: np.ndarray, b: np.ndarray) -> float:
    return math.degrees(math.atan2(np.linalg.norm(np.cross(a, b)), a @ b))


def test_the_t_handle_spun_about_its_largest_axis_reads_as_a_steady_spin():
    proc = run_rbi("simulate", BODIES / "tbar.yaml", "--omega", "0.01,8,0.01", "--format", "json", check=True)
    out = json.loads(proc.stdout)
    unit = OMEGA / np.linalg.norm(OMEGA)
    np.testing.assert_allclose(out["spin_axis"], unit, rtol=0, atol=1e-15)
    # the axis lies level (identity start): it wobbles by a tenth of a degree, no flip
    assert 89.7 < out["tilt_min_deg"] <= out["tilt_max_deg"] < 90.3
    # at t = 0 the axis is ω: its angle to h = I ω, with the moments worked out by hand
    inertia = np.diag(t_handle_moments())
    start = _angle_deg(unit, inertia @ OMEGA)
    cone = out["angle_to_h_deg"]
    assert set(cone) == {"min", "max", "final"}
    assert cone["min"] <= start + 1e-9 and cone["max"] >= start - 1e-9
    assert 0.0 < cone["min"] <= cone["final"] <= cone["max"] < 0.2  # stable: it stays close to h
    assert out["conserved"]["h_world"]["drift"] < 1e-10


def test_the_angle_to_h_follows_the_euler_poinsot_solution():
    body = rbi.load(BODIES / "tbar.yaml")
    run = rbi.simulate(body, omega=OMEGA, duration=3.0, samples=601, error_estimate=False)
    loaded = load_body(BODIES / "tbar.yaml")
    scene = scene_from_properties(loaded.props, None, 0.0, OMEGA)
    q0, w0 = initial_state(0.0, OMEGA)
    _, omega = exact.solve(scene, q0, w0).state_at(run.t)
    h = angular_momentum_body(scene, omega)
    axis = OMEGA / np.linalg.norm(OMEGA)
    angles = np.array([_angle_deg(axis, row) for row in h])
    cone = run.summary.angle_to_h_deg
    assert cone["min"] == pytest.approx(angles.min(), abs=1e-8)
    assert cone["max"] == pytest.approx(angles.max(), abs=1e-8)
    assert cone["final"] == pytest.approx(angles[-1], abs=1e-8)


def test_a_symmetric_free_body_keeps_its_axis_in_a_cone_about_h(write_spec):
    # A cylinder (I1 = m(3r² + L²)/12 across, I3 = m r²/2 along z) started with ω = (w1, 0, w3):
    # ω, h = I ω and z are coplanar at t = 0, so the body-fixed axis along ω0 starts at the
    # angle θa − θh from h; h turns about z in the body at (I3 − I1) w3 / I1, and half a turn
    # later it is θa + θh away (θa, θh: the angles of ω0 and h from z).
    m, r, length = 2.0, 0.05, 0.4
    spec = write_spec(
        f"parts:\n  - {{shape: cylinder, mass: {m}, radius: {r}, start: [0, 0, 0], end: [0, 0, {length}]}}\n"
    )
    i1, i3 = m * (3 * r**2 + length**2) / 12, m * r**2 / 2
    w1, w3 = 0.3, 5.0
    theta_a, theta_h = math.atan2(w1, w3), math.atan2(i1 * w1, i3 * w3)
    rate = abs((i3 - i1) * w3 / i1)
    duration = 1.5 * math.pi / rate  # past the half turn
    run = rbi.simulate(rbi.load(spec), omega=[w1, 0.0, w3], duration=duration, samples=30001)
    cone = run.summary.angle_to_h_deg
    np.testing.assert_allclose(run.summary.spin_axis, np.array([w1, 0.0, w3]) / math.hypot(w1, w3))
    assert cone["min"] == pytest.approx(math.degrees(theta_h - theta_a), rel=1e-9)
    assert cone["max"] == pytest.approx(math.degrees(theta_h + theta_a), rel=1e-6)
    assert run.summary.conserved["h_world"]["drift"] < 1e-10


def test_spin_axis_given_wins_over_omega():
    run = rbi.simulate(rbi.load(BODIES / "tbar.yaml"), omega=OMEGA, spin_axis="z", duration=4.0)
    assert run.summary.spin_axis.tolist() == [0.0, 0.0, 1.0]
    assert run.summary.tilt_max_deg > 170.0  # body z turns over as the handle spins about y
    out = json.loads(
        run_rbi_inprocess(
            "simulate", BODIES / "tbar.yaml", "--omega", "0.01,8,0.01", "--spin-axis", "z", "--format", "json"
        ).stdout
    )
    assert out["spin_axis"] == [0.0, 0.0, 1.0] and out["angle_to_h_deg"]["max"] > 89.0


def test_a_top_given_omega_spins_about_it_and_has_no_angle_to_h():
    w = [0.0, 0.5, 150.0]
    run = rbi.simulate(rbi.load(BODIES / "top.yaml"), omega=w, duration=0.2)
    np.testing.assert_allclose(run.summary.spin_axis, np.array(w) / np.linalg.norm(w), atol=1e-16)
    assert (
        run.summary.angle_to_h_deg is None and "angle_to_h_deg" not in run.to_dict()
    )  # a top's h is not conserved
    assert run.summary.initial["tilt_deg"] == pytest.approx(math.degrees(math.atan2(0.5, 150.0)))


def test_a_free_body_at_rest_has_no_angle_to_h():
    run = rbi.simulate(rbi.load(BODIES / "tbar.yaml"), omega=[0, 0, 0], duration=1.0)
    assert run.summary.angle_to_h_deg == {"min": None, "max": None, "final": None}
    assert run.summary.spin_axis.tolist() == [0.0, 0.0, 1.0]  # no direction: the default axis


def test_the_table_and_animate_speak_of_the_axis_of_omega(tmp_path):
    table = run_rbi_inprocess("simulate", BODIES / "tbar.yaml", "--omega", "0.01,8,0.01").stdout
    assert "spin axis to h: min … max" in table and "[0.00125, 0.999998, 0.00125]" in table
    out = tmp_path / "t.html"
    proc = run_rbi_inprocess(
        "animate", BODIES / "tbar.yaml", "--omega", "0.01,8,0.01", "--duration", "2", "--out", out
    )
    assert proc.returncode == 0, proc.stderr
    largest = float(proc.stdout.split("largest tilt of the spin axis ")[1].split("°")[0])
    assert 90.0 < largest < 90.3  # was 180: body z turning over
