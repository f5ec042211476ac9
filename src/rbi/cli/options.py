"""Parsing of command-line values (vectors, reference points, rotations) and shared options."""

from __future__ import annotations

import math
from enum import Enum
from typing import Annotated, Optional

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


UnitsOption = Annotated[
    Optional[str],
    typer.Option("--units", "-u", metavar="SI|LENGTH,MASS",
                 help="Report results in other units: SI (m, kg) or e.g. mm,g. Default: the spec file's "
                      "units. Command-line inputs (--about X,Y,Z, --velocity) stay in the file's units."),
]


def in_output_units(body, units: str | None, *lengths):
    """The body converted to ``--units`` (unchanged when None), and each of ``lengths`` (points
    or velocities in the file's length unit, or None) scaled alongside."""
    if units is None:
        return body, lengths
    from rbi.spec.units import convert_body, parse_output_units, scale_factors

    target = parse_output_units(units)
    factor, _ = scale_factors((body.length_unit, body.mass_unit), target)
    scaled = tuple(None if v is None else [factor * float(x) for x in v] for v in lengths)
    return convert_body(body, *target), scaled
