"""The motion's uncertainty from the uncertainty of a spec's inputs (``rbi simulate --draws``):
the numbers written with ± drawn N times (JCGM 101), the N bodies built as stacks
(:func:`rbi.spec.uncertain.drawn`), and the N runs integrated by the batched compiled kernel
that sweeps use, in calls of at most :data:`rbi.sim.compiled.OUT_BYTES_PER_CHUNK` of sampled
states (memory bounded whatever N × samples), summarised together as sweep rows are."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.errors import ArgumentError, literal
from rbi.sim.api import DEFAULT_RTOL, sample_times
from rbi.sim.budget import check_batch, estimated_steps
from rbi.sim.compiled import STATUS_DONE, integrate_scenes, runs_per_call
from rbi.sim.scene import scene_from_properties
from rbi.sim.summary import tilt_figures
from rbi.spec.uncertain import drawn, generator

FIGURES = {
    "tilt_min_deg": "min_tilt_deg",
    "tilt_max_deg": "max_tilt_deg",
    "final_tilt_deg": "final_tilt_deg",
    "mean_precession_rate_deg_s": "precession_rate_deg_s",
}
"""The summary's names of the figures (as ``rbi simulate`` reports them) and a sweep row's."""


def input_uncertainty(prepared: Any, samples: int, draws: int, seed: int | None) -> dict[str, Any]:
    """The standard deviation over ``draws`` runs of the summary's tilt range, final tilt, mean
    precession rate and final ω, every input written with ± drawn (``seed``: reproducible), the
    runs set up as ``prepared`` (a :class:`~rbi.runs.run.PreparedRun`: same start, spin axis,
    duration and tolerance). Runs the kernel could not finish are counted in ``failed``;
    ``warnings``: the drawn parts the spec refuses (:func:`rbi.spec.uncertain.refused_draws`)."""
    if isinstance(draws, bool) or not isinstance(draws, int) or not 2 <= draws <= 100_000:
        raise ArgumentError("draws", f"must be a whole number from 2 to 100,000 (got {literal(draws)})")
    body, scene, settings = prepared.body, prepared.scene, prepared.settings
    if body.spec is None or not body.spec._uncertain:  # every spread would be 0, and say nothing
        raise ArgumentError("draws", f"needs a spec that writes numbers with ± ({body.path} has none)")
    rtol = DEFAULT_RTOL if settings.rtol is None else settings.rtol
    total = estimated_steps(scene, prepared.omega0, settings.duration, "default", rtol) * draws
    check_batch(body.path, f"{draws:,} drawn runs", total, "fewer {draws}", settings.check_budget)
    notes: list[str] = []
    scenes = []
    for _, bodies in drawn(body, draws, generator(seed), notes):
        for each in bodies:
            try:
                scenes.append(scene_from_properties(each, body.pivot, scene.gravity, scene.spin_axis))
            except ValueError:  # a drawn body no run starts from (negative mass, singular inertia): failed
                continue
    t = sample_times(settings.duration, samples)
    start = np.concatenate((prepared.q0, prepared.omega0))[None, :]
    size, rows, final = runs_per_call(t.size), [], []
    for first in range(0, draws, size):  # chunks of runs: memory bounded whatever draws × samples
        batch = scenes[first : first + size]
        starts = np.repeat(start, len(batch), axis=0)
        out, _, status = integrate_scenes(batch, starts, t, rtol, prepared.budget)
        done = [k for k in range(len(batch)) if status[k] == STATUS_DONE and np.all(np.isfinite(out[k]))]
        # every drawn scene spins about scene's axis
        rows += tilt_figures(t, out[done, :, :4], scene.spin_frame)
        final.append(out[done, -1, 4:])
    spread: dict[str, Any] = {name: _sd([row[key] for row in rows]) for name, key in FIGURES.items()}
    spread["final_omega"] = [_sd(omega) for omega in np.concatenate(final).T]
    return {"draws": draws, "seed": seed, "failed": draws - len(rows)} | spread | {"warnings": notes}


def _sd(values: Any) -> float | None:
    """The standard deviation of ``values``; None for fewer than two, or when a figure is
    undefined (NaN: the precession rate of a run that does not precess, null in the summary)."""
    values = np.asarray(values, dtype=float)
    return (
        float(np.std(values - values[0], ddof=1)) if values.size > 1 and np.isfinite(values).all() else None
    )
