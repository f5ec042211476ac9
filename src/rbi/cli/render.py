"""Rendering: JSON, CSV and rich tables. The only module that formats numbers."""

from __future__ import annotations

import csv
import io
import json
import math
import sys
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from rbi.cli.terminal import terminal_safe  # noqa: F401  (re-exported: tables and commands escape names with it)


def plain(value: Any) -> Any:
    """Recursively turn numpy arrays and scalars into plain Python lists, floats and ints.

    ``-0.0`` becomes ``0.0``; JSON then carries each float's shortest round-tripping repr.
    """
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, (np.floating, float)):
        f = float(value)
        return 0.0 if f == 0.0 else f
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.bool_):
        return bool(value)
    return value


def to_json(result: dict[str, Any]) -> str:
    """One JSON object; non-finite floats become null (JSON has no NaN)."""
    return json.dumps(_finite_or_none(plain(result)))


def _finite_or_none(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _finite_or_none(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite_or_none(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


_XYZ = ("x", "y", "z")


def flatten(result: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Flatten nested results into CSV columns: vectors get ``_x/_y/_z``, 3×3 matrices
    ``_xx … _zz``, nested mappings ``outer_inner``, other lists ``_1, _2, …``."""
    out: dict[str, Any] = {}
    for key, value in plain(result).items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, prefix=f"{name}_"))
        elif (
            isinstance(value, list)
            and len(value) == 3
            and all(isinstance(r, list) and len(r) == 3 for r in value)
        ):
            if key == "axes":
                for i, row in enumerate(value):
                    for axis, v in zip(_XYZ, row):
                        out[f"{name}_{i + 1}_{axis}"] = v
            else:
                for i, row in enumerate(value):
                    for j, v in enumerate(row):
                        out[f"{name}_{_XYZ[i]}{_XYZ[j]}"] = v
        elif (
            isinstance(value, list)
            and len(value) == 3
            and not any(isinstance(v, list) for v in value)
            and not key.endswith("moments")
        ):
            for axis, v in zip(_XYZ, value):
                out[f"{name}_{axis}"] = v
        elif isinstance(value, list):
            for i, v in enumerate(value):
                out[f"{name}_{i + 1}"] = v
        else:
            out[name] = value
    return out


def to_csv(rows: Iterable[dict[str, Any]]) -> str:
    """CSV text: a header row from the first row's (flattened) keys, then one line a row.
    A row's ``warnings`` are not a column: they go to stderr (:func:`say_warnings`)."""
    rows = [flatten({k: v for k, v in r.items() if k != "warnings"}) for r in rows]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    if rows:
        writer.writerow(rows[0].keys())
        for row in rows:
            writer.writerow([_csv_cell(v) for v in row.values()])
    return buffer.getvalue()


def _csv_cell(value: Any) -> Any:
    """A CSV cell: floats at full precision, empty for a missing or undefined (NaN) value,
    text made safe for spreadsheets (see :func:`spreadsheet_safe`)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, str):
        return spreadsheet_safe(value)
    return repr(value) if isinstance(value, float) else value


_FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_safe(text: str) -> str:
    """A text cell a spreadsheet will not run: one starting with ``=``, ``+``, ``-``, ``@``, a
    tab or a carriage return (a name such as ``=HYPERLINK(...)``) gets a leading ``'`` (OWASP's
    advice against CSV injection), and control characters are escaped as in
    :func:`terminal_safe`. Numbers are never touched, nor is text that reads as a number
    (``-0.5``)."""
    if text.startswith(_FORMULA_STARTS) and not _is_number(text):
        text = "'" + text
    return terminal_safe(text)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return text.strip() == text


def number(value: float | None, digits: int = 6) -> str:
    """A number for people: ``digits`` significant figures, no noise like ``-0``."""
    if value is None:
        return "—"
    value = float(value)
    if value == 0.0:
        return "0"
    if not math.isfinite(value):
        return str(value)
    return f"{value:.{digits}g}"


NOISE_RELATIVE = 1e-12
"""An entry smaller than this fraction of the largest entry of its matrix or vector is rounding
noise (a 1e-18 beside a 1e-4) and prints as 0 in tables; JSON and CSV keep every digit."""


def without_noise(values, scale: float = 0.0) -> np.ndarray:
    """``values`` (a vector or matrix) with every entry below :data:`NOISE_RELATIVE` of the
    largest magnitude among them, or of ``scale`` (a position: the body's size), set to 0, for
    printing."""
    values = np.array(values, dtype=float)
    finite = np.abs(values[np.isfinite(values)])
    peak = max(float(finite.max()) if finite.size else 0.0, scale if math.isfinite(scale) else 0.0)
    values[np.abs(values) < NOISE_RELATIVE * peak] = 0.0
    return values


def matrix_digits(matrix) -> tuple[float, str]:
    """A common power-of-ten scale for a matrix, so a table can print ``×10⁻⁶`` once."""
    peak = float(np.max(np.abs(matrix))) if np.size(matrix) else 0.0
    if peak == 0.0 or 1e-3 <= peak < 1e4 or not 1e-300 < peak < 1e300:  # 10.0**-324 is 0: print as is
        return 1.0, ""
    exponent = int(math.floor(math.log10(peak)))
    return 10.0**exponent, f"×10{_superscript(exponent)}"


_SUPER = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _superscript(n: int) -> str:
    return str(n).translate(_SUPER)


def _color_system() -> str | None:
    # rich's own NO_COLOR handling drops colours but keeps bold, dim and italic escapes;
    # NO_COLOR users get plain text.
    import os

    return None if os.environ.get("NO_COLOR") else "auto"


def stdout_console():
    return _safe_console(highlight=False, soft_wrap=False, color_system=_color_system())


def stderr_console():
    return _safe_console(stderr=True, highlight=False, color_system=_color_system())


def _safe_console(**options):
    """A rich Console whose printed text never carries a control character from data: the last
    line of defence behind :func:`rbi.cli.tables.plain_text` (rich's own colour and cursor codes
    are styles and control segments, not text, and pass unchanged)."""
    from rich.console import Console
    from rich.segment import Segment

    class SafeConsole(Console):
        def render(self, renderable, options=None):
            for segment in super().render(renderable, options):
                if segment.control or not segment.text:
                    yield segment
                else:
                    text = terminal_safe(segment.text, keep="\n")
                    yield segment if text is segment.text else Segment(text, segment.style, segment.control)

    return SafeConsole(**options)


def emit(
    fmt: str,
    result: dict[str, Any],
    table: Callable[[], Any],
    csv_rows: list[dict[str, Any]] | None = None,
    source: str | None = None,
) -> None:
    """Write ``result`` to stdout in the chosen format. ``table`` builds the rich renderable
    lazily (rich is imported only for tables); ``csv_rows`` defaults to ``[result]``;
    ``source`` names the file in an error."""
    refuse_non_finite(result, source)
    if fmt != "json":
        say_warnings(result.get("warnings", ()))
    if fmt == "json":
        sys.stdout.write(to_json(result) + "\n")
    elif fmt == "csv":
        sys.stdout.write(to_csv(csv_rows if csv_rows is not None else [result]))
    else:
        print_table(table())


def say_warnings(warnings: Iterable[str]) -> None:
    """Each warning about a body (``Body.warnings``: units that look wrong ...) as one line
    ``rbi: warning: ...`` on stderr; JSON output carries them as ``"warnings"`` instead."""
    from rbi.cli.terminal import say

    for warning in warnings:
        say(f"warning: {warning}")


def print_table(renderable) -> None:
    """Print a table (or a group of them) on stdout fitted to the terminal's width: no number
    cut, split or shortened (see :func:`rbi.cli.tables.fitted`)."""
    from rbi.cli.tables import fitted

    console = stdout_console()
    console.print(fitted(renderable, console))


def refuse_non_finite(result: dict[str, Any], source: str | None = None) -> None:
    """Inputs of absurd size (``--omega 1e200,0,0``) overflow to inf/NaN: refuse them as bad
    input (exit 2, naming the file ``source`` when given) rather than print nulls."""
    from rbi.spec.errors import InputError

    bad = [key for key, value in plain(result).items() if _has_non_finite(value)]
    if bad:
        where = f"{source}: " if source else ""
        raise InputError(
            f"{where}result {', '.join(bad)} is not finite: the input values are too large for double "
            "precision"
        )


def _has_non_finite(value: Any) -> bool:
    if isinstance(value, dict):
        return any(_has_non_finite(v) for v in value.values())
    if isinstance(value, list):
        return any(_has_non_finite(v) for v in value)
    return isinstance(value, float) and not math.isfinite(value)


def vector_text(v, digits: int = 6, scale: float = 0.0) -> str:
    """``[x, y, z]`` with noise below :data:`NOISE_RELATIVE` of the vector's largest entry, or
    of ``scale``, printed as 0."""
    return "[" + ", ".join(number(x, digits) for x in without_noise(v, scale)) + "]"


def body_size(props) -> float:
    """A body's size for telling a position from rounding noise: its radius of gyration about
    the centre of mass, √(trace I / 2m), file length unit (0 without mass or inertia)."""
    try:
        size = math.sqrt(float(np.trace(props.inertia_about_com)) / (2.0 * float(props.mass)))
    except (ValueError, ZeroDivisionError, OverflowError):
        return 0.0
    return size if math.isfinite(size) else 0.0
