"""Numbers a simulation run reports: the summary of a trajectory and its sample table.

Public names: :func:`summarize`, :func:`sample_columns`, :func:`error_estimate`, :func:`angle_to_h`,
:data:`CSV_COLUMNS`. Plain numbers and arrays only (rendering is the CLI's job).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.sim import diagnostics, exact
from rbi.sim.api import DEFAULT_RTOL, Trajectory, simulate
from rbi.sim.scene import Scene

Array = np.ndarray

CSV_COLUMNS = ("t", "qw", "qx", "qy", "qz", "wx", "wy", "wz", "tilt_deg", "precession_deg", "energy")
"""Trajectory columns: the contract's eight, then the tilt of the spin axis from the upward
vertical (deg), the azimuth of that axis seen from above (the precession angle, deg, unwrapped)
and the total energy."""

ESTIMATE_FIGURES = (
    "orientation_deg",
    "omega_rad_s",
    "omega_relative",
    "final_orientation_deg",
    "final_omega_rad_s",
)
"""The numbers of an :func:`error_estimate` after its ``reference`` (None where no tighter run exists)."""

COST_FIELDS = tuple("method integrator rtol steps rejected_steps rhs_evals wall_seconds load_seconds".split())
"""The fields of a :class:`~rbi.sim.api.Trajectory` its summary reports as they are: how it was
integrated and what that cost."""

REFERENCE_RTOL_FACTOR = 1e-3
REFERENCE_RTOL_FLOOR = 1e-15
"""The tightest tolerance the compiled integrator accepts; a run already at it has no
strictly tighter reference, and gets no error estimate."""


def sample_columns(scene: Scene, trajectory: Trajectory) -> dict[str, np.ndarray]:
    """The trajectory as named columns (see :data:`CSV_COLUMNS`)."""
    q, omega, frame = trajectory.q, trajectory.omega, scene.spin_frame
    tilt, precession = diagnostics.tilt_deg(q, frame), diagnostics.precession_deg(q, frame)
    return columns_of(trajectory.t, q, omega, tilt, precession, diagnostics.energy(scene, q, omega))


def columns_of(
    t: Array, q: Array, omega: Array, tilt_deg: Array, precession_deg: Array, energy: Array
) -> dict[str, Array]:
    """A run's samples (t (N,), q (N, 4), omega (N, 3), then three (N,)) as the columns of
    :data:`CSV_COLUMNS` by name, each (N,)."""
    return dict(zip(CSV_COLUMNS, (t, *q.T, *omega.T, tilt_deg, precession_deg, energy)))


def reference_rtol(trajectory: Trajectory) -> float | None:
    """Tolerance of the comparison run behind :func:`error_estimate`: 1000× tighter than the
    default method's own, but no tighter than :data:`REFERENCE_RTOL_FLOOR`; the floor for the
    scipy methods (cheap, since the reference always uses the compiled integrator). None when
    the run is already at the floor: no strictly tighter reference exists."""
    if trajectory.method != "default":
        return REFERENCE_RTOL_FLOOR
    rtol = trajectory.rtol if trajectory.rtol is not None else DEFAULT_RTOL
    reference = max(rtol * REFERENCE_RTOL_FACTOR, REFERENCE_RTOL_FLOOR)
    return reference if reference < rtol else None


def error_estimate(
    scene: Scene, trajectory: Trajectory, q0, omega0, max_steps: int | None = None
) -> dict[str, Any]:
    """Estimate the trajectory's error by a second run of the default (compiled) method at
    :func:`reference_rtol`: the largest orientation difference over the samples
    (deg) and the largest ω difference (rad/s, and relative to the largest |ω|). At the
    tightest tolerance there is nothing tighter to compare with: the numbers are None and
    ``reference`` says why."""
    rtol = reference_rtol(trajectory)
    if rtol is None:
        return {
            "reference": f"not available: rtol {trajectory.rtol:g} is already the tightest the integrator "
            "accepts, so no tighter run can check it",
            **dict.fromkeys(ESTIMATE_FIGURES),
        }
    duration = float(trajectory.t[-1])
    reference = simulate(
        scene,
        q0,
        omega0,
        duration,
        trajectory.t.size,
        method="default",
        rtol=rtol,
        max_steps=None if max_steps is None else 4 * max_steps,
    )
    angle = np.atleast_1d(diagnostics.orientation_error_deg(trajectory.q, reference.q))
    d_omega = float(np.max(np.abs(trajectory.omega - reference.omega)))
    size = float(np.max(np.linalg.norm(reference.omega, axis=1)))
    return {  # the keys of ESTIMATE_FIGURES
        "reference": f"default method at rtol {rtol:g}",
        "orientation_deg": float(np.max(angle)),
        "omega_rad_s": d_omega,
        "omega_relative": d_omega / size if size > 0 else 0.0,
        "final_orientation_deg": float(angle[-1]),
        "final_omega_rad_s": float(np.max(np.abs(trajectory.omega[-1] - reference.omega[-1]))),
    }


def tilt_figures(t: np.ndarray, q: np.ndarray, frame: np.ndarray | None = None) -> list[dict[str, Any]]:
    """For each of B runs (q (B, N, 4)): the smallest, largest and final tilt of the spin axis
    (deg; body z without ``frame``, see :attr:`rbi.sim.scene.Scene.spin_frame`) and the mean
    precession rate (deg/s; None when the axis stood vertical at some sample, where the
    azimuth is undefined)."""
    B, N = q.shape[0], q.shape[1]
    flat_q = q.reshape(B * N, 4)
    tilt = diagnostics.tilt_deg(flat_q, frame).reshape(B, N)
    axis = diagnostics.spin_axis_in_world(flat_q, frame).reshape(B, N, 3)
    defined = np.hypot(axis[..., 0], axis[..., 1]) > diagnostics.VERTICAL_TOLERANCE
    azimuth = np.degrees(np.unwrap(np.arctan2(axis[..., 1], axis[..., 0]), axis=1))
    duration = float(t[-1] - t[0])
    rates = (azimuth[:, -1] - azimuth[:, 0]) / duration if duration > 0 and t.size > 1 else np.zeros(B)
    return [
        {
            "min_tilt_deg": float(np.min(tilt[b])),
            "max_tilt_deg": float(np.max(tilt[b])),
            "final_tilt_deg": float(tilt[b, -1]),
            "precession_rate_deg_s": float(rates[b]) if defined[b].all() else None,
        }
        for b in range(B)
    ]


def summarize(scene: Scene, trajectory: Trajectory, q0, omega0) -> dict[str, Any]:
    """The run's summary: final state, nutation bounds, mean precession rate, invariants and
    their drift, cost, stability."""
    q, omega, t = trajectory.q, trajectory.omega, trajectory.t
    figures = tilt_figures(t, q[None], scene.spin_frame)[0]
    rate_deg = figures["precession_rate_deg_s"]
    conserved = diagnostics.conserved_quantities(scene, q, omega)
    norms = np.linalg.norm(q, axis=1)
    free = {} if scene.pivoted else {"angle_to_h_deg": angle_to_h(scene, omega)}
    return {
        "spin_axis": np.array(scene.spin_axis, dtype=float),
        "final": {"t": float(t[-1]), "q": q[-1], "omega": omega[-1], "tilt_deg": figures["final_tilt_deg"]},
        **{name: getattr(trajectory, name) for name in COST_FIELDS},
        "tilt_min_deg": figures["min_tilt_deg"],
        "tilt_max_deg": figures["max_tilt_deg"],
        "mean_precession_rate_deg_s": rate_deg,
        "mean_precession_rate_rad_s": None if rate_deg is None else float(np.radians(rate_deg)),
        **free,
        "conserved": conserved,
        "max_relative_drift": max(v["drift"] for v in conserved.values()),
        "quaternion_norm_error": max(float(np.max(np.abs(norms - 1.0))), trajectory.quaternion_norm_error),
        "stability": diagnostics.stability(scene, q0, omega0),
        "closed_form": closed_form_facts(scene, q0, omega0),
    }


def angle_to_h(scene: Scene, omega: np.ndarray) -> dict[str, float | None]:
    """The angle between a free body's spin axis and its angular momentum h = I ω (conserved in
    world axes, so the angle is that of the axis's cone about h): smallest, largest and final
    over the samples, degrees; None for a body that does not turn (h = 0). Measured in body
    axes, ``atan2(|a × h|, a · h)``, accurate near 0° and 180°."""
    h = diagnostics.angular_momentum_body(scene, omega)
    size = np.max(np.abs(h), axis=1, keepdims=True)
    if not np.all(size > 0.0):
        return dict.fromkeys(("min", "max", "final"))
    h = h / size  # no overflow in the cross product for a huge h
    angle = np.degrees(np.arctan2(np.linalg.norm(np.cross(scene.spin_axis, h), axis=1), h @ scene.spin_axis))
    return {"min": float(np.min(angle)), "max": float(np.max(angle)), "final": float(angle[-1])}


def closed_form_facts(scene: Scene, q0, omega0) -> dict[str, Any] | None:
    """Characteristic numbers of the closed-form solution (nutation bounds and period of a
    Lagrange top, period of ω of a free body ...), or None when the scene has none."""
    try:
        return exact.solve(scene, q0, omega0).facts()
    except exact.NotIntegrable:
        return None
