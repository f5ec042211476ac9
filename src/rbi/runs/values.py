"""Numbers given to the Python API, checked: a vector is a sequence of finite numbers (text such
as ``"1,2,3"`` is the command line's, parsed in :mod:`rbi.cli.option_values`)."""

from __future__ import annotations

import math
import numbers
from typing import Any

from rbi.errors import ArgumentError, literal


def vector_value(value: Any, parameter: str, count: int = 3) -> list[float]:
    """``value`` as a list of ``count`` floats; :class:`ArgumentError` naming ``parameter``
    unless it is a sequence (or array) of ``count`` finite numbers."""
    values: list[float] = []
    if not isinstance(value, (str, bytes)):
        try:
            values = [float(v) for v in value]
        except (TypeError, ValueError, OverflowError):
            values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise ArgumentError(parameter, f"expected {count} finite numbers, got {literal(value)}")
    return values


def require_numbers(integral: bool = False, **values: Any) -> None:
    """TypeError naming the parameter when one of ``values`` (None allowed) is not a number
    (``spin=True``, ``duration="4"``); with ``integral``, not a whole number."""
    kind = numbers.Integral if integral else numbers.Real
    for name, value in values.items():
        if value is not None and (isinstance(value, bool) or not isinstance(value, kind)):
            what = "a whole number" if integral else "a number"
            raise TypeError(f"{name}: must be {what} (got {type(value).__name__} {value!r:.60})")
