"""`rbi inertia`, `rbi principal`, `rbi momentum`: mass properties of a body.

The options are declared here; what `inertia` and `principal` print for each file is in
:mod:`rbi.cli.mass_reports`."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import numpy as np
import typer

from rbi.cli import mass_reports
from rbi.cli.mass_reports import header, load_body, place_rows, title
from rbi.cli.options import (
    AboutOption,
    FormatOption,
    OutputFormat,
    SpecFile,
    SpecFiles,
    UnitsOption,
    in_output_units,
    parse_about,
    parse_vector,
)
from rbi.cli.render import emit, number


class ProductsSign(str, Enum):
    tensor = "tensor"
    cad = "cad"


def inertia(
    files: SpecFiles,
    about: AboutOption = "com",
    rotate: Annotated[
        list[str] | None,
        typer.Option(
            "--rotate",
            "-r",
            metavar="AXIS:DEG",
            help="Turn the body about a world axis (x, y or z) by DEG degrees; repeat to chain, "
            "applied in order. The inertia is then given in world axes: R I Rᵀ.",
        ),
    ] = None,
    axis: Annotated[
        str | None,
        typer.Option(
            "--axis",
            metavar="X,Y,Z",
            help="Also give the scalar moment of inertia about the line through the --about point along "
            "this direction (any length; in the axes the matrix is given in: body axes, or world "
            "axes after --rotate).",
            show_default=False,
        ),
    ] = None,
    products: Annotated[
        ProductsSign,
        typer.Option(
            "--products",
            help="Sign of the off-diagonal entries: tensor (the matrix, I_xy = -∫xy dm) or "
            "cad (the positive integrals +∫xy dm that SolidWorks and CATIA print).",
        ),
    ] = ProductsSign.tensor,
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

    return mass_reports.inertia(files, about, rotate, axis, products.value, units, format.value)


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

    return mass_reports.principal(files, about, units, format.value)


def momentum(
    file: SpecFile,
    omega: Annotated[
        str,
        typer.Option(
            "--omega",
            "-w",
            metavar="WX,WY,WZ",
            help="Angular velocity in body axes, rad/s.",
            show_default=False,
        ),
    ],
    about: AboutOption = "com",
    velocity: Annotated[
        str | None,
        typer.Option(
            "--velocity",
            "-v",
            metavar="VX,VY,VZ",
            help="Velocity of the centre of mass (body axes, file length unit/s). Without it the "
            "--about point is taken as fixed, so the body turns about it.",
        ),
    ] = None,
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

    w = np.array(parse_vector(omega, "--omega"))
    v_given = None if velocity is None else np.array(parse_vector(velocity, "--velocity"))
    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point, v_given) = in_output_units(body, units, point, v_given)
    # Without a given velocity the reference point is fixed: v_c = ω × r_{c/o} (zero at the CoM).
    motion = body.momentum(w, point, v_given)
    result = header(body, about_label, point) | {
        "omega": w,
        "com_velocity": motion.com_velocity,
        "angular_momentum": motion.angular_momentum,
        "angle_deg": motion.angle_deg,
        "kinetic_energy": motion.kinetic_energy,
    }

    emit(format.value, result, lambda: _momentum_table(body, result, about_label))


def _momentum_table(body, result: dict, about_label: str):
    """The table of ``rbi momentum``'s result."""
    # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
    from rbi.cli import tables

    labels = body.unit_labels
    return tables.quantities(
        title(body, f"momentum about {about_label}"),
        [
            *place_rows(body, about_label, result["about"]),
            ("ω (body axes)", "rad/s", tables.vector(result["omega"])),
            ("v of centre of mass", labels["velocity"], tables.vector(result["com_velocity"])),
            ("angular momentum h", labels["angular_momentum"], tables.vector(result["angular_momentum"])),
            ("angle between h and ω", "deg", number(result["angle_deg"], 6)),
            ("kinetic energy", labels["energy"], number(result["kinetic_energy"], 8)),
        ],
    )
