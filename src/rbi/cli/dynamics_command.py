"""`rbi dynamics`: the Newton–Euler equations of the body, inverse or forward."""

from __future__ import annotations

import rbi
from rbi import SpecError
from rbi.cli.option_values import parse_about, parse_vector
from rbi.cli.options import AboutOption, FormatOption, OutputFormat, SpecFile, option
from rbi.cli.render import emit_result

_VEC = "X,Y,Z"


OmegaOption = option(str, "--omega", "-w", metavar="WX,WY,WZ", help="Angular velocity, rad/s.")
AlphaOption = option(
    str | None, "--alpha", metavar="AX,AY,AZ", help="Angular acceleration, rad/s² (inverse dynamics)."
)
AccelOption = option(
    str | None,
    "--accel",
    metavar=_VEC,
    help="Acceleration of the --about point, length/s² (default 0: a fixed point).",
)
ForceOption = option(
    str | None, "--force", metavar=_VEC, help="Applied force, mass·length/s² (forward dynamics)."
)
TorqueOption = option(
    str | None,
    "--torque",
    metavar=_VEC,
    help="Applied torque about the --about point, mass·length²/s² (forward dynamics). Without --force a "
    "non-CoM --about point is held (a pivot): the force needed to hold it is reported.",
)


def dynamics(
    file: SpecFile,
    omega: OmegaOption = "0,0,0",
    alpha: AlphaOption = None,
    accel: AccelOption = None,
    force: ForceOption = None,
    torque: TorqueOption = None,
    about: AboutOption = "com",
    format: FormatOption = OutputFormat.table,
) -> None:
    """Newton–Euler: force and torque for a given motion (--alpha), or the motion a force and
    torque produce (--force/--torque). All vectors in body axes, at this instant.

    \b
    Examples:
      rbi dynamics robot_link.yaml --alpha 0,0,10 --omega 0,0,2 --about pivot
      rbi dynamics cubesat.yaml --torque 0,0,1e-3 --format json
    """

    inverse = alpha is not None
    forward = force is not None or torque is not None
    if inverse == forward:
        raise SpecError(
            "dynamics: give either --alpha (inverse: force and torque) or --force/--torque (forward: accelerations)"
        )
    w = parse_vector(omega, "--omega")
    body = rbi.load(file)
    # the API decides which apply: forward without --force about a point other than the CoM
    # holds the point (at --accel); otherwise --accel goes with --alpha only
    result = body.dynamics(
        w,
        about=parse_about(about),
        alpha=None if alpha is None else parse_vector(alpha, "--alpha"),
        point_acceleration=_vector(accel, "--accel"),
        force=_vector(force, "--force"),
        torque=_vector(torque, "--torque"),
    )
    emit_result(format.value, result)


def _vector(text: str | None, option: str):
    """An optional ``X,Y,Z`` option as an array: None stays None, an empty one is zero."""
    if text is None:
        return None
    return parse_vector(text, option) if text else [0.0, 0.0, 0.0]
