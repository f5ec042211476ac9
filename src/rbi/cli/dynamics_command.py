"""`rbi dynamics`: the Newton–Euler equations of the body, inverse or forward."""

from __future__ import annotations

import rbi
from rbi.cli.option_values import parse_vector
from rbi.cli.options import ABOUT, FORMAT, OutputFormat, SpecFile, command, option
from rbi.cli.render import emit_result

_VEC = "X,Y,Z"


def _vector(text: str, option: str) -> list[float]:
    """An optional ``X,Y,Z`` option whose empty value is zero."""
    return parse_vector(text, option) if text else [0.0, 0.0, 0.0]


@command(
    option(
        str,
        "--omega",
        "-w",
        default="0,0,0",
        metavar="WX,WY,WZ",
        parser=parse_vector,
        help="Angular velocity, rad/s.",
    ),
    option(
        str | None,
        "--alpha",
        metavar="AX,AY,AZ",
        parser=parse_vector,
        help="Angular acceleration, rad/s² (inverse dynamics).",
    ),
    option(
        str | None,
        "--accel",
        name="point_acceleration",
        metavar=_VEC,
        parser=_vector,
        help="Acceleration of the --about point, length/s² (default 0: a fixed point).",
    ),
    option(
        str | None,
        "--force",
        metavar=_VEC,
        parser=_vector,
        help="Applied force, mass·length/s² (forward dynamics).",
    ),
    option(
        str | None,
        "--torque",
        metavar=_VEC,
        parser=_vector,
        help="Applied torque about the --about point, mass·length²/s² (forward dynamics). Without --force a "
        "non-CoM --about point is held (a pivot): the force needed to hold it is reported.",
    ),
    ABOUT,
    FORMAT,
)
def dynamics(file: SpecFile, *, omega, format: OutputFormat, **settings) -> None:
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
    emit_result(format.value, body.dynamics(omega, **settings))
