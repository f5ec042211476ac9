"""`rbi simulate`: the motion of a heavy top on its pivot, or of a free body."""

from __future__ import annotations

import sys
import time
from typing import Annotated, Optional

import numpy as np
import typer

from rbi.cli.options import FormatOption, OutputFormat, SpecFile, parse_vector
from rbi.cli.render import emit, number, to_csv
from rbi.sim.budget import DEFAULT_MAX_STEPS
from rbi.spec.errors import InputError

PLOT_FORMATS = ("png", "svg", "pdf")
MAX_SAMPLES = 1_000_000
"""Most samples one run reports (a CSV of 10⁶ rows is about 250 MB)."""

PLOT_SAMPLES = 8001
"""Samples drawn in a plot: enough to show nutation loops and the wobble of a fast top."""

METHOD_HELP = ("default: compiled adaptive DOP853 (fast, tight); rk45: the seed chapter's set-up (scipy RK45, "
               "rtol 1e-8, Python right-hand side); dop853: scipy DOP853, Python right-hand side; exact: closed "
               "form (free body; axisymmetric top with its centre of mass on the axis).")


def simulate(
    file: SpecFile,
    spin: Annotated[Optional[float], typer.Option("--spin", "-s", metavar="W",
                                                  help="Spin about the body z axis, rad/s (ω = [0, 0, W]).")] = None,
    omega: Annotated[Optional[str], typer.Option("--omega", "-w", metavar="WX,WY,WZ",
                                                 help="Initial angular velocity in body axes, rad/s.")] = None,
    tilt: Annotated[float, typer.Option("--tilt", metavar="DEG",
                                        help="Initial tilt about the world y axis (see --tilt-axis), degrees.")] = 0.0,
    tilt_axis: Annotated[str, typer.Option("--tilt-axis", metavar="x|y",
                                           help="World axis the initial tilt turns about.")] = "y",
    gravity: Annotated[Optional[float], typer.Option(
        "--gravity", "-g", metavar="G", help="Gravity's magnitude in m/s² (SI, whatever the spec's units); "
                                             "0 switches it off. Default 9.81.")] = None,
    duration: Annotated[float, typer.Option("--duration", "-t", metavar="T", help="Simulated time, s.")] = 4.0,
    samples: Annotated[int, typer.Option("--samples", "-n", metavar="N",
                                         help="Samples, equally spaced from t=0 to t=T (1: only the end).")] = 481,
    out: Annotated[Optional[str], typer.Option("--out", "-o", metavar="FILE.csv",
                                               help="Write the trajectory as CSV (only if the run succeeds; "
                                                    "'-' for standard output).")] = None,
    method: Annotated[str, typer.Option("--method", "-m", metavar="NAME", help=METHOD_HELP)] = "default",
    rtol: Annotated[Optional[float], typer.Option(
        "--rtol", metavar="RTOL", help="Tolerance of the integrator (default 1e-12 for default, 1e-8 for rk45/dop853): smaller "
                       "is more accurate and slower.")] = None,
    error_estimate: Annotated[bool, typer.Option(
        "--error-estimate/--no-error-estimate",
        help="Estimate the trajectory's error with a second run of the compiled integrator at a tolerance "
             "1000x tighter (at most down to 1e-15; not for --method exact, which has no numerical error).")] = True,
    max_steps: Annotated[Optional[int], typer.Option(
        "--max-steps", metavar="N", help="Most integration steps this run may take (default "
                                         f"{DEFAULT_MAX_STEPS:.0e}); a run estimated to need more is refused "
                                         "before it starts.")] = None,
    yes: Annotated[bool, typer.Option("--yes", "-y", help="Run even when the run is estimated to exceed the "
                                                          "step budget (the budget still stops it).")] = False,
    plot: Annotated[Optional[str], typer.Option("--plot", metavar="FILE.png|.svg|.pdf",
                                                help="Plot the path of the body z axis seen from above, tilt "
                                                     "(a free body: each principal axis's turn), ω and energy "
                                                     "drift against time (needs matplotlib: pip install '.[plot]' "
                                                     "from rbi's source folder, or pip install matplotlib).")] = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Simulate the body: a heavy top on its pivot (spec with `pivot`) or a torque-free body.

    Prints the conserved quantities' drift, an error estimate and, for a top, whether it
    sleeps; --out writes the trajectory (t, quaternion, ω, tilt, precession) as CSV, --plot
    draws it.

    \b
    Examples:
      rbi simulate top.yaml --spin 200 --tilt 0.01 --plot top.png
      rbi simulate top_bolted.yaml --spin 200 --duration 2 --out run.csv
      rbi simulate tbar.yaml --omega 0.01,0.01,3 --duration 20 --plot flip.png
    """
    from rbi.cli.output import check_distinct, output_target
    from rbi.sim.api import SimulationError

    check_run_options(method, spin, omega, tilt, duration, tilt_axis, gravity, max_steps, rtol)
    if samples < 1 or samples > MAX_SAMPLES:
        raise InputError(f"--samples: must be between 1 and {MAX_SAMPLES:,} (got {samples!r})")
    out_target = None if out is None else output_target(out, "--out", ("csv",), inputs=[file], stdout_format="csv")
    plot_target = None if plot is None else output_target(plot, "--plot", PLOT_FORMATS, inputs=[file])
    check_distinct([out_target, plot_target])
    if out_target is not None and out_target.is_stdout and format != OutputFormat.csv:
        format = OutputFormat.csv  # the trajectory is what goes to standard output
    if plot is not None:
        from rbi.cli.plot import require_matplotlib

        require_matplotlib()

    body, scene, q0, omega0, budget = prepare_run(file, spin, omega, tilt, tilt_axis, gravity, duration, method,
                                                  rtol, max_steps, yes)
    from rbi.sim.summary import CSV_COLUMNS, error_estimate as estimate, sample_columns, summarize

    progress = _ProgressBar() if format == OutputFormat.table and sys.stdout.isatty() else None
    try:
        from rbi.sim.api import simulate as run

        trajectory = run(scene, q0, omega0, duration, samples, method=method, rtol=rtol, progress=progress,
                         max_steps=budget)
        result = summarize(scene, trajectory, q0, omega0)
        result["error_estimate"] = (estimate(scene, trajectory, q0, omega0, max_steps=budget)
                                    if error_estimate and method != "exact" else None)
    except SimulationError as exc:
        raise InputError(f"{file}: {exc}") from None
    finally:
        if progress is not None:
            progress.close()

    columns = sample_columns(scene, trajectory)
    _refuse_non_finite(file, columns)
    shown = columns
    if plot is not None and method in ("default", "exact") and trajectory.t.size < PLOT_SAMPLES and duration > 0:
        try:  # the same run sampled more densely (dense output: the steps do not change)
            dense = run(scene, q0, omega0, duration, PLOT_SAMPLES, method=method, rtol=rtol, max_steps=budget)
        except SimulationError as exc:
            raise InputError(f"{file}: {exc}") from None
        shown = sample_columns(scene, dense)
    rows = [dict(zip(CSV_COLUMNS, values)) for values in zip(*(columns[c] for c in CSV_COLUMNS))]
    trajectory_csv = to_csv(rows) if out is not None or format == OutputFormat.csv else ""
    result = {
        "name": body.name,
        "units": body.units,
        "scene": "heavy top on a fixed pivot" if scene.pivoted else "free body (torque-free about the centre of mass)",
        "pivot": scene.pivot,
        "gravity": scene.gravity,
        "duration": duration,
        "samples": int(trajectory.t.size),
        "initial": {"t": 0.0, "q": q0, "omega": omega0, "tilt_deg": float(tilt)},
    } | result
    if out is not None and not out_target.is_stdout:
        result["out"] = out
    if format != OutputFormat.csv:
        from rbi.cli.render import refuse_non_finite

        refuse_non_finite(result)

    from rbi.cli.output import write_output

    if out_target is not None and not out_target.is_stdout:
        write_output(out_target, trajectory_csv)
    if plot_target is not None:
        from rbi.cli.plot import plot_trajectory

        title = f"{body.name or file}: spin {number(float(np.linalg.norm(omega0)))} rad/s, tilt {number(tilt)}°"
        free = {} if scene.pivoted else {"principal_axes": scene.principal_axes, "inertia": scene.inertia}
        write_output(plot_target, writer=lambda path: plot_trajectory(
            shown, path, title=title, format=plot_target.format, energy_unit=energy_unit(body), **free))
    if format == OutputFormat.csv:
        sys.stdout.write(trajectory_csv)
        return
    emit(format.value, result, lambda: _table(body, result))


def energy_unit(body) -> str:
    """The unit of an energy in the spec's units: J in SI, otherwise mass·length²/s²."""
    return "J" if (body.mass_unit, body.length_unit) == ("kg", "m") else body.labels["energy"]


def check_run_options(method, spin, omega, tilt, duration, tilt_axis, gravity, max_steps, rtol) -> None:
    """Refuse, before any work, the run options that `simulate` and `animate` share."""
    from rbi.sim.api import METHODS

    if method not in METHODS:
        raise InputError(f"--method: must be one of {', '.join(METHODS)} (got {method!r})")
    if spin is not None and omega is not None:
        raise InputError("--spin and --omega: give one or the other, not both")
    if spin is not None and not np.isfinite(spin):
        raise InputError(f"--spin: must be a finite number (got {spin!r})")
    if not np.isfinite(tilt):
        raise InputError(f"--tilt: must be a finite number (got {tilt!r})")
    check_run_settings(duration, tilt_axis, gravity, max_steps, rtol)
    if omega is not None:
        parse_vector(omega, "--omega")


def check_run_settings(duration, tilt_axis, gravity, max_steps, rtol) -> None:
    """Refuse, before any work, the settings of a run that `simulate`, `animate` and `sweep`
    all take: duration, tilt axis, gravity, step budget and tolerance."""
    from rbi.sim.api import RTOL_RANGE

    if not (np.isfinite(duration) and duration >= 0.0):
        raise InputError(f"--duration: must be a finite number of seconds >= 0 (got {duration!r})")
    if tilt_axis.lower() not in ("x", "y"):
        raise InputError(f"--tilt-axis: must be x or y (got {tilt_axis!r})")
    if gravity is not None and not (np.isfinite(gravity) and gravity >= 0.0):
        raise InputError(f"--gravity: must be a finite number of m/s² >= 0 (got {gravity!r})")
    if max_steps is not None and max_steps < 1:
        raise InputError(f"--max-steps: must be at least 1 (got {max_steps!r})")
    if rtol is not None and not (np.isfinite(rtol) and RTOL_RANGE[0] <= rtol < RTOL_RANGE[1]):
        raise InputError(f"--rtol: must be between {RTOL_RANGE[0]:g} and {RTOL_RANGE[1]:g} (got {rtol!r})")


def prepare_run(file, spin, omega, tilt, tilt_axis, gravity, duration, method, rtol, max_steps, yes):
    """Load the spec and set up the run: ``(body, scene, q0, omega0, step budget)``; the run
    estimated to exceed the budget is refused unless ``yes``."""
    from rbi.spec.load import load_body
    from rbi.spec.units import STANDARD_GRAVITY_SI, gravity_in

    w0 = parse_vector(omega, "--omega") if omega is not None else [0.0, 0.0, 0.0 if spin is None else spin]
    body = load_body(file)
    g_si = STANDARD_GRAVITY_SI if gravity is None else float(gravity)
    scene = _scene(body, gravity_in(body.length_unit, g_si))
    from rbi.sim.budget import estimated_steps
    from rbi.sim.scene import initial_state

    q0, omega0 = initial_state(tilt, w0, tilt_axis.lower())
    budget = DEFAULT_MAX_STEPS if max_steps is None else int(max_steps)
    if method != "exact":
        needed = estimated_steps(scene, omega0, duration, method, rtol)
        if needed > budget and not yes:
            raise InputError(
                f"{file}: this run is estimated to need about {needed:.2g} integration steps, more than the "
                f"budget of {budget:.2g}: shorten --duration, lower the spin, loosen --rtol, or raise the budget "
                f"with --max-steps N (or --yes to try anyway)")
    return body, scene, q0, omega0, budget


def _refuse_non_finite(file: str, columns: dict) -> None:
    """A trajectory that overflowed is bad input (absurd spin or inertia), never written out."""
    for name, values in columns.items():
        if name != "precession_deg" and not np.all(np.isfinite(values)):
            raise InputError(f"{file}: the trajectory's {name} is not finite: the input values are too large "
                             "for double precision")


def _scene(body, gravity: float):
    from rbi.sim.scene import scene_from_properties

    try:
        return scene_from_properties(body.props, body.pivot, gravity)
    except ValueError as exc:
        where = "pivot: " if body.pivot is not None else ""
        raise InputError(f"{body.path}: {where}cannot simulate: {exc}") from None


class _ProgressBar:
    """A rich progress bar that appears only once a run has taken more than a moment."""

    DELAY_SECONDS = 0.5

    def __init__(self) -> None:
        self.start = time.perf_counter()
        self.bar = None
        self.task = None

    def __call__(self, fraction: float) -> None:
        if self.bar is None:
            if time.perf_counter() - self.start < self.DELAY_SECONDS:
                return
            from rich.progress import BarColumn, Progress, TextColumn, TimeRemainingColumn

            from rbi.cli.render import stdout_console

            self.bar = Progress(TextColumn("simulating"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                                TimeRemainingColumn(), console=stdout_console(), transient=True)
            self.task = self.bar.add_task("simulate", total=1.0)
            self.bar.start()
        self.bar.update(self.task, completed=min(max(fraction, 0.0), 1.0))

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


def _table(body, result: dict):
    from rich.text import Text

    from rbi.cli import tables

    labels = body.labels
    final = result["final"]
    motion = [
        ("scene", "", result["scene"]),
        ("method", "", result["method"]),
        ("duration, samples", "s", f"{number(result['duration'])}, {result['samples']}"),
        ("final q [w, x, y, z]", "", tables.vector(final["q"])),
        ("final ω (body axes)", "rad/s", tables.vector(final["omega"])),
        ("final tilt of body z", "deg", number(final["tilt_deg"])),
        ("tilt min … max (nutation)", "deg", f"{number(result['tilt_min_deg'])} … {number(result['tilt_max_deg'])}"),
        ("mean precession rate", "deg/s", "undefined (the axis was vertical)"
         if result["mean_precession_rate_deg_s"] is None else number(result["mean_precession_rate_deg_s"])),
    ]
    names = {"energy": "energy", "h_vertical": "vertical h about pivot", "h_spin": "spin h·axis",
             "h_world": "h (world axes)"}
    accuracy = []
    for key, item in result["conserved"].items():
        initial = item["initial"]
        shown = tables.vector(initial) if np.ndim(initial) else number(initial, 10)
        unit = energy_unit(body) if item["unit"] == "energy" else labels[item["unit"]]
        accuracy.append((f"{names[key]}", unit, f"{shown}  (drift {number(item['drift'], 2)})"))
    accuracy.append(("| |q| − 1 | largest", "", number(result["quaternion_norm_error"], 2)))
    estimate = result.get("error_estimate")
    if estimate and estimate.get("orientation_deg") is None:
        accuracy.append(("error estimate", "", estimate["reference"]))
    elif estimate:
        accuracy.append(("error estimate: orientation", "deg", number(estimate["orientation_deg"], 2)))
        accuracy.append(("error estimate: ω", "rad/s", number(estimate["omega_rad_s"], 2)))
    accuracy += [
        ("steps (rejected)", "", f"{result['steps']} ({result['rejected_steps']})"),
        ("right-hand-side evaluations", "", str(result["rhs_evals"])),
        ("integration wall time", "s", number(result["wall_seconds"], 3)),
    ]
    if result["load_seconds"] > 0.05:
        accuracy.append(("loading the compiled kernel", "s", number(result["load_seconds"], 3)))
    notes = [f"Integrator: {result['integrator']}.", f"Stability: {result['stability']['verdict']}."]
    facts = result.get("closed_form")
    if facts and facts.get("kind") == "Lagrange top":
        notes.append(f"Closed form (Lagrange top): tilt between {number(facts['nutation_tilt_min_deg'])} and "
                     f"{number(facts['nutation_tilt_max_deg'])} deg, nutation period {number(facts['nutation_period_s'])} s, "
                     f"mean precession {number(facts['mean_precession_rate_deg_s'])} deg/s.")
    elif facts and facts.get("kind") == "asymmetric free body":
        flips = (f"; near the intermediate axis the body turns over every {number(facts['half_period_s'])} s"
                 if result["stability"].get("intermediate_axis") else "")
        notes.append(f"Closed form (Euler–Poinsot): ω repeats every {number(facts['omega_period_s'])} s "
                     f"(4K(m)/λ, m = {number(facts['elliptic_parameter'])}){flips}.")
    if "out" in result:
        notes.append(f"Trajectory written to {result['out']}.")
    return tables.stack(
        tables.quantities(f"{body.name or body.path} — simulate", motion),
        tables.quantities("Accuracy and cost", accuracy),
        Text("\n".join(notes)),
    )
