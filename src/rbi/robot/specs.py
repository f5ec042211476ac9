"""The whole robot as one rbi spec: each link with mass becomes a ``custom`` part placed where
the link is at the reference configuration (URDF/SDF: every joint at zero, in the root link's
frame; MJCF: ``qpos0``, in the world frame), its inertia turned into those axes. ``rbi inertia``
on that spec gives the totals ``rbi audit`` prints."""

from __future__ import annotations

from typing import Any

from rbi.formats.robot import RobotModel
from rbi.formats.robot_files import custom_part
from rbi.robot.tree import placement


def robot_spec(model: RobotModel, joints: dict[str, float] | None = None) -> tuple[dict[str, Any], list[str]]:
    """(spec, names of the links left out because they have no mass)."""

    at = placement(model, joints)  # in the frame of the totals
    parts, left_out, used = [], [], set()
    for link in model.links:
        inertial = link.inertial
        name = link.name or f"{model.link_word}{link.index}"
        if inertial is None or inertial.mass == 0.0:
            left_out.append(name)
            continue
        row = link.index
        placed = inertial.properties.transformed(at.placed_rotations[row], at.placed_translations[row])
        unique = name if name not in used else f"{name}_{link.index}"
        used.add(unique)
        parts.append(custom_part(unique, inertial.mass, placed.center_of_mass, placed.inertia_about_com))
    return {"name": model.name or "robot", "units": {"length": "m", "mass": "kg"}, "parts": parts}, left_out
