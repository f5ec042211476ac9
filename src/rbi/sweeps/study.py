"""A whole sweep of one spec, below the CLI and the API: the settings checked, the plan of runs
built, the runs executed (local cores or a Dask cluster) and streamed to an output file, and the
result `rbi sweep` prints.

:class:`SweepSettings` holds what the user chose; :func:`check_settings` refuses bad
settings before any file is read; :class:`Study`
plans the sweep of a parsed spec and runs it. Messages name :func:`rbi.sweep`'s parameters
(:class:`~rbi.errors.ArgumentError`); `rbi sweep` spells them as its options.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import numbers
import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.core.validity import require_callable, require_flags, whole
from rbi.errors import ArgumentError, InputError, literal
from rbi.files import safe
from rbi.runs.run import RunSettings, body_spin_axis, check_run_settings, check_tilt, spin_axis_value
from rbi.sim.api import DEFAULT_RTOL, check_samples
from rbi.sim.budget import DEFAULT_MAX_STEPS, check_batch, estimated_steps
from rbi.sim.diagnostics import sleeping_threshold
from rbi.spec.load import spec_label
from rbi.spec.units import STANDARD_GRAVITY_SI
from rbi.spec.variations import current_values, resolve
from rbi.sweeps import execute, runs, store
from rbi.sweeps.execute import Chunks, check_address
from rbi.sweeps.plan import MAX_RUNS, Draw, Plan, axis_of, axis_record
from rbi.sweeps.runs import RESULT_COLUMNS, SweepJob
from rbi.sweeps.tolerance import MASS_COLUMNS, mass_rows

MAX_ROWS_SHOWN = 100_000
"""Most runs a sweep may print (json/csv/table) or hold in memory instead of writing them with --out."""

MAX_SWEEP_SAMPLES = 100_000
"""Most samples per run of a sweep."""

SECONDS_PER_STEP = 4e-7
"""A first guess of the time one estimated step (:func:`rbi.sim.budget.estimated_steps`) of a
sweep run takes on one core (0.22–0.26 µs measured for the textbook top, 100 s at 150 and
250 rad/s, on the shared 2-core development machine), which sizes the first chunks of a sweep;
the later ones are sized by how long chunks took."""

RESUME_SETTINGS = ("duration", "samples", "rtol", "gravity_si", "tilt_axis", "max_steps")
"""The settings of each run that ``--resume`` finds in the settings file as they were."""

MASS_CHUNK = 256
"""Runs per chunk of a study of mass properties (no simulation: each run takes microseconds)."""


@dataclass(frozen=True)
class SweepSettings(RunSettings):
    """The settings of a sweep, in numbers: :func:`rbi.sweep`'s parameters of the same names,
    with their units and defaults (``vary`` as ``(PATH, VALUES)`` pairs). Those of each run
    are a :class:`~rbi.runs.run.RunSettings`' (a sweep does not take ``omega``, ``method`` or
    ``error_estimate``), ``spin``, ``tilt_deg`` and ``rtol`` defaulting as a sweep's."""

    spin: Any = 0.0
    tilt_deg: Any = 0.0
    rtol: float = 1e-12
    vary: tuple[tuple[str, Any], ...] = ()
    runs: int = 1
    seed: int = 0
    workers: int | None = None
    dask: str | None = None
    mass_properties: bool = False


def check_settings(settings: SweepSettings) -> None:
    """Refuse the number of runs, the run settings, the samples, the workers and (a study of
    mass properties) a spin or tilt, before any file is read."""

    if not whole(settings.runs) or settings.runs < 1:
        raise ArgumentError("runs", f"must be a whole number, at least 1 (got {literal(settings.runs)})")
    if not whole(settings.seed) or settings.seed < 0:
        raise ArgumentError("seed", f"must be a whole number 0 or above (got {literal(settings.seed)})")
    check_run_settings(settings)
    require_flags(mass_properties=settings.mass_properties)
    check_samples(settings.samples, MAX_SWEEP_SAMPLES, " for a sweep")
    spin_axis_value(settings.spin_axis)
    if settings.workers is not None and not (whole(settings.workers) and 1 <= settings.workers <= 1024):
        raise ArgumentError("workers", f"must be between 1 and 1024 (got {literal(settings.workers)})")
    if settings.mass_properties and (_nonzero(settings.spin) or _nonzero(settings.tilt_deg)):
        raise ArgumentError(
            "mass_properties", "takes {vary} only (no {spin} or {tilt_deg}: nothing is simulated)"
        )
    if settings.dask is not None:
        check_address(settings.dask)


def _nonzero(value: Any) -> bool:
    """True unless ``value`` is None or the single number 0."""
    return value is not None and not (isinstance(value, numbers.Real) and value == 0)


class Study:
    """The planned sweep of one parsed spec.

    path: the spec (for messages and the files it names); raw: its parsed YAML; settings:
    :class:`SweepSettings` (checked); spec_bytes: the bytes ``raw`` was parsed from, as the
    loader read them (:func:`rbi.spec.load.read_spec`; None for a spec given as text, a dict or
    on standard input), for the resume check. After construction: ``plan`` (the runs),
    ``job`` (:class:`~rbi.sweeps.runs.SweepJob`), ``nominal`` (the body at the spec's own
    values), ``columns`` (of each row). :class:`InputError` for a sweep that cannot be made.
    """

    def __init__(
        self,
        path: str,
        raw: Any,
        settings: SweepSettings,
        *,
        rows_printed: bool = True,
        spec_bytes: bytes | None = None,
    ) -> None:

        self.path, self.raw, self.settings, self.spec_bytes = path, raw, settings, spec_bytes
        axes, varied = self._axes()
        self.plan = _plan(axes, settings, rows_printed)
        self.job = SweepJob(
            path=str(path),
            raw=raw,
            plan=self.plan,
            varied=tuple(varied),
            duration=float(settings.duration),
            samples=int(settings.samples),
            rtol=DEFAULT_RTOL if settings.rtol is None else float(settings.rtol),  # None: as simulate's
            gravity_si=STANDARD_GRAVITY_SI if settings.gravity is None else float(settings.gravity),
            tilt_axis=settings.tilt_axis.lower(),
            max_steps=DEFAULT_MAX_STEPS if settings.max_steps is None else int(settings.max_steps),
        )
        self.nominal = self.job.body(tuple(current_values(raw, varied)))
        if isinstance(self.nominal, str):
            raise InputError(f"{spec_label(path)}: {self.nominal}")
        # one spin axis for every run (unit, body frame): spin_axis, else the spec's, else the
        # nominal body's default, so every row's tilt is of one body axis, whatever a varied value breaks
        axis = body_spin_axis(self.nominal, settings.spin_axis)
        self.job = dataclasses.replace(self.job, spin_axis=tuple(float(c) for c in axis))
        results = MASS_COLUMNS if settings.mass_properties else RESULT_COLUMNS
        self.columns = ["run", *self.plan.names, *results]
        if not settings.mass_properties:
            self._check_budget()
        remote = settings.dask not in (None, "local")
        self.cores = None if remote else execute.usable_workers(settings.workers)
        """The cores the runs use here (``workers``, at most this machine's), None on a cluster."""
        self.output = None
        """The :class:`~rbi.sweeps.store.SweepOutput` while :meth:`run` writes one (its ``done``
        counts the runs kept there)."""

    def _axes(self):

        s = self.settings
        axes = [] if s.mass_properties else [_axis("spin", s.spin), _axis("tilt_deg", s.tilt_deg)]
        if axes:
            check_tilt(axes[1].largest())
        varied = []
        for path_text, value in s.vary:
            try:
                varied.append(resolve(self.raw, path_text))
            except ArgumentError as exc:
                raise ArgumentError(
                    exc.parameters, exc.detail, item=exc.item, file=spec_label(self.path)
                ) from None
            axes.append(_axis(path_text, value, "vary"))
        names = [a.name for a in axes]
        if len(set(names)) != len(names):
            raise ArgumentError("vary", "a path is given twice")
        if s.mass_properties and not varied:
            raise ArgumentError("mass_properties", "give at least one path to {vary}")
        return axes, varied

    def _steps_per_run(self) -> float | None:
        """The estimated integration steps of a run at the fastest spin, or None when the
        nominal body cannot be simulated (every run will say why)."""

        scene = self.nominal_scene()
        if scene is None:
            return None
        fastest = [a for a in self.plan.axes if a.name == "spin"][0].largest()
        return estimated_steps(
            scene, np.array([0.0, 0.0, fastest]), self.job.duration, "default", self.job.rtol
        )

    def _check_budget(self) -> None:
        """Refuse, before any run, a sweep estimated to take more than the step budget."""

        per_run = self._steps_per_run()
        if per_run is None:
            return
        runs = f"this sweep's {self.plan.size:,} runs"
        check_batch(self.job.path, runs, per_run * self.plan.size, "fewer runs", self.settings.check_budget)

    def nominal_scene(self):
        """The scene of the nominal body, or None when it cannot be simulated."""

        try:
            return self.job.scene_of(self.nominal)
        except ValueError:
            return None

    def _compute(self):
        """``compute(start, stop, threads) -> rows`` for the executors."""
        job = self.job
        if self.settings.mass_properties:
            axes_nominal = principal_axes(self.nominal.props.inertia_about_com)[1]
            return lambda a, b, threads: mass_rows(job, axes_nominal, a, b)
        return lambda a, b, threads: runs.run_chunk(job, a, b, threads)

    def _chunks(self, start: int) -> Chunks:
        """The chunks of runs ``start ..`` (:class:`~rbi.sweeps.execute.Chunks`): at most
        :meth:`SweepJob.chunk_size <rbi.sweeps.runs.SweepJob.chunk_size>` runs, fewer where runs
        are long, so that each chunk ends within about a second (sized first by the estimated
        steps of a run at the fastest spin, then by how long chunks take)."""
        if self.settings.mass_properties:
            return Chunks(start, self.plan.size, MASS_CHUNK)
        threads = execute.usable_workers(self.settings.workers)
        if self.settings.dask is not None:  # a task runs on one core
            share, least = 1.0, 1
        else:  # the two chunks in flight share the cores
            share, least = threads / 2, (threads + 1) // 2
        steps = self._steps_per_run()
        run_seconds = None if steps is None else steps * SECONDS_PER_STEP / share
        return Chunks(start, self.plan.size, self.job.chunk_size(threads), least, run_seconds)

    def store_settings(self) -> dict:
        """What makes two sweeps the same, for ``--resume``: the spec's bytes, those the rows
        come from (:attr:`spec_bytes`, as the loader read them: the file is not read again), or
        its parsed form when it was given as text, a dict or on standard input; the bytes of
        each file it reads (a sub-assembly, a mesh, a STEP file: ``files_sha256``, when there
        are any); and every setting."""

        job, spec_bytes = self.job, self.spec_bytes
        if spec_bytes is None:
            spec_bytes = json.dumps(self.raw, sort_keys=True, default=str).encode()
        same = {name: getattr(job, name) for name in RESUME_SETTINGS}
        record = same | {
            "spec_sha256": hashlib.sha256(spec_bytes).hexdigest(),
            "spin_axis": list(job.spin_axis),
        }
        record |= {"axes": [[a.name, axis_record(a)] for a in self.plan.axes], "runs": job.plan.runs}
        record |= {"seed": job.plan.seed, "mass_properties": self.settings.mass_properties}
        files = [_file_sha256(path) for path in self.nominal.files]
        return record | ({"files_sha256": files} if files else {})

    def run(
        self, out_target=None, resume: bool = False, progress: Callable[[int, int], Any] | None = None
    ) -> list[list[Any]] | None:
        """Run every run not already in the output: rows (lists in :attr:`columns` order) when
        the sweep has at most :data:`MAX_ROWS_SHOWN` runs, else None (they are in the output).

        out_target: a checked output (:func:`rbi.files.output.output_target`) the rows stream
        to, or None. resume: continue the sweep already there. progress: called with ``(runs
        done, runs)`` once the output is open, as rows arrive, and after an interruption (any
        exception) with the runs the output kept: the output is closed keeping the rows
        written, and :attr:`output` tells how many.
        """
        require_callable(progress=progress)
        compute = self._compute()
        rows: list | None = [] if self.plan.size <= MAX_ROWS_SHOWN else None
        tell = progress or (lambda done, total: None)
        done = [0]

        def on_rows(new_rows):
            if self.output is not None:
                self.output.write(new_rows)
            if rows is not None:
                rows.extend(new_rows)
            done[0] += len(new_rows)
            tell(done[0], self.plan.size)

        self.output, kept = None, []
        if out_target is not None:
            self.output = store.SweepOutput(out_target, self.columns, self.plan, self.store_settings())
            kept = self.output.open(resume, keep=rows is not None)
        try:  # from here on the output is closed, keeping its rows, whatever stops the sweep
            done[0] = 0 if self.output is None else self.output.done
            if rows is not None:
                rows.extend(kept)
            tell(done[0], self.plan.size)
            ranges = self._chunks(done[0])
            if self.settings.dask is not None:
                execute.run_dask(compute, ranges, self.settings.dask, on_rows, self.settings.workers)
            else:
                execute.run_local(compute, ranges, execute.usable_workers(self.settings.workers), on_rows)
        except BaseException:
            if self.output is not None:
                self.output.close()  # what was written is kept (a failed write has said how much)
                tell(self.output.done, self.plan.size)
            raise
        if self.output is not None:
            self.output.finish()
        return rows

    def stability_map(self, rows: list[list[Any]]) -> dict[str, Any]:
        """The data of the stability map: the largest tilt over the first one or two swept axes,
        and the sleeping threshold (rad/s) when the first one is the spin (else None)."""
        if self.settings.mass_properties:
            raise ArgumentError("plot", "a map needs simulated runs (not {mass_properties})")
        # a grid axis of several values, or a value drawn afresh for each of several runs
        swept = [a.name for a in self.plan.axes if (self.plan.runs if isinstance(a, Draw) else a.count) > 1]
        if not swept:
            raise ArgumentError("plot", "the map needs at least one axis with more than one value")
        threshold = None
        if swept[0] == "spin":
            scene = self.nominal_scene()
            try:
                found = None if scene is None else sleeping_threshold(scene)
            except ValueError:
                found = None
            threshold = None if found is None else found["omega3"]
        x_name, y_name = swept[0], swept[1] if len(swept) > 1 else None
        index = {name: i for i, name in enumerate(self.columns)}
        return {
            "x": [r[index[x_name]] for r in rows],
            "y": [r[index[y_name]] for r in rows] if y_name else None,
            "values": [r[index["max_tilt_deg"]] for r in rows],
            "x_label": _label(x_name),
            "y_label": _label(y_name) if y_name else None,
            "threshold": threshold,
            "title": f"{self.nominal.name or self.job.path}: largest tilt over {self.job.duration:g} s",
        }


def _plan(axes, settings: SweepSettings, rows_printed: bool):

    if settings.runs > 1 and not any(isinstance(a, Draw) for a in axes):
        raise ArgumentError(
            "runs", "Monte Carlo needs a {vary} path drawn from a normal or uniform distribution"
        )
    plan = Plan(tuple(axes), runs=settings.runs, seed=settings.seed)
    if plan.size > MAX_RUNS:
        raise ArgumentError((), f"the sweep has {plan.size:.3g} runs, more than the 1e8 one sweep may have")
    if rows_printed and plan.size > MAX_ROWS_SHOWN:
        raise ArgumentError(
            (),
            f"the sweep has {plan.size:,} runs: more than {MAX_ROWS_SHOWN:,} are written to a file "
            "only: give {out} (a .csv or .parquet file)",
        )
    return plan


def _axis(name: str, value: Any, parameter: str | None = None):
    """The axis ``name`` of the value given to ``parameter`` (default: ``name``)."""

    try:
        return axis_of(name, value)
    except (TypeError, ValueError) as exc:
        if parameter is None:
            raise ArgumentError(name, literal(exc, quoted=False)) from None
        raise ArgumentError(parameter, literal(exc, quoted=False), item=name) from None


def _label(name: str) -> str:
    """A map axis's label, unit in brackets as on every other picture: the ``tilt_deg`` column
    holds each run's nudge at t = 0 (``--tilt``), not the tilt of its spin axis then (90° for
    a gyroscope on its side with no nudge)."""
    return {"spin": "spin [rad/s]", "tilt_deg": "nudge at t = 0 [deg]"}.get(name, name)


def _file_sha256(path: str) -> str:
    """The SHA-256 of a file the spec reads, as it is now (a regular file, never followed
    through a link nor waited on)."""
    with os.fdopen(safe.open_regular(path, f"{path}: cannot resume"), "rb") as handle:
        return hashlib.file_digest(handle, "sha256").hexdigest()
