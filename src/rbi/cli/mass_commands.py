"""`rbi inertia`, `rbi principal`, `rbi momentum`: mass properties of a body. Every number is
in the spec's units unless ``--units`` asks for others."""

from __future__ import annotations

from enum import Enum

import rbi
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.option_values import parse_about, parse_rotation, parse_units, parse_vector
from rbi.cli.options import AboutOption, FormatOption, OutputFormat, SpecFile, SpecFiles, UnitsOption, option
from rbi.cli.render import emit_result


class ProductsSign(str, Enum):
    """Signs of the off-diagonal entries: ``tensor`` (the matrix, ``I_xy = −∫xy dm``) or ``cad``
    (the positive integrals ``+∫xy dm`` SolidWorks and CATIA print)."""

    tensor = "tensor"
    cad = "cad"


RotateOption = option(
    list[str] | None,
    "--rotate",
    "-r",
    metavar="AXIS:DEG",
    help="Turn the body about a world axis (x, y or z) by DEG degrees; repeat to chain, "
    "applied in order. The inertia is then given in world axes: R I Rᵀ.",
)
AxisOption = option(
    str | None,
    "--axis",
    metavar="X,Y,Z",
    help="Also give the scalar moment of inertia about the line through the --about point along this "
    "direction (any length; in the axes the matrix is given in: body axes, or world axes after --rotate).",
    show_default=False,
)
ProductsOption = option(
    ProductsSign,
    "--products",
    help="Sign of the off-diagonal entries: tensor (the matrix, I_xy = -∫xy dm) or "
    "cad (the positive integrals +∫xy dm that SolidWorks and CATIA print).",
)
OmegaOption = option(
    str, "--omega", "-w", metavar="WX,WY,WZ", help="Angular velocity in body axes, rad/s.", show_default=False
)
VelocityOption = option(
    str | None,
    "--velocity",
    "-v",
    metavar="VX,VY,VZ",
    help="Velocity of the centre of mass (body axes, file length unit/s). Without it the "
    "--about point is taken as fixed, so the body turns about it.",
)


def inertia(
    files: SpecFiles,
    about: AboutOption = "com",
    rotate: RotateOption = None,
    axis: AxisOption = None,
    products: ProductsOption = ProductsSign.tensor,
    units: UnitsOption = None,
    format: FormatOption = OutputFormat.table,
) -> int:
    """Mass, centre of mass and the inertia matrix about a point, in body or rotated axes.

    \b
    Examples:
      rbi inertia top_bolted.yaml
      rbi inertia top_bolted.yaml --about pivot --rotate y:30 --format json
      rbi inertia rocket.yaml --axis 1,1,0 --about origin
      rbi inertia robot_link.yaml --products cad --units mm,g
    """

    turns = [parse_rotation(r) for r in rotate or []]
    direction = None
    if axis is not None:
        try:
            direction = rbi.unit_vector(parse_vector(axis, "--axis"))
        except ValueError:
            raise rbi.SpecError(f"--axis: must be a non-zero direction X,Y,Z (got {axis!r})") from None

    def one(file: str) -> FileReport:
        body, point, _ = _body_and_point(file, about, units)
        return FileReport(body.inertia_report(point, turns, products=products.value, axis=direction))

    return report_each(files, one, format.value)


def principal(
    files: SpecFiles,
    about: AboutOption = "com",
    units: UnitsOption = None,
    format: FormatOption = OutputFormat.table,
) -> int:
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


def momentum(
    file: SpecFile,
    omega: OmegaOption,
    about: AboutOption = "com",
    velocity: VelocityOption = None,
    units: UnitsOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Angular momentum h, its angle to ω, and kinetic energy.

    \b
    Examples:
      rbi momentum top.yaml --omega 0,0,200
      rbi momentum top_bolted.yaml --omega 1,0,200 --about pivot --format json
      rbi momentum rocket.yaml --omega 0,0,10 --velocity 0,0,50
    """

    w = parse_vector(omega, "--omega")
    velocity_given = None if velocity is None else parse_vector(velocity, "--velocity")
    body, point, velocity_given = _body_and_point(file, about, units, velocity_given)
    # Without a given velocity the reference point is fixed: v_c = ω × r_{c/o} (zero at the CoM).
    emit_result(format.value, body.momentum(w, point, velocity_given))


def _body_and_point(file: str, about: str, units: str | None, velocity=None):
    """The body of ``file`` in ``--units``, the ``--about`` point as the API takes it (its name,
    or X,Y,Z given in the file's length unit, in the body's) and ``velocity`` likewise."""
    body = rbi.load(file)
    point = parse_about(about)
    if units is not None:
        body = body.in_units(*parse_units(units))
        velocity = body.from_spec_units(velocity)
        point = point if isinstance(point, str) else body.from_spec_units(point)
    return body, point, velocity
