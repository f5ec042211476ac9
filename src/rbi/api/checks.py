"""The `Checks` of a spec's ``expect:`` block against its body, as ``rbi check`` gives them: a
result (:class:`rbi.reprs.Result`) whose ``to_dict()`` is the command's JSON, its CSV one row a
compared number, its table one line a number with ``ok`` or ``FAIL``; and the `Validation` of
spec files, as ``rbi validate`` reports it."""

from __future__ import annotations

from typing import Any

from rbi.api.results import named
from rbi.reprs import Results, Rows
from rbi.spec.checks import Check
from rbi.text import number

_MATRIX_ENTRIES = (("xx", 0, 0), ("yy", 1, 1), ("zz", 2, 2), ("xy", 0, 1), ("xz", 0, 2), ("yz", 1, 2))


CHECK_KEYS = ("quantity", "unit", "expected", "actual", "deviation", "tol", "allowed", "passed", "about")
"""The fields of a `Check` that ``rbi check --format json`` lists, in its order (``passed`` as
``pass``; ``about`` only where there is one)."""


def _check_dict(check: Check) -> dict[str, Any]:
    """A check as ``rbi check --format json`` lists it (see :data:`CHECK_KEYS`)."""
    keys = CHECK_KEYS if check.about is not None else CHECK_KEYS[:-1]
    return {"pass" if k == "passed" else k: getattr(check, k) for k in keys}


def _components(check: Check) -> list[tuple[str, Any, Any, Any]]:
    """(component, expected, actual, deviation) for each number a check compares; a matrix
    gives its six distinct entries."""
    want, got, deviation = check.expected, check.actual, check.component_deviation
    if check.quantity == "mass":
        return [("mass", float(want), float(got), float(deviation))]
    if check.quantity == "inertia":
        return [(f"I{name}", want[i, j], got[i, j], deviation[i, j]) for name, i, j in _MATRIX_ENTRIES]
    names = ("I1", "I2", "I3") if check.quantity == "moments" else ("com x", "com y", "com z")
    return list(zip(names, want, got, deviation))


class Checks(Results[Check]):
    """The expectations of a spec's ``expect:`` block against the body, as ``rbi check``
    compares them: a sequence of `Check`, with ``passed`` and ``failed`` counts and ``ok``."""

    def __init__(self, body: Any, checks: list[Check]) -> None:
        self._body = body
        self._items = checks
        self.failed: int = sum(not c.passed for c in checks)
        self.passed: int = len(checks) - self.failed
        self.ok: bool = self.failed == 0

    def __repr__(self) -> str:
        return f"<rbi.Checks {self.passed} passed, {self.failed} failed>"

    def to_dict(self) -> dict[str, Any]:
        return named(self._body) | {
            "ok": self.ok,
            "passed": self.passed,
            "failed": self.failed,
            "checks": [_check_dict(c) for c in self._items],
        }

    def csv_rows(self) -> list[dict[str, Any]]:
        return [
            {
                "quantity": c.quantity,
                "component": component,
                "about": c.about or "",
                "unit": c.unit,
                "expected": want,
                "actual": got,
                "deviation": deviation,
                "allowed": c.allowed,
                "tol": str(c.tol),
                "pass": bool(deviation <= c.allowed),
            }
            for c in self._items
            for component, want, got, deviation in _components(c)
        ]

    def csv_summary(self) -> dict[str, Any]:
        return {k: v for k, v in self.to_dict().items() if k in ("name", "units", "ok", "passed", "failed")}

    def rows(self) -> list[Rows]:
        body, n = self._body, len(self)
        verdict = "all expectations hold" if not self.failed else f"{self.failed} of {n} expectations FAIL"
        cells = [
            (
                row["component"] + (f" @{row['about']}" if row["about"] not in ("", "com") else ""),
                row["unit"],
                number(row["expected"], 6),
                number(row["actual"], 6),
                number(row["deviation"], 3),
                number(row["allowed"], 3),
                "ok" if row["pass"] else "FAIL",
            )
            for row in self.csv_rows()
        ]
        columns = ("quantity", "unit", "expected", "actual", "deviation", "allowed", "")
        return [Rows(f"{body.name or body.path} — check: {verdict}", columns, cells, left=2, kind="check")]


class Validation(Results[list[str]]):
    """The problems `rbi.validate` found in spec files, as ``rbi validate`` reports them: a
    sequence of each file's problems (one line each; empty for a valid file), with ``files``
    (each as messages name it: ``-`` is ``<stdin>``) and ``ok`` (every file is valid). Its
    JSON lists each file with its problems; its CSV is one row a problem (a valid file's row
    has none)."""

    def __init__(self, files: list[str], problems: list[list[str]]) -> None:
        self.files = files
        self._items = problems
        self.ok: bool = not any(problems)

    def __repr__(self) -> str:
        return f"<rbi.Validation {len(self)} files, {sum(map(bool, self))} invalid>"

    def to_dict(self) -> dict[str, Any]:
        return {
            "ok": self.ok,
            "files": [{"file": f, "problems": found, "ok": not found} for f, found in zip(self.files, self)],
        }

    def csv_rows(self) -> list[dict[str, Any]]:
        return [
            {"file": f, "ok": not found, "problem": line}
            for f, found in zip(self.files, self)
            for line in found or [""]
        ]

    @property
    def summary(self) -> str:
        """One line: ``3 file(s) valid``, or ``2 of 3 file(s) invalid, 3 problem(s)``."""
        bad, count = sum(map(bool, self)), sum(map(len, self))
        if not bad:
            return f"{len(self)} file(s) valid"
        return f"{bad} of {len(self)} file(s) invalid, {count} problem(s)"

    def rows(self) -> list[Rows]:
        cells = [(row["file"], "ok" if row["ok"] else row["problem"]) for row in self.csv_rows()]
        return [Rows(f"validate: {self.summary}", ("file", "problem"), cells, left=2)]
