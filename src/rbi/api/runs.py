"""Runs: `simulate` a body, its `Trajectory`."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbi.api.body import Body, loaded_body
from rbi.api.outputs import Destination, checked_output, keywords_checked
from rbi.errors import ArgumentError
from rbi.reprs import QUANTITY_COLUMNS, TableRepr
from rbi.text import number, vector_text


@dataclass(frozen=True, repr=False)
class Trajectory(TableRepr):
    """A simulated motion, sampled at equally spaced times (spec units).

    Attributes:
        t: (N,) time, s.
        q: (N, 4) unit quaternions [w, x, y, z] (scalar first), body → world.
        omega: (N, 3) angular velocity in the body frame, rad/s.
        tilt_deg: (N,) angle of the spin axis (body z unless ``spin_axis`` says otherwise) from
            the upward vertical, degrees.
        precession_deg: (N,) azimuth of that axis seen from above, degrees (unwrapped; NaN
            while the axis stands vertical).
        energy: (N,) total energy (kinetic + potential), mass·length²/s².
        summary: what ``rbi simulate --format json`` prints for the run (initial state, final
            state, tilt bounds, conserved quantities and their drift, error estimate, cost,
            stability), as plain values and numpy arrays.
    """

    t: np.ndarray
    q: np.ndarray
    omega: np.ndarray
    tilt_deg: np.ndarray
    precession_deg: np.ndarray
    energy: np.ndarray
    summary: dict = field(default_factory=dict)
    body: Body | None = field(default=None, compare=False)
    """The simulated `Body` (None for a trajectory made by hand)."""
    omega_given: bool = field(default=False, compare=False)
    """The run was given its ω (``omega``), not a spin about the spin axis."""

    def plot(self, path: Destination) -> None:
        """Draw the run at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib), as ``rbi
        simulate --plot`` does: the path of the tip of the spin axis seen from above (world
        frame), its tilt against time (a free body: each principal axis's angle to the angular
        momentum), degrees; ω in body axes, rad/s; the energy's drift. The file is replaced
        atomically."""
        from rbi.viz.plots import plot_simulation  # matplotlib loads only to draw

        body = self.body
        if body is None:
            raise ArgumentError("body", "plot needs the Body of the run: a Trajectory from rbi.simulate")
        free = (
            {"principal_axes": body.principal().axes, "inertia": body.inertia()} if body.pivot is None else {}
        )
        plot_simulation(
            self.columns(),
            checked_output(path, ("png", "svg", "pdf"), body),
            name=body.name or body.path,
            omega0=self.summary["initial"]["omega"],
            nudge_deg=self.summary["initial"]["nudge_deg"],
            energy_unit=body.unit_labels["energy"],
            spin_axis=self.summary["spin_axis"],
            titled_axis=None if self.omega_given else self.summary["spin_axis"],
            **free,
        )

    def to_csv(self) -> str:
        """The trajectory as the CSV ``rbi simulate --out`` writes (columns t, qw, qx, qy, qz, wx,
        wy, wz, tilt_deg, precession_deg, energy; full precision)."""
        # not at top level: `rbi inertia` would load rbi.runs.run too
        from rbi.runs.run import trajectory_csv

        return trajectory_csv(self.columns())

    def columns(self) -> dict[str, np.ndarray]:
        """The CSV's columns by name (``t``, ``qw`` … ``energy``), each (N,)."""
        # not at top level: `rbi inertia` would load rbi.sim.summary too
        from rbi.sim.summary import columns_of

        return columns_of(self.t, self.q, self.omega, self.tilt_deg, self.precession_deg, self.energy)

    def __repr__(self) -> str:
        return (
            f"<rbi.Trajectory {self.t.size} samples over {number(self.t[-1])} s, "
            f"{self.summary.get('method', '')}>"
        )

    def _table(self) -> tuple[str, list[tuple[str, str, str]], tuple[str, ...]]:
        s = self.summary
        final = s.get("final", {})
        rows = [
            ("scene", "", str(s.get("scene", ""))),
            ("method", "", str(s.get("method", ""))),
            ("duration", "s", number(self.t[-1])),
            ("samples", "", str(self.t.size)),
            ("final q [w, x, y, z]", "", vector_text(self.q[-1])),
            ("final ω (body axes)", "rad/s", vector_text(self.omega[-1])),
            (f"final tilt of {_axis_name(s.get('spin_axis'))}", "deg", number(self.tilt_deg[-1])),
            ("tilt min … max", "deg", f"{number(np.min(self.tilt_deg))} … {number(np.max(self.tilt_deg))}"),
        ]
        if final and "energy" in s.get("conserved", {}):
            rows.append(("energy drift", "", number(s["conserved"]["energy"]["drift"], 2)))
        return f"{s.get('name') or 'trajectory'} — simulate", rows, QUANTITY_COLUMNS


@keywords_checked
def simulate(
    body: Body,
    *,
    spin: float | None = None,
    omega: Sequence[float] | None = None,
    tilt_deg: float = 0.0,
    tilt_axis: str = "y",
    duration: float = 4.0,
    samples: int = 481,
    gravity: float | None = None,
    method: str = "default",
    rtol: float | None = None,
    max_steps: int | None = None,
    error_estimate: bool = True,
    check_budget: bool = True,
    progress: Callable[[float], None] | None = None,
    spin_axis: str | Sequence[float] | None = None,
) -> Trajectory:
    """Simulate the body: a heavy top on its pivot (a spec with ``pivot``) or a torque-free body
    about its centre of mass — the run ``rbi simulate`` makes with the same settings. Returns
    the `Trajectory`.

    Args:
        body: the `Body`.
        spin: initial spin about the spin axis, rad/s.
        omega: instead of ``spin``, the initial angular velocity (3,), body axes, rad/s.
        tilt_deg: the nudge: the body turned at t = 0 by this angle (degrees) about
            ``tilt_axis``. The tilt reported is the spin axis's from the vertical.
        tilt_axis: the world axis of the nudge, ``"x"`` or ``"y"``.
        duration: simulated time, s.
        samples: samples, equally spaced from t = 0 (1: only the end).
        gravity: m/s² (SI whatever the spec's units); 0 switches it off; None is 9.81.
        method: ``"default"`` (compiled adaptive DOP853), ``"rk45"``, ``"dop853"`` (scipy) or
            ``"exact"`` (closed forms, where they apply).
        rtol: integrator tolerance (None: 1e-12 for default, 1e-8 for the scipy methods).
        max_steps: most integration steps (None: rbi's `DEFAULT_MAX_STEPS`); they stop the run.
        check_budget: refuse a run estimated past ``max_steps`` before it starts.
        error_estimate: estimate the error with a second run 1000× tighter.
        progress: called now and then with the fraction done (0…1).
        spin_axis: the body-frame axis of ``spin`` and of the reported tilt and precession:
            ``"x"``, ``"y"``, ``"z"`` (``"-y"``: reversed) or a direction (3,); None for the
            spec's ``spin_axis``, else `Body.spin_axis`'s default.

    Raises:
        ValueError: a setting is out of range, named as this function's parameter
            (``duration: must be ...``), or the run is estimated to exceed ``max_steps``.
        SpecError: the run cannot be made (no mass, too many steps, overflow).
    """
    # not at top level: `rbi inertia` would load rbi.runs.run too
    from rbi.runs.run import prepare_run
    from rbi.sim.api import check_samples

    samples = check_samples(samples)
    run: dict[str, Any] = dict(
        spin=spin, omega=omega, tilt_deg=tilt_deg, tilt_axis=tilt_axis, gravity=gravity
    )
    run |= dict(duration=duration, method=method, rtol=rtol, max_steps=max_steps, check_budget=check_budget)
    prepared = prepare_run(loaded_body(body, "body"), spin_axis=spin_axis, **run)
    return _trajectory(prepared.simulate(samples, error_estimate=error_estimate, progress=progress), body)


def input_uncertainty(
    body: Body, *, draws: int, seed: int | None = None, samples: int = 481, **run: Any
) -> dict[str, Any]:
    """The spread of `simulate`'s summary that the inputs written with ± give: the standard
    deviation of the tilt range, final tilt, mean precession rate and final ω over ``draws``
    runs with the inputs drawn (``seed``: the same draws again), all in one call of the batched
    kernel; ``run``: `simulate`'s settings (``spin``, ``tilt_deg``, ``duration`` ...). What
    ``rbi simulate --draws`` adds to its JSON as ``"input_uncertainty"``."""
    # not at top level: `rbi inertia` would load rbi.runs.run too
    from rbi.runs.draws import input_uncertainty as spread
    from rbi.runs.run import prepare_run
    from rbi.sim.api import check_samples

    return spread(prepare_run(loaded_body(body, "body"), **run), check_samples(samples), draws, seed)


def _trajectory(run: Any, body: Body) -> Trajectory:
    """The `Trajectory` of a finished run (:class:`rbi.runs.run.SimulationRun`) of ``body``."""
    columns = run.columns
    return Trajectory(
        t=columns["t"],
        q=run.trajectory.q,
        omega=run.trajectory.omega,
        tilt_deg=columns["tilt_deg"],
        precession_deg=columns["precession_deg"],
        energy=columns["energy"],
        summary=run.summary,
        body=body,
        omega_given=run.omega_given,
    )


def _axis_name(axis: Any) -> str:
    """``body y`` for a coordinate axis of the body frame, else ``the spin axis [x, y, z]``."""
    if axis is None:
        return "the spin axis"
    axis = np.asarray(axis, dtype=float)
    for index, name in enumerate("xyz"):
        if axis[index] == 1.0:
            return f"body {name}"
    return f"the spin axis {vector_text(axis)}"
