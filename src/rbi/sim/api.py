"""Simulating a scene: one entry point, :func:`simulate`, for every method of :data:`METHODS`
(the API checks a run's settings first: :mod:`rbi.runs.run`)."""

from __future__ import annotations

import numbers
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from rbi.core.validity import finite
from rbi.errors import ArgumentError, literal
from rbi.sim import exact
from rbi.sim.compiled import FAILURES, STATUS_DONE, STATUS_MORE, STATUS_NOT_FINITE, integrator
from rbi.sim.scene import Scene

METHODS = ("default", "rk45", "dop853", "exact")
"""``default``: compiled adaptive DOP853, the quaternion projected to unit length every step;
``rk45``: the seed chapter's set-up (scipy ``solve_ivp`` RK45, rtol 1e-8, atol 1e-10, Python
right-hand side); ``dop853``: scipy DOP853, the same right-hand side; ``exact``: the closed
forms of :mod:`rbi.sim.exact`, where they apply."""

DEFAULT_RTOL = 1e-12
"""Tolerance of the default method (local error per step; see :mod:`rbi.sim.kernels`)."""

RTOL_RANGE = (1e-15, 1e-2)
"""Tolerances accepted by :func:`simulate`."""

MAX_SAMPLES = 1_000_000
"""Most samples one run reports (a CSV of 10⁶ rows is about 250 MB)."""

SCIPY_DEFAULT_RTOL = 1e-8
SCIPY_ATOL_RATIO = 1e-2  # atol = rtol / 100, as in the chapter's (1e-8, 1e-10)

CHUNK_STEPS = 20_000
"""Steps per call of the compiled kernel: between calls the progress is reported and Ctrl-C
can interrupt."""


class SimulationError(ValueError):
    """The integration could not be carried out (step size underflow, overflow, or a method
    that does not apply to the scene)."""


@dataclass
class Trajectory:
    """Samples of a simulated motion.

    t (N,) s; q (N, 4) unit quaternions [w, x, y, z], body -> world; omega (N, 3) body-frame
    angular velocity, rad/s. steps: accepted integration steps (0 for a closed form);
    rejected_steps; rhs_evals: right-hand-side evaluations; wall_seconds: time of the
    integration in this process; method: one of :data:`METHODS`; rtol: the tolerance used
    (None for a closed form); integrator: a description of the solver; load_seconds: time
    spent loading the compiled kernel in this process (0 after the first run);
    quaternion_norm_error: the largest ``| |q| - 1 |`` the solver produced before rbi
    normalised its output.
    """

    t: np.ndarray
    q: np.ndarray
    omega: np.ndarray
    steps: int
    rhs_evals: int
    wall_seconds: float
    method: str
    rtol: float | None = None
    rejected_steps: int = 0
    integrator: str = ""
    load_seconds: float = 0.0
    quaternion_norm_error: float = 0.0
    dense: Trajectory | None = None
    """The same integration sampled more densely (``simulate``'s ``dense``), or None."""

    def at(self, rows: np.ndarray) -> Trajectory:
        """The samples ``rows`` (indices) of this trajectory, with its counts."""
        return replace(self, t=self.t[rows], q=self.q[rows], omega=self.omega[rows])


def sample_times(duration: float, samples: int) -> np.ndarray:
    """``samples`` equally spaced times from 0 to ``duration`` (both included).

    One sample is the final time; a zero duration gives the single time 0.
    """
    if duration == 0.0:
        return np.zeros(1)
    if samples == 1:
        return np.array([float(duration)])
    return np.linspace(0.0, float(duration), int(samples))


def check_method(method: Any) -> None:
    """ArgumentError (a ValueError) unless ``method`` is one of :data:`METHODS`."""
    if method not in METHODS:
        raise ArgumentError("method", f"must be one of {', '.join(METHODS)} (got {literal(method)})")


def check_duration(duration: Any) -> None:
    """ArgumentError (a ValueError) unless ``duration`` is a finite number of seconds >= 0."""
    if not (finite(duration) and duration >= 0.0):
        raise ArgumentError("duration", f"must be a finite number of seconds >= 0 (got {literal(duration)})")


def check_rtol(rtol: Any) -> None:
    """ArgumentError (a ValueError) unless ``rtol`` is None (the method's own) or in
    :data:`RTOL_RANGE`."""
    if rtol is not None and not (finite(rtol) and RTOL_RANGE[0] <= rtol < RTOL_RANGE[1]):
        raise ArgumentError(
            "rtol", f"must be between {RTOL_RANGE[0]:g} and {RTOL_RANGE[1]:g} (got {literal(rtol)})"
        )


def check_samples(samples: Any, most: int = MAX_SAMPLES, what: str = "") -> int:
    """The one check of a number of samples: ``samples`` as an int when it is a whole number
    (an int, or a float with no fraction such as 481.0, as ``--samples 481.0`` is read) from
    1 to ``most`` (``what``: said after the range); TypeError for what is no number (a bool, a
    text), ArgumentError (a ValueError) naming ``samples`` otherwise."""
    if isinstance(samples, bool) or not isinstance(samples, numbers.Real):
        raise TypeError(f"samples: must be a whole number (got {type(samples).__name__} {samples!r:.60})")
    if not (1 <= samples <= most and float(samples).is_integer()):
        raise ArgumentError(
            "samples", f"must be a whole number between 1 and {most:,}{what} (got {literal(samples)})"
        )
    return int(samples)


def simulate(
    scene: Scene,
    q0,
    omega0,
    duration: float,
    samples: int,
    method: str = "default",
    rtol: float | None = None,
    progress: Callable[[float], None] | None = None,
    max_steps: int | None = None,
    dense: int = 0,
) -> Trajectory:
    """Integrate the scene from ``(q0, omega0)`` at t = 0 and sample it at
    :func:`sample_times` ``(duration, samples)``.

    q0: [w, x, y, z] (normalised here), omega0: body frame, rad/s. method: one of
    :data:`METHODS`. rtol: the method's tolerance (default :data:`DEFAULT_RTOL` for
    ``default``, 1e-8 for the scipy methods; ignored by ``exact``). progress: called with the
    fraction done, now and then, by the default method. max_steps: the default method stops
    with :class:`SimulationError` once it has taken more accepted steps than this. dense: with
    more samples than ``samples``, the same integration is also sampled at ``dense`` equally
    spaced times (a plot's), as the result's ``dense`` (the default and exact methods, whose
    dense output does not change the steps: the ``samples`` are the same bit for bit).
    """
    # the kernel's guard: ArgumentError (a ValueError) for a run that cannot be made, in the words
    # the API uses (rbi.runs.run checks the same settings with these functions before any work)
    check_duration(duration)
    check_samples(samples)
    check_rtol(rtol)
    check_method(method)
    q0 = np.asarray(q0, dtype=float)
    q0 = q0 / np.linalg.norm(q0)
    omega0 = np.asarray(omega0, dtype=float).reshape(3)
    t = sample_times(duration, samples)
    fine = sample_times(duration, dense)
    both = np.union1d(t, fine) if method in ("default", "exact") and fine.size > t.size else t
    if method == "default":
        run = _run_compiled(
            scene, q0, omega0, both, DEFAULT_RTOL if rtol is None else rtol, progress, max_steps
        )
    elif method == "exact":
        run = _run_exact(scene, q0, omega0, both)
    else:
        run = _run_scipy(scene, q0, omega0, t, method, SCIPY_DEFAULT_RTOL if rtol is None else rtol)
    if both is t:
        return run
    return replace(run.at(np.searchsorted(both, t)), dense=run.at(np.searchsorted(both, fine)))


def _run_compiled(
    scene: Scene, q0, omega0, t: np.ndarray, rtol: float, progress, max_steps: int | None = None
) -> Trajectory:

    loaded = integrator()
    y = np.concatenate((q0, omega0))
    clock = np.zeros(9)
    out = np.empty((t.size, 7))
    counts = np.zeros(4, dtype=np.int64)
    settings = np.array([rtol, max(scene.natural_rate, 0.0)])
    inertia = np.ascontiguousarray(scene.inertia, dtype=float)
    inertia_inv = np.ascontiguousarray(scene.inertia_inv, dtype=float)
    c = np.ascontiguousarray(scene.gravity_moment, dtype=float)
    t_end = float(t[-1])
    start = time.perf_counter()
    while True:
        chunk = CHUNK_STEPS if max_steps is None else max(1, min(CHUNK_STEPS, max_steps - int(counts[1])))
        status = loaded.integrate(y, clock, t, out, inertia, inertia_inv, c, settings, counts, chunk)
        if status != STATUS_MORE:
            break
        if max_steps is not None and counts[1] >= max_steps:
            raise SimulationError(
                f"stopped at t = {clock[0]:.6g} s after {int(counts[1]):,} steps, the step "
                "budget (raise it with --max-steps)"
            )
        if progress is not None and t_end > 0.0:
            progress(clock[0] / t_end)
    wall = time.perf_counter() - start
    if status != STATUS_DONE:
        raise SimulationError(
            f"integration failed at t = {clock[0]:.6g} s: {FAILURES.get(int(status), FAILURES[STATUS_NOT_FINITE])}"
        )
    if progress is not None:
        progress(1.0)
    return Trajectory(
        t=t,
        q=out[:, :4].copy(),
        omega=out[:, 4:].copy(),
        steps=int(counts[1]),
        rhs_evals=int(counts[3]),
        wall_seconds=wall,
        method="default",
        rtol=rtol,
        rejected_steps=int(counts[2]),
        integrator=f"DOP853, compiled ({loaded.how}), unit quaternion projection",
        load_seconds=loaded.load_seconds,
    )


def _run_scipy(scene: Scene, q0, omega0, t: np.ndarray, method: str, rtol: float) -> Trajectory:
    from rbi.sim.baselines import solve_with_scipy  # heavy: scipy.integrate, for these methods only

    atol = rtol * SCIPY_ATOL_RATIO
    solver = {"rk45": "RK45", "dop853": "DOP853"}[method]
    start = time.perf_counter()
    try:
        y, steps, nfev = solve_with_scipy(scene, q0, omega0, t, solver, rtol, atol)
    except RuntimeError as exc:
        raise SimulationError(str(exc)) from None
    wall = time.perf_counter() - start
    q_raw = y[:4].T
    norms = np.linalg.norm(q_raw, axis=1)
    return Trajectory(
        t=t,
        q=q_raw / norms[:, None],
        omega=y[4:].T.copy(),
        steps=steps,
        rhs_evals=nfev,
        wall_seconds=wall,
        method=method,
        rtol=rtol,
        integrator=f"scipy solve_ivp {solver}, rtol {rtol:g}, atol {atol:g}, Python right-hand side",
        quaternion_norm_error=float(np.max(np.abs(norms - 1.0))),
    )


def _run_exact(scene: Scene, q0, omega0, t: np.ndarray) -> Trajectory:
    start = time.perf_counter()
    try:
        solution = exact.solve(scene, q0, omega0)
    except exact.NotIntegrable as exc:
        raise SimulationError(f"--method exact does not apply: {exc}") from None
    q, omega = solution.state_at(t)
    wall = time.perf_counter() - start
    return Trajectory(
        t=t,
        q=q,
        omega=omega,
        steps=0,
        rhs_evals=0,
        wall_seconds=wall,
        method="exact",
        integrator=f"closed form: {solution.description}",
    )
