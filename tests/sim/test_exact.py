"""Closed forms: checked against the laws they must obey, against textbook formulas computed
here, and against the integrators (which they in turn test)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import ellipk

from rbi.core.mass import MassProperties
from rbi.core.rotation import quaternion_multiply, quaternion_to_matrix
from rbi.sim import exact
from rbi.sim.api import simulate
from rbi.sim.diagnostics import conserved_quantities, orientation_error_deg, tilt_deg
from rbi.sim.scene import initial_state, scene_from_properties

FREE_SPINS = [
    [1.0, 0.5, 2.0],  # circulates about the largest axis
    [-1.0, 0.5, -2.0],  # same, other signs
    [3.0, 0.5, 0.2],  # circulates about the smallest axis
    [-3.0, -0.5, 0.2],
    [0.01, 5.0, 0.01],  # next to the intermediate axis
]


def _omega_body_from_quaternions(t, q):
    """ω in body axes from a central difference of q: ω_body = 2 vec(q* q̇)."""
    dq = (q[2:] - q[:-2]) / (t[2:] - t[:-2])[:, None]
    conj = q[1:-1] * np.array([1.0, -1.0, -1.0, -1.0])
    return 2.0 * np.array([quaternion_multiply(c, d)[1:] for c, d in zip(conj, dq)])


@pytest.mark.parametrize("spin", FREE_SPINS)
def test_euler_poinsot_obeys_kinematics_and_conservation(free_scene, spin):
    q0, w0 = initial_state(20.0, np.linalg.solve(free_scene.principal_axes, spin))
    solution = exact.solve(free_scene, q0, w0)
    assert isinstance(solution, exact.EulerPoinsot)
    t = np.linspace(0.0, 7.0, 7001)
    q, omega = solution.state_at(t)
    np.testing.assert_allclose(omega[0], w0, rtol=0, atol=1e-13 * np.linalg.norm(w0))
    assert orientation_error_deg(q[0], q0) < 1e-12
    # the orientation and ω belong together: q' = ½ q ⊗ ω (to the finite difference's accuracy)
    np.testing.assert_allclose(
        _omega_body_from_quaternions(t, q), omega[1:-1], atol=2e-5 * np.linalg.norm(w0)
    )
    # energy and the world angular momentum are constant
    drifts = conserved_quantities(free_scene, q, omega)
    assert drifts["energy"]["drift"] < 1e-13
    assert drifts["h_world"]["drift"] < 1e-13


@pytest.mark.parametrize("spin", FREE_SPINS)
def test_integrator_matches_euler_poinsot(free_scene, spin):
    q0, w0 = initial_state(20.0, np.linalg.solve(free_scene.principal_axes, spin))
    numeric = simulate(free_scene, q0, w0, 20.0, 201, rtol=1e-13)
    closed = simulate(free_scene, q0, w0, 20.0, 201, method="exact")
    assert np.max(orientation_error_deg(numeric.q, closed.q)) < 1e-7
    assert np.max(np.abs(numeric.omega - closed.omega)) < 1e-9 * np.linalg.norm(w0)


def test_dzhanibekov_flip_period_is_the_elliptic_value():
    """A T-handle spun near its intermediate axis flips over; the time between flips is half
    the period 4K(m)/λ of Landau's solution (computed here from the textbook formulas)."""
    I1, I2, I3 = 1.0, 2.0, 3.0
    scene = scene_from_properties(MassProperties(1.0, np.zeros(3), np.diag([I1, I2, I3])), None, 0.0)
    w = np.array([0.01, 2.0, 0.02])
    two_T = float(np.sum(np.array([I1, I2, I3]) * w * w))
    M2 = float(np.sum((np.array([I1, I2, I3]) * w) ** 2))
    assert M2 > two_T * I2  # circulates about axis 3
    lam = math.sqrt((I3 - I2) * (M2 - two_T * I1) / (I1 * I2 * I3))
    m = (I2 - I1) * (two_T * I3 - M2) / ((I3 - I2) * (M2 - two_T * I1))
    period = 4.0 * ellipk(m) / lam
    q0, w0 = initial_state(0.0, w)
    run = simulate(scene, q0, w0, 3.2 * period, 40001)
    # the intermediate axis turns over: its world z component changes sign at each flip
    axis_z = np.array([quaternion_to_matrix(q)[2, 1] for q in run.q])
    sign_changes = run.t[1:][np.diff(np.sign(run.omega[:, 1])) != 0]
    flips = np.diff(sign_changes)
    assert len(flips) >= 4
    np.testing.assert_allclose(flips, period / 2, rtol=1e-6)
    assert axis_z.min() < -0.9 and axis_z.max() > 0.9
    assert exact.solve(scene, q0, w0).period == pytest.approx(period, rel=1e-12)


def test_symmetric_free_body_is_steady_precession(free_scene):
    scene = scene_from_properties(MassProperties(1.0, np.zeros(3), np.diag([2.0, 2.0, 1.0])), None, 0.0)
    q0, w0 = initial_state(15.0, [0.3, -0.4, 5.0])
    solution = exact.solve(scene, q0, w0)
    assert isinstance(solution, exact.SymmetricFreeBody)
    t = np.linspace(0.0, 10.0, 101)
    q, omega = solution.state_at(t)
    # Euler's equations with I₁ = I₂: ω₃ constant, (ω₁, ω₂) turns at −(I₁ − I₃) ω₃ / I₁ in the body
    np.testing.assert_allclose(omega[:, 2], 5.0, rtol=1e-14)
    angle = np.unwrap(np.arctan2(omega[:, 1], omega[:, 0]))
    np.testing.assert_allclose(np.diff(angle), -(2.0 - 1.0) * 5.0 / 2.0 * 0.1, rtol=1e-12)
    numeric = simulate(scene, q0, w0, 10.0, 101, rtol=1e-13)
    assert np.max(orientation_error_deg(numeric.q, q)) < 1e-8


@pytest.mark.parametrize(
    "tilt,spin",
    [(10.0, [0, 0, 200.0]), (10.0, [0, 0, 50.0]), (30.0, [1.0, 2.0, 100.0]), (120.0, [0.0, 3.0, 20.0])],
)
def test_lagrange_top_matches_the_integrator_and_conserves(top_scene, tilt, spin):
    q0, w0 = initial_state(tilt, spin)
    closed = simulate(top_scene, q0, w0, 4.0, 481, method="exact")
    numeric = simulate(top_scene, q0, w0, 4.0, 481, rtol=1e-13)
    assert np.max(orientation_error_deg(numeric.q, closed.q)) < 1e-6
    assert np.max(np.abs(numeric.omega - closed.omega)) < 1e-8 * np.linalg.norm(spin)
    drifts = conserved_quantities(top_scene, closed.q, closed.omega)
    assert max(d["drift"] for d in drifts.values()) < 1e-12


def test_lagrange_nutation_bounds_and_period(top_scene):
    """Tilt bounds from the cubic's roots and the period 2K(m)/σ̇ against a densely sampled
    numerical run: tilt extremes and the times of the tilt maxima."""
    q0, w0 = initial_state(10.0, [0, 0, 200.0])
    solution = exact.solve(top_scene, q0, w0)
    low, high = solution.tilt_bounds_deg
    assert low == pytest.approx(10.0, abs=1e-12)  # started at rest in θ: a turning point
    run = simulate(top_scene, q0, w0, 3.0, 30001, rtol=1e-13)
    tilt = tilt_deg(run.q)
    assert tilt.max() == pytest.approx(high, abs=1e-5)
    assert tilt.min() == pytest.approx(low, abs=1e-9)
    peaks = [i for i in range(1, tilt.size - 1) if tilt[i] >= tilt[i - 1] and tilt[i] > tilt[i + 1]]
    # refine each maximum with a parabola through three samples
    times = []
    for i in peaks:
        a, b, c = tilt[i - 1], tilt[i], tilt[i + 1]
        times.append(run.t[i] + 0.5 * (a - c) / (a - 2 * b + c) * (run.t[1] - run.t[0]))
    np.testing.assert_allclose(np.diff(times), solution.nutation_period, rtol=1e-6)
    # the cubic's roots bracket the motion and u₃ > 1
    assert solution.u1 < solution.u2 <= 1.0 < solution.u3


def test_lagrange_mean_precession_rate(top_scene):
    from rbi.sim.diagnostics import precession_deg

    q0, w0 = initial_state(10.0, [0, 0, 200.0])
    solution = exact.solve(top_scene, q0, w0)
    # the integrator's azimuth of the axis after exactly three nutation periods
    run = simulate(top_scene, q0, w0, 3.0 * solution.nutation_period, 3001, rtol=1e-13)
    azimuth = np.radians(precession_deg(run.q))
    mean_rate = (azimuth[-1] - azimuth[0]) / run.t[-1]
    assert mean_rate == pytest.approx(solution.mean_precession_rate, rel=1e-9)
    # a fast top precesses at about the gyroscopic rate m g l / (I₃ ω₃)
    fast = exact.solve(top_scene, *initial_state(10.0, [0, 0, 3000.0]))
    I3 = top_scene.inertia[2, 2]
    gyroscopic = top_scene.mass * top_scene.gravity * top_scene.com_from_pivot[2] / (I3 * 3000.0)
    assert fast.mean_precession_rate == pytest.approx(gyroscopic, rel=3e-3)  # next term ~ (208/3000)² / 4


def test_sleeping_top_and_principal_spins_are_uniform_rotation(top_scene, free_scene):
    assert isinstance(exact.solve(top_scene, *initial_state(0.0, [0, 0, 150.0])), exact.UniformRotation)
    w = free_scene.principal_axes[1] * 3.0
    solution = exact.solve(free_scene, *initial_state(5.0, w))
    assert isinstance(solution, exact.UniformRotation)
    q, omega = solution.state_at(np.array([0.0, 1.0]))
    np.testing.assert_allclose(omega[1], w, atol=1e-15)


def test_not_integrable_cases_are_refused(bolted_scene, top_scene):
    with pytest.raises(exact.NotIntegrable, match="Lagrange"):
        exact.solve(bolted_scene, *initial_state(0.0, [0, 0, 200.0]))
    with pytest.raises(exact.NotIntegrable, match="vertical"):
        exact.solve(top_scene, *initial_state(60.0, [0, 0, 0]))  # a pendulum swinging through the bottom
