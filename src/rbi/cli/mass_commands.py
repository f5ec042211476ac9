"""`rbi inertia`, `rbi principal`, `rbi momentum`: mass properties of a body. Every number is
in the spec's units unless ``--units`` asks for others."""

from __future__ import annotations

from typing import Literal

import rbi
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.option_values import parse_direction, parse_rotation, parse_vector
from rbi.cli.options import ABOUT, FORMAT, REQUIRED, UNITS, OutputFormat, SpecFile, SpecFiles, command, option
from rbi.cli.render import emit_result


@command(
    ABOUT,
    option(
        list[str] | None,
        "--rotate",
        "-r",
        metavar="AXIS:DEG",
        parser=parse_rotation,
        help="Turn the body about a world axis (x, y or z) by DEG degrees; repeat to chain, "
        "applied in order. The inertia is then given in world axes: R I Rᵀ.",
    ),
    option(
        str | None,
        "--axis",
        metavar="X,Y,Z",
        parser=parse_direction,
        help="Also give the scalar moment of inertia about the line through the --about point along this "
        "direction (any length; in the axes the matrix is given in: body axes, or world axes after --rotate).",
    ),
    option(
        Literal["tensor", "cad"],
        "--products",
        default="tensor",
        help="Sign of the off-diagonal entries: tensor (the matrix, I_xy = -∫xy dm) or "
        "cad (the positive integrals +∫xy dm that SolidWorks and CATIA print).",
    ),
    UNITS,
    FORMAT,
)
def inertia(files: SpecFiles, *, about, rotate, axis, products, units, format: OutputFormat) -> int:
    """Mass, centre of mass and the inertia matrix about a point, in body or rotated axes.

    \b
    Examples:
      rbi inertia top_bolted.yaml
      rbi inertia top_bolted.yaml --about pivot --rotate y:30 --format json
      rbi inertia rocket.yaml --axis 1,1,0 --about origin
      rbi inertia robot_link.yaml --products cad --units mm,g
    """

    def one(file: str) -> FileReport:
        body, point, _ = _body_and_point(file, about, units)
        return FileReport(body.inertia_report(point, rotate, products=products, axis=axis))

    return report_each(files, one, format.value)


@command(ABOUT, UNITS, FORMAT)
def principal(files: SpecFiles, *, about, units, format: OutputFormat) -> int:
    """Principal moments (ascending), axes (unit, right-handed, body frame) and radii of gyration.

    \b
    Examples:
      rbi principal top_bolted.yaml
      rbi principal top_bolted.yaml --about pivot --format json
      rbi principal flywheel.yaml --units SI
    """

    def one(file: str) -> FileReport:
        body, point, _ = _body_and_point(file, about, units)
        return FileReport(body.principal(point))

    return report_each(files, one, format.value)


@command(
    option(
        str,
        "--omega",
        "-w",
        default=REQUIRED,
        metavar="WX,WY,WZ",
        parser=parse_vector,
        help="Angular velocity in body axes, rad/s.",
    ),
    ABOUT,
    option(
        str | None,
        "--velocity",
        "-v",
        metavar="VX,VY,VZ",
        parser=parse_vector,
        help="Velocity of the centre of mass (body axes, file length unit/s). Without it the "
        "--about point is taken as fixed, so the body turns about it.",
    ),
    UNITS,
    FORMAT,
)
def momentum(file: SpecFile, *, omega, about, velocity, units, format: OutputFormat) -> None:
    """Angular momentum h, its angle to ω, and kinetic energy.

    \b
    Examples:
      rbi momentum top.yaml --omega 0,0,200
      rbi momentum top_bolted.yaml --omega 1,0,200 --about pivot --format json
      rbi momentum rocket.yaml --omega 0,0,10 --velocity 0,0,50
    """

    body, point, velocity = _body_and_point(file, about, units, velocity)
    # Without a given velocity the reference point is fixed: v_c = ω × r_{c/o} (zero at the CoM).
    emit_result(format.value, body.momentum(omega, point, velocity))


def _body_and_point(file: str, about: str | list[float], units: tuple[str, str] | None, velocity=None):
    """The body of ``file`` in ``--units`` (length, mass), the ``--about`` point as the API
    takes it (its name, or X,Y,Z given in the file's length unit, in the body's) and
    ``velocity`` likewise."""
    body = rbi.load(file)
    if units is not None:
        body = body.in_units(*units)
    return body, body.from_spec_units(about), body.from_spec_units(velocity)
