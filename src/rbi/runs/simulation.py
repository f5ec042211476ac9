"""One simulation run of a prepared body: the trajectory, its sample columns and the summary
`rbi simulate --format json` prints."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbi.errors import InputError
from rbi.runs.prepare import PreparedRun

SCENE_NAMES = {True: "heavy top on a fixed pivot", False: "free body (torque-free about the centre of mass)"}


@dataclass(frozen=True)
class SimulationRun:
    """A finished run: ``trajectory`` (:class:`rbi.sim.api.Trajectory`), ``columns`` (the CSV's
    columns by name, :data:`rbi.sim.summary.CSV_COLUMNS`) and ``summary`` (plain values and
    numpy arrays: what `rbi simulate --format json` prints, without ``out``)."""

    trajectory: Any
    columns: dict[str, np.ndarray]
    summary: dict[str, Any]


def integrate(run: PreparedRun, samples: int, progress: Callable[[float], None] | None = None):
    """The trajectory of ``run`` at ``samples`` equally spaced times; :class:`InputError` (naming
    the spec) when the integration fails."""
    from rbi.sim.api import SimulationError, simulate

    try:
        return simulate(
            run.scene,
            run.q0,
            run.omega0,
            run.duration,
            samples,
            method=run.method,
            rtol=run.rtol,
            progress=progress,
            max_steps=run.budget,
        )
    except SimulationError as exc:
        raise InputError(f"{run.body.path}: {exc}") from None


def simulate_run(
    run: PreparedRun,
    samples: int,
    *,
    error_estimate: bool = True,
    progress: Callable[[float], None] | None = None,
) -> SimulationRun:
    """Integrate ``run``, summarise it and (unless ``error_estimate`` is False or the method is
    the closed form) estimate its error by a tighter second run. A trajectory that overflowed
    is refused with :class:`InputError` (absurd spin or inertia)."""
    from rbi.sim.api import SimulationError
    from rbi.sim.summary import error_estimate as estimate
    from rbi.sim.summary import sample_columns, summarize

    trajectory = integrate(run, samples, progress)
    try:
        figures = summarize(run.scene, trajectory, run.q0, run.omega0)
        figures["error_estimate"] = (
            estimate(run.scene, trajectory, run.q0, run.omega0, max_steps=run.budget)
            if error_estimate and run.method != "exact"
            else None
        )
    except SimulationError as exc:
        raise InputError(f"{run.body.path}: {exc}") from None
    columns = sample_columns(run.scene, trajectory)
    refuse_non_finite(run.body.path, columns)
    body, scene = run.body, run.scene
    summary = {
        "name": body.name,
        "units": body.units,
        "warnings": list(body.warnings),
        "scene": SCENE_NAMES[bool(scene.pivoted)],
        "pivot": scene.pivot,
        "gravity": scene.gravity,
        "duration": run.duration,
        "samples": int(trajectory.t.size),
        "initial": {
            "t": 0.0,
            "q": run.q0,
            "omega": run.omega0,
            "tilt_deg": initial_tilt_deg(run),
            "nudge_deg": run.tilt_deg,
        },
    } | figures
    return SimulationRun(trajectory=trajectory, columns=columns, summary=summary)


def initial_tilt_deg(run: PreparedRun) -> float:
    """The tilt of the spin axis from the upward vertical at t = 0, degrees."""
    from rbi.sim.diagnostics import tilt_deg

    return float(tilt_deg(run.q0, run.scene.spin_frame)[0])


def refuse_non_finite(path: str, columns: dict) -> None:
    """A trajectory that overflowed is bad input (absurd spin or inertia), never written out."""
    for name, values in columns.items():
        if name != "precession_deg" and not np.all(np.isfinite(values)):
            raise InputError(
                f"{path}: the trajectory's {name} is not finite: the input values are too large "
                "for double precision"
            )


def trajectory_csv(columns: dict[str, np.ndarray]) -> str:
    """The CSV `rbi simulate --out` writes: a header of :data:`rbi.sim.summary.CSV_COLUMNS`,
    then one line a sample, each number at full precision (its shortest round-tripping
    ``repr``; ``-0.0`` as ``0.0``; an undefined value, NaN, as an empty cell)."""
    from rbi.sim.summary import CSV_COLUMNS

    lines = [",".join(CSV_COLUMNS)]
    table = np.column_stack([np.asarray(columns[name], dtype=float) for name in CSV_COLUMNS])
    for row in table.tolist():
        lines.append(",".join("" if v != v else repr(v + 0.0) for v in row))
    return "\n".join(lines) + "\n"
