"""`rbi simulate`: the motion of a heavy top on its pivot, or of a free body."""

from __future__ import annotations

import sys
from typing import Annotated

import numpy as np
import typer

from rbi import SpecError, api
from rbi.api import check_distinct, output_target, write_output
from rbi.cli.option_values import run_settings
from rbi.cli.options import FormatOption, OutputFormat, SpecFile, needs, require_matplotlib
from rbi.cli.render import emit, number, progress_bar, refuse_non_finite, vector_text
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
    settings |= dict(duration=duration, method=method, rtol=rtol, max_steps=max_steps)
    settings |= dict(draws=draws, seed=seed)
    body, run = _run(file, settings, samples, error_estimate, format, (out_target, plot_target))
    trajectory_csv = run.to_csv() if out is not None or format == OutputFormat.csv else ""
    result = dict(run.summary)
    if out is not None and not out_target.is_stdout:
        result["out"] = out
    if format != OutputFormat.csv:
        refuse_non_finite(result, file)
    if out_target is not None and not out_target.is_stdout:
        write_output(out_target, trajectory_csv)
    if plot_target is not None:
        _plot(plot_target, body, run, settings)
    if format == OutputFormat.csv:
        sys.stdout.write(trajectory_csv)
        return
    emit(format.value, result, lambda: _table(body, result))


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


def _run(file: str, settings: dict, samples: int, error_estimate: bool, format: OutputFormat, targets):
    """Load the spec and simulate it, with a progress bar on a terminal: ``(body, trajectory)``.
    Before simulating, the output ``targets`` are checked again, against every file the body
    was read from (a point cloud, a mesh): rbi never overwrites its input."""

    settings = dict(settings)
    draws, seed = settings.pop("draws"), settings.pop("seed")
    body = api.load(file)
    for target in targets:
        if target is not None and not target.is_stdout:
            output_target(target.given, target.option, (target.format,), inputs=body.files_read)
    with progress_bar("simulating", stdout=True, delay=0.5, show=format == OutputFormat.table) as progress:
        run = api.simulate(
            body, samples=samples, error_estimate=error_estimate, progress=progress, **settings
        )
    if draws is not None:  # beside the error estimate
        run.summary["input_uncertainty"] = api.input_uncertainty(
            body, draws=draws, seed=seed, samples=samples, **settings
        )
    return body, run


def _plot(target, body, run, settings: dict) -> None:
    """Draw the run (resampled densely when the method's dense output allows it) at ``target``."""

    shown = run
    if settings["method"] in ("default", "exact") and run.t.size < PLOT_SAMPLES and settings["duration"] > 0:
        # the same run sampled more densely (dense output: the steps do not change)
        settings = {k: v for k, v in settings.items() if k not in ("draws", "seed")}
        shown = api.simulate(body, samples=PLOT_SAMPLES, error_estimate=False, **settings)
    shown.plot(target)


def _table(body, result: dict):
    # not at top level: `rbi simulate --format csv` would load rich.text too
    from rich.text import Text

    # not at top level: `rbi simulate --format csv` would load rbi.cli.tables too
    from rbi.cli import tables

    return tables.stack(
        tables.quantities(f"{body.name or body.path} — simulate", _motion_rows(result)),
        tables.quantities("Accuracy and cost", _accuracy_rows(body, result)),
        Text("\n".join(_notes(result))),
    )


def _motion_rows(result: dict) -> list[tuple[str, str, str]]:
    """(quantity, unit, value) rows of the motion: scene, method, final state, tilt, precession."""

    final = result["final"]
    to_h = result.get("angle_to_h_deg") or {}
    cone = (
        []
        if to_h.get("min") is None
        else [("spin axis to h: min … max", "deg", f"{number(to_h['min'])} … {number(to_h['max'])}")]
    )
    return [
        ("scene", "", result["scene"]),
        ("method", "", result["method"]),
        ("duration", "s", number(result["duration"])),
        ("samples", "", str(result["samples"])),
        ("final q [w, x, y, z]", "", vector_text(final["q"])),
        ("final ω (body axes)", "rad/s", vector_text(final["omega"])),
        ("spin axis (body axes)", "", vector_text(result["spin_axis"])),
        ("nudge at t=0 (--tilt)", "deg", number(result["initial"]["nudge_deg"])),
        ("tilt of spin axis: final", "deg", number(final["tilt_deg"])),
        (
            "tilt min … max (nutation)",
            "deg",
            f"{number(result['tilt_min_deg'])} … {number(result['tilt_max_deg'])}",
        ),
        (
            "mean precession rate",
            "deg/s",
            "undefined (the axis was vertical)"
            if result["mean_precession_rate_deg_s"] is None
            else number(result["mean_precession_rate_deg_s"]),
        ),
        *cone,
    ]


def _accuracy_rows(body, result: dict) -> list[tuple[str, str, str]]:
    """(quantity, unit, value) rows of the run's accuracy (conserved quantities' drift, error
    estimate) and cost (steps, evaluations, time)."""

    labels = body.unit_labels
    names = {
        "energy": "energy",
        "h_vertical": "vertical h about pivot",
        "h_spin": "spin h·axis",
        "h_world": "h (world axes)",
    }
    accuracy = []
    for key, item in result["conserved"].items():
        initial = item["initial"]
        shown = vector_text(initial) if np.ndim(initial) else number(initial, 10)
        unit = labels[item["unit"]]
        accuracy.append((f"{names[key]}", unit, f"{shown}  (drift {number(item['drift'], 2)})"))
    accuracy.append(("| |q| − 1 | largest", "", number(result["quaternion_norm_error"], 2)))
    estimate = result.get("error_estimate")
    if estimate and estimate.get("orientation_deg") is None:
        accuracy.append(("error estimate", "", estimate["reference"]))
    elif estimate:
        accuracy.append(("error estimate: orientation", "deg", number(estimate["orientation_deg"], 2)))
        accuracy.append(("error estimate: ω", "rad/s", number(estimate["omega_rad_s"], 2)))
    spread = result.get("input_uncertainty")
    if spread:
        accuracy += [
            ("inputs drawn (--draws)", "", f"{spread['draws']} ({spread['failed']} failed)"),
            ("± inputs: tilt max", "deg", number(spread["tilt_max_deg"], 2)),
            ("± inputs: final tilt", "deg", number(spread["final_tilt_deg"], 2)),
            ("± inputs: precession rate", "deg/s", number(spread["mean_precession_rate_deg_s"], 2)),
            ("± inputs: final ω", "rad/s", vector_text(spread["final_omega"], 2)),
        ]
    accuracy += [
        ("steps (rejected)", "", f"{result['steps']} ({result['rejected_steps']})"),
        ("right-hand-side evaluations", "", str(result["rhs_evals"])),
        ("integration wall time", "s", number(result["wall_seconds"], 3)),
    ]
    if result["load_seconds"] > 0.05:
        accuracy.append(("loading the compiled kernel", "s", number(result["load_seconds"], 3)))
    return accuracy


def _notes(result: dict) -> list[str]:
    """The sentences under the tables: integrator, stability, closed form, file written."""
    notes = [f"Integrator: {result['integrator']}.", f"Stability: {result['stability']['verdict']}."]
    facts = result.get("closed_form")
    if facts and facts.get("kind") == "Lagrange top":
        notes.append(
            f"Closed form (Lagrange top): tilt between {number(facts['nutation_tilt_min_deg'])} and "
            f"{number(facts['nutation_tilt_max_deg'])} deg, nutation period {number(facts['nutation_period_s'])} s, "
            f"mean precession {number(facts['mean_precession_rate_deg_s'])} deg/s."
        )
    elif facts and facts.get("kind") == "asymmetric free body":
        flips = (
            f"; near the intermediate axis the body turns over every {number(facts['half_period_s'])} s"
            if result["stability"].get("intermediate_axis")
            else ""
        )
        notes.append(
            f"Closed form (Euler–Poinsot): ω repeats every {number(facts['omega_period_s'])} s "
            f"(4K(m)/λ, m = {number(facts['elliptic_parameter'])}){flips}."
        )
    if "out" in result:
        notes.append(f"Trajectory written to {result['out']}.")
    return notes
