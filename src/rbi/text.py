"""Text from outside (a name in a spec, a robot file, a file name) made plainly visible.

Used wherever such text reaches a medium where a hidden character would act rather than show:
YAML comments and values (:mod:`rbi.spec.yaml_writer`), picture labels
(:mod:`rbi.viz.labels`), listings, CSV cells (the CLI's ``--format csv`` and the sweep's rows
file). Standard library only, importable from every layer.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Iterable
from typing import Any


def is_hidden(char: str) -> bool:
    """Whether ``char`` would not show as itself on a terminal (or would move the text around
    it): a control, a format character (bidirectional overrides, zero-width characters, the
    byte order mark), a surrogate, a private use or unassigned character, a line or paragraph
    separator, or a space other than the plain space U+0020 (so none hides in a name). Those
    are Unicode's "Other" and "Separator" categories but U+0020: exactly what
    :meth:`str.isprintable` calls non-printable."""
    return not char.isprintable()


def visible(text: str, keep: str = "") -> str:
    """``text`` with every hidden character (see :func:`is_hidden`) written as an escape
    (``\\n``, ``\\x9b``, ``\\u202e``): one line of plainly visible characters, so a name cannot
    drive a terminal (escape sequences, bells), reorder what is shown (bidirectional overrides)
    or break a line (U+2028). Characters in ``keep`` (a message's own newline) pass. A
    backslash already in ``text`` is kept as it is: this is for the eye, not for reading back
    (data goes through the YAML or JSON writer). The one escaper for terminals, listings, YAML
    comments and picture labels."""
    if text.isprintable():  # nothing hidden (fast, in C)
        return text
    return "".join(escaped(c) if is_hidden(c) and c not in keep else c for c in text)


def escaped(char: str) -> str:
    """A hidden character (:func:`is_hidden`) as Python writes it escaped: ``\\n``, ``\\x9b``,
    ``\\u202e``, ``\\U000e0001`` (its ``repr`` without the quotes: never a quote or a backslash)."""
    return repr(char)[1:-1]


def number(value: float | None, digits: int = 6) -> str:
    """A number for people (tables, reports): ``digits`` significant figures, ``0`` for zero
    (no ``-0``), ``—`` for none, ``inf``/``nan`` as Python writes them. The one number
    formatter: the CLI's tables (:mod:`rbi.cli.render`), the reprs of :mod:`rbi.api` and of the
    audit report, and the bench report use it."""
    if value is None:
        return "—"
    value = float(value)
    if value == 0.0:
        return "0"
    if not math.isfinite(value):
        return str(value)
    return f"{value:.{digits}g}"


def plus_minus(value: float, u: float) -> str:
    """``value ± u`` for people: u to two significant figures and the value to the digits u
    leaves meaningful (at least 3)."""
    if not u > 0 or not math.isfinite(u):
        return f"{number(value, 8)} ± {number(u, 2)}"
    ratio = min(max(abs(value) / u, 1.0), 1e13)  # past a double's range (u subnormal or huge): 3 or 12 digits
    digits = int(math.floor(math.log10(ratio))) + 2 if value else 3
    return f"{number(value, min(max(digits, 3), 12))} ± {number(u, 2)}"


NOISE_RELATIVE = 1e-12
"""An entry smaller than this fraction of the largest entry of its matrix or vector is rounding
noise (a 1e-18 beside a 1e-4) and prints as 0 in tables; JSON and CSV keep every digit."""


def without_noise(values: Iterable[float], scale: float = 0.0) -> list[float]:
    """``values`` as floats, each entry below :data:`NOISE_RELATIVE` of the largest finite
    magnitude among them or of ``scale`` (a position: the body's size) set to 0: the one rule
    for rounding noise in tables (a vector, or a matrix's entries in one row)."""
    values = [float(x) for x in values]
    peak = max([abs(x) for x in values if math.isfinite(x)] + [scale if math.isfinite(scale) else 0.0])
    return [0.0 if abs(x) < NOISE_RELATIVE * peak else x for x in values]


def vector_text(values: Any, digits: int = 6, brackets: str = "[]", scale: float | None = None) -> str:
    """A vector for people: its entries as :func:`number` writes them (``digits`` significant
    figures, ``0`` for zero and ``-0``), comma-separated between ``brackets`` (``"[]"``, or
    ``"()"`` for a vector in prose). With ``scale`` (0: the vector's own), an entry below
    :data:`NOISE_RELATIVE` of the largest magnitude among them or of ``scale`` (a position: the
    body's size) is rounding noise, written 0 (:func:`without_noise`). The one vector formatter: the reprs of
    :mod:`rbi.api`, the CLI's tables and the bench report use it."""
    values = [float(x) for x in values] if scale is None else without_noise(values, scale)
    return brackets[0] + ", ".join(number(x, digits) for x in values) + brackets[1]


FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
"""First characters that make a spreadsheet run a text cell as a formula (OWASP's list)."""


def csv_cell(value: Any) -> Any:
    """One CSV cell, the one rule for every CSV rbi writes (the CLI's ``--format csv``, the
    sweep's rows file, the trajectory CSV): empty for None or NaN; a float at full precision
    (Python's shortest round-trip repr), ``-0.0`` written ``0.0`` as the CLI's tables and JSON
    write it; text made inert for spreadsheets (one starting with ``=``, ``+``, ``-``, ``@``, a tab
    or a carriage return, such as ``=HYPERLINK(...)``, gets a leading ``'``; text that reads as
    a number, ``-0.5``, is left alone) with hidden characters escaped (:func:`visible`). Other
    values (ints) pass as they are. :func:`csv_text_read` is its inverse for text cells."""
    if isinstance(value, float):
        return "" if value != value else repr(float(value) + 0.0)  # + 0.0: -0.0 is 0.0
    if isinstance(value, str):
        if value.startswith(FORMULA_STARTS) and not _is_number(value):
            value = "'" + value
        return visible(value)
    return "" if value is None else value


def csv_text_read(cell: str) -> str | None:
    """The text :func:`csv_cell` wrote as ``cell`` (its ``'`` taken off), or None when
    :func:`csv_cell` never writes ``cell`` (a formula left live, a hidden character)."""
    if any(is_hidden(c) for c in cell):
        return None
    if cell.startswith("'") and cell[1:].startswith(FORMULA_STARTS) and not _is_number(cell[1:]):
        return cell[1:]
    if cell.startswith(FORMULA_STARTS) and not _is_number(cell):
        return None
    return cell


def csv_lines(rows: Iterable[Iterable[Any]], header: Iterable[str] = ()) -> str:
    """CSV text, each line ended by ``\\n``: ``header`` (column names rbi chooses, written as
    they are) when given, then one line a row, every value through :func:`csv_cell`."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    header = list(header)
    if header:
        writer.writerow(header)
    writer.writerows([csv_cell(v) for v in row] for row in rows)
    return buffer.getvalue()


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return text.strip() == text
