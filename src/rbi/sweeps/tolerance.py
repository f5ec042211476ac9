"""Mass-property tolerance studies: how varied part dimensions and masses spread the mass,
centre of mass, principal moments and the direction of each principal axis (what a balancing
engineer asks of a rotor). No simulation."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.sweeps.runs import SweepJob

MASS_COLUMNS = tuple(
    "mass com_x com_y com_z moment_1 moment_2 moment_3 axis_1_tilt_deg axis_2_tilt_deg axis_3_tilt_deg status".split()
)
"""Columns after ``run`` and the varied values: mass (M), centre of mass (L, body axes),
principal moments about the centre of mass (M·L², ascending) and the angle of each principal
axis from the nominal body's (deg, sign-free)."""

PERCENTILES = (0, 5, 50, 95, 100)


def mass_rows(job: SweepJob, nominal: np.ndarray, start: int, stop: int) -> list[list[Any]]:
    """Rows of runs ``start .. stop-1``; ``nominal``: the principal axes (rows) of the body as
    written, which each run's axes are measured from."""

    rows = []
    for i, v in enumerate(job.plan.values(start, stop)):
        row: list[Any] = [start + i, *map(float, v)]
        body = job.body(tuple(v))
        if isinstance(body, str):
            rows.append(row + [None] * (len(MASS_COLUMNS) - 1) + [body])
            continue
        moments, axes = principal_axes(body.props.inertia_about_com)
        tilts = np.degrees(np.arccos(np.clip(np.abs(np.sum(axes * nominal, axis=1)), 0.0, 1.0)))
        props = body.props
        figures = [props.mass, *props.center_of_mass, *moments, *tilts]
        rows.append(row + [*map(float, figures), "ok"])
    return rows


def spread(columns: list[str], rows: list[list[Any]], skip: int) -> dict[str, dict[str, float]]:
    """Percentiles (0, 5, 50, 95, 100), mean and standard deviation of every numeric column
    from index ``skip`` on, over the rows whose status is ok."""
    ok = [r for r in rows if r[-1] == "ok"]
    out = {}
    for j, name in enumerate(columns):
        if j < skip or name == "status" or not ok:
            continue
        values = np.array([float(r[j]) for r in ok])
        stats = {f"p{p}": float(v) for p, v in zip(PERCENTILES, np.percentile(values, PERCENTILES))}
        stats |= {
            "mean": float(np.mean(values)),
            "std": float(np.std(values, ddof=1)) if values.size > 1 else 0.0,
        }
        out[name] = stats
    return out
