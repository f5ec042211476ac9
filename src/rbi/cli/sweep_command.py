"""`rbi sweep`: many simulations of one spec — stability maps, Monte Carlo tolerance studies —
or, with --mass-properties, the spread of the mass properties alone."""

from __future__ import annotations

from rich.console import Group

import rbi
from rbi.cli import tables
from rbi.cli.option_values import sweep_values, vary_option
from rbi.cli.options import (
    FORMAT,
    OutputFormat,
    SpecFile,
    command,
    needs,
    option,
    out_option,
    plot_option,
    require,
)
from rbi.cli.render import emit_result, note, progress_bar
from rbi.cli.run_options import RUN, budget
from rbi.cli.terminal import Terminated, say

OPTIONS = (
    option(
        str,
        "--spin",
        "-s",
        default="0",
        metavar="START:STOP:COUNT",
        parser=sweep_values,
        help="Spins about the spin axis, rad/s (or one value).",
    ),
    option(
        str,
        "--tilt",
        default="0",
        name="tilt_deg",
        metavar="START:STOP:COUNT",
        parser=sweep_values,
        help="Nudges at t=0: turns of the body about --tilt-axis, degrees (or one value).",
    ),
    option(
        list[str] | None,
        "--vary",
        metavar="PATH=RANGE",
        help="Vary a number of the spec: PATH is parts.NAME.FIELD or "
        "parts.NAME.FIELD[i] (e.g. parts.bolt.position[0]); RANGE is START:STOP:COUNT, or normal(MEAN,SD) / "
        "uniform(LOW,HIGH) with --runs. Repeatable.",
    ),
    option(
        int,
        "--runs",
        metavar="N",
        help="Monte Carlo: N draws of every normal()/uniform() --vary per grid point.",
    ),
    option(int, "--seed", metavar="S", help="Seed of the draws (same seed, same rows)."),
    RUN["duration"],
    RUN["samples"],
    RUN["rtol"],
    RUN["gravity"],
    RUN["tilt_axis"],
    option(
        int | None,
        "--max-steps",
        metavar="N",
        help="Most steps one run may take (default 1e+07, as simulate's); a run that needs more is a failed row.",
    ),
    option(int | None, "--workers", "-j", metavar="N", help="Cores to use (default: all)."),
    option(
        str | None,
        "--dask",
        metavar="ADDRESS",
        help="Run on the Dask scheduler at ADDRESS (tcp://host:8786), or 'local' "
        f"for a local cluster ({needs('Dask', 'dask')}).",
    ),
    out_option(
        "FILE.csv|FILE.parquet",
        f"Write one row per run, streamed as runs finish (FILE.parquet {needs('pyarrow', 'parquet')}).",
    ),
    option(
        bool,
        "--resume",
        help="Continue an interrupted sweep into --out: compute only the runs missing there.",
    ),
    plot_option("Draw the map: largest tilt over the first two swept axes"),
    option(
        bool,
        "--mass-properties",
        help="No simulation: the spread of mass, centre of mass, principal moments and "
        "principal-axis directions over the --vary values.",
    ),
    RUN["yes"],
    RUN["spin_axis"],
    FORMAT,
)


@command(*OPTIONS, api=rbi.sweep)
def sweep(file: SpecFile, *, format: OutputFormat, **settings) -> None:
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

    if settings["dask"] is not None:
        require("distributed", "dask", "--dask")
    if settings["dask"] == "local":
        require("cryptography", "dask", "--dask local")  # its private TLS certificates
    table = _run(file, budget(settings) | {"vary": vary_option(settings["vary"] or [])})
    workers = settings["workers"]
    if workers is not None and table.cores is not None and table.cores < workers:
        say(f"--workers {workers}: this machine gives rbi {table.cores} cores; using {table.cores}")
    emit_result(format.value, table, table=lambda: _drawn(table))


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


def _drawn(table):
    """The runs (or a study's spread) as rbi's tables, then the table's notes."""
    return Group(*([tables.drawn(table.rows())] if table.held else []), note("\n".join(table.notes())))
