"""`rbi simulate`: the motion of a heavy top on its pivot, or of a free body."""

from __future__ import annotations

import os
import sys
import tempfile
import time
from typing import Annotated, Optional

import numpy as np
import typer

from rbi.cli.options import FormatOption, OutputFormat, SpecFile, parse_vector
from rbi.cli.render import emit, number, to_csv
from rbi.spec.errors import InputError

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
                                        help="Initial tilt about the world y axis, degrees.")] = 0.0,
    duration: Annotated[float, typer.Option("--duration", "-t", metavar="T", help="Simulated time, s.")] = 4.0,
    samples: Annotated[int, typer.Option("--samples", "-n", metavar="N",
                                         help="Samples, equally spaced from t=0 to t=T (1: only the end).")] = 481,
    out: Annotated[Optional[str], typer.Option("--out", "-o", metavar="FILE.csv",
                                               help="Write the trajectory as CSV (only if the run succeeds).")] = None,
    method: Annotated[str, typer.Option("--method", "-m", help=METHOD_HELP)] = "default",
    rtol: Annotated[Optional[float], typer.Option(
        "--rtol", help="Tolerance of the integrator (default 1e-12 for default, 1e-8 for rk45/dop853): smaller "
                       "is more accurate and slower.")] = None,
    error_estimate: Annotated[bool, typer.Option(
        "--error-estimate/--no-error-estimate",
        help="Estimate the trajectory's error with a second run at a 1000x tighter tolerance.")] = True,
    plot: Annotated[Optional[str], typer.Option("--plot", metavar="FILE.png",
                                                help="Plot tilt against time and the path of the body z axis "
                                                     "seen from above (needs matplotlib: pip install 'rbi[plot]').")] = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Simulate the body: a heavy top on its pivot (spec with `pivot`) or a torque-free body."""
    from rbi.sim.api import METHODS, RTOL_RANGE, SimulationError
    from rbi.spec.load import load_body
    from rbi.spec.units import gravity_in

    if method not in METHODS:
        raise InputError(f"--method: must be one of {', '.join(METHODS)} (got {method!r})")
    if spin is not None and omega is not None:
        raise InputError("--spin and --omega: give one or the other, not both")
    if spin is not None and not np.isfinite(spin):
        raise InputError(f"--spin: must be a finite number (got {spin!r})")
    if not np.isfinite(tilt):
        raise InputError(f"--tilt: must be a finite number (got {tilt!r})")
    w0 = parse_vector(omega, "--omega") if omega is not None else [0.0, 0.0, 0.0 if spin is None else spin]
    if not (np.isfinite(duration) and duration >= 0.0):
        raise InputError(f"--duration: must be a finite number of seconds >= 0 (got {duration!r})")
    if samples < 1:
        raise InputError(f"--samples: must be at least 1 (got {samples!r})")
    if rtol is not None and not (np.isfinite(rtol) and RTOL_RANGE[0] <= rtol < RTOL_RANGE[1]):
        raise InputError(f"--rtol: must be between {RTOL_RANGE[0]:g} and {RTOL_RANGE[1]:g} (got {rtol!r})")
    for path, option in ((out, "--out"), (plot, "--plot")):
        if path is not None:
            _check_writable(path, option)
    if plot is not None:
        from rbi.cli.plot import require_matplotlib

        require_matplotlib()

    body = load_body(file)
    scene = _scene(body, gravity_in(body.length_unit))
    from rbi.sim.scene import initial_state
    from rbi.sim.summary import CSV_COLUMNS, error_estimate as estimate, sample_columns, summarize

    q0, omega0 = initial_state(tilt, w0)
    progress = _ProgressBar() if format == OutputFormat.table and sys.stdout.isatty() else None
    try:
        from rbi.sim.api import simulate as run

        trajectory = run(scene, q0, omega0, duration, samples, method=method, rtol=rtol, progress=progress)
        result = summarize(scene, trajectory, q0, omega0)
        result["error_estimate"] = estimate(scene, trajectory, q0, omega0) if error_estimate else None
    except SimulationError as exc:
        raise InputError(f"{file}: {exc}") from None
    finally:
        if progress is not None:
            progress.close()

    columns = sample_columns(scene, trajectory)
    rows = [dict(zip(CSV_COLUMNS, values)) for values in zip(*(columns[c] for c in CSV_COLUMNS))]
    trajectory_csv = to_csv(rows) if out is not None or format == OutputFormat.csv else ""
    if out is not None:
        _write_atomically(out, trajectory_csv)
    if plot is not None:
        from rbi.cli.plot import plot_trajectory

        shown = columns
        if method in ("default", "exact") and trajectory.t.size < PLOT_SAMPLES and duration > 0:
            # the same run sampled more densely (dense output: the steps do not change)
            dense = run(scene, q0, omega0, duration, PLOT_SAMPLES, method=method, rtol=rtol)
            shown = sample_columns(scene, dense)
        _write_atomically(plot, None, lambda path: plot_trajectory(shown, path, title=body.name or file))
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
    if out is not None:
        result["out"] = out

    if format == OutputFormat.csv:
        sys.stdout.write(trajectory_csv)
        return
    emit(format.value, result, lambda: _table(body, result))


def _scene(body, gravity: float):
    from rbi.sim.scene import scene_from_properties

    try:
        return scene_from_properties(body.props, body.pivot, gravity)
    except ValueError as exc:
        where = "pivot: " if body.pivot is not None else ""
        raise InputError(f"{body.path}: {where}cannot simulate: {exc}") from None


def _check_writable(path: str, option: str) -> None:
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise InputError(f"{option}: {path}: folder {folder} does not exist")
    if os.path.isdir(path):
        raise InputError(f"{option}: {path}: is a folder, not a file")
    if not os.access(folder, os.W_OK):
        raise InputError(f"{option}: {path}: folder {folder} is not writable")


def _write_atomically(path: str, text: str | None, writer=None) -> None:
    """Write ``text`` (or let ``writer(temp_path)`` write) to a temporary file beside ``path``,
    then rename it into place: ``path`` never holds a half-written file."""
    folder = os.path.dirname(os.path.abspath(path))
    suffix = os.path.splitext(path)[1]
    fd, temp = tempfile.mkstemp(prefix=".rbi-", suffix=suffix, dir=folder)
    try:
        with os.fdopen(fd, "w") as handle:
            if text is not None:
                handle.write(text)
        if writer is not None:
            writer(temp)
        os.replace(temp, path)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


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
        ("mean precession rate", "deg/s", number(result["mean_precession_rate_deg_s"])),
    ]
    names = {"energy": "energy", "h_vertical": "vertical h about pivot", "h_spin": "spin h·axis",
             "h_world": "h (world axes)"}
    accuracy = []
    for key, item in result["conserved"].items():
        initial = item["initial"]
        shown = tables.vector(initial) if np.ndim(initial) else number(initial, 10)
        accuracy.append((f"{names[key]}", labels[item["unit"]], f"{shown}  (drift {number(item['drift'], 2)})"))
    accuracy.append(("| |q| − 1 | largest", "", number(result["quaternion_norm_error"], 2)))
    estimate = result.get("error_estimate")
    if estimate:
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
