"""Parsing of command-line values (vectors ``X,Y,Z``, reference points, rotations ``y:30``,
sweep axes ``START:STOP:COUNT``, output units) into the numbers the API takes, and the API's
errors spelled with the command line's options. Each parser takes the text and the option it
was given to (:func:`rbi.cli.options.option` passes it), which its errors name."""

from __future__ import annotations

import math
import re
from typing import Any

import rbi
from rbi import ArgumentError, SpecError

OPTION_NAMES = {
    "tilt_deg": "--tilt",
    "check_budget": "--yes",
    "check_budget=False": "--yes",
    "axes": "--rotate",
    "package_paths": "--package-path",
    "links": "--link",
    "vary[]": "--vary {}",
    "path": "--out",
    "fix=True": "--fix",
    "to='mjcf'": "--to mjcf",
}
"""The API's parameters whose option is not ``--`` + the name with ``-`` for ``_``."""


def option_name(parameter: str) -> str:
    """The command-line option of an API parameter: ``spin_axis`` → ``--spin-axis``; a
    parameter with a value, ``links=NAME``, as the option with it: ``--link NAME``."""
    if parameter in OPTION_NAMES:
        return OPTION_NAMES[parameter]
    name, given, value = parameter.partition("=")
    option = OPTION_NAMES.get(name) or "--" + name.replace("_", "-")
    return f"{option} {value}" if given else option


def error_line(error: SpecError) -> str:
    """The one line the CLI prints for ``error``: an API argument named as its option
    (``--duration: must be ...``), any other error as it is."""
    return error.named(option_name) if isinstance(error, ArgumentError) else str(error)


def parse_vector(text: str, option: str, count: int = 3) -> list[float]:
    """``"1,2,3"`` -> ``[1.0, 2.0, 3.0]``; :class:`SpecError` naming ``option`` otherwise."""
    pieces = [p.strip() for p in text.replace(";", ",").split(",")]
    try:
        values = [float(p) for p in pieces]
    except ValueError:
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise SpecError(f"{option}: expected {count} finite numbers separated by commas, got {text!r}")
    return values


def spin_axis_option(text: str | None, option: str = "--spin-axis") -> str | list[float] | None:
    """``--spin-axis``: a named axis (``x``, ``-y``) as it is, ``X,Y,Z`` as three numbers."""
    if text is None or "," not in text:
        return text
    return parse_vector(text, option)


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_RANGE = re.compile(rf"^\s*({_NUMBER})\s*:\s*({_NUMBER})\s*:\s*(\d+)\s*$")
_DRAW = re.compile(rf"^\s*(normal|uniform)\s*\(\s*({_NUMBER})\s*,\s*({_NUMBER})\s*\)\s*$")


def sweep_values(text: str, option: str) -> Any:
    """A sweep axis as ``rbi.sweep`` takes it: ``START:STOP:COUNT`` → ``Grid``, one number,
    ``normal(MEAN,SD)`` → ``Normal``, ``uniform(LOW,HIGH)`` → ``Uniform``; :class:`SpecError`
    naming ``option`` otherwise."""
    text = str(text)
    try:
        if (match := _RANGE.match(text)) is not None:
            return rbi.Grid(float(match[1]), float(match[2]), int(match[3]))
        if (match := _DRAW.match(text)) is not None:
            kind = rbi.Normal if match[1] == "normal" else rbi.Uniform
            return kind(float(match[2]), float(match[3]))
    except ValueError as exc:
        raise SpecError(f"{option}: {exc}") from None
    try:
        value = float(text)
    except ValueError:
        raise SpecError(
            f"{option}: expected START:STOP:COUNT, a number, normal(MEAN,SD) or uniform(LOW,HIGH) "
            f"(got {text[:60]!r})"
        ) from None
    if not math.isfinite(value):
        raise SpecError(f"{option}: must be a finite number (got {text!r})")
    return value


def vary_option(items: list[str]) -> dict[str, Any]:
    """``--vary PATH=RANGE`` items as ``rbi.sweep``'s ``vary``: path → values."""
    vary: dict[str, Any] = {}
    for item in items:
        path, sep, text = item.rpartition("=")  # a range has no '=', a part's name may
        if not sep:
            raise SpecError(f"--vary {item}: expected PATH=RANGE, e.g. parts.bolt.mass=0.01:0.03:5")
        path = path.strip()
        if path in vary:
            raise SpecError("--vary: a path is given twice")
        vary[path] = sweep_values(text, f"--vary {path}")
    return vary


def parse_about(text: str, option: str = "--about") -> str | list[float]:
    """``--about`` as `rbi.Body.point` takes it: a reference point's name
    (`rbi.Body.reference_points`, any case) or X,Y,Z (three numbers)."""
    key = text.strip().lower()
    if key in rbi.Body.reference_points:
        return key
    try:
        return parse_vector(text, option)
    except SpecError:
        names = ", ".join(rbi.Body.reference_points)
        raise SpecError(
            f"{option}: expected {names} or a point X,Y,Z (three numbers separated by commas, file "
            f"units), got {text!r}"
        ) from None


def parse_direction(text: str, option: str = "--axis") -> list[float]:
    """``--axis``: a direction X,Y,Z, of any length but zero."""
    direction = parse_vector(text, option)
    if not any(direction):
        raise SpecError(f"{option}: must be a non-zero direction X,Y,Z (got {text!r})")
    return direction


def parse_rotation(text: str, option: str = "--rotate") -> tuple[str, str]:
    """``"y:30"`` -> ``("y", "30")``: a turn as `rbi.Body.inertia`'s ``axes`` takes it, the
    angle as written (the API names it so when rounding would lose the turn)."""
    axis, sep, angle = text.partition(":")
    axis = axis.strip().lower()
    try:
        degrees = float(angle)
    except ValueError:
        degrees = math.nan
    if not sep or axis not in ("x", "y", "z") or not math.isfinite(degrees):
        raise SpecError(f"{option}: expected AXIS:DEG with AXIS one of x, y, z (e.g. y:30), got {text!r}")
    return axis, angle.strip()


def parse_units(text: str, option: str = "--units") -> tuple[str, str]:
    """``--units``: ``SI`` (m, kg) or ``LENGTH,MASS`` such as ``mm,g`` -> (length, mass)."""
    key = text.strip()
    if key.lower() == "si":
        return "m", "kg"
    length, _, mass = key.partition(",")
    length, mass = length.strip(), mass.strip()
    if length not in rbi.Body.length_units or mass not in rbi.Body.mass_units:
        raise SpecError(
            f"{option}: expected SI or LENGTH,MASS with LENGTH one of {', '.join(rbi.Body.length_units)} "
            f"and MASS one of {', '.join(rbi.Body.mass_units)} (e.g. mm,g), got {text!r}"
        )
    return length, mass
