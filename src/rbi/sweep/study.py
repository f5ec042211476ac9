"""A whole sweep of one spec, below the CLI and the API: the settings checked, the plan of runs
built, the runs executed (local cores or a Dask cluster) and streamed to an output file, and the
result `rbi sweep` prints.

:class:`SweepSettings` holds what the user chose; :func:`check_settings` and
:func:`check_mass_properties` refuse bad settings before any file is read; :class:`Study`
plans the sweep of a parsed spec and runs it. Messages name the CLI's options (``--runs``,
``--vary`` ...), so `rbi sweep` and :func:`rbi.sweep` report a mistake with the same line.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rbi.errors import InputError

MAX_ROWS_SHOWN = 100_000
"""Most runs a sweep may print (json/csv/table) or hold in memory instead of writing them with --out."""

MAX_RUNS = 10**8
"""Most runs one sweep may have."""

SWEEP_STEP_BUDGET = 2e10
"""Most integration steps a whole sweep is estimated to take before --yes is needed (about
four hours of one core)."""

MAX_SWEEP_SAMPLES = 100_000
"""Most samples per run of a sweep."""


@dataclass(frozen=True)
class SweepSettings:
    """The settings of a sweep, as the CLI's options spell them.

    spin, tilt: ``"START:STOP:COUNT"`` or one value (rad/s about the spin axis; the nudge in
    degrees), None for 0. spin_axis: ``x|y|z|X,Y,Z`` (body frame), None for the spec's
    ``spin_axis`` or the nominal body's default (:func:`rbi.core.spin_axis.default_spin_axis`). vary: ``"PATH=RANGE"`` items (``parts.NAME.FIELD[i]=START:STOP:COUNT``,
    ``=normal(MEAN,SD)`` or ``=uniform(LOW,HIGH)``). runs: Monte Carlo draws per grid point;
    seed: of the draws. duration (s), samples, rtol, gravity (m/s², None for 9.81), tilt_axis,
    max_steps (per run, None for the default): as a single simulation. workers: cores (None:
    all); dask: a scheduler address or ``"local"``. mass_properties: no simulation, the spread
    of the mass properties over the varied values. yes: run even past the step budget.
    """

    spin: str | None = None
    tilt: str | None = None
    vary: tuple[str, ...] = ()
    runs: int = 1
    seed: int = 0
    duration: float = 4.0
    samples: int = 481
    rtol: float = 1e-12
    gravity: float | None = None
    tilt_axis: str = "y"
    max_steps: int | None = None
    workers: int | None = None
    dask: str | None = None
    mass_properties: bool = False
    yes: bool = False
    spin_axis: str | None = None


def check_settings(settings: SweepSettings) -> None:
    """Refuse the number of runs, the run settings, the samples and the workers (before any file
    is read)."""
    from rbi.runs.settings import check_run_settings

    if settings.runs < 1:
        raise InputError(f"--runs: must be at least 1 (got {settings.runs})")
    check_run_settings(
        settings.duration, settings.tilt_axis, settings.gravity, settings.max_steps, settings.rtol
    )
    if not 1 <= settings.samples <= MAX_SWEEP_SAMPLES:
        raise InputError(
            f"--samples: must be between 1 and {MAX_SWEEP_SAMPLES:,} for a sweep (got {settings.samples})"
        )
    from rbi.runs.prepare import spin_axis_value

    spin_axis_value(settings.spin_axis)
    if settings.workers is not None and not 1 <= settings.workers <= 1024:
        raise InputError(f"--workers: must be between 1 and 1024 (got {settings.workers})")
    if settings.dask is not None:
        from rbi.sweep.execute import check_address

        check_address(settings.dask)


def check_mass_properties(settings: SweepSettings) -> None:
    """A mass-property study simulates nothing: it takes no spin and no tilt."""
    if settings.mass_properties and (settings.spin not in (None, "0") or settings.tilt not in (None, "0")):
        raise InputError("--mass-properties: takes --vary only (no --spin or --tilt: nothing is simulated)")


def require(module: str, extra: str, option: str) -> None:
    """:class:`InputError` with the install command when an optional package is missing."""
    import importlib.util

    if importlib.util.find_spec(module) is None:
        raise InputError(
            f"{option}: needs the optional package {module!r}: pip install '.[{extra}]' from rbi's "
            f"source folder, or pip install {module}"
        )


class Study:
    """The planned sweep of one parsed spec.

    path: the spec (for messages, the files it names and the resume check); raw: its parsed
    YAML; settings: :class:`SweepSettings` (checked). After construction: ``plan`` (the runs),
    ``job`` (:class:`~rbi.sweep.runs.SweepJob`), ``nominal`` (the body at the spec's own
    values), ``columns`` (of each row). :class:`InputError` for a sweep that cannot be made.
    """

    def __init__(self, path: str, raw: Any, settings: SweepSettings, *, rows_printed: bool = True) -> None:
        from rbi.sim.budget import DEFAULT_MAX_STEPS
        from rbi.spec.units import STANDARD_GRAVITY_SI
        from rbi.spec.variations import current_values
        from rbi.sweep.runs import SweepJob

        self.path, self.raw, self.settings = path, raw, settings
        axes, varied = self._axes()
        self.plan = _plan(axes, settings, rows_printed)
        self.job = SweepJob(
            path=str(path),
            raw=raw,
            plan=self.plan,
            varied=tuple(varied),
            duration=float(settings.duration),
            samples=int(settings.samples),
            rtol=float(settings.rtol),
            gravity_si=STANDARD_GRAVITY_SI if settings.gravity is None else float(settings.gravity),
            tilt_axis=settings.tilt_axis.lower(),
            max_steps=DEFAULT_MAX_STEPS if settings.max_steps is None else int(settings.max_steps),
        )
        self.nominal = self.job.body(tuple(current_values(raw, varied)))
        if isinstance(self.nominal, str):
            raise InputError(f"{path}: {self.nominal}")
        self.job = dataclasses.replace(self.job, spin_axis=self._spin_axis())
        if settings.mass_properties:
            from rbi.sweep.tolerance import MASS_COLUMNS

            self.columns = ["run", *self.plan.names, *MASS_COLUMNS]
        else:
            self._check_budget()
            self.columns = self.job.columns
        self.output = None
        """The :class:`~rbi.sweep.store.SweepOutput` while :meth:`run` writes one (its ``done``
        counts the runs kept there)."""

    def _axes(self):
        from rbi.spec.variations import resolve
        from rbi.sweep.plan import parse_axis

        s = self.settings
        axes = (
            []
            if s.mass_properties
            else [
                _axis(parse_axis, "spin", s.spin or "0", "--spin"),
                _axis(parse_axis, "tilt_deg", s.tilt or "0", "--tilt"),
            ]
        )
        varied = []
        for item in s.vary:
            path_text, sep, range_text = item.partition("=")
            if not sep:
                raise InputError(f"--vary {item}: expected PATH=RANGE, e.g. parts.bolt.mass=0.01:0.03:5")
            path_text = path_text.strip()
            try:
                varied.append(resolve(self.raw, path_text))
            except InputError as exc:
                raise InputError(f"{self.path}: {exc}") from None
            axes.append(_axis(parse_axis, path_text, range_text, f"--vary {path_text}"))
        names = [a.name for a in axes]
        if len(set(names)) != len(names):
            raise InputError("--vary: a path is given twice")
        if s.mass_properties and not varied:
            raise InputError("--mass-properties: give at least one --vary PATH=RANGE")
        return axes, varied

    def _check_budget(self) -> None:
        """Refuse, before any run, a sweep estimated to take more than the step budget."""
        import numpy as np

        from rbi.sim.budget import estimated_steps

        scene = self.nominal_scene()
        if scene is None:
            return  # every run will say why it cannot be simulated
        spins = [a for a in self.plan.axes if a.name == "spin"][0]
        fastest = max(abs(spins.start), abs(spins.stop)) if hasattr(spins, "start") else 0.0
        per_run = estimated_steps(
            scene, np.array([0.0, 0.0, fastest]), self.job.duration, "default", self.job.rtol
        )
        total = per_run * self.plan.size
        if total > SWEEP_STEP_BUDGET and not self.settings.yes:
            raise InputError(
                f"{self.job.path}: this sweep is estimated to need about {total:.2g} integration steps "
                f"({self.plan.size:,} runs), more than the budget of {SWEEP_STEP_BUDGET:.0e}: fewer runs, "
                "a shorter --duration or a looser --rtol, or --yes to run it anyway"
            )

    def nominal_scene(self):
        """The scene of the nominal body, or None when it cannot be simulated."""
        from rbi.sim.scene import scene_from_properties
        from rbi.spec.units import gravity_in

        body = self.nominal
        try:
            return scene_from_properties(
                body.props, body.pivot, gravity_in(body.length_unit, self.job.gravity_si), self.job.spin_axis
            )
        except ValueError:
            return None

    def _spin_axis(self) -> tuple[float, float, float]:
        """The one spin axis of every run (unit, body frame): ``--spin-axis``, else the spec's
        ``spin_axis``, else the nominal body's default, so that every row's tilt is of the same
        body axis even where a varied value breaks the body's symmetry."""
        from rbi.runs.prepare import body_spin_axis

        return tuple(float(c) for c in body_spin_axis(self.nominal, self.settings.spin_axis))

    def _compute(self):
        """``(compute(start, stop, threads) -> rows, chunk size)`` for the executors."""
        job = self.job
        if self.settings.mass_properties:
            from rbi.sweep.tolerance import mass_rows, nominal_axes

            axes_nominal = nominal_axes(job)

            def compute(a, b, threads):
                return mass_rows(job, axes_nominal, a, b)

            return compute, 256
        from rbi.sweep.execute import available_cores
        from rbi.sweep.runs import run_chunk

        def compute(a, b, threads):
            return run_chunk(job, a, b, threads)

        return compute, job.chunk_size(self.settings.workers or available_cores())

    def store_settings(self) -> dict:
        """What makes two sweeps the same, for ``--resume``: the spec's bytes (or its parsed
        form when it was given as text or a dict) and every setting."""
        s, job = self.settings, self.job
        try:
            spec_bytes = Path(self.path).read_bytes()
        except OSError:
            spec_bytes = json.dumps(self.raw, sort_keys=True, default=str).encode()
        return {
            "spec_sha256": hashlib.sha256(spec_bytes).hexdigest(),
            "spin": s.spin or "0",
            "tilt": s.tilt or "0",
            "vary": list(s.vary),
            "runs": job.plan.runs,
            "seed": job.plan.seed,
            "duration": job.duration,
            "samples": job.samples,
            "rtol": job.rtol,
            "gravity_si": job.gravity_si,
            "tilt_axis": job.tilt_axis,
            "spin_axis": list(job.spin_axis),
            "max_steps": job.max_steps,
            "mass_properties": s.mass_properties,
        }

    def run(
        self, out_target=None, resume: bool = False, progress: Callable[[int, int], Any] | None = None
    ) -> list[list[Any]] | None:
        """Run every run not already in the output: rows (lists in :attr:`columns` order) when
        the sweep has at most :data:`MAX_ROWS_SHOWN` runs, else None (they are in the output).

        out_target: a checked output (:func:`rbi.files.output.output_target`) the rows stream
        to, or None. resume: continue the sweep already there. progress: called with ``(total,
        done before this run)`` once, returning an object whose ``update(done)`` is called as
        rows arrive and ``close()`` at the end. An interruption (any exception) closes the
        output keeping the rows written; :attr:`output` then tells how many.
        """
        from rbi.sweep import store
        from rbi.sweep.execute import available_cores, chunk_ranges, run_dask, run_local

        compute, chunk = self._compute()
        rows: list | None = [] if self.plan.size <= MAX_ROWS_SHOWN else None
        start = 0
        if out_target is not None:
            self.output = store.SweepOutput(out_target, self.columns, self.plan, self.store_settings())
            kept = self.output.open(resume, keep=rows is not None)
            start = self.output.done
            if rows is not None:
                rows.extend(kept)
        bar = progress(self.plan.size, start) if progress is not None else None
        done = [start]

        def on_rows(new_rows):
            if self.output is not None:
                self.output.write(new_rows)
            if rows is not None:
                rows.extend(new_rows)
            done[0] += len(new_rows)
            if bar is not None:
                bar.update(done[0])

        try:
            ranges = chunk_ranges(start, self.plan.size, chunk)
            if self.settings.dask is not None:
                run_dask(compute, ranges, self.settings.dask, on_rows, self.settings.workers)
            else:
                run_local(compute, ranges, self.settings.workers or available_cores(), on_rows)
        except BaseException:
            if self.output is not None:
                self.output.close()  # what was written is kept (a failed write has said how much)
            raise
        finally:
            if bar is not None:
                bar.close()
        if self.output is not None:
            self.output.finish()
        return rows

    def result(self, rows: list[list[Any]] | None) -> dict[str, Any]:
        """What `rbi sweep --format json` prints: name, units, count, columns and, when the rows
        were held, the runs as objects, how many failed and (mass properties) their spread."""
        result = {
            "name": self.nominal.name,
            "units": self.nominal.units,
            "warnings": list(self.nominal.warnings),
            "count": self.plan.size,
            "columns": self.columns,
        }
        if rows is not None:
            result["runs"] = [dict(zip(self.columns, r)) for r in rows]
            result["failed"] = self.plan.size - sum(1 for r in rows if r[-1] == "ok")
        return result

    def spread(self, rows: list[list[Any]]) -> dict[str, dict[str, float]]:
        """Percentiles and standard deviation of each mass property over the ok runs."""
        from rbi.sweep.tolerance import spread

        return spread(self.columns, rows, 1)

    def stability_map(self, rows: list[list[Any]]) -> dict[str, Any]:
        """The data of the stability map: the largest tilt over the first one or two swept axes,
        and the sleeping threshold (rad/s) when the first one is the spin (else None)."""
        if self.settings.mass_properties:
            raise InputError("--plot: a map needs simulated runs (not --mass-properties)")
        swept = [a.name for a in self.plan.axes if self.plan.is_grid_axis(a.name)]
        if not swept:
            raise InputError("--plot: the map needs at least one axis with more than one value")
        threshold = None
        if swept[0] == "spin":
            from rbi.sim.diagnostics import sleeping_threshold

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
    from rbi.sweep.plan import Draw, Plan

    if settings.runs > 1 and not any(isinstance(a, Draw) for a in axes):
        raise InputError("--runs: Monte Carlo needs a --vary PATH=normal(MEAN,SD) or uniform(LOW,HIGH)")
    if settings.seed < 0:
        raise InputError(f"--seed: must be a whole number 0 or above (got {settings.seed})")
    plan = Plan(tuple(axes), runs=settings.runs, seed=settings.seed)
    if plan.size > MAX_RUNS:
        raise InputError(f"the sweep has {plan.size:.3g} runs, more than the 1e8 one sweep may have")
    if rows_printed and plan.size > MAX_ROWS_SHOWN:
        raise InputError(
            f"the sweep has {plan.size:,} runs: more than {MAX_ROWS_SHOWN:,} are written to a file "
            "only: add --out FILE.csv"
        )
    return plan


def _axis(parse, name, text, option):
    try:
        return parse(name, text)
    except ValueError as exc:
        raise InputError(f"{option}: {exc}") from None


def _label(name: str) -> str:
    return {"spin": "spin, rad/s", "tilt_deg": "initial tilt, deg"}.get(name, name)
