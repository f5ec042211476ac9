"""Sweeps: `sweep` a body over settings and spec values, its `SweepTable`."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from rbi.api.body import Body, loaded_body
from rbi.api.outputs import Destination, checked_output, keywords_checked
from rbi.errors import ArgumentError
from rbi.files.output import OutputTarget
from rbi.reprs import TableRepr, pandas_module
from rbi.spec.load import read_spec
from rbi.sweeps.study import Study, SweepSettings, check_settings
from rbi.text import number

if TYPE_CHECKING:  # served by rbi.api's __getattr__ on first use (the sweep's modules load then)
    from rbi.sweeps.plan import Grid, Normal, Uniform


class SweepTable(TableRepr):
    """The rows of a sweep, one per run in run order: ``len(table)`` runs, each column by name
    as a numpy array (``table["max_tilt_deg"]``; float columns hold NaN where a failed run has
    no value, ``status`` holds text), ``table.columns`` their names, ``table.records()`` the
    rows as dicts (as ``rbi sweep --format json`` prints ``runs``), ``table.to_pandas()``.

    Attributes:
        columns: the column names: ``run``, the swept values (``spin``, ``tilt_deg``, each
            varied path), then the results.
        count: the runs of the sweep; held: whether the table holds their rows (a sweep of
            more than 100,000 runs keeps them in its ``out`` file only).
        name, units, warnings: of the nominal body.
        failed: how many runs failed (their ``status`` says why).
        spread: with ``mass_properties``, each quantity's percentiles (``p0``, ``p50``,
            ``p100``...) and standard deviation over the ok runs; else None.
    """

    def __init__(self, study: Any, rows: Sequence[Sequence[Any]] | None, body: Body) -> None:
        nominal = study.nominal
        self._body = body  # the swept Body: no map replaces a file it was read from
        self.columns: list[str] = list(study.columns)
        self.count: int = study.plan.size
        self.held = rows is not None
        self._rows = [list(row) for row in rows or []]
        self._study = study
        self.name: str | None = nominal.name
        self.units: dict[str, str] = dict(nominal.units)
        self.warnings: list[str] = list(nominal.warnings)
        mass_properties = study.settings.mass_properties and self.held
        self.spread: dict[str, dict[str, float]] | None = (
            study.spread(self._rows) if mass_properties else None
        )
        self.failed = sum(1 for row in self._rows if row[-1] != "ok")

    def plot(self, path: Destination) -> None:
        """Draw the stability map at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib),
        as ``rbi sweep --plot`` does: the largest tilt (degrees) over the first one or two
        swept axes, and the nominal top's sleeping threshold (rad/s) when the first is the spin.
        ValueError for a sweep of mass properties, with nothing swept, or whose rows are not held."""
        from rbi.viz.plots import plot_map  # matplotlib loads only to draw

        if not self.held:
            raise ArgumentError("plot", "the map is drawn from the rows, and this table does not hold them")
        plot_map(
            self._study.stability_map(self._rows), checked_output(path, ("png", "svg", "pdf"), self._body)
        )

    def __len__(self) -> int:
        return len(self._rows)

    def __iter__(self) -> Iterator[str]:
        return iter(self.columns)

    def keys(self) -> list[str]:
        """The column names (so ``dict(table)`` maps each to its array)."""
        return list(self.columns)

    def __getitem__(self, column: str) -> np.ndarray:
        if column not in self.columns:
            raise KeyError(f"{column!r}: no such column (columns: {', '.join(self.columns)})")
        i = self.columns.index(column)
        values = [row[i] for row in self._rows]
        if any(isinstance(v, str) for v in values):
            return np.array(values, dtype=object)
        if column in ("run", "steps") and None not in values:
            return np.array(values, dtype=np.int64)
        return np.array([np.nan if v is None else v for v in values], dtype=float)

    def records(self) -> list[dict[str, Any]]:
        """One dict per run, column name → value (None where a failed run has none)."""
        return [dict(zip(self.columns, row)) for row in self._rows]

    def to_dict(self) -> dict[str, Any]:
        """What ``rbi sweep --format json`` prints (JSON-ready, less the files it wrote): name,
        units, warnings, count, columns and, when the rows are held, the runs as objects and
        how many failed; a study of mass properties adds each quantity's ``spread``."""
        result: dict[str, Any] = dict(
            name=self.name, units=self.units, warnings=self.warnings, count=self.count
        )
        result["columns"] = self.columns
        if self.held:
            result |= {"runs": self.records(), "failed": self.failed}
        if self.spread is not None:
            result["spread"] = self.spread
        return result

    def csv_rows(self) -> list[dict[str, Any]]:
        """One row per run (``rbi sweep --format csv``)."""
        return self.records()

    def to_pandas(self) -> Any:
        """The table as a :class:`pandas.DataFrame`, one row per run, the columns in order."""
        return pandas_module(self).DataFrame(self.records(), columns=self.columns)

    def __repr__(self) -> str:
        return f"<rbi.SweepTable {len(self)} runs × {len(self.columns)} columns, {self.failed} failed>"

    def _table(self) -> tuple[str, list[list[str]], list[str]]:
        shown: list[list[Any] | None] = list(self._rows)
        if len(shown) > 20:
            shown = shown[:10] + [None] + shown[-10:]
        rows = [
            ["…"] * len(self.columns)
            if row is None
            else [v if isinstance(v, str) else number(v) for v in row]
            for row in shown
        ]
        return f"{self.name or 'sweep'} — {len(self)} runs, {self.failed} failed", rows, self.columns


if TYPE_CHECKING:
    AxisValues = float | Sequence[float] | np.ndarray | Grid | Normal | Uniform
    """A sweep axis: one value, the grid's values, or a draw per run."""


@keywords_checked
def sweep(
    body: Body | str | os.PathLike[str],
    *,
    spin: AxisValues = 0.0,
    tilt_deg: AxisValues = 0.0,
    vary: Mapping[str, AxisValues] | None = None,
    runs: int = 1,
    seed: int = 0,
    duration: float = 4.0,
    samples: int = 481,
    rtol: float = 1e-12,
    gravity: float | None = None,
    tilt_axis: str = "y",
    max_steps: int | None = None,
    spin_axis: str | Sequence[float] | None = None,
    workers: int | None = None,
    dask: str | None = None,
    mass_properties: bool = False,
    check_budget: bool = True,
    out: Destination | None = None,
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> SweepTable:
    """Many simulations of one body — a grid over spin, tilt and numbers of the spec, or Monte
    Carlo draws — as ``rbi sweep`` runs them (on every core). A failed run never stops the
    others: its row says why in ``status``. Returns a `SweepTable`. ``duration``, ``samples``,
    ``rtol``, ``gravity``, ``tilt_axis``, ``max_steps`` and ``spin_axis`` are `simulate`'s, per run.

    Args:
        body: the `Body`, or its spec file's path (the spec is varied; files it names are read beside it).
        spin: initial spin about the spin axis, rad/s: one number, the grid's values (numbers,
            or ``Grid(start, stop, count)``), or a draw per run: ``Normal(mean, sd)``, ``Uniform(low, high)``.
        tilt_deg: the nudge at t = 0, degrees, given the same way.
        vary: numbers of the spec, path → values given as ``spin``'s:
            ``{"parts.bolt.mass": [0.01, 0.02]}``, ``{"parts.bolt.position[0]": Normal(0.04, 0.001)}``.
        runs: Monte Carlo draws of every `Normal`/`Uniform` per grid point.
        seed: the seed of the draws.
        workers: cores to use (None: all).
        dask: instead, a Dask scheduler's address, or ``"local"``.
        mass_properties: simulate nothing: each row gives the mass properties at the varied values.
        check_budget: refuse a sweep estimated past rbi's step budget (about four core-hours).
        out: stream the rows to this ``.csv`` or ``.parquet`` file (only there past 100,000 runs).
        resume: continue the sweep already in ``out``.
        progress: called with (runs done, runs).

    Raises:
        ValueError, TypeError: a setting or a variation is invalid (named as this function's
            parameter), or the sweep has more than 100,000 runs and no ``out``.
    """
    grid = (spin, tilt_deg, _variations(vary), runs, seed, duration, samples, rtol, gravity, tilt_axis)
    settings = SweepSettings(*grid, max_steps, workers, dask, mass_properties, check_budget, spin_axis)
    check_settings(settings)
    path, raw, spec_bytes = _spec_source(body)
    target = _target(out, resume, body if isinstance(body, Body) else path)  # a Body: every file it read
    study = Study(path, raw, settings, rows_printed=out is None, spec_bytes=spec_bytes)
    swept, target = _swept(body, study, out, target)
    return SweepTable(study, study.run(target, resume, progress), swept)


def _target(out: Destination | None, resume: bool, read: Body | str) -> OutputTarget | None:
    """`sweep`'s ``out`` checked (never a file the body is read from: a `Body`'s every file);
    ``resume`` needs it."""
    if out is None and resume:
        raise ArgumentError("resume", "needs {out}, the file of the interrupted sweep")
    return None if out is None else checked_output(out, ("csv", "parquet"), read, "out")


def _swept(
    body: Any, study: Any, out: Destination | None, target: OutputTarget | None
) -> tuple[Body, OutputTarget | None]:
    """`sweep`'s `Body` and ``out``'s target. For a spec path, the nominal body the study has
    just translated, whose files are known only now: ``out`` is checked again against each
    file it was read from (`Body.files_read`), before any run."""
    if isinstance(body, Body):
        return body, target
    nominal = Body(study.nominal, study.raw, study.spec_bytes)
    return nominal, None if out is None else checked_output(out, ("csv", "parquet"), nominal, "out")


def _variations(vary: Any) -> tuple[tuple[str, Any], ...]:
    """`sweep`'s ``vary`` as (path, values) pairs."""
    if vary is not None and not isinstance(vary, Mapping):
        raise TypeError(f"vary: expected a mapping of spec paths to values, got {type(vary).__name__}")
    return tuple((str(path), value) for path, value in (vary or {}).items())


def _spec_source(body: Any) -> tuple[str, Any, bytes | None]:
    """`sweep`'s ``body`` as (path, parsed spec, the bytes of its file as read: None for text, a
    dict or standard input): a `Body`'s, or a spec file read once (a sweep validates each varied
    spec, not the file as it stands, and hashes those bytes for ``resume``)."""
    if isinstance(body, (str, os.PathLike)):
        path = os.fsdecode(os.fspath(body))
        return (path, *read_spec(path))
    return loaded_body(body, "body").path, body._raw, body._spec_bytes
