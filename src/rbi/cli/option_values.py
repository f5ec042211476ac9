"""Parsing of command-line values (reference points, rotations, output units) into what the
commands compute with."""

from __future__ import annotations

import math

from rbi.errors import InputError
from rbi.runs.values import parse_vector


def parse_about(text: str, body) -> tuple[str, list[float]]:
    """Resolve ``--about`` against a loaded body: (label, point in body coordinates)."""
    key = text.strip().lower()
    if key == "com":
        return "com", body.props.center_of_mass.tolist()
    if key == "origin":
        return "origin", [0.0, 0.0, 0.0]
    if key == "pivot":
        if body.pivot is None:
            raise InputError(
                f"{body.path}: pivot: --about pivot needs a `pivot` in the spec, and there is none"
            )
        return "pivot", body.pivot.tolist()
    try:
        return "point", parse_vector(text, "--about")
    except InputError:
        raise InputError(
            f"--about: expected com, origin, pivot or a point X,Y,Z (three numbers separated by "
            f"commas, file units), got {text!r}"
        ) from None


def parse_rotation(text: str) -> tuple[str, float]:
    """``"y:30"`` -> ``("y", radians(30))``."""
    from rbi.core.rotation import LARGEST_ANGLE_DEG, angle_is_kept

    axis, sep, angle = text.partition(":")
    axis = axis.strip().lower()
    try:
        degrees = float(angle)
    except ValueError:
        degrees = math.nan
    if not sep or axis not in ("x", "y", "z") or not math.isfinite(degrees):
        raise InputError(f"--rotate: expected AXIS:DEG with AXIS one of x, y, z (e.g. y:30), got {text!r}")
    if not angle_is_kept(degrees):
        raise InputError(
            f"--rotate: {angle.strip()} degrees is too large to be a turn: rounding loses it "
            f"(at most {LARGEST_ANGLE_DEG:g} degrees)"
        )
    return axis, math.radians(degrees)


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
