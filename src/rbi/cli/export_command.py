"""`rbi export`: the body's inertial element for URDF, MJCF or SDF, always in SI units."""

from __future__ import annotations

import sys
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from rbi import api
from rbi.api import SpecError
from rbi.cli.options import FormatOption, OutputFormat, SpecFile
from rbi.cli.render import emit, say_warnings, to_csv


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

    if diagonal and to is not ExportTarget.mjcf:
        raise SpecError(
            "--diagonal: only for --to mjcf (URDF and SDF take the full matrix about the centre of mass)"
        )
    source = api.load(file)
    body = source.in_units("m", "kg")
    props = body.mass_properties
    name = body.name or ("body" if file == "-" else Path(file).stem)
    xml = source.inertial_xml(to.value, name=name, document=document, diagonal=diagonal)
    warnings = source.export_warnings()
    result = {
        "name": body.name,
        "to": to.value,
        "units": body.units,
        "warnings": warnings,
        "mass": props.mass,
        "center_of_mass": props.center_of_mass,
        "inertia": props.inertia_about_com,
        "xml": xml,
    }
    if format is not OutputFormat.json:
        say_warnings(warnings)
    if format is OutputFormat.table:
        sys.stdout.write(xml)
    elif format is OutputFormat.csv:
        sys.stdout.write(to_csv([{k: v for k, v in result.items() if k != "xml"}]))
    else:
        emit(format.value, result, lambda: None)
