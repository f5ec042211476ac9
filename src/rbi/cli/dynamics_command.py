"""`rbi dynamics`: the Newton–Euler equations of the body, inverse or forward."""

from __future__ import annotations

from typing import Annotated

import numpy as np
import typer

from rbi.cli.options import AboutOption, FormatOption, OutputFormat, SpecFile, parse_about, parse_vector
from rbi.cli.render import emit, number
from rbi.spec.errors import InputError

_VEC = "X,Y,Z"


OmegaOption = Annotated[
    str, typer.Option("--omega", "-w", metavar="WX,WY,WZ", help="Angular velocity, rad/s.")
]
AlphaOption = Annotated[
    str | None,
    typer.Option("--alpha", metavar="AX,AY,AZ", help="Angular acceleration, rad/s² (inverse dynamics)."),
]
AccelOption = Annotated[
    str | None,
    typer.Option(
        "--accel",
        metavar=_VEC,
        help="Acceleration of the --about point, length/s² (default 0: a fixed point).",
    ),
]
ForceOption = Annotated[
    str | None,
    typer.Option("--force", metavar=_VEC, help="Applied force, mass·length/s² (forward dynamics)."),
]
TorqueOption = Annotated[
    str | None,
    typer.Option(
        "--torque",
        metavar=_VEC,
        help="Applied torque about the --about point, mass·length²/s² (forward dynamics). "
        "Without --force a non-CoM --about point is held (a pivot): "
        "the force needed to hold it is reported.",
    ),
]


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
    from rbi.spec.load import load_body

    inverse = alpha is not None
    forward = force is not None or torque is not None
    if inverse == forward:
        raise InputError(
            "dynamics: give either --alpha (inverse: force and torque) or --force/--torque (forward: accelerations)"
        )
    w = np.array(parse_vector(omega, "--omega"))
    body = load_body(file)
    about_label, point = parse_about(about, body)
    props = body.props
    r = props.center_of_mass - np.asarray(point)
    I_point = props.inertia_about(point)
    if not np.all(np.isfinite(I_point)):
        raise InputError(
            f"--about: the point is too far from the body: the inertia about it overflows "
            f"double precision (got {about!r})"
        )
    if inverse:
        motion, loads = _inverse(props, I_point, r, w, about_label, alpha, accel)
    else:
        motion, loads = _forward(file, props, I_point, r, w, about_label, force, torque, accel)
    result = {
        "name": body.name,
        "units": body.units,
        "warnings": list(body.warnings),
        "mode": "inverse" if inverse else "forward",
        "mass": props.mass,
        "center_of_mass": props.center_of_mass,
        "about": point,
        "about_label": about_label,
        "omega": w,
        **motion,
        **loads,
    }
    held = not inverse and force is None and about_label != "com"
    emit(format.value, result, lambda: _table(body, result, held))


def _table(body, result: dict, held: bool):
    """The table of a Newton–Euler result; ``held``: the --about point was held (a pivot)."""
    from rbi.cli import tables

    labels, about_label = body.labels, result["about_label"]
    given, found = ("given", "result") if result["mode"] == "inverse" else ("result", "given")
    force_note = "needed to hold the point" if held else found
    return tables.quantities(
        f"{body.name or body.path} — Newton–Euler about {about_label} ({result['mode']})",
        [
            ("mass", labels["mass"], number(result["mass"], 8)),
            (f"about ({about_label})", labels["length"], tables.vector(result["about"])),
            ("ω", "rad/s", tables.vector(result["omega"])),
            (f"α ({given})", "rad/s²", tables.vector(result["alpha"])),
            (
                f"a of {about_label} ({'given' if held else given})",
                f"{labels['length']}/s²",
                tables.vector(result["point_acceleration"]),
            ),
            (f"force ({force_note})", _load_unit(body, 1), tables.vector(result["force"])),
            (f"torque about {about_label} ({found})", _load_unit(body, 2), tables.vector(result["torque"])),
        ],
    )


def _inverse(props, I_point, r, w, about_label: str, alpha, accel):
    """The force and torque a given angular acceleration (and acceleration of the point) needs:
    ``(motion, loads)``."""
    from rbi.core import dynamics as ne

    a = np.array(parse_vector(alpha, "--alpha"))
    acc = np.array(parse_vector(accel, "--accel")) if accel else np.zeros(3)
    if about_label == "com":
        wrench = ne.newton_euler_com(props.mass, props.inertia_about_com, w, a, acc)
    else:
        wrench = ne.newton_euler_point(props.mass, I_point, r, w, a, acc)
    return {"alpha": a, "point_acceleration": acc}, {"force": wrench.force, "torque": wrench.torque}


def _forward(file, props, I_point, r, w, about_label: str, force, torque, accel):
    """The motion an applied force and torque produce: ``(motion, loads)``; without a force, a
    point other than the centre of mass is held and the force holding it is found."""
    from rbi.core import dynamics as ne

    t = np.array(parse_vector(torque, "--torque")) if torque else np.zeros(3)
    if np.linalg.matrix_rank(I_point) < 3:
        raise InputError(
            f"{file}: the inertia about the {about_label} is singular: the body cannot be given an angular acceleration"
        )
    if force is None and about_label != "com":
        # The point is held (a pivot): its acceleration is prescribed and the force that
        # holds it is part of the answer.
        acc = np.array(parse_vector(accel, "--accel")) if accel else np.zeros(3)
        a = np.linalg.solve(I_point, t - np.cross(w, I_point @ w) - props.mass * np.cross(r, acc))
        f = ne.newton_euler_point(props.mass, I_point, r, w, a, acc).force
        return {"alpha": a, "point_acceleration": acc}, {"force": f, "torque": t}
    f = np.array(parse_vector(force, "--force")) if force else np.zeros(3)
    if about_label == "com":
        result_acc = ne.newton_euler_com_forward(props.mass, props.inertia_about_com, w, f, t)
    else:
        result_acc = ne.newton_euler_point_forward(props.mass, I_point, r, w, f, t)
    return {"alpha": result_acc.angular, "point_acceleration": result_acc.linear}, {"force": f, "torque": t}


def _load_unit(body, length_power: int) -> str:
    """Unit of a force (``length_power`` 1) or torque (2) in the file's units: N and N·m in SI,
    otherwise the file's unit with its value in N or N·m."""
    from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

    si = "N" if length_power == 1 else "N·m"
    length = body.length_unit if length_power == 1 else f"{body.length_unit}²"
    factor = MASS_UNITS_IN_KG[body.mass_unit] * LENGTH_UNITS_IN_M[body.length_unit] ** length_power
    if factor == 1.0:
        return si
    return f"{body.mass_unit}·{length}/s² (= {factor:g} {si})"
