"""`rbi export`: the body's inertial element for URDF, MJCF or SDF, always in SI units."""

from __future__ import annotations

import sys
from enum import Enum

import rbi
from rbi import SpecError
from rbi.cli.options import FormatOption, OutputFormat, SpecFile, option
from rbi.cli.render import emit_result, say_warnings


class ExportTarget(str, Enum):
    urdf = "urdf"
    mjcf = "mjcf"
    sdf = "sdf"


ToOption = option(
    ExportTarget, "--to", "-t", help="Robot description format: urdf, mjcf or sdf.", show_default=False
)
DocumentOption = option(
    bool,
    "--document",
    help="Print a whole minimal document (robot/link, "
    "mujoco/worldbody/body, sdf/model/link) instead of the bare element.",
)
DiagonalOption = option(
    bool,
    "--diagonal",
    help="MJCF only: principal moments (diaginertia) and the principal frame (quat) instead of fullinertia.",
)


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
    source = rbi.load(file)
    result = source.export(to.value, document=document, diagonal=diagonal)
    if format is OutputFormat.table:  # the element itself: no table
        say_warnings(result.warnings)
        sys.stdout.write(result.xml)
    else:
        emit_result(format.value, result)
