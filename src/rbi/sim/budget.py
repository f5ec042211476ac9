"""How much work a run will take, estimated before it starts, so that a mistyped spin or
duration is refused in a moment instead of running for hours.

The compiled DOP853 takes about 3 accepted steps per radian the body turns at the default
tolerance (measured on the textbook's tops and the T-handle: 2,363 steps for the bolted top,
200 rad/s over 4 s); its step length scales as rtol^(1/8). The scipy baselines (RK45, order 5)
take many more, and each costs about a hundred times as much in Python.
"""

from __future__ import annotations

import math

import numpy as np

from rbi.errors import ArgumentError
from rbi.sim.api import DEFAULT_RTOL, SCIPY_DEFAULT_RTOL

DEFAULT_MAX_STEPS = 10_000_000
"""Steps a run may take unless ``--max-steps`` says otherwise (about 10 s of the compiled
integrator; the scipy methods are refused far earlier, see :func:`estimated_steps`)."""

BATCH_STEP_BUDGET = 2e10
"""Most integration steps a batch of runs (a sweep, the drawn runs of ``--draws``) is estimated
to take before it is refused (about four hours of one core)."""


def check_batch(path: str, runs: str, total: float, fewer: str, check: bool) -> None:
    """Refuse, before the first of them starts, a batch of runs estimated to need ``total``
    integration steps together, more than :data:`BATCH_STEP_BUDGET`, unless not ``check``
    (``--yes``): an `ArgumentError` naming the file, the ``runs`` (``"this sweep's 400 runs"``)
    and what to give ``fewer`` of."""
    if check and total > BATCH_STEP_BUDGET:
        raise ArgumentError(
            (),
            f"{path}: {runs} are estimated to need about {total:.2g} integration steps, more than the "
            f"budget of {BATCH_STEP_BUDGET:.0e}: {fewer}, a shorter {{duration}} or a looser {{rtol}}, or "
            "{check_budget=False} to run them anyway",
        )


STEPS_PER_RADIAN = 3.0
"""Accepted steps per radian turned, compiled DOP853 at its default tolerance."""

SAFETY = 2.0
"""Headroom for nutation faster than the spin (flat bodies) and for rejected steps."""

SCIPY_COST = {"rk45": 300.0, "dop853": 100.0}
"""Cost of one scipy step in units of a compiled step, folded into the estimate so one
budget serves every method."""


def estimated_steps(
    scene, omega0, duration: float, method: str = "default", rtol: float | None = None
) -> float:
    """Roughly how many compiled-step equivalents integrating ``scene`` from body angular
    velocity ``omega0`` (rad/s) for ``duration`` seconds costs."""

    if duration == 0.0:
        return 0.0
    rate = max(math.hypot(*(float(w) for w in np.ravel(omega0))), scene.natural_rate)
    if not math.isfinite(rate) or not math.isfinite(duration):
        return math.inf
    radians = SAFETY * rate * float(duration)
    scipy = method in SCIPY_COST
    cost, scale = (SCIPY_COST[method], 0.1) if scipy else (1.0, 1.0)
    order = 5.0 if method == "rk45" else 8.0  # steps scale as rtol^(-1/order)
    tolerance = rtol if rtol is not None else (SCIPY_DEFAULT_RTOL if scipy else DEFAULT_RTOL)
    return cost * STEPS_PER_RADIAN * radians * (DEFAULT_RTOL / tolerance) ** (1.0 / order) * scale
