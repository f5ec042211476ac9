"""Parsing of command-line values (vectors, reference points, rotations) and shared options."""

from __future__ import annotations

import math
from enum import Enum
from typing import Annotated, Optional

import typer

from rbi.runs.values import parse_vector  # noqa: F401  (re-exported: the commands parse vectors with it)
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
    typer.Option("--about", "-a", metavar="com|origin|pivot|X,Y,Z",
                 help="Reference point: com, origin, pivot, or X,Y,Z in body coordinates (file units)."),
]


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
    try:
        return "point", parse_vector(text, "--about")
    except InputError:
        raise InputError(f"--about: expected com, origin, pivot or a point X,Y,Z (three numbers separated by "
                         f"commas, file units), got {text!r}") from None


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


def plain_argument_help(command) -> None:
    """Show ``command``'s positional arguments by their metavar alone: ``rbi inertia
    [OPTIONS] FILE`` rather than ``{FILE}`` in the usage line and ``FILE <str>`` in the list."""
    from typer.core import TyperArgument

    for param in command.params:
        if isinstance(param, TyperArgument) and param.metavar is not None:
            param.__class__ = _PlainArgument


def _plain_argument_class():
    from typer.core import TyperArgument

    class PlainArgument(TyperArgument):
        def _usage_display_name(self) -> str:
            name = self.metavar if self.required else f"[{self.metavar}]"
            return name if self.nargs == 1 or self.metavar.endswith("...") else name + "..."

        def display_type_rich(self, ctx) -> None:
            return None

    return PlainArgument


_PlainArgument = _plain_argument_class()
