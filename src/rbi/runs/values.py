"""Values given as text on a command line (``"1,2,3"``), turned into numbers."""

from __future__ import annotations

import math

from rbi.errors import InputError


def parse_vector(text: str, option: str, count: int = 3) -> list[float]:
    """``"1,2,3"`` -> ``[1.0, 2.0, 3.0]``; :class:`InputError` naming ``option`` otherwise."""
    pieces = [p.strip() for p in text.replace(";", ",").split(",")]
    try:
        values = [float(p) for p in pieces]
    except ValueError:
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise InputError(f"{option}: expected {count} finite numbers separated by commas, got {text!r}")
    return values


def vector_value(value, option: str, count: int = 3) -> list[float]:
    """A vector given as text (``"1,2,3"``) or as a sequence of numbers; :class:`InputError`
    naming ``option`` unless it holds ``count`` finite numbers."""
    if isinstance(value, str):
        return parse_vector(value, option, count)
    try:
        values = [float(v) for v in value]
    except (TypeError, ValueError):
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise InputError(f"{option}: expected {count} finite numbers, got {value!r}")
    return values
