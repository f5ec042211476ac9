"""Sweeps: `sweep` a body over settings and spec values, its `SweepTable`."""

from __future__ import annotations

import contextlib
import importlib.util
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from rbi.api.body import Body, loaded_body
from rbi.api.outputs import PLOT_FORMATS, as_parameter, checked_output, keywords_checked, out_and_plot
from rbi.core.validity import require_flags
from rbi.errors import ArgumentError
from rbi.files.output import Destination, OutputTarget
from rbi.reprs import Result, Rows, pandas_module
from rbi.spec.load import read_spec, spec_label
from rbi.spec.units import unit_labels
from rbi.sweeps.study import MAX_ROWS_SHOWN, Study, SweepSettings, check_settings
from rbi.sweeps.tolerance import spread as spread_over
from rbi.text import number
from rbi.viz.plots import plot_stability_map

if TYPE_CHECKING:  # served by rbi.api's __getattr__ on first use (the sweep's modules load then)
    from rbi.sweeps.plan import Grid, Normal, Uniform

UNITS = {
    "spin": "rad/s",
    "precession_rate_deg_s": "deg/s",
    "energy_drift": "relative",
}
"""The unit of each summary column not named by its field (``..._deg`` is in degrees)."""

_LENGTH_FIELDS = frozenset(
    "radius inner_radius outer_radius start_radius end_radius major_radius minor_radius length height "
    "size semi_axes position center start end apex base through step pivot center_of_mass com".split()
)
_INERTIA_FIELDS = frozenset("ixx iyy izz ixy ixz iyz inertia moment".split())

SHOWN_ROWS = 40
"""Most runs a table shows: past them, the first and last half of them."""
HIDDEN = frozenset({"min_tilt_deg", "precession_rate_deg_s", "steps"})
"""Columns of --out, json and csv that the table leaves out, to fit 80 columns."""


class SweepTable(Result):
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
        out: the file the rows were written to (as given), or None.
        cores: the cores the runs used on this machine (``workers``, at most the machine's;
            None on a Dask cluster).
    """

    json_keys = ("name", "units", "warnings", "count", "columns")

    def __init__(
        self, study: Any, rows: Sequence[Sequence[Any]] | None, body: Body, out: OutputTarget | None = None
    ) -> None:
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
            spread_over(self.columns, self._rows, 1) if mass_properties else None
        )
        if self.spread:  # varied values of absurd size (normal(1, 1e308)) overflow the statistics
            body._refuse_non_finite(spread=[list(stats.values()) for stats in self.spread.values()])
        self.failed = sum(1 for row in self._rows if row[-1] != "ok")
        self.out = None if out is None else out.given
        self.cores: int | None = study.cores
        self._drawn: str | None = None  # where plot() drew the map

    def plot(self, path: Destination) -> None:
        """Draw the stability map at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib),
        as ``rbi sweep --plot`` does: the largest tilt (degrees) over the first one or two
        swept axes, and the nominal top's sleeping threshold (rad/s) when the first is the spin.
        ValueError for a sweep of mass properties, with nothing swept, or whose rows are not held."""
        if not self.held:
            raise ArgumentError("plot", "the map is drawn from the rows, and this table does not hold them")
        target = checked_output(path, PLOT_FORMATS, self._body)
        plot_stability_map(target=target, **self._study.stability_map(self._rows))
        self._drawn = target.given

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

    def unit(self, column: str) -> str:
        """The unit of a column or a spread quantity in the body's units: a summary's
        (``deg``, ``rad/s``...), or a varied spec field's (``parts.bolt.mass`` in the mass unit,
        ``parts.bolt.position[0]`` in the length unit, ``...angle_deg`` in degrees); empty for
        a number without one (a run number, a direction, a count)."""
        if column in UNITS:
            return UNITS[column]
        field = column.rsplit(".", 1)[-1].split("[", 1)[0]
        kind = field.split("_")[0] if field.startswith(("com_", "moment_")) else field
        if kind in _INERTIA_FIELDS:
            kind = "inertia"
        elif kind in _LENGTH_FIELDS:
            kind = "length"
        if kind in ("mass", "density", "inertia", "length"):  # as the body's unit labels write them
            return unit_labels(self.units["length"], self.units["mass"])[kind]
        return "deg" if field.endswith("_deg") else ""

    def to_dict(self) -> dict[str, Any]:
        """What ``rbi sweep --format json`` prints (JSON-ready): name, units, warnings, count,
        columns and, when the rows are held, the runs as objects and how many failed; the
        ``out`` file; a study of mass properties adds each quantity's ``spread``; the map's
        file (``plot``) once drawn."""
        result = self.json_fields()
        if self.held:
            result |= {"runs": self.records(), "failed": self.failed}
        given = {"out": self.out, "spread": self.spread, "plot": self._drawn}
        return result | {key: value for key, value in given.items() if value is not None}

    def csv_rows(self) -> list[dict[str, Any]]:
        """One row per run (``rbi sweep --format csv``)."""
        return self.records()

    def to_pandas(self) -> Any:
        """The table as a :class:`pandas.DataFrame`, one row per run, the columns in order."""
        return pandas_module(self).DataFrame(self.records(), columns=self.columns)

    def __repr__(self) -> str:
        return f"<rbi.SweepTable {len(self)} runs × {len(self.columns)} columns, {self.failed} failed>"

    def rows(self) -> list[Rows]:
        """The table ``print()``, a notebook and ``rbi sweep`` show: a study's spread of the
        mass properties (min, median, max, standard deviation) or the runs (the first and last
        20 of more than 40)."""
        if self.spread:
            stats = ("p0", "p50", "p100", "std")
            cells = [(k, self.unit(k), *(number(s[q], 4) for q in stats)) for k, s in self.spread.items()]
            columns = ("quantity", "unit", "min", "median", "max", "std")
            return [Rows("Spread over the ok runs", columns, cells, left=2)]
        half = SHOWN_ROWS // 2
        shown = self._rows if len(self) <= SHOWN_ROWS else [*self._rows[:half], None, *self._rows[-half:]]
        keep = [i for i, name in enumerate(self.columns) if name not in HIDDEN]
        cells = [tuple("…" if row is None else _cell(row[i]) for i in keep) for row in shown]
        headers = tuple(self._header(self.columns[i]) for i in keep)
        title = f"{self.name or self._body.path} — sweep"
        return [Rows(title, headers, cells, left=0, kind="parts", text_last=True)]  # numbers never wrap

    def _header(self, column: str) -> str:
        """A column's header over its unit: ``max tilt`` over ``deg``; a spec field as written."""
        words = column.removesuffix("_deg_s").removesuffix("_deg").replace("_", " ")  # the unit is below
        return "\n".join(filter(None, (column if column.startswith("parts.") else words, self.unit(column))))

    def notes(self) -> list[str]:
        """The lines ``rbi sweep`` prints under its table: the runs, the files written."""
        failed = f", {self.failed:,} failed" if self.held else ""
        notes = [f"{self.count:,} runs{failed}"]
        notes += [] if self.out is None else [f"Rows written to {self.out}."]
        return notes + ([] if self._drawn is None else [f"Map drawn in {self._drawn}."])


def _cell(value: Any) -> str:
    """A run's value in a table: text and whole numbers as they are, numbers to 4 digits."""
    return value if isinstance(value, str) else str(value) if isinstance(value, int) else number(value, 4)


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
    plot: Destination | None = None,
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
        workers: cores to use (None: all; more than this machine gives are not used).
        dask: instead, a Dask scheduler's address, or ``"local"``.
        mass_properties: simulate nothing: each row gives the mass properties at the varied values.
        check_budget: refuse a sweep estimated past rbi's step budget (about four core-hours).
        out: stream the rows to this ``.csv`` or ``.parquet`` file (only there past 100,000 runs).
        resume: continue the sweep already in ``out``.
        plot: draw the stability map there once the runs are done, as `SweepTable.plot` does.
        progress: called with (runs done, runs).

    Raises:
        ValueError, TypeError: a setting or a variation is invalid (named as this function's
            parameter), or the sweep has more than 100,000 runs and no ``out``.
    """
    settings = SweepSettings.of(locals() | {"vary": _variations(vary)})
    check_settings(settings)
    study, body, (out_target, plot_target) = _study(body, settings, out, plot, resume)
    with contextlib.nullcontext() if out_target is None else as_parameter("out"):  # its messages say out
        rows = study.run(out_target, resume, progress)
    table = SweepTable(study, rows, body, out_target)
    if plot_target is not None:
        table.plot(plot_target)
    return table


def _study(
    body: Any, settings: SweepSettings, out: Destination | None, plot: Destination | None, resume: bool
) -> tuple[Study, Body, tuple[OutputTarget | None, OutputTarget | None]]:
    """`sweep`'s planned study, its `Body` and its outputs, checked before any run. For a spec
    path, the body is the nominal one the study has just translated, whose files are known
    only now: the outputs are checked against the spec first, then against every file it read."""
    path, raw, spec_bytes = _spec_source(body)
    _targets(out, plot, resume, body if isinstance(body, Body) else path)
    study = Study(path, raw, settings, rows_printed=out is None, spec_bytes=spec_bytes)
    if not isinstance(body, Body):
        body = Body(study.nominal, study.raw, study.spec_bytes)
    targets = _targets(out, plot, resume, body)
    if plot is not None and study.plan.size > MAX_ROWS_SHOWN:
        raise ArgumentError(
            "plot",
            f"the map is drawn from the rows of this run; with more than {MAX_ROWS_SHOWN:,} runs draw it "
            "from the {out} file",
        )
    return study, body, targets


def _targets(
    out: Destination | None, plot: Destination | None, resume: bool, read: Body | str
) -> tuple[OutputTarget | None, OutputTarget | None]:
    """`sweep`'s ``out`` and ``plot`` checked before any run: never a file the body is read
    from (a `Body`'s every file), not one file for both; ``resume`` needs ``out``, a Parquet
    ``out`` pyarrow."""
    require_flags(resume=resume)
    if out is None and resume:
        raise ArgumentError("resume", "needs {out}, the file of the interrupted sweep")
    out_target, plot_target = out_and_plot(out, plot, ("csv", "parquet"), read)
    if out_target is not None and out_target.format == "parquet" and not importlib.util.find_spec("pyarrow"):
        raise ArgumentError(
            "out",
            "a .parquet file needs the optional package 'pyarrow': pip install '.[parquet]' from rbi's "
            "source folder, or pip install pyarrow",
        )
    return out_target, plot_target


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
        return (spec_label(path), *read_spec(path))  # "-" reads standard input, named <stdin>
    return loaded_body(body, "body").path, body._raw, body._spec_bytes
