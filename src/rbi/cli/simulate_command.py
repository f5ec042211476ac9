"""`rbi simulate`: the motion of a heavy top on its pivot, or of a free body."""

from __future__ import annotations

import sys

import rbi
from rbi.cli.options import FORMAT, OutputFormat, SpecFile, command, option, out_option, plot_option
from rbi.cli.render import emit_result, note, progress_bar, tables_of
from rbi.cli.run_options import RUN, budget

STANDARD_OUTPUT = ("-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1")
"""The names of standard output ``--out`` takes (as rbi's writer knows them)."""

METHOD_HELP = (
    "default: compiled adaptive DOP853 (fast, tight); rk45: scipy RK45 at rtol 1e-8 with a Python "
    "right-hand side, as the textbook Mass and Inertia integrates it; dop853: scipy DOP853, Python right-hand side; exact: closed "
    "form (free body; axisymmetric top with its centre of mass on the axis)."
)

OPTIONS = (
    *RUN.values(),
    out_option(
        "FILE.csv", "Write the trajectory as CSV (only if the run succeeds; '-' for standard output)."
    ),
    option(str, "--method", "-m", metavar="NAME", help=METHOD_HELP),
    option(
        bool,
        "--error-estimate/--no-error-estimate",
        help="Estimate the trajectory's error with a second run of the compiled integrator at a tolerance "
        "1000x tighter (at most down to 1e-15; not for --method exact, which has no numerical error).",
    ),
    plot_option(
        "Plot the path of the spin axis seen from above, its tilt (a free body: each principal axis's "
        "turn), ω and energy drift against time"
    ),
    option(
        int | None,
        "--draws",
        metavar="N",
        help="For a spec with ±: N more runs with the inputs drawn, the summary's spread from them.",
    ),
    option(int | None, "--seed", metavar="S", help="Seed of the --draws."),
    FORMAT,
)


@command(*OPTIONS, api=rbi.simulate)
def simulate(file: SpecFile, *, format: OutputFormat, out: str | None, **settings) -> None:
    """Simulate the body: a heavy top on its pivot (spec with `pivot`) or a torque-free body.

    Prints the conserved quantities' drift, an error estimate and, for a top, whether it
    sleeps; --out writes the trajectory (t, quaternion, ω, tilt and precession of the spin axis)
    as CSV, --plot draws it.

    \b
    Examples:
      rbi simulate top.yaml --spin 200 --tilt 0.01 --plot top.png
      rbi simulate top_bolted.yaml --spin 200 --duration 2 --out run.csv
      rbi simulate tbar.yaml --omega 0.01,0.01,3 --duration 20 --plot flip.png
    """

    streamed = out in STANDARD_OUTPUT  # the trajectory goes to standard output
    if streamed and format == OutputFormat.json:  # one JSON object on stdout, or the trajectory: not both
        raise rbi.SpecError(
            "--out -: the trajectory goes to standard output, where --format json prints its "
            "object; write the trajectory to a file (--out FILE.csv) or leave out --format json"
        )
    format = OutputFormat.csv if streamed else format
    body = rbi.load(file)
    with progress_bar("simulating", stdout=True, delay=0.5, show=format == OutputFormat.table) as progress:
        run = rbi.simulate(body, **budget(settings), out=None if streamed else out, progress=progress)
    if format == OutputFormat.csv:
        sys.stdout.write(run.to_csv())
        return
    written = [] if out is None else [f"Trajectory written to {out}."]
    emit_result(format.value, run, table=lambda: _table(run, run.notes() + written))


def _table(run, notes: list[str]):
    """The run's tables (`Trajectory.rows`) and the sentences under them."""
    from rich.console import Group  # not at top level: `rbi simulate --format csv` would load rich

    return Group(tables_of(run), note("\n".join(notes)))
