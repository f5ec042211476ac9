"""`rbi inertia`, `rbi principal`, `rbi momentum`: mass properties of a body. Every number is
in the spec's units unless ``--units`` asks for others."""

from __future__ import annotations

from enum import Enum
from typing import Annotated

import numpy as np
import typer

from rbi import api
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import (
    AboutOption,
    FormatOption,
    OutputFormat,
    SpecFile,
    SpecFiles,
    UnitsOption,
    in_output_units,
    parse_about,
    parse_rotation,
    parse_vector,
)
from rbi.cli.render import body_size, emit, matrix_digits, number, plus_minus, vector_text

PRODUCT_SIGN_TITLES = {"tensor": "products −∫xy dm", "cad": "CAD products +∫xy dm"}
"""Signs of the off-diagonal entries: ``tensor`` (the matrix, ``I_xy = −∫xy dm``) or ``cad``
(the positive integrals ``+∫xy dm`` SolidWorks and CATIA print), with their tables' titles."""


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

    turns = [parse_rotation(r) for r in rotate or []]
    direction = None
    if axis is not None:
        try:
            direction = api.unit_vector(parse_vector(axis, "--axis"))
        except ValueError:
            raise api.SpecError(f"--axis: must be a non-zero direction X,Y,Z (got {axis!r})") from None
    return report_each(
        files, lambda file: _inertia_of(file, about, turns, direction, products.value, units), format.value
    )


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

    return report_each(files, lambda file: _principal_of(file, about, units), format.value)


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
    body = api.load(file)
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
            ("ω (body axes)", "rad/s", vector_text(result["omega"])),
            ("v of centre of mass", labels["velocity"], vector_text(result["com_velocity"])),
            ("angular momentum h", labels["angular_momentum"], vector_text(result["angular_momentum"])),
            ("angle between h and ω", "deg", number(result["angle_deg"], 6)),
            ("kinetic energy", labels["energy"], number(result["kinetic_energy"], 8)),
        ],
    )


def header(body: api.Body, about_label: str, about_point) -> dict:
    """The keys every mass-properties result starts with."""
    return {
        "name": body.name,
        "units": body.units,
        "mass": body.mass,
        "center_of_mass": body.center_of_mass,
        "about": about_point,
        "about_label": about_label,
        "warnings": list(body.warnings),
    }


def with_product_sign(inertia, sign: str):
    """The inertia matrix with its off-diagonal entries in convention ``sign`` (see
    :data:`PRODUCT_SIGN_TITLES`); the moments on the diagonal never change."""

    shown = np.array(inertia, dtype=float)
    if sign == "tensor":
        return shown
    if sign == "cad":
        off_diagonal = ~np.eye(3, dtype=bool)
        shown[off_diagonal] = 0.0 - shown[off_diagonal]  # 0.0 - 0.0 is +0.0, no '-0' printed
        return shown
    raise ValueError(f"unknown products sign {sign!r} (expected one of {tuple(PRODUCT_SIGN_TITLES)})")


def place_rows(body: api.Body, about_label: str, point, spread=None) -> list[tuple[str, str, str]]:
    """The rows every mass-properties table starts with: the mass, the centre of mass and the
    ``--about`` point (a coordinate below 1e-12 of the body's size printed 0); with ``spread``
    (`Body.standard_uncertainty`), the mass and centre of mass ``± u``."""

    labels, size = body.unit_labels, body_size(body)
    mass, com = number(body.mass, 8), vector_text(body.center_of_mass, scale=size)
    if spread is not None:
        mass, com = (
            plus_minus(body.mass, spread["mass"]),
            f"{com} ± {vector_text(spread['center_of_mass'], 2)}",
        )
    return [
        ("mass", labels["mass"], mass),
        ("centre of mass", labels["length"], com),
        (f"about ({about_label})", labels["length"], vector_text(point, scale=size)),
    ]


def title(body, what: str) -> str:
    return f"{body.name or body.path} — {what}"


def _inertia_of(file: str, about: str, turns, direction, products: str, units: str | None):

    body = api.load(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    axes = turns or None
    shown = with_product_sign(body.inertia(point, axes), products)
    result = header(body, about_label, point) | {
        "frame": "world (rotated)" if turns else "body",
        "rotations": [f"{a}:{np.degrees(np.radians(d)):g}" for a, d in turns],
        "products_sign": products,
        "inertia": shown,
    }
    if direction is not None:
        result |= {"axis": direction, "moment_about_axis": body.moment_about_axis(direction, point, axes)}
    spread = body.standard_uncertainty(point, axes)
    if spread is not None:
        result["uncertainty"] = {k: spread[k] for k in ("mass", "center_of_mass", "inertia")}

    def table():
        # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
        from rbi.cli import tables

        labels = body.unit_labels
        frame = "world axes after " + ", then ".join(result["rotations"]) if turns else "body axes"
        rows = place_rows(body, about_label, point, spread)
        if direction is not None:
            rows += [
                ("axis (unit)", "", vector_text(direction)),
                ("moment about axis", labels["inertia"], number(result["moment_about_axis"], 8)),
            ]
        matrix_title = f"Inertia about {about_label}, {frame}; {PRODUCT_SIGN_TITLES[products]}"
        return tables.stack(
            tables.quantities(title(body, "inertia"), rows),
            tables.matrix(matrix_title, shown, labels["inertia"]),
            *(
                []
                if spread is None
                else [tables.matrix("± its standard uncertainty", spread["inertia"], labels["inertia"])]
            ),
        )

    return FileReport(result, table)


def _principal_of(file: str, about: str, units: str | None):
    body = api.load(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    principal = body.principal(point)
    moments, axes, radii = principal.moments, principal.axes, principal.radii_of_gyration
    result = header(body, about_label, point) | {"moments": moments, "axes": axes, "radii_of_gyration": radii}
    spread = body.standard_uncertainty(point)
    if spread is not None:
        result["uncertainty"] = {k: spread[k] for k in ("mass", "center_of_mass", "moments", "axes_deg")}
        result["warnings"] += [
            f"principal axis {i + 1} is not determined: its moment is within 3 standard uncertainties of another's"
            for i, deg in enumerate(spread["axes_deg"])
            if deg is None
        ]

    def table():
        # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
        from rbi.cli import tables

        labels = body.unit_labels
        scale, scale_text = matrix_digits(moments)
        t = tables.titled(f"Principal axes about {about_label} (body frame)")
        t.add_column("#")
        t.add_column(tables.unit_header("moment", labels["inertia"], scale_text), justify="right")
        for c in "xyz":
            t.add_column(f"axis {c}", justify="right")
        t.add_column(tables.unit_header("radius of gyration", labels["length"]), justify="right")
        if spread is not None:
            t.add_column("axis ±°", justify="right")
        for i, (m, a, k) in enumerate(zip(moments, axes, radii), start=1):
            moment = (
                number(m / scale, 7)
                if spread is None
                else plus_minus(m / scale, spread["moments"][i - 1] / scale)
            )
            turn = [] if spread is None else [number(spread["axes_deg"][i - 1], 2)]
            t.add_row(f"I{i}", moment, *(number(v, 7) for v in a), number(k, 7), *turn)
        return tables.stack(
            tables.quantities(
                title(body, "principal"),
                place_rows(body, about_label, point, spread),
            ),
            t,
        )

    # CSV: radii numbered like the moments they belong to (radii_of_gyration_1 ...), not _x, _y, _z
    csv_row = {k: v for k, v in result.items() if k != "radii_of_gyration"}
    csv_row |= {f"radii_of_gyration_{i}": k for i, k in enumerate(radii, start=1)}
    return FileReport(result, table, csv_rows=[csv_row])
