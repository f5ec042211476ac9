"""`rbi export`: the body's inertial element for URDF, MJCF or SDF, always in SI units."""

from __future__ import annotations

import sys
from typing import Literal

import rbi
from rbi.cli.options import FORMAT, REQUIRED, OutputFormat, SpecFile, command, option
from rbi.cli.render import emit_result, say_warnings


@command(
    option(
        Literal["urdf", "mjcf", "sdf"],
        "--to",
        "-t",
        default=REQUIRED,
        help="Robot description format: urdf, mjcf or sdf.",
    ),
    option(
        bool,
        "--document",
        help="Print a whole minimal document (robot/link, "
        "mujoco/worldbody/body, sdf/model/link) instead of the bare element.",
    ),
    option(
        bool,
        "--diagonal",
        help="MJCF only: principal moments (diaginertia) and the principal frame (quat) instead of fullinertia.",
    ),
    FORMAT,
    api=rbi.Body.export,
)
def export(file: SpecFile, *, to, format: OutputFormat, **settings) -> None:
    """The <inertial> element (mass, centre of mass, inertia about it) in SI units: kg, m, kg·m².

    \b
    Examples:
      rbi export robot_link.yaml --to urdf
      rbi export robot_link.yaml --to mjcf --diagonal --document
    """

    result = rbi.load(file).export(to, **settings)
    if format is OutputFormat.table:  # the element itself: no table
        say_warnings(result.warnings)
        sys.stdout.write(result.xml)
    else:
        emit_result(format.value, result)
