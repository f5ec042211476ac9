"""`rbi inertia`, `rbi principal`, `rbi momentum`: mass properties of a body."""

from __future__ import annotations

from enum import Enum
from typing import Annotated, Optional

import numpy as np
import typer

from rbi.cli.options import (AboutOption, FormatOption, OutputFormat, SpecFile, UnitsOption, in_output_units, parse_about,
                             parse_rotation, parse_vector)
from rbi.cli.render import emit, number
from rbi.spec.errors import InputError


class ProductsSign(str, Enum):
    tensor = "tensor"
    cad = "cad"


PRODUCT_SIGN_TITLES = {
    "tensor": "products −∫xy dm",
    "cad": "CAD products +∫xy dm",
}


def _header(body, about_label: str, about_point) -> dict:
    return {
        "name": body.name,
        "units": body.units,
        "mass": body.props.mass,
        "center_of_mass": body.props.com,
        "about": about_point,
        "about_label": about_label,
    }


def inertia(
    file: SpecFile,
    about: AboutOption = "com",
    rotate: Annotated[
        Optional[list[str]],
        typer.Option("--rotate", "-r", metavar="AXIS:DEG",
                     help="Turn the body about a world axis (x, y or z) by DEG degrees; repeat to chain, "
                          "applied in order. The inertia is then given in world axes: R I Rᵀ."),
    ] = None,
    axis: Annotated[Optional[str], typer.Option(
        "--axis", metavar="X,Y,Z",
        help="Also give the scalar moment of inertia about the line through the --about point along "
             "this direction (any length; in the axes the matrix is given in: body axes, or world "
             "axes after --rotate).", show_default=False)] = None,
    products: Annotated[ProductsSign, typer.Option(
        "--products", help="Sign of the off-diagonal entries: tensor (the matrix, I_xy = -∫xy dm) or "
                           "cad (the positive integrals +∫xy dm that SolidWorks and CATIA print).")] = ProductsSign.tensor,
    units: UnitsOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Mass, centre of mass and the inertia matrix about a point, in body or rotated axes.

    \b
    Examples:
      rbi inertia top_bolted.yaml
      rbi inertia top_bolted.yaml --about pivot --rotate y:30 --format json
      rbi inertia rocket.yaml --axis 1,1,0 --about origin
      rbi inertia robot_link.yaml --products cad --units mm,g
    """
    from rbi.core.inertia import inertia_about, moment_about_axis, re_express, unit_axis, with_product_sign
    from rbi.core.rotation import compose_world_rotations
    from rbi.spec.load import load_body

    turns = [parse_rotation(r) for r in rotate or []]
    direction = None
    if axis is not None:
        try:
            direction = unit_axis(parse_vector(axis, "--axis"))
        except ValueError:
            raise InputError(f"--axis: must be a non-zero direction X,Y,Z (got {axis!r})") from None
    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    I = inertia_about(body.props, point)
    if turns:
        I = re_express(I, compose_world_rotations(turns))
    shown = with_product_sign(I, products.value)
    result = _header(body, about_label, point) | {
        "frame": "world (rotated)" if turns else "body",
        "rotations": [f"{a}:{np.degrees(t):g}" for a, t in turns],
        "products_sign": products.value,
        "inertia": shown,
    }
    if direction is not None:
        result |= {"axis": direction, "moment_about_axis": moment_about_axis(I, direction)}

    def table():
        from rbi.cli import tables

        labels = body.labels
        frame = "world axes after " + ", then ".join(result["rotations"]) if turns else "body axes"
        rows = [
            ("mass", labels["mass"], number(body.props.mass, 8)),
            ("centre of mass", labels["length"], tables.vector(body.props.com)),
            (f"about ({about_label})", labels["length"], tables.vector(point)),
        ]
        if direction is not None:
            rows += [("axis (unit)", "", tables.vector(direction)),
                     ("moment about axis", labels["inertia"], number(result["moment_about_axis"], 8))]
        return tables.stack(
            tables.quantities(_title(body, "inertia"), rows),
            tables.matrix(f"Inertia about {about_label}, {frame}; {PRODUCT_SIGN_TITLES[products.value]}",
                          shown, labels["inertia"]),
        )

    emit(format.value, result, table)


def principal(file: SpecFile, about: AboutOption = "com", units: UnitsOption = None,
              format: FormatOption = OutputFormat.table) -> None:
    """Principal moments (ascending), axes (unit, right-handed, body frame) and radii of gyration.

    \b
    Examples:
      rbi principal top_bolted.yaml
      rbi principal top_bolted.yaml --about pivot --format json
      rbi principal flywheel.yaml --units SI
    """
    from rbi.core.inertia import inertia_about, principal_axes, radii_of_gyration
    from rbi.spec.load import load_body

    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    I = inertia_about(body.props, point)
    moments, axes = principal_axes(I)
    radii = radii_of_gyration(moments, body.props.mass)
    result = _header(body, about_label, point) | {"moments": moments, "axes": axes, "radii_of_gyration": radii}

    def table():
        from rbi.cli import tables
        from rbi.cli.render import matrix_digits

        labels = body.labels
        scale, scale_text = matrix_digits(moments)
        t = tables.titled(f"Principal axes about {about_label} (body frame)")
        t.add_column("#")
        t.add_column(tables.unit_header("moment", labels["inertia"], scale_text), justify="right")
        for c in "xyz":
            t.add_column(f"axis {c}", justify="right")
        t.add_column(tables.unit_header("radius of gyration", labels["length"]), justify="right")
        for i, (m, a, k) in enumerate(zip(moments, axes, radii), start=1):
            t.add_row(f"I{i}", number(m / scale, 7), *(number(v, 7) for v in a), number(k, 7))
        return tables.stack(
            tables.quantities(_title(body, "principal"), [
                ("mass", labels["mass"], number(body.props.mass, 8)),
                ("centre of mass", labels["length"], tables.vector(body.props.com)),
                (f"about ({about_label})", labels["length"], tables.vector(point)),
            ]),
            t,
        )

    # CSV: radii numbered like the moments they belong to (radii_of_gyration_1 ...), not _x, _y, _z
    csv_row = {k: v for k, v in result.items() if k != "radii_of_gyration"}
    csv_row |= {f"radii_of_gyration_{i}": k for i, k in enumerate(radii, start=1)}
    emit(format.value, result, table, csv_rows=[csv_row])


def momentum(
    file: SpecFile,
    omega: Annotated[str, typer.Option("--omega", "-w", metavar="WX,WY,WZ",
                                       help="Angular velocity in body axes, rad/s.", show_default=False)],
    about: AboutOption = "com",
    velocity: Annotated[Optional[str], typer.Option(
        "--velocity", "-v", metavar="VX,VY,VZ",
        help="Velocity of the centre of mass (body axes, file length unit/s). Without it the "
             "--about point is taken as fixed, so the body turns about it.")] = None,
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
    from rbi.core.dynamics import angle_between_deg, angular_momentum_about_point, kinetic_energy
    from rbi.spec.load import load_body

    w = np.array(parse_vector(omega, "--omega"))
    v_given = None if velocity is None else np.array(parse_vector(velocity, "--velocity"))
    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point, v_given) = in_output_units(body, units, point, v_given)
    v_given = None if v_given is None else np.array(v_given)
    props = body.props
    com_from_point = props.com - np.asarray(point)
    # Without a given velocity the reference point is fixed: v_c = ω × r_{c/o} (zero at the CoM).
    v_com = v_given if v_given is not None else np.cross(w, com_from_point)
    h = angular_momentum_about_point(props.inertia_com, props.mass, com_from_point, w, v_com)
    energy = kinetic_energy(props.inertia_com, w, props.mass, v_com)
    result = _header(body, about_label, point) | {
        "omega": w,
        "com_velocity": v_com,
        "angular_momentum": h,
        "angle_deg": angle_between_deg(h, w),
        "kinetic_energy": energy,
    }

    def table():
        from rbi.cli import tables

        labels = body.labels
        return tables.quantities(_title(body, f"momentum about {about_label}"), [
            ("mass", labels["mass"], number(props.mass, 8)),
            ("centre of mass", labels["length"], tables.vector(props.com)),
            (f"about ({about_label})", labels["length"], tables.vector(point)),
            ("ω (body axes)", "rad/s", tables.vector(w)),
            ("v of centre of mass", labels["velocity"], tables.vector(v_com)),
            ("angular momentum h", labels["angular_momentum"], tables.vector(h)),
            ("angle between h and ω", "deg", number(result["angle_deg"], 6)),
            ("kinetic energy", labels["energy"], number(energy, 8)),
        ])

    emit(format.value, result, table)


def _title(body, what: str) -> str:
    return f"{body.name or body.path} — {what}"
