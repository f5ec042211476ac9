"""`rbi export`: the body's inertial element for URDF, MJCF or SDF, always in SI units."""

from __future__ import annotations

import sys
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from rbi.cli.options import FormatOption, OutputFormat, SpecFile


class ExportTarget(str, Enum):
    urdf = "urdf"
    mjcf = "mjcf"
    sdf = "sdf"


ToOption = Annotated[
    ExportTarget,
    typer.Option("--to", "-t", help="Robot description format: urdf, mjcf or sdf.", show_default=False),
]
DocumentOption = Annotated[
    bool,
    typer.Option(
        "--document",
        help="Print a whole minimal document (robot/link, "
        "mujoco/worldbody/body, sdf/model/link) instead of the bare element.",
    ),
]
DiagonalOption = Annotated[
    bool,
    typer.Option(
        "--diagonal",
        help="MJCF only: principal moments (diaginertia) and the "
        "principal frame (quat) instead of fullinertia.",
    ),
]


def export(
    file: SpecFile,
    to: ToOption,
    document: DocumentOption = False,
    diagonal: DiagonalOption = False,
    format: FormatOption = OutputFormat.table,
) -> None:
    """The <inertial> element (mass, centre of mass, inertia about it) in SI units: kg, m, kg·m².

    \b
    Examples:
      rbi export robot_link.yaml --to urdf
      rbi export robot_link.yaml --to mjcf --diagonal --document
    """
    from rbi.cli.export_format import export_xml
    from rbi.cli.render import emit, to_csv
    from rbi.spec.errors import InputError
    from rbi.spec.load import load_body
    from rbi.spec.units import convert_body

    if diagonal and to is not ExportTarget.mjcf:
        raise InputError(
            "--diagonal: only for --to mjcf (URDF and SDF take the full matrix about the centre of mass)"
        )
    source = load_body(file)
    body = convert_body(source, "m", "kg")
    props = body.props
    name = body.name or ("body" if file == "-" else Path(file).stem)
    xml = export_xml(
        to.value,
        props.mass,
        props.center_of_mass,
        props.inertia_about_com,
        name=name,
        document=document,
        diagonal=diagonal,
        comment=_comment(source),
    )
    _warn_if_singular(props.inertia_about_com)
    result = {
        "name": body.name,
        "to": to.value,
        "units": body.units,
        "warnings": list(source.warnings),
        "mass": props.mass,
        "center_of_mass": props.center_of_mass,
        "inertia": props.inertia_about_com,
        "xml": xml,
    }
    if format is not OutputFormat.json:
        from rbi.cli.render import say_warnings

        say_warnings(source.warnings)
    if format is OutputFormat.table:
        sys.stdout.write(xml)
    elif format is OutputFormat.csv:
        sys.stdout.write(to_csv([{k: v for k, v in result.items() if k != "xml"}]))
    else:
        emit(format.value, result, lambda: None)


def _comment(source) -> str:
    """The comment above the element: where it came from, in which units."""
    return (
        f"rbi export of {Path(source.path).name}: SI units (kg, m, kg·m²); inertia about the centre of mass, "
        f"body axes"
        + (
            f"; spec units were {source.length_unit}, {source.mass_unit}"
            if (source.length_unit, source.mass_unit) != ("m", "kg")
            else ""
        )
    )


def _warn_if_singular(inertia) -> None:
    import numpy as np

    moments = np.linalg.eigvalsh(np.asarray(inertia, dtype=float))
    if moments[0] <= 1e-12 * max(moments[-1], 0.0):
        print(
            "rbi: warning: the inertia has a zero principal moment (a point mass or thin rod); "
            "simulators such as MuJoCo refuse a moving body without rotational inertia",
            file=sys.stderr,
        )
