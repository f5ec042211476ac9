"""`rbi check`: compare the body with the spec's `expect:` block (mass budgets in CI).

Exit 0 when every expectation holds, 1 when any fails, 2 on bad input (including a spec
without an `expect:` block or with a malformed one); with several files, the worst of these.
"""

from __future__ import annotations

from typing import Any

from rich.markup import escape

from rbi import api
from rbi.cli import tables
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import FormatOption, OutputFormat, SpecFiles
from rbi.cli.render import number


def check(files: SpecFiles, format: FormatOption = OutputFormat.table) -> int:
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


def check_of(file: str):
    """What `rbi check` gives for one file (:class:`rbi.cli.each_file.FileReport`); among
    several files, its CSV row is ``name, units, ok, passed, failed``."""

    body = api.load(file)
    checks = [_as_dict(c) for c in body.check()]
    failed = sum(not c["pass"] for c in checks)
    result = {
        "name": body.name,
        "units": body.units,
        "warnings": list(body.warnings),
        "ok": failed == 0,
        "passed": len(checks) - failed,
        "failed": failed,
        "checks": [{k: v for k, v in c.items() if k != "component_deviation"} for c in checks],
    }
    summary = {k: result[k] for k in ("name", "units", "ok", "passed", "failed")}
    return FileReport(
        result,
        lambda: _table(body, checks, failed),
        csv_rows=_csv_rows(checks),
        summary=summary,
        failed=bool(failed),
    )


def _as_dict(check) -> dict[str, Any]:
    """A `rbi.api.Check` as its JSON object (``component_deviation`` kept for the tables)."""
    out = {
        "quantity": check.quantity,
        "unit": check.unit,
        "expected": check.expected,
        "actual": check.actual,
        "deviation": check.deviation,
        "tol": check.tol,
        "allowed": check.allowed,
        "pass": check.passed,
        "component_deviation": check.component_deviation,
    }
    return out if check.about is None else out | {"about": check.about}


_MATRIX_ENTRIES = (("xx", 0, 0), ("yy", 1, 1), ("zz", 2, 2), ("xy", 0, 1), ("xz", 0, 2), ("yz", 1, 2))


def _components(check: dict[str, Any]):
    """(label, expected, actual, deviation) for each number a check compares; a matrix gives
    its six distinct entries."""
    want, got, deviation = check["expected"], check["actual"], check["component_deviation"]
    about = f" @{check['about']}" if check.get("about") not in (None, "com") else ""
    if check["quantity"] == "mass":
        return [("mass", float(want), float(got), float(deviation))]
    if check["quantity"] == "inertia":
        return [(f"I{name}{about}", want[i, j], got[i, j], deviation[i, j]) for name, i, j in _MATRIX_ENTRIES]
    names = ("I1", "I2", "I3") if check["quantity"] == "moments" else ("com x", "com y", "com z")
    return [(f"{name}{about}", w, g, d) for name, w, g, d in zip(names, want, got, deviation)]


def _csv_rows(checks) -> list[dict[str, Any]]:
    rows = []
    for c in checks:
        for label, want, got, deviation in _components(c):
            rows.append(
                {
                    "quantity": c["quantity"],
                    "component": label.split(" @")[0],
                    "about": c.get("about", ""),
                    "unit": c["unit"],
                    "expected": want,
                    "actual": got,
                    "deviation": deviation,
                    "allowed": c["allowed"],
                    "tol": str(c["tol"]),
                    "pass": bool(deviation <= c["allowed"]),
                }
            )
    return rows


def _table(body, checks, failed: int):

    verdict = "all expectations hold" if not failed else f"{failed} of {len(checks)} expectations FAIL"
    t = tables.titled(f"{body.name or body.path} — check: {verdict}")
    for header, justify in (
        ("quantity", "left"),
        ("unit", "left"),
        ("expected", "right"),
        ("actual", "right"),
        ("deviation", "right"),
        ("allowed", "right"),
        ("", "left"),
    ):
        t.add_column(header, justify=justify)
    for c in checks:
        for label, want, got, deviation in _components(c):
            ok = deviation <= c["allowed"]
            t.add_row(
                escape(label),
                escape(c["unit"]),
                number(want, 6),
                number(got, 6),
                number(deviation, 3),
                number(c["allowed"], 3),
                "ok" if ok else "[bold red]FAIL[/]",
            )
    return t
