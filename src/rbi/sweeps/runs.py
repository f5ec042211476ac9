"""A chunk of sweep runs → rows: each run's body re-derived from the varied spec, all runs of
the chunk integrated in one call of the batched compiled kernel, each summarised as
``rbi simulate`` summarises a single run.

Everything here is picklable plain data, so a chunk can run in this process or on a Dask
worker and give the same rows.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbi.memory import cached
from rbi.sim import compiled
from rbi.sim.api import sample_times
from rbi.sim.compiled import FAILURES, STATUS_DONE, STATUS_MORE, STATUS_NOT_FINITE, integrate_scenes
from rbi.sim.diagnostics import energy_drifts
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.sim.summary import tilt_figures
from rbi.spec.errors import InputError
from rbi.spec.load import spec_from_raw
from rbi.spec.translate import body_from_spec
from rbi.spec.units import gravity_in
from rbi.spec.variations import FieldPath, with_values
from rbi.sweeps.plan import Plan

RESULT_COLUMNS = tuple(
    "max_tilt_deg final_tilt_deg min_tilt_deg precession_rate_deg_s energy_drift steps status".split()
)
"""Columns after ``run`` and the swept values, in order."""

CACHED_ENTRIES = 4096
"""Bodies and scenes a sweep keeps, each set of values used last (runs repeat values: a grid's
spin axis, a spec field varied alone)."""


@dataclass(frozen=True)
class SweepJob:
    """What every run of a sweep shares. path: the spec file (for messages and files it names);
    raw: the parsed spec; varied: the paths of ``plan``'s axes after spin and tilt; duration (s),
    samples, rtol: as ``rbi simulate``; gravity_si: m/s²; tilt_axis: "x" or "y"; max_steps: per
    run; spin_axis: the unit body-frame axis every run spins about and reports the tilt of (None:
    each body's default)."""

    path: str
    raw: Any
    plan: Plan
    varied: tuple[FieldPath, ...]
    duration: float
    samples: int
    rtol: float
    gravity_si: float
    tilt_axis: str = "y"
    max_steps: int = 10**7
    spin_axis: tuple[float, float, float] | None = None
    _bodies: OrderedDict = field(default_factory=OrderedDict, compare=False, repr=False)
    _scenes: OrderedDict = field(default_factory=OrderedDict, compare=False, repr=False)

    def chunk_size(self, threads: int) -> int:
        """Runs per kernel call: enough to keep every thread busy, bounded in memory."""
        return min(max(64, 16 * threads), compiled.runs_per_call(self.samples))

    def body(self, values: tuple[float, ...]):
        """The body with the varied fields set to ``values`` (cached per distinct values), or the
        one-line reason it cannot be built."""
        key = tuple(values)
        return cached(
            self._bodies, CACHED_ENTRIES, key, lambda: _derive_body(self.path, self.raw, self.varied, key)
        )

    def scene_of(self, body):
        """The scene of one of this sweep's bodies, under its gravity and spinning about its spin
        axis; ValueError when the body cannot be simulated (no mass, a singular inertia)."""
        gravity = gravity_in(body.length_unit, self.gravity_si)
        return scene_from_properties(body.props, body.pivot, gravity, self.spin_axis)


def _derive_body(path: str, raw: Any, varied: tuple[FieldPath, ...], values: tuple[float, ...]):

    try:
        spec_raw = with_values(raw, list(varied), values) if varied else raw
        return body_from_spec(spec_from_raw(path, spec_raw), path)
    except InputError as exc:
        return _one_line(str(exc).removeprefix(f"{path}: "))


def _scene(job: SweepJob, values: tuple[float, ...]):
    """The run's scene, or the reason it has none (cached per distinct values)."""
    return cached(job._scenes, CACHED_ENTRIES, values, lambda: _derive_scene(job, values))


def _derive_scene(job: SweepJob, values: tuple[float, ...]):

    body = job.body(values)
    if isinstance(body, str):
        return body
    try:
        return job.scene_of(body)
    except ValueError as exc:
        return _one_line(f"cannot simulate: {exc}")


def run_chunk(job: SweepJob, start: int, stop: int, threads: int = 0) -> list[list[Any]]:
    """Rows of runs ``start .. stop-1``: ``run``, the swept values, then :data:`RESULT_COLUMNS`."""

    values = job.plan.values(start, stop)
    t = sample_times(job.duration, job.samples)
    rows: list[list[Any]] = [[start + i, *map(float, v)] for i, v in enumerate(values)]
    scenes, starts, ready = [], [], []
    for i, v in enumerate(values):
        scene = _scene(job, tuple(v[2:]))
        if isinstance(scene, str):
            rows[i] += [None] * (len(RESULT_COLUMNS) - 1) + [scene]
            continue
        q0, omega0 = initial_state(v[1], v[0] * scene.spin_axis, job.tilt_axis)
        scenes.append(scene)
        starts.append(np.concatenate((q0 / np.linalg.norm(q0), omega0)))
        ready.append(i)
    if not ready:
        return rows
    out, counts, status = integrate_scenes(scenes, np.array(starts), t, job.rtol, job.max_steps, threads)
    finite = np.all(np.isfinite(out), axis=(1, 2))
    figures_of = _figures(scenes, t, out, status, finite)
    _fill_rows(job, rows, ready, status, finite, counts, figures_of)
    return rows


def _figures(scenes: list, t: np.ndarray, out: np.ndarray, status: np.ndarray, finite: np.ndarray) -> dict:
    """Each finished, finite run's summary figures by its batch index: the tilts and precession
    rate (:func:`~rbi.sim.summary.tilt_figures`) and the energy's relative drift, as ``rbi
    simulate`` reports them; the runs of one scene are summarised together."""

    figures_of: dict[int, dict] = {}
    by_scene: dict[int, list[int]] = {}
    for b in range(len(scenes)):
        if status[b] == STATUS_DONE and finite[b]:
            by_scene.setdefault(id(scenes[b]), []).append(b)
    for group in by_scene.values():
        scene, q, omega = scenes[group[0]], out[group, :, :4], out[group, :, 4:]
        with np.errstate(all="ignore"):
            batch, drifts = tilt_figures(t, q, scene.spin_frame), energy_drifts(scene, q, omega)[1]
        figures_of.update((b, row | {"energy_drift": drift}) for b, row, drift in zip(group, batch, drifts))
    return figures_of


def _fill_rows(job: SweepJob, rows: list, ready: list, status, finite, counts, figures_of: dict) -> None:
    """Complete each integrated run's row with its figures and status, or why it failed."""

    for b, i in enumerate(ready):
        if status[b] == STATUS_DONE and finite[b]:
            rows[i] += [figures_of[b][name] for name in RESULT_COLUMNS[:5]] + [int(counts[b, 1]), "ok"]
        elif status[b] == STATUS_DONE:
            rows[i] += [None] * (len(RESULT_COLUMNS) - 1) + ["failed: " + FAILURES[STATUS_NOT_FINITE]]
        else:
            reason = FAILURES.get(int(status[b]), FAILURES[STATUS_NOT_FINITE])
            if status[b] == STATUS_MORE:
                reason = f"step budget of {job.max_steps:,} steps reached"
            rows[i] += [None] * (len(RESULT_COLUMNS) - 2) + [int(counts[b, 1]), "failed: " + reason]


def _one_line(text: str) -> str:
    return " ".join(text.split())
