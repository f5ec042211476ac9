"""`rbi sweep`: many simulations of one spec — stability maps, Monte Carlo tolerance studies —
or, with --mass-properties, the spread of the mass properties alone."""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path
from typing import Annotated, Optional

import typer

from rbi.cli.options import FormatOption, OutputFormat, SpecFile
from rbi.cli.render import emit, number
from rbi.sim.budget import DEFAULT_MAX_STEPS
from rbi.spec.errors import InputError

MAX_ROWS_SHOWN = 100_000
"""Most runs a sweep may print (json/csv/table) instead of writing them with --out."""

SWEEP_STEP_BUDGET = 2e10
"""Most integration steps a whole sweep is estimated to take before --yes is needed (about
four hours of one core)."""

def sweep(
    file: SpecFile,
    spin: Annotated[str, typer.Option("--spin", "-s", metavar="START:STOP:COUNT",
                                      help="Spins about the body z axis, rad/s (or one value).")] = "0",
    tilt: Annotated[str, typer.Option("--tilt", metavar="START:STOP:COUNT",
                                      help="Initial tilts, degrees (or one value).")] = "0",
    vary: Annotated[Optional[list[str]], typer.Option(
        "--vary", metavar="PATH=RANGE", help="Vary a number of the spec: PATH is parts.NAME.FIELD or "
        "parts.NAME.FIELD[i] (e.g. parts.bolt.position[0]); RANGE is START:STOP:COUNT, or normal(MEAN,SD) / "
        "uniform(LOW,HIGH) with --runs. Repeatable.")] = None,
    runs: Annotated[int, typer.Option("--runs", metavar="N", help="Monte Carlo: N draws of every "
                                      "normal()/uniform() --vary per grid point.")] = 1,
    seed: Annotated[int, typer.Option("--seed", metavar="S", help="Seed of the draws (same seed, same rows).")] = 0,
    duration: Annotated[float, typer.Option("--duration", "-t", metavar="T", help="Simulated time, s.")] = 4.0,
    samples: Annotated[int, typer.Option("--samples", "-n", metavar="N",
                                         help="Samples per run the summaries are taken over (as rbi simulate).")] = 481,
    rtol: Annotated[float, typer.Option("--rtol", metavar="RTOL", help="Integrator tolerance (as rbi simulate).")] = 1e-12,
    gravity: Annotated[Optional[float], typer.Option("--gravity", "-g", metavar="G",
                                                     help="Gravity in m/s² (default 9.81).")] = None,
    tilt_axis: Annotated[str, typer.Option("--tilt-axis", metavar="x|y",
                                           help="World axis the initial tilt turns about.")] = "y",
    max_steps: Annotated[Optional[int], typer.Option(
        "--max-steps", metavar="N", help=f"Most steps one run may take (default {DEFAULT_MAX_STEPS:.0e}); a run "
                                         "that needs more is a failed row.")] = None,
    workers: Annotated[Optional[int], typer.Option("--workers", "-j", metavar="N",
                                                   help="Cores to use (default: all).")] = None,
    dask: Annotated[Optional[str], typer.Option(
        "--dask", metavar="ADDRESS", help="Run on the Dask scheduler at ADDRESS (tcp://host:8786), or 'local' "
                                          "for a local cluster (needs: pip install '.[dask]').")] = None,
    out: Annotated[Optional[str], typer.Option("--out", "-o", metavar="FILE.csv|FILE.parquet",
                                               help="Write one row per run, streamed as runs finish.")] = None,
    resume: Annotated[bool, typer.Option("--resume", help="Continue an interrupted sweep into --out: compute "
                                                          "only the runs missing there.")] = False,
    plot: Annotated[Optional[str], typer.Option("--plot", metavar="FILE.png|.svg|.pdf",
                                                help="Draw the map: largest tilt over the first two swept "
                                                     "axes (needs matplotlib).")] = None,
    mass_properties: Annotated[bool, typer.Option(
        "--mass-properties", help="No simulation: the spread of mass, centre of mass, principal moments and "
                                  "principal-axis directions over the --vary values.")] = False,
    yes: Annotated[bool, typer.Option("--yes", "-y", help="Run even when the sweep is estimated to take "
                                                          "longer than the budget.")] = False,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Many runs of one spec: a grid over spin, tilt and spec fields, or Monte Carlo draws.

    One row per run: the swept values, the largest, final and smallest tilt of the body z axis,
    the mean precession rate, the energy drift, the steps taken and a status (ok, or why that
    run failed: one failed run never stops the others). Runs use every core.

    \b
    Examples:
      rbi sweep top.yaml --spin 150:260:12 --tilt 0.01:1:5 --out map.csv --plot map.png
      rbi sweep top_bolted.yaml --spin 200 --vary 'parts.bolt.mass=normal(0.02,0.002)' --runs 500
      rbi sweep top_bolted.yaml --mass-properties --vary 'parts.bolt.position[0]=uniform(0.039,0.041)' --runs 1000
    """
    from rbi.cli.output import check_distinct, output_target
    from rbi.spec.load import read_yaml
    from rbi.spec.variations import current_values, resolve
    from rbi.runs.settings import check_run_settings
    from rbi.sweep.plan import Plan, parse_axis

    if runs < 1:
        raise InputError(f"--runs: must be at least 1 (got {runs})")
    check_run_settings(duration, tilt_axis, gravity, max_steps, rtol)
    if not 1 <= samples <= 100_000:
        raise InputError(f"--samples: must be between 1 and 100,000 for a sweep (got {samples})")
    if workers is not None and not 1 <= workers <= 1024:
        raise InputError(f"--workers: must be between 1 and 1024 (got {workers})")
    if resume and out is None:
        raise InputError("--resume: needs --out, the file of the interrupted sweep")
    if mass_properties and (spin != "0" or tilt != "0"):
        raise InputError("--mass-properties: takes --vary only (no --spin or --tilt: nothing is simulated)")
    out_target = None if out is None else output_target(out, "--out", ("csv", "parquet"), inputs=[file])
    plot_target = None if plot is None else output_target(plot, "--plot", ("png", "svg", "pdf"), inputs=[file])
    check_distinct([out_target, plot_target])
    if out_target is not None and out_target.format == "parquet":
        _require("pyarrow", "parquet", "--out FILE.parquet")
    if plot is not None:
        from rbi.cli.plot import require_matplotlib

        require_matplotlib()
    if dask is not None:
        _require("distributed", "dask", "--dask")

    raw = read_yaml(file)
    axes = []
    if not mass_properties:
        axes += [_axis(parse_axis, "spin", spin, "--spin"), _axis(parse_axis, "tilt_deg", tilt, "--tilt")]
    varied = []
    for item in vary or []:
        path_text, sep, range_text = item.partition("=")
        if not sep:
            raise InputError(f"--vary {item}: expected PATH=RANGE, e.g. parts.bolt.mass=0.01:0.03:5")
        path_text = path_text.strip()
        try:
            varied.append(resolve(raw, path_text))
        except InputError as exc:
            raise InputError(f"{file}: {exc}") from None
        axes.append(_axis(parse_axis, path_text, range_text, f"--vary {path_text}"))
    names = [a.name for a in axes]
    if len(set(names)) != len(names):
        raise InputError("--vary: a path is given twice")
    if mass_properties and not varied:
        raise InputError("--mass-properties: give at least one --vary PATH=RANGE")
    from rbi.sweep.plan import Draw

    if runs > 1 and not any(isinstance(a, Draw) for a in axes):
        raise InputError("--runs: Monte Carlo needs a --vary PATH=normal(MEAN,SD) or uniform(LOW,HIGH)")
    if seed < 0:
        raise InputError(f"--seed: must be a whole number 0 or above (got {seed})")
    plan = Plan(tuple(axes), runs=runs, seed=seed)
    if plan.size > 10**8:
        raise InputError(f"the sweep has {plan.size:.3g} runs, more than the 1e8 one sweep may have")
    if out is None and plan.size > MAX_ROWS_SHOWN:
        raise InputError(f"the sweep has {plan.size:,} runs: more than {MAX_ROWS_SHOWN:,} are written to a file "
                         "only: add --out FILE.csv")

    from rbi.spec.units import STANDARD_GRAVITY_SI
    from rbi.sweep.runs import SweepJob

    job = SweepJob(path=str(file), raw=raw, plan=plan, varied=tuple(varied), duration=float(duration),
                   samples=int(samples), rtol=float(rtol),
                   gravity_si=STANDARD_GRAVITY_SI if gravity is None else float(gravity),
                   tilt_axis=tilt_axis.lower(), max_steps=DEFAULT_MAX_STEPS if max_steps is None else int(max_steps))
    nominal = job.body(tuple(current_values(raw, varied)))
    if isinstance(nominal, str):
        raise InputError(f"{file}: {nominal}")
    if mass_properties:
        from rbi.sweep.tolerance import MASS_COLUMNS, mass_rows, nominal_axes

        columns = ["run", *plan.names, *MASS_COLUMNS]
        axes_nominal = nominal_axes(job)

        def compute(a, b, threads):
            return mass_rows(job, axes_nominal, a, b)
        chunk = 256
    else:
        _check_budget(job, nominal, plan, yes)
        from rbi.sweep.runs import run_chunk

        columns = job.columns

        def compute(a, b, threads):
            return run_chunk(job, a, b, threads)
        from rbi.sweep.execute import available_cores

        chunk = job.chunk_size(workers or available_cores())

    rows, done = _execute(job, columns, compute, chunk, out_target, resume, workers, dask, format, file, out,
                          spin, tilt, vary, mass_properties)
    result = {"name": nominal.name, "units": nominal.units, "count": plan.size, "columns": columns}
    ok = sum(1 for r in rows if r[-1] == "ok") if rows is not None else None
    if rows is not None:
        result["runs"] = [dict(zip(columns, r)) for r in rows]
        result["failed"] = plan.size - ok
    if out is not None:
        result["out"] = out
    if mass_properties and rows is not None:
        from rbi.sweep.tolerance import spread

        result["spread"] = spread(columns, rows, 1)
    if plot_target is not None:
        if rows is None:
            raise InputError("--plot: the map is drawn from the rows of this run; with more than "
                             f"{MAX_ROWS_SHOWN:,} runs draw it from the --out file")
        _plot(plot_target, job, nominal, columns, rows, mass_properties)
        result["plot"] = plot
    if format == OutputFormat.csv:
        from rbi.cli.render import to_csv

        sys.stdout.write(to_csv(result.get("runs", [])))
        return
    emit(format.value, result, lambda: _table(result, columns, rows, file))


def _axis(parse, name, text, option):
    try:
        return parse(name, text)
    except ValueError as exc:
        raise InputError(f"{option}: {exc}") from None


def _require(module: str, extra: str, option: str) -> None:
    import importlib.util

    if importlib.util.find_spec(module) is None:
        raise InputError(f"{option}: needs the optional package {module!r}: pip install '.[{extra}]' from rbi's "
                         f"source folder, or pip install {module}")


def _check_budget(job, nominal, plan, yes: bool) -> None:
    """Refuse, before any run, a sweep estimated to take more than the step budget."""
    import numpy as np

    from rbi.sim.budget import estimated_steps
    from rbi.sim.scene import scene_from_properties
    from rbi.spec.units import gravity_in

    try:
        scene = scene_from_properties(nominal.props, nominal.pivot, gravity_in(nominal.length_unit, job.gravity_si))
    except ValueError:
        return  # every run will say why it cannot be simulated
    spins = [a for a in plan.axes if a.name == "spin"][0]
    fastest = max(abs(spins.start), abs(spins.stop)) if hasattr(spins, "start") else 0.0
    per_run = estimated_steps(scene, np.array([0.0, 0.0, fastest]), job.duration, "default", job.rtol)
    total = per_run * plan.size
    if total > SWEEP_STEP_BUDGET and not yes:
        raise InputError(f"{job.path}: this sweep is estimated to need about {total:.2g} integration steps "
                         f"({plan.size:,} runs), more than the budget of {SWEEP_STEP_BUDGET:.0e}: fewer runs, a "
                         "shorter --duration or a looser --rtol, or --yes to run it anyway")


def _settings(job, file, spin, tilt, vary, mass_properties) -> dict:
    return {"spec_sha256": hashlib.sha256(Path(file).read_bytes()).hexdigest(), "spin": spin, "tilt": tilt,
            "vary": list(vary or []), "runs": job.plan.runs, "seed": job.plan.seed, "duration": job.duration,
            "samples": job.samples, "rtol": job.rtol, "gravity_si": job.gravity_si, "tilt_axis": job.tilt_axis,
            "max_steps": job.max_steps, "mass_properties": mass_properties}


def _execute(job, columns, compute, chunk, out_target, resume, workers, dask, format, file, out, spin, tilt, vary,
             mass_properties):
    """Run every run not already in --out; rows in memory when they are to be printed or drawn
    (None for a sweep too large to hold)."""
    from rbi.sweep import store
    from rbi.sweep.execute import available_cores, chunk_ranges, run_dask, run_local

    plan = job.plan
    keep_in_memory = plan.size <= MAX_ROWS_SHOWN
    rows: list | None = [] if keep_in_memory else None
    output = None
    start = 0
    if out_target is not None:
        output = store.SweepOutput(out_target, columns, plan, _settings(job, file, spin, tilt, vary, mass_properties))
        kept = output.open(resume, keep=keep_in_memory)
        start = output.done
        if rows is not None:
            rows.extend(kept)
    progress = _Progress(plan.size, start) if sys.stderr.isatty() else None
    done = [start]

    def on_rows(new_rows):
        if output is not None:
            output.write(new_rows)
        if rows is not None:
            rows.extend(new_rows)
        done[0] += len(new_rows)
        if progress is not None:
            progress.update(done[0])

    from rbi.cli.terminal import Terminated, say

    try:
        ranges = chunk_ranges(start, plan.size, chunk)
        if dask is not None:
            run_dask(compute, ranges, dask, on_rows, workers)
        else:
            run_local(compute, ranges, workers or available_cores(), on_rows)
    except (KeyboardInterrupt, Terminated) as stop:
        if output is None:
            raise
        output.close()
        if progress is not None:
            progress.close()
            progress = None
        word, code = ("terminated", 143) if isinstance(stop, Terminated) else ("interrupted", 130)
        say(f"{word}: {output.done:,} of {plan.size:,} runs kept in {out}; run the same command with --resume "
            "to compute the rest")
        raise SystemExit(code) from None
    except BaseException:
        if output is not None:
            output.close()  # a failed write has said how many runs are kept
        raise
    finally:
        if progress is not None:
            progress.close()
    if output is not None:
        output.finish()
    return rows, done[0]


class _Progress:
    """Runs done, with a rate and the time left, on standard error."""

    def __init__(self, total: int, done: int) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

        self.bar = Progress(TextColumn("sweep"), BarColumn(), MofNCompleteColumn(), TextColumn("runs"),
                            TimeRemainingColumn(), console=Console(stderr=True), transient=True)
        self.task = self.bar.add_task("sweep", total=total, completed=done)
        self.bar.start()

    def update(self, done: int) -> None:
        self.bar.update(self.task, completed=done)

    def close(self) -> None:
        self.bar.stop()


def _plot(target, job, nominal, columns, rows, mass_properties) -> None:
    from rbi.cli.output import write_output
    from rbi.cli.plot import plot_stability_map

    if mass_properties:
        raise InputError("--plot: a map needs simulated runs (not --mass-properties)")
    swept = [a.name for a in job.plan.axes if job.plan.is_grid_axis(a.name)]
    if not swept:
        raise InputError("--plot: the map needs at least one axis with more than one value")
    threshold = None
    if "spin" in swept:
        from rbi.sim.diagnostics import sleeping_threshold
        from rbi.sim.scene import scene_from_properties
        from rbi.spec.units import gravity_in

        try:
            scene = scene_from_properties(nominal.props, nominal.pivot, gravity_in(nominal.length_unit, job.gravity_si))
            found = sleeping_threshold(scene)
            threshold = None if found is None else found["omega3"]
        except ValueError:
            threshold = None
    x_name = swept[0]
    y_name = swept[1] if len(swept) > 1 else None
    index = {name: i for i, name in enumerate(columns)}
    xs = [r[index[x_name]] for r in rows]
    ys = [r[index[y_name]] for r in rows] if y_name else None
    values = [r[index["max_tilt_deg"]] for r in rows]
    from rbi.viz.labels import label

    title = f"{label(nominal.name or job.path)}: largest tilt over {job.duration:g} s"
    write_output(target, writer=lambda path: plot_stability_map(
        xs, ys, values, path, x_label=_label(x_name), y_label=_label(y_name) if y_name else None,
        threshold=threshold if x_name == "spin" else None, title=title, format=target.format))


def _label(name: str) -> str:
    return {"spin": "spin, rad/s", "tilt_deg": "initial tilt, deg"}.get(name, name)


def _table(result, columns, rows, file):
    from rbi.cli import tables

    from rich.table import Table
    from rich.text import Text

    units = {"spin": "rad/s", "tilt_deg": "deg", "max_tilt_deg": "deg", "final_tilt_deg": "deg",
             "min_tilt_deg": "deg", "precession_rate_deg_s": "deg/s", "energy_drift": "relative",
             "axis_1_tilt_deg": "deg", "axis_2_tilt_deg": "deg", "axis_3_tilt_deg": "deg"}
    notes = [f"{result['count']:,} runs"]
    if "failed" in result:
        notes[0] += f", {result['failed']:,} failed"
    if "out" in result:
        notes.append(f"Rows written to {result['out']}.")
    if "plot" in result:
        notes.append(f"Map drawn in {result['plot']}.")
    parts = []
    if rows is not None and not result.get("spread"):  # a tolerance study shows its spread instead
        shown = rows if len(rows) <= 40 else rows[:20] + [None] + rows[-20:]
        table = Table(title=tables.plain_text(f"{result['name'] or file} — sweep"))
        hidden = {"min_tilt_deg", "precession_rate_deg_s", "steps"}  # in --out, json and csv
        keep = [i for i, name in enumerate(columns) if name not in hidden]
        columns = [columns[i] for i in keep]
        shown = [None if row is None else [row[i] for i in keep] for row in shown]
        for name in columns:
            # words wrap in a narrow terminal and no cell is cut short: a number is never shown truncated
            words = name.removesuffix("_deg_s").removesuffix("_deg").replace("_", " ")  # the unit is below
            header = tables.plain_text(name if name.startswith("parts.") else words)
            table.add_column(f"{header}\n{units.get(name, '')}".rstrip(), overflow="fold",
                             justify="left" if name == "status" else "right")
        for row in shown:
            if row is None:
                table.add_row(*["…"] * len(columns))
                continue
            table.add_row(*[tables.plain_text(str(v)) if isinstance(v, str) else
                            ("—" if v is None else (str(v) if isinstance(v, int) else number(v, 4))) for v in row])
        parts.append(table)
    if result.get("spread"):
        spread = Table(title="Spread over the ok runs")
        spread.add_column("quantity", no_wrap=True)
        spread.add_column("unit")
        for name in ("min", "median", "max", "std"):
            spread.add_column(name, justify="right")
        labels = {"mass": result["units"]["mass"], "com_x": result["units"]["length"]}
        for name, stats in result["spread"].items():
            unit = units.get(name) or labels.get(name) or ("" if not name.startswith(("com_", "moment_")) else
                                                           result["units"]["length"] if name.startswith("com_") else
                                                           f"{result['units']['mass']}·{result['units']['length']}²")
            spread.add_row(name, unit, *[number(stats[k], 4) for k in ("p0", "p50", "p100", "std")])
        parts.append(spread)
    parts.append(Text("\n".join(notes)))
    return tables.stack(*parts)

