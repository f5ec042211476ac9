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

    rows, placed = placement(model, joints).heavy  # in the frame of the totals
    names = [link.name or f"{model.link_word}{link.index}" for link in model.links]
    parts, used = [], set()
    for row, each in zip(rows, placed):
        unique = names[row] if names[row] not in used else f"{names[row]}_{row}"
        used.add(unique)
        parts.append(custom_part(unique, each.mass, each.center_of_mass, each.inertia_about_com))
    kept = set(rows)
    left_out = [name for row, name in enumerate(names) if row not in kept]
    return {"name": model.name or "robot", "units": {"length": "m", "mass": "kg"}, "parts": parts}, left_out
