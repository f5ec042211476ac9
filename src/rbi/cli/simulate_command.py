"""`rbi simulate`: the motion of a heavy top on its pivot, or of a free body."""

from __future__ import annotations

import sys
from typing import Annotated

import typer

from rbi import SpecError, api
from rbi.api import check_distinct, output_target, write_output
from rbi.cli.option_values import run_settings
from rbi.cli.options import FormatOption, OutputFormat, SpecFile, needs, require_matplotlib
from rbi.cli.render import emit, progress_bar, refuse_non_finite
from rbi.cli.run_options import (
    DurationOption,
    GravityOption,
    MaxStepsOption,
    OmegaOption,
    RtolOption,
    SamplesOption,
    SpinAxisOption,
    SpinOption,
    TiltAxisOption,
    TiltOption,
    YesOption,
)

PLOT_FORMATS = ("png", "svg", "pdf")

PLOT_SAMPLES = 8001
"""Samples drawn in a plot: enough to show nutation loops and the wobble of a fast top."""

METHOD_HELP = (
    "default: compiled adaptive DOP853 (fast, tight); rk45: scipy RK45 at rtol 1e-8 with a Python "
    "right-hand side, as the textbook Mass and Inertia integrates it; dop853: scipy DOP853, Python right-hand side; exact: closed "
    "form (free body; axisymmetric top with its centre of mass on the axis)."
)

OutOption = Annotated[
    str | None,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE.csv",
        help="Write the trajectory as CSV (only if the run succeeds; '-' for standard output).",
    ),
]
DrawsOption = Annotated[
    int | None,
    typer.Option(
        "--draws",
        metavar="N",
        help="For a spec with ±: N more runs with the inputs drawn, the summary's spread from them.",
        show_default=False,
    ),
]
SeedOption = Annotated[int | None, typer.Option("--seed", metavar="S", help="Seed of the --draws.")]
MethodOption = Annotated[str, typer.Option("--method", "-m", metavar="NAME", help=METHOD_HELP)]
ErrorEstimateOption = Annotated[
    bool,
    typer.Option(
        "--error-estimate/--no-error-estimate",
        help="Estimate the trajectory's error with a second run of the compiled integrator at a tolerance "
        "1000x tighter (at most down to 1e-15; not for --method exact, which has no numerical error).",
    ),
]
PlotOption = Annotated[
    str | None,
    typer.Option(
        "--plot",
        metavar="FILE.png|.svg|.pdf",
        help="Plot the path of the spin axis seen from above, its tilt "
        "(a free body: each principal axis's turn), ω and energy "
        f"drift against time ({needs('matplotlib', 'plot')}).",
    ),
]


def simulate(
    file: SpecFile,
    spin: SpinOption = None,
    omega: OmegaOption = None,
    tilt: TiltOption = 0.0,
    tilt_axis: TiltAxisOption = "y",
    gravity: GravityOption = None,
    duration: DurationOption = 4.0,
    samples: SamplesOption = 481,
    out: OutOption = None,
    method: MethodOption = "default",
    rtol: RtolOption = None,
    error_estimate: ErrorEstimateOption = True,
    max_steps: MaxStepsOption = None,
    yes: YesOption = False,
    plot: PlotOption = None,
    spin_axis: SpinAxisOption = None,
    draws: DrawsOption = None,
    seed: SeedOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
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

    out_target, plot_target = _targets(file, out, plot)
    if out_target is not None and out_target.is_stdout:
        if format == OutputFormat.json:  # one JSON object on stdout, or the trajectory: not both
            raise SpecError(
                "--out -: the trajectory goes to standard output, where --format json prints its "
                "object; write the trajectory to a file (--out FILE.csv) or leave out --format json"
            )
        format = OutputFormat.csv  # the trajectory is what goes to standard output
    settings = run_settings(spin, omega, tilt, yes, spin_axis, tilt_axis=tilt_axis, gravity=gravity)
    settings |= dict(duration=duration, samples=samples, method=method, rtol=rtol, max_steps=max_steps)
    run = _run(file, settings | dict(error_estimate=error_estimate), format, (out_target, plot_target))
    run = run if draws is None else run.with_input_uncertainty(draws, seed)  # beside the error estimate
    trajectory_csv = run.to_csv() if out is not None or format == OutputFormat.csv else ""
    result = run.to_dict()
    if out is not None and not out_target.is_stdout:
        result["out"] = out
    if format != OutputFormat.csv:
        refuse_non_finite(result, file)
    if out_target is not None and not out_target.is_stdout:
        write_output(out_target, trajectory_csv)
    if plot_target is not None:
        run.plot(plot_target)
    if format == OutputFormat.csv:
        sys.stdout.write(trajectory_csv)
        return
    emit(format.value, result, lambda: _table(run, result))


def _targets(file: str, out: str | None, plot: str | None):
    """The checked ``--out`` and ``--plot`` targets (None when not asked for); matplotlib is
    required before any work when a plot is."""

    out_target = (
        None if out is None else output_target(out, "--out", ("csv",), inputs=[file], stdout_format="csv")
    )
    plot_target = None if plot is None else output_target(plot, "--plot", PLOT_FORMATS, inputs=[file])
    check_distinct([out_target, plot_target])
    if plot is not None:
        require_matplotlib()
    return out_target, plot_target


def _run(file: str, settings: dict, format: OutputFormat, targets):
    """Load the spec and simulate it (sampled densely too for --plot, in the same integration),
    with a progress bar on a terminal. Before simulating, the output ``targets`` are checked
    again, against every file the body was read from (a point cloud, a mesh): rbi never
    overwrites its input."""

    body = api.load(file)
    for target in targets:
        if target is not None and not target.is_stdout:
            output_target(target.given, target.option, (target.format,), inputs=body.files_read)
    dense = PLOT_SAMPLES if targets[1] is not None else 0
    with progress_bar("simulating", stdout=True, delay=0.5, show=format == OutputFormat.table) as progress:
        return api.simulate(body, progress=progress, plot_samples=dense, **settings)


def _table(run, result: dict):
    # not at top level: `rbi simulate --format csv` would load rich.text too
    from rich.text import Text

    # not at top level: `rbi simulate --format csv` would load rbi.cli.tables too
    from rbi.cli import tables

    notes = run.notes() + ([f"Trajectory written to {result['out']}."] if "out" in result else [])
    return tables.stack(
        *(tables.quantities(rows.title, rows.cells) for rows in run.rows()), Text("\n".join(notes))
    )
