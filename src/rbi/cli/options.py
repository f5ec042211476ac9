"""Parsing of command-line values (vectors, reference points, rotations) and shared options."""

from __future__ import annotations

import math
from enum import Enum
from typing import Annotated

import typer

from rbi.spec.errors import InputError


class OutputFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


FormatOption = Annotated[
    OutputFormat,
    typer.Option("--format", "-f", help="table (for people), json (one object) or csv (header + rows)."),
]
SpecFile = Annotated[str, typer.Argument(help="Body spec (YAML).", show_default=False, metavar="FILE")]
AboutOption = Annotated[
    str,
    typer.Option("--about", "-a", help="Reference point: com, origin, pivot, or X,Y,Z in body coordinates (file units)."),
]


def parse_vector(text: str, option: str, count: int = 3) -> list[float]:
    """``"1,2,3"`` -> ``[1.0, 2.0, 3.0]``; :class:`InputError` naming the option otherwise."""
    pieces = [p.strip() for p in text.replace(";", ",").split(",")]
    try:
        values = [float(p) for p in pieces]
    except ValueError:
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise InputError(f"{option}: expected {count} finite numbers separated by commas, got {text!r}")
    return values


def parse_about(text: str, body) -> tuple[str, list[float]]:
    """Resolve ``--about`` against a loaded body: (label, point in body coordinates)."""
    key = text.strip().lower()
    if key == "com":
        return "com", body.props.com.tolist()
    if key == "origin":
        return "origin", [0.0, 0.0, 0.0]
    if key == "pivot":
        if body.pivot is None:
            raise InputError(f"{body.path}: pivot: --about pivot needs a `pivot` in the spec, and there is none")
        return "pivot", body.pivot.tolist()
    return "point", parse_vector(text, "--about")


def parse_rotation(text: str) -> tuple[str, float]:
    """``"y:30"`` -> ``("y", radians(30))``."""
    axis, sep, angle = text.partition(":")
    axis = axis.strip().lower()
    try:
        degrees = float(angle)
    except ValueError:
        degrees = math.nan
    if not sep or axis not in ("x", "y", "z") or not math.isfinite(degrees):
        raise InputError(f"--rotate: expected AXIS:DEG with AXIS one of x, y, z (e.g. y:30), got {text!r}")
    return axis, math.radians(degrees)
