"""`rbi dynamics`: the Newton–Euler equations of the body, inverse or forward."""

from __future__ import annotations

from typing import Annotated

import numpy as np
import typer

from rbi import api
from rbi.api import LENGTH_UNITS, MASS_UNITS, SpecError
from rbi.cli import tables
from rbi.cli.options import AboutOption, FormatOption, OutputFormat, SpecFile, parse_about, parse_vector
from rbi.cli.render import emit, number, vector_text

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

    inverse = alpha is not None
    forward = force is not None or torque is not None
    if inverse == forward:
        raise SpecError(
            "dynamics: give either --alpha (inverse: force and torque) or --force/--torque (forward: accelerations)"
        )
    w = np.array(parse_vector(omega, "--omega"))
    body = api.load(file)
    about_label, point = parse_about(about, body)
    given = _given(about_label, alpha, accel, force, torque)
    found = body.dynamics(w, about=point if about_label == "point" else about_label, **given)
    result = {
        "name": body.name,
        "units": body.units,
        "warnings": list(body.warnings),
        "mode": found.mode,
        "mass": body.mass,
        "center_of_mass": body.center_of_mass,
        "about": point,
        "about_label": about_label,
        "omega": w,
        "alpha": found.alpha,
        "point_acceleration": found.point_acceleration,
        "force": found.force,
        "torque": found.torque,
    }
    emit(format.value, result, lambda: _table(body, result, found.held))


def _given(about_label: str, alpha, accel, force, torque) -> dict:
    """The vectors the options give, as `rbi.Body.dynamics` takes them (each parsed where the
    command uses it; the API refuses an inertia about the point that overflows or, for forward
    dynamics, is singular)."""
    if alpha is not None:
        return {
            "alpha": np.array(parse_vector(alpha, "--alpha")),
            "point_acceleration": _vector(accel, "--accel"),
        }
    given = {"torque": _vector(torque, "--torque")}
    if force is None and about_label != "com":  # the point is held (a pivot)
        return given | {"point_acceleration": _vector(accel, "--accel")}
    return given | {"force": _vector(force, "--force")}


def _vector(text: str | None, option: str):
    """An optional ``X,Y,Z`` option as an array: None stays None, an empty one is zero."""
    if text is None:
        return None
    return np.array(parse_vector(text, option)) if text else np.zeros(3)


def _table(body, result: dict, held: bool):
    """The table of a Newton–Euler result; ``held``: the --about point was held (a pivot)."""

    labels, about_label = body.unit_labels, result["about_label"]
    given, found = ("given", "result") if result["mode"] == "inverse" else ("result", "given")
    force_note = "needed to hold the point" if held else found
    return tables.quantities(
        f"{body.name or body.path} — Newton–Euler about {about_label} ({result['mode']})",
        [
            ("mass", labels["mass"], number(result["mass"], 8)),
            (f"about ({about_label})", labels["length"], vector_text(result["about"])),
            ("ω", "rad/s", vector_text(result["omega"])),
            (f"α ({given})", "rad/s²", vector_text(result["alpha"])),
            (
                f"a of {about_label} ({'given' if held else given})",
                f"{labels['length']}/s²",
                vector_text(result["point_acceleration"]),
            ),
            (f"force ({force_note})", _load_unit(body, 1), vector_text(result["force"])),
            (f"torque about {about_label} ({found})", _load_unit(body, 2), vector_text(result["torque"])),
        ],
    )


def _load_unit(body, length_power: int) -> str:
    """Unit of a force (``length_power`` 1) or torque (2) in the file's units: N and N·m in SI,
    otherwise the file's unit with its value in N or N·m."""

    units = body.units
    si = "N" if length_power == 1 else "N·m"
    length = units["length"] if length_power == 1 else f"{units['length']}²"
    factor = MASS_UNITS[units["mass"]] * LENGTH_UNITS[units["length"]] ** length_power
    if factor == 1.0:
        return si
    return f"{units['mass']}·{length}/s² (= {factor:g} {si})"
