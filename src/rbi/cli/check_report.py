"""What `rbi check` prints for one file: each expectation of the spec's `expect:` block against
the computed value (the options are declared in :mod:`rbi.cli.check_command`)."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.cli.each_file import FileReport, report_each
from rbi.cli.mass_reports import load_body
from rbi.cli.render import number
from rbi.errors import InputError


def compare(quantity: str, expected, actual, tol, unit: str) -> dict[str, Any]:
    """One expectation: per-component deviation against the allowed deviation.

    A percentage ``tol`` is taken of the largest magnitude in the expected value, so a
    zero component (a CoM on an axis) gets the same allowance as the others.
    """
    from rbi.spec.fields import tolerance_allowed

    want = np.asarray(expected, dtype=float)
    got = np.asarray(actual, dtype=float)
    allowed = tolerance_allowed(tol, float(np.max(np.abs(want))))
    deviation = np.abs(got - want)
    return {
        "quantity": quantity,
        "unit": unit,
        "expected": want,
        "actual": got,
        "deviation": float(np.max(deviation)),
        "tol": tol,
        "allowed": allowed,
        "pass": bool(np.all(deviation <= allowed)),
        "component_deviation": deviation,
    }


def _point(about, body) -> tuple[str, np.ndarray]:
    from rbi.spec.errors import InputError

    if isinstance(about, list):
        return "point", np.asarray(about, dtype=float)
    if about == "com":
        return "com", body.props.center_of_mass
    if about == "origin":
        return "origin", np.zeros(3)
    if body.pivot is None:
        raise InputError(f"{body.path}: expect: about: pivot needs a `pivot` in the spec, and there is none")
    return "pivot", body.pivot


def run_checks(body) -> list[dict[str, Any]]:
    """Every comparison the body's `expect:` block asks for, in a fixed order."""
    from rbi.core.inertia import principal_axes

    expect = body.spec.expect
    labels = body.labels
    checks = []
    if expect.mass is not None:
        checks.append(compare("mass", expect.mass.value, body.props.mass, expect.mass.tol, labels["mass"]))
    if expect.center_of_mass is not None:
        e = expect.center_of_mass
        checks.append(compare("center_of_mass", e.value, body.props.center_of_mass, e.tol, labels["length"]))
    if expect.moments is not None:
        e = expect.moments
        label, point = _point(e.about, body)
        moments, _ = principal_axes(body.props.inertia_about(point))
        checks.append(
            compare("moments", sorted(e.value), moments, e.tol, labels["inertia"]) | {"about": label}
        )
    if expect.inertia is not None:
        e = expect.inertia
        label, point = _point(e.about, body)
        checks.append(
            compare("inertia", e.value, body.props.inertia_about(point), e.tol, labels["inertia"])
            | {"about": label}
        )
    return checks


def check(files, fmt: str = "table") -> int:
    """`rbi check FILE...`: the exit status (see :func:`rbi.cli.each_file.report_each`)."""

    return report_each(files, check_of, fmt)


def check_of(file: str):
    """What `rbi check` gives for one file (:class:`rbi.cli.each_file.FileReport`); among
    several files, its CSV row is ``name, units, ok, passed, failed``."""

    body = load_body(file)
    if body.spec.expect is None:
        raise InputError(
            f"{body.path}: expect: the spec has no `expect:` block, so there is nothing to check "
            f"(see docs/check.md)"
        )
    checks = run_checks(body)
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


_SHORT = {"mass": "mass", "center_of_mass": "com", "moments": "", "inertia": "I"}
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
    from rich.markup import escape

    from rbi.cli import tables

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
