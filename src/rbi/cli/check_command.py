"""`rbi check`: compare the body with the spec's `expect:` block (mass budgets in CI).

Exit 0 when every expectation holds, 1 when any fails, 2 on bad input (including a spec
without an `expect:` block or with a malformed one); with several files, the worst of these.
"""

from __future__ import annotations

import rbi
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import FORMAT, OutputFormat, SpecFiles, command


@command(FORMAT)
def check(files: SpecFiles, *, format: OutputFormat) -> int:
    """Compare mass, centre of mass, principal moments and inertia with the spec's `expect:` block.

    Exit 0 when every expectation holds, 1 when any fails (for CI), 2 on bad input. With
    several files: 2 if any file is bad input, else 1 if any expectation fails, else 0.

    \b
    Examples:
      rbi check robot_link.yaml
      rbi check wheel_with_holes.yaml --format json
      rbi check specs/*.yaml --format csv
    """

    return report_each(files, check_of, format.value)


def check_of(file: str) -> FileReport:
    """What `rbi check` gives for one file; among several files, its CSV row is ``name, units,
    ok, passed, failed``."""
    checks = rbi.load(file).check()
    return FileReport(checks, failed=not checks.ok)
