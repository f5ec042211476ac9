"""`rbi dynamics`: the Newton–Euler equations of the body, inverse or forward."""

from __future__ import annotations

import rbi
from rbi.cli.option_values import parse_about, vector_parser
from rbi.cli.options import ABOUT, FORMAT, OutputFormat, SpecFile, command, option
from rbi.cli.render import emit_result

_VEC = "X,Y,Z"


def _vector(option: str):
    """The parser of an optional ``X,Y,Z`` option whose empty value is zero."""
    parse = vector_parser(option)
    return lambda text: parse(text) if text else [0.0, 0.0, 0.0]


@command(
    option(
        str,
        "--omega",
        "-w",
        default="0,0,0",
        metavar="WX,WY,WZ",
        parser=vector_parser("--omega"),
        help="Angular velocity, rad/s.",
    ),
    option(
        str | None,
        "--alpha",
        metavar="AX,AY,AZ",
        parser=vector_parser("--alpha"),
        help="Angular acceleration, rad/s² (inverse dynamics).",
    ),
    option(
        str | None,
        "--accel",
        name="point_acceleration",
        metavar=_VEC,
        parser=_vector("--accel"),
        help="Acceleration of the --about point, length/s² (default 0: a fixed point).",
    ),
    option(
        str | None,
        "--force",
        metavar=_VEC,
        parser=_vector("--force"),
        help="Applied force, mass·length/s² (forward dynamics).",
    ),
    option(
        str | None,
        "--torque",
        metavar=_VEC,
        parser=_vector("--torque"),
        help="Applied torque about the --about point, mass·length²/s² (forward dynamics). Without --force a "
        "non-CoM --about point is held (a pivot): the force needed to hold it is reported.",
    ),
    ABOUT,
    FORMAT,
)
def dynamics(file: SpecFile, *, omega, about, format: OutputFormat, **settings) -> None:
    """Newton–Euler: force and torque for a given motion (--alpha), or the motion a force and
    torque produce (--force/--torque). All vectors in body axes, at this instant.

    \b
    Examples:
      rbi dynamics robot_link.yaml --alpha 0,0,10 --omega 0,0,2 --about pivot
      rbi dynamics cubesat.yaml --torque 0,0,1e-3 --format json
    """

    # the API decides which apply: forward without --force about a point other than the CoM
    # holds the point (at --accel); otherwise --accel goes with --alpha only
    body = rbi.load(file)
    emit_result(format.value, body.dynamics(omega, about=parse_about(about), **settings))
