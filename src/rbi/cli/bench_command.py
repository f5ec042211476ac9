"""`rbi bench`: work-precision, mass-property throughput and latency, measured in one run."""

from __future__ import annotations

import sys

from rich import box
from rich.console import Group

from rbi.bench import report, suite
from rbi.cli.options import FORMAT, OutputFormat, command, needs, option, require_matplotlib
from rbi.cli.render import emit_result, note, progress_bar
from rbi.cli.tables import SafeTable
from rbi.cli.terminal import terminal_safe

OPTIONS = (
    option(
        bool,
        "--quick",
        help="A CI-sized run of a few seconds: shorter cases, fewer tolerances and sizes, fewer repeats.",
    ),
    option(
        str | None,
        "--only",
        metavar="SECTIONS",
        help=f"Comma-separated sections to run: {', '.join(suite.NAMES)} (default: all).",
    ),
    option(
        str | None,
        "--plot",
        metavar="FILE.png",
        help="Write a log–log plot of error against time, .png, .svg or .pdf "
        f"({needs('matplotlib', 'plot')}).",
    ),
    option(
        str | None,
        "--write-docs",
        metavar="FILE.md",
        help="Write the report as Markdown (docs/performance.md).",
    ),
    FORMAT,
)


@command(*OPTIONS, api=suite.run)
def bench(*, format: OutputFormat, **settings) -> None:
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
    if settings["plot"]:
        require_matplotlib()
    with progress_bar("rbi bench", "", elapsed=True, show=format == OutputFormat.table) as bar:
        result = suite.run(**settings, progress=bar.update if bar else lambda *_: None)
    if settings["write_docs"]:
        print(f"rbi: wrote {terminal_safe(settings['write_docs'])}", file=sys.stderr)
    emit_result(format.value, report.Report(result), table=lambda: _tables(result))


def _tables(result: dict) -> Group:
    """The report as rich tables and text: the machine (one line), each :class:`rbi.bench.report.Section`
    as docs/performance.md has it (its title, notes dim, table; code without backticks), then
    the headline."""

    parts = [note(" · ".join(report.machine_facts(result)).replace("`", ""), style="dim")]
    for section in report.report_sections(result):
        parts += [note(section.title.replace("`", ""))] if section.title else []
        parts += [note(section.notes.replace("`", ""), style="dim")] if section.notes else []
        if section.rows:
            table = SafeTable(box=box.SIMPLE_HEAD, show_edge=False)  # headers and cells are text, not markup
            for header in section.columns:
                table.add_column(header, justify=section.justify(header), no_wrap=header in section.no_wrap)
            for row in section.rows:
                table.add_row(*row)
            parts.append(table)
    lines = report.headline(result)
    return Group(*parts, *([note("\n".join("• " + line for line in lines))] if lines else []))
