"""`rbi sweep`: many simulations of one spec — stability maps, Monte Carlo tolerance studies —
or, with --mass-properties, the spread of the mass properties alone."""

from __future__ import annotations

import sys
from typing import Annotated

import typer
from rich import box
from rich.table import Table
from rich.text import Text

from rbi import api
from rbi.api import DEFAULT_MAX_STEPS, SpecError, check_distinct, output_target
from rbi.cli import tables
from rbi.cli.option_values import spin_axis_option, sweep_values, vary_option
from rbi.cli.options import FormatOption, OutputFormat, SpecFile, needs, require, require_matplotlib
from rbi.cli.render import emit, number, progress_bar
from rbi.cli.run_options import (
    DurationOption,
    GravityOption,
    RtolOption,
    SamplesOption,
    SpinAxisOption,
    TiltAxisOption,
    YesOption,
)
from rbi.cli.terminal import Terminated, say

SpinOption = Annotated[
    str,
    typer.Option(
        "--spin", "-s", metavar="START:STOP:COUNT", help="Spins about the spin axis, rad/s (or one value)."
    ),
]
TiltOption = Annotated[
    str,
    typer.Option(
        "--tilt",
        metavar="START:STOP:COUNT",
        help="Nudges at t=0: turns of the body about --tilt-axis, degrees (or one value).",
    ),
]
VaryOption = Annotated[
    list[str] | None,
    typer.Option(
        "--vary",
        metavar="PATH=RANGE",
        help="Vary a number of the spec: PATH is parts.NAME.FIELD or "
        "parts.NAME.FIELD[i] (e.g. parts.bolt.position[0]); RANGE is START:STOP:COUNT, or normal(MEAN,SD) / "
        "uniform(LOW,HIGH) with --runs. Repeatable.",
    ),
]
RunsOption = Annotated[
    int,
    typer.Option(
        "--runs", metavar="N", help="Monte Carlo: N draws of every normal()/uniform() --vary per grid point."
    ),
]
SeedOption = Annotated[
    int, typer.Option("--seed", metavar="S", help="Seed of the draws (same seed, same rows).")
]
MaxStepsOption = Annotated[
    int | None,
    typer.Option(
        "--max-steps",
        metavar="N",
        help=f"Most steps one run may take (default {DEFAULT_MAX_STEPS:.0e}); a run "
        "that needs more is a failed row.",
    ),
]
WorkersOption = Annotated[
    int | None, typer.Option("--workers", "-j", metavar="N", help="Cores to use (default: all).")
]
DaskOption = Annotated[
    str | None,
    typer.Option(
        "--dask",
        metavar="ADDRESS",
        help="Run on the Dask scheduler at ADDRESS (tcp://host:8786), or 'local' "
        f"for a local cluster ({needs('Dask', 'dask')}).",
    ),
]
OutOption = Annotated[
    str | None,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE.csv|FILE.parquet",
        help=f"Write one row per run, streamed as runs finish (FILE.parquet {needs('pyarrow', 'parquet')}).",
    ),
]
ResumeOption = Annotated[
    bool,
    typer.Option(
        "--resume", help="Continue an interrupted sweep into --out: compute only the runs missing there."
    ),
]
PlotOption = Annotated[
    str | None,
    typer.Option(
        "--plot",
        metavar="FILE.png|.svg|.pdf",
        help=f"Draw the map: largest tilt over the first two swept axes ({needs('matplotlib', 'plot')}).",
    ),
]
MassPropertiesOption = Annotated[
    bool,
    typer.Option(
        "--mass-properties",
        help="No simulation: the spread of mass, centre of mass, principal moments and "
        "principal-axis directions over the --vary values.",
    ),
]


UNITS = {
    "spin": "rad/s",
    "tilt_deg": "deg",
    "max_tilt_deg": "deg",
    "final_tilt_deg": "deg",
    "min_tilt_deg": "deg",
    "precession_rate_deg_s": "deg/s",
    "energy_drift": "relative",
    "axis_1_tilt_deg": "deg",
    "axis_2_tilt_deg": "deg",
    "axis_3_tilt_deg": "deg",
}
"""The unit shown under each swept or summary column."""

_LENGTH_FIELDS = frozenset(
    "radius inner_radius outer_radius start_radius end_radius major_radius minor_radius length height "
    "size semi_axes position center start end apex base through step pivot center_of_mass".split()
)
_INERTIA_FIELDS = frozenset("ixx iyy izz ixy ixz iyz inertia".split())


def column_unit(name: str, units: dict[str, str]) -> str:
    """The unit of a sweep column: a summary column's (:data:`UNITS`), or a varied spec field's
    (``parts.bolt.mass`` in the spec's mass unit, ``parts.bolt.position[0]`` in its length unit,
    ``...angle_deg`` in degrees); empty for a number without one (a direction, a count)."""
    if name in UNITS:
        return UNITS[name]
    length, mass = units["length"], units["mass"]
    field = name.rsplit(".", 1)[-1].split("[", 1)[0]
    if field == "mass":
        return mass
    if field == "density":
        return f"{mass}/{length}³"
    if field in _INERTIA_FIELDS:
        return f"{mass}·{length}²"
    if field in _LENGTH_FIELDS:
        return length
    return "deg" if field.endswith("_deg") else ""


def sweep(
    file: SpecFile,
    spin: SpinOption = "0",
    tilt: TiltOption = "0",
    vary: VaryOption = None,
    runs: RunsOption = 1,
    seed: SeedOption = 0,
    duration: DurationOption = 4.0,
    samples: SamplesOption = 481,
    rtol: RtolOption = 1e-12,
    gravity: GravityOption = None,
    tilt_axis: TiltAxisOption = "y",
    max_steps: MaxStepsOption = None,
    workers: WorkersOption = None,
    dask: DaskOption = None,
    out: OutOption = None,
    resume: ResumeOption = False,
    plot: PlotOption = None,
    mass_properties: MassPropertiesOption = False,
    yes: YesOption = False,
    spin_axis: SpinAxisOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Many runs of one spec: a grid over spin, tilt and spec fields, or Monte Carlo draws.

    One row per run: the swept values, the largest, final and smallest tilt of the spin axis,
    the mean precession rate, the energy drift, the steps taken and a status (ok, or why that
    run failed: one failed run never stops the others). Runs use every core.

    \b
    Examples:
      rbi sweep top.yaml --spin 150:260:12 --tilt 0.01:1:5 \\
          --out map.csv --plot map.png
      rbi sweep top_bolted.yaml --spin 200 \\
          --vary 'parts.bolt.mass=normal(0.02,0.002)' --runs 500
      rbi sweep top_bolted.yaml --mass-properties \\
          --vary 'parts.bolt.position[0]=uniform(0.039,0.041)' --runs 1000
    """

    settings = dict(spin=sweep_values(spin, "--spin"), tilt_deg=sweep_values(tilt, "--tilt"))
    settings |= dict(
        vary=vary_option(vary or []), spin_axis=spin_axis_option(spin_axis), runs=runs, seed=seed
    )
    settings |= dict(duration=duration, samples=samples, rtol=rtol, gravity=gravity, tilt_axis=tilt_axis)
    settings |= dict(max_steps=max_steps, dask=dask, mass_properties=mass_properties, check_budget=not yes)
    if resume and out is None:
        raise SpecError("--resume: needs --out, the file of the interrupted sweep")
    settings["out"], plot_target = _targets(file, out, plot)
    source = _source(file, plot_target)
    table = _run(source, settings | {"workers": _workers(workers, dask)}, out, resume)
    result = _result(table, out, plot, plot_target)
    if format == OutputFormat.csv:
        sys.stdout.write(table.to_csv())
        return
    emit(format.value, result, lambda: _table(result, table, file))


def _result(table, out: str | None, plot: str | None, plot_target) -> dict:
    """What `rbi sweep --format json` prints: name, units, count, columns and, when the rows
    were held, the runs as objects and how many failed; the files written, the mass-properties
    spread (--mass-properties). The map is drawn here."""
    # looked up per call: tests replace it
    from rbi.api import MAX_ROWS_SHOWN

    result = table.to_dict()
    if out is not None:  # before the spread, as it always was
        result = {k: v for k, v in result.items() if k != "spread"} | {"out": out} | result
    if plot is not None:
        if not table.held:
            raise SpecError(
                "--plot: the map is drawn from the rows of this run; with more than "
                f"{MAX_ROWS_SHOWN:,} runs draw it from the --out file"
            )
        table.plot(plot_target)
        result["plot"] = plot
    return result


def _targets(file: str, out: str | None, plot: str | None):
    """The ``--out`` and ``--plot`` targets, checked before any work (None when not asked
    for); the optional packages they need are required then too."""

    out_target = None if out is None else output_target(out, "--out", ("csv", "parquet"), inputs=[file])
    plot_target = (
        None if plot is None else output_target(plot, "--plot", ("png", "svg", "pdf"), inputs=[file])
    )
    check_distinct([out_target, plot_target])
    if out_target is not None and out_target.format == "parquet":
        require("pyarrow", "parquet", "--out FILE.parquet")
    if plot is not None:
        require_matplotlib()
    return out_target, plot_target


def _source(file: str, plot_target):
    """What is swept: the spec's path (rbi.sweep checks --out against every file the spec names
    once it has translated the spec, before any run); with --plot, the loaded body, the map's
    file checked against the files it was read from now, since the map is drawn after the runs."""

    if plot_target is None:
        return file
    body = api.load(file)
    output_target(plot_target.given, plot_target.option, (plot_target.format,), inputs=body.files_read)
    return body


def _workers(workers: int | None, dask: str | None) -> int | None:
    """The optional packages --dask needs; --workers above the cores this process may use is
    said, and the cores are used (a remote cluster has its own; past 1024 rbi.sweep refuses it)."""
    # looked up per call: tests replace it
    from rbi.api import available_cores

    if dask is not None:
        require("distributed", "dask", "--dask")
    if dask == "local":
        require("cryptography", "dask", "--dask local")  # its private TLS certificates
    if workers is None or dask not in (None, "local") or not available_cores() < workers <= 1024:
        return workers

    say(f"--workers {workers}: this machine gives rbi {available_cores()} cores; using {available_cores()}")
    return available_cores()


def _run(source, settings: dict, out: str | None, resume: bool):
    """Run the sweep with a progress bar on a terminal; on Ctrl-C or SIGTERM say how many runs
    --out kept (exit 130 or 143)."""

    told: list[int] = []
    with progress_bar("sweep", "runs") as bar:

        def progress(done: int, total: int) -> None:
            told[:] = [done, total]
            if bar is not None:
                bar.update(done, total)

        try:
            return api.sweep(source, resume=resume, progress=progress, **settings)
        except (KeyboardInterrupt, Terminated) as stop:
            if out is None or not told:
                raise
            word, code = ("terminated", 143) if isinstance(stop, Terminated) else ("interrupted", 130)
            say(
                f"{word}: {told[0]:,} of {told[1]:,} runs kept in {out}; run the same command with "
                "--resume to compute the rest"
            )
            raise SystemExit(code) from None


def _table(result, table, file):

    notes = [f"{result['count']:,} runs"]
    if "failed" in result:
        notes[0] += f", {result['failed']:,} failed"
    if "out" in result:
        notes.append(f"Rows written to {result['out']}.")
    if "plot" in result:
        notes.append(f"Map drawn in {result['plot']}.")
    parts = []
    if table.held and not result.get("spread"):  # a tolerance study shows its spread instead
        columns = table.columns
        rows = [[record[name] for name in columns] for record in table.records()]
        parts.append(_runs_table(result, columns, rows, file))
    if result.get("spread"):
        parts.append(_spread_table(result))
    parts.append(Text("\n".join(notes)))
    return tables.stack(*parts)


def _runs_table(result, columns, rows, file):
    """One row per run (the first and last 20 of more than 40), in rbi's table style."""

    shown = rows if len(rows) <= 40 else rows[:20] + [None] + rows[-20:]
    table = Table(
        title=tables.plain_text(f"{result['name'] or file} — sweep"),
        box=box.SIMPLE_HEAD,
        title_justify="left",
        show_edge=False,
    )  # rbi's style; headers hold a line break
    hidden = {"min_tilt_deg", "precession_rate_deg_s", "steps"}  # in --out, json and csv
    keep = [i for i, name in enumerate(columns) if name not in hidden]
    columns = [columns[i] for i in keep]
    shown = [None if row is None else [row[i] for i in keep] for row in shown]
    for name in columns:
        # words wrap in a narrow terminal and no cell is cut short: a number is never shown truncated
        words = name.removesuffix("_deg_s").removesuffix("_deg").replace("_", " ")  # the unit is below
        header = tables.plain_text(name if name.startswith("parts.") else words)
        table.add_column(
            f"{header}\n{column_unit(name, result['units'])}".rstrip(),
            overflow="fold",
            justify="left" if name == "status" else "right",
        )
    for row in shown:
        if row is None:
            table.add_row(*["…"] * len(columns))
            continue
        table.add_row(
            *[
                tables.plain_text(str(v))
                if isinstance(v, str)
                else ("—" if v is None else (str(v) if isinstance(v, int) else number(v, 4)))
                for v in row
            ]
        )
    return table


def _spread_table(result):
    """min, median, max and standard deviation of each quantity over the ok runs."""

    spread = tables.titled("Spread over the ok runs")
    spread.add_column("quantity", no_wrap=True)
    spread.add_column("unit")
    for name in ("min", "median", "max", "std"):
        spread.add_column(name, justify="right")
    length, mass = result["units"]["length"], result["units"]["mass"]
    prefixed = {"mass": mass, "com": length, "moment": f"{mass}·{length}²"}  # mass, com_x, moment_1 ...
    for name, stats in result["spread"].items():
        unit = prefixed.get(name.split("_")[0]) or column_unit(name, result["units"])
        spread.add_row(name, unit, *[number(stats[k], 4) for k in ("p0", "p50", "p100", "std")])
    return spread
