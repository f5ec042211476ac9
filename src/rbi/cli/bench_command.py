"""`rbi bench`: work-precision, mass-property throughput and latency, measured in one run."""

from __future__ import annotations

import contextlib
import os
import sys
from pathlib import Path
from typing import Annotated

import typer
from rich import box
from rich.console import Group
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from rbi.api import SpecError, check_distinct, output_target, write_output
from rbi.bench import report, suite
from rbi.bench.paths import bodies_folder
from rbi.bench.workprecision import plot as draw
from rbi.cli.options import FormatOption, OutputFormat, needs, require_matplotlib
from rbi.cli.render import emit, progress_bar
from rbi.cli.terminal import terminal_safe

QuickOption = Annotated[
    bool,
    typer.Option(
        "--quick",
        help="A CI-sized run of a few seconds: shorter cases, fewer tolerances and sizes, fewer repeats.",
    ),
]
OnlyOption = Annotated[
    str | None,
    typer.Option(
        "--only",
        metavar="SECTIONS",
        help=f"Comma-separated sections to run: {', '.join(suite.NAMES)} (default: all).",
    ),
]
PlotOption = Annotated[
    str | None,
    typer.Option(
        "--plot",
        metavar="FILE.png",
        help="Write a log–log plot of error against time, .png, .svg or .pdf "
        f"({needs('matplotlib', 'plot')}).",
    ),
]
WriteDocsOption = Annotated[
    str | None,
    typer.Option(
        "--write-docs", metavar="FILE.md", help="Write the report as Markdown (docs/performance.md)."
    ),
]


def bench(
    quick: QuickOption = False,
    only: OnlyOption = None,
    plot: PlotOption = None,
    write_docs: WriteDocsOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Measure what accuracy costs and how fast rbi is, each target against its baseline measured in
    the same run: the integrator against the textbook's scipy RK45 set-up and a minimal loop, error against time
    for each integrator, mass properties of 10³…10⁶ point masses, large specs against a bare YAML
    load, whole-process latency against importing numpy, sweep throughput and memory, and a CAD
    plate with 200 holes read as STEP (exact) against the same plate as an STL of 10⁵ triangles.

    \b
    Examples:
      rbi bench --quick
      rbi bench --write-docs docs/performance.md \\
          --plot docs/performance-workprecision.png
    """

    sections = _sections(only)
    if plot and "workprecision" not in sections:
        raise SpecError("--plot: needs the workprecision section (drop --only or include it)")

    plot_target = output_target(plot, "--plot", ("png", "svg", "pdf")) if plot is not None else None
    docs_target = output_target(write_docs, "--write-docs", ("md",)) if write_docs is not None else None
    check_distinct([plot_target, docs_target])
    if plot:
        require_matplotlib()
    options = (("--only", only), ("--write-docs", write_docs), ("--plot", plot))
    command = " ".join(["rbi", "bench"] + ["--quick"] * quick + [w for o in options if o[1] for w in o])

    try:
        bodies_folder()
    except FileNotFoundError as exc:
        raise SpecError(str(exc)) from None

    with _progress(format, suite.planned_steps(quick, sections)) as step:
        result = suite.run(quick, sections, step, command)

    if plot:
        write_output(plot_target, writer=lambda temp: draw(result["workprecision"], temp))
    if write_docs:
        link = os.path.relpath(Path(plot).resolve(), Path(write_docs).resolve().parent) if plot else None
        write_output(docs_target, report.markdown(result, command, link))
        print(f"rbi: wrote {terminal_safe(write_docs)}", file=sys.stderr)
    emit(format.value, result, lambda: _tables(result), csv_rows=report.csv_rows(result))


def _sections(only: str | None) -> list[str]:
    if only is None:
        return list(suite.NAMES)
    chosen = [s.strip().lower() for s in only.split(",") if s.strip()]
    unknown = [s for s in chosen if s not in suite.NAMES]
    if unknown or not chosen:
        raise SpecError(f"--only: expected a comma-separated list of {', '.join(suite.NAMES)} (got {only!r})")
    return chosen


@contextlib.contextmanager
def _progress(format: OutputFormat, total: int):
    """A step callback: the progress bar on a terminal (table output only), else silent; each
    step names the measurement it starts."""

    steps = [0]
    with progress_bar("rbi bench", "", total=total, elapsed=True, show=format == OutputFormat.table) as bar:

        def step(label: str) -> None:
            if bar is not None:
                bar.update(steps[0], what=label)
            steps[0] += 1

        yield step


def _tables(result: dict) -> Group:
    """The report as rich tables and text: the machine (one line), each :class:`rbi.bench.report.Section`
    as docs/performance.md has it (its title, notes dim, table; code without backticks), then
    the headline."""

    parts = [Text(" · ".join(report.machine_facts(result)).replace("`", ""), style="dim")]
    for section in report.report_sections(result):
        parts += [Text(section.title.replace("`", ""))] if section.title else []
        parts += [Text(section.notes.replace("`", ""), style="dim")] if section.notes else []
        if section.rows:
            table = Table(box=box.SIMPLE_HEAD, show_edge=False)
            for header in section.columns:
                justify = section.justify(header)
                table.add_column(escape(header), justify=justify, no_wrap=header in section.no_wrap)
            for row in section.rows:
                table.add_row(*row)
            parts.append(table)
    lines = report.headline(result)
    return Group(*parts, *([Text("\n".join("• " + line for line in lines))] if lines else []))
