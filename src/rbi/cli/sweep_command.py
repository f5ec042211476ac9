"""`rbi sweep`: many simulations of one spec — stability maps, Monte Carlo tolerance studies —
or, with --mass-properties, the spread of the mass properties alone."""

from __future__ import annotations

from rich.console import Group
from rich.text import Text

import rbi
from rbi.cli import tables
from rbi.cli.option_values import spin_axis_option, sweep_values, vary_option
from rbi.cli.options import FormatOption, OutputFormat, SpecFile, needs, option, require, require_matplotlib
from rbi.cli.render import emit_result, note, progress_bar
from rbi.cli.run_options import RUN
from rbi.cli.terminal import Terminated, say, terminal_safe

SpinOption = option(
    str, "--spin", "-s", metavar="START:STOP:COUNT", help="Spins about the spin axis, rad/s (or one value)."
)
TiltOption = option(
    str,
    "--tilt",
    metavar="START:STOP:COUNT",
    help="Nudges at t=0: turns of the body about --tilt-axis, degrees (or one value).",
)
VaryOption = option(
    list[str] | None,
    "--vary",
    metavar="PATH=RANGE",
    help="Vary a number of the spec: PATH is parts.NAME.FIELD or "
    "parts.NAME.FIELD[i] (e.g. parts.bolt.position[0]); RANGE is START:STOP:COUNT, or normal(MEAN,SD) / "
    "uniform(LOW,HIGH) with --runs. Repeatable.",
)
RunsOption = option(
    int, "--runs", metavar="N", help="Monte Carlo: N draws of every normal()/uniform() --vary per grid point."
)
SeedOption = option(int, "--seed", metavar="S", help="Seed of the draws (same seed, same rows).")
MaxStepsOption = option(
    int | None,
    "--max-steps",
    metavar="N",
    help="Most steps one run may take (default 1e+07, as simulate's); a run that needs more is a failed row.",
)
WorkersOption = option(int | None, "--workers", "-j", metavar="N", help="Cores to use (default: all).")
DaskOption = option(
    str | None,
    "--dask",
    metavar="ADDRESS",
    help="Run on the Dask scheduler at ADDRESS (tcp://host:8786), or 'local' "
    f"for a local cluster ({needs('Dask', 'dask')}).",
)
OutOption = option(
    str | None,
    "--out",
    "-o",
    metavar="FILE.csv|FILE.parquet",
    help=f"Write one row per run, streamed as runs finish (FILE.parquet {needs('pyarrow', 'parquet')}).",
)
ResumeOption = option(
    bool, "--resume", help="Continue an interrupted sweep into --out: compute only the runs missing there."
)
PlotOption = option(
    str | None,
    "--plot",
    metavar="FILE.png|.svg|.pdf",
    help=f"Draw the map: largest tilt over the first two swept axes ({needs('matplotlib', 'plot')}).",
)
MassPropertiesOption = option(
    bool,
    "--mass-properties",
    help="No simulation: the spread of mass, centre of mass, principal moments and "
    "principal-axis directions over the --vary values.",
)


HIDDEN = frozenset({"min_tilt_deg", "precession_rate_deg_s", "steps"})
"""Columns of --out, json and csv that the table leaves out, to fit 80 columns."""


def sweep(
    file: SpecFile,
    spin: SpinOption = "0",
    tilt: TiltOption = "0",
    vary: VaryOption = None,
    runs: RunsOption = 1,
    seed: SeedOption = 0,
    duration: RUN.duration = 4.0,
    samples: RUN.samples = 481,
    rtol: RUN.rtol = 1e-12,
    gravity: RUN.gravity = None,
    tilt_axis: RUN.tilt_axis = "y",
    max_steps: MaxStepsOption = None,
    workers: WorkersOption = None,
    dask: DaskOption = None,
    out: OutOption = None,
    resume: ResumeOption = False,
    plot: PlotOption = None,
    mass_properties: MassPropertiesOption = False,
    yes: RUN.yes = False,
    spin_axis: RUN.spin_axis = None,
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

    if dask is not None:
        require("distributed", "dask", "--dask")
    if dask == "local":
        require("cryptography", "dask", "--dask local")  # its private TLS certificates
    if plot is not None:
        require_matplotlib()
    settings = dict(runs=runs, seed=seed, duration=duration, samples=samples, rtol=rtol, gravity=gravity)
    settings |= dict(tilt_axis=tilt_axis, max_steps=max_steps, workers=workers, dask=dask, plot=plot)
    settings |= dict(spin=sweep_values(spin, "--spin"), tilt_deg=sweep_values(tilt, "--tilt"))
    settings |= dict(vary=vary_option(vary or []), spin_axis=spin_axis_option(spin_axis))
    settings |= dict(mass_properties=mass_properties, check_budget=not yes, out=out, resume=resume)
    table = _run(file, settings)
    if workers is not None and table.cores is not None and table.cores < workers:
        say(f"--workers {workers}: this machine gives rbi {table.cores} cores; using {table.cores}")
    emit_result(format.value, table, table=lambda: _drawn(table, file))


def _run(file: str, settings: dict):
    """Run the sweep with a progress bar on a terminal; on Ctrl-C or SIGTERM say how many runs
    --out kept (exit 130 or 143)."""

    told: list[int] = []
    with progress_bar("sweep", "runs") as bar:

        def progress(done: int, total: int) -> None:
            told[:] = [done, total]
            if bar is not None:
                bar.update(done, total)

        try:
            return rbi.sweep(file, progress=progress, **settings)
        except (KeyboardInterrupt, Terminated) as stop:
            if settings["out"] is None or not told:
                raise
            word, code = ("terminated", 143) if isinstance(stop, Terminated) else ("interrupted", 130)
            say(
                f"{word}: {told[0]:,} of {told[1]:,} runs kept in {settings['out']}; run the same command "
                "with --resume to compute the rest"
            )
            raise SystemExit(code) from None


def _drawn(table, file: str):
    """The runs (or a study's spread, drawn as rbi's tables) of ``table.rows()``, then its notes."""
    rows = table.rows()
    drawn = [tables.drawn(rows)] if table.spread else [_runs(each, table, file) for each in rows]
    return Group(*(drawn if table.held else []), note("\n".join(table.notes())))


def _runs(rows, table, file: str):
    """The runs, in rbi's table style; each header over its unit."""
    keep = [i for i, name in enumerate(rows.columns) if name not in HIDDEN]
    drawn = tables.titled(f"{table.name or file} — sweep")
    for name in (rows.columns[i] for i in keep):
        # words wrap in a narrow terminal and no cell is cut short: a number is never shown truncated
        words = name.removesuffix("_deg_s").removesuffix("_deg").replace("_", " ")  # the unit is below
        header = name if name.startswith("parts.") else words
        justify = "left" if name == "status" else "right"
        lines = [Text(terminal_safe(line)) for line in (header, table.unit(name)) if line]
        drawn.add_column(Text("\n").join(lines), overflow="fold", justify=justify)
    for row in rows.cells:
        drawn.add_row(*(row[i] for i in keep))
    return drawn
