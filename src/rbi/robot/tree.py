"""The kinematic tree of a robot model: each link's frame at a configuration, and the whole
robot's mass properties there.

A link's pose is its parent's pose, then its ``origin`` (where it sits at the reference
configuration), then each of its joints' motions in order (a revolute joint turns about its
axis through its anchor by ``q − reference`` radians; a prismatic joint slides along its axis
by ``q − reference`` metres; other joints stay at the reference pose). The reference
configuration is every joint at zero for URDF and SDF and MuJoCo's ``qpos0`` for MJCF (each
joint at its ``ref``), so with no values given every link is where the file draws it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.rotation import axis_angle_matrix
from rbi.errors import InputError
from rbi.formats.robot import Pose, RobotModel


def parse_joint_values(values: list[str] | None) -> dict[str, float]:
    """``NAME=VALUE`` strings (``--joints``) as a mapping; InputError for a malformed one."""
    import math

    found: dict[str, float] = {}
    for value in values or []:
        name, sep, number = value.rpartition("=")
        try:
            q = float(number)
        except ValueError:
            q = math.nan
        if not sep or not name or not math.isfinite(q):
            raise InputError(
                f"--joints: {value!r}: give NAME=VALUE with VALUE a finite number (radians for a "
                "revolute joint, metres for a prismatic one)"
            )
        if name in found:
            raise InputError(
                f"--joints: {name!r} is given twice ({found[name]:g} and {q:g}): give each joint once"
            )
        found[name] = q
    return found


def link_poses(model: RobotModel, joints: dict[str, float] | None = None) -> dict[int, Pose]:
    """Every link's frame in the model's frame (URDF: the root link's; SDF, MJCF: the world's)
    at the configuration ``joints`` (joint name → coordinate; others at the reference)."""
    return placement(model, joints).poses


@dataclass
class Placement:
    """The links placed at one configuration: ``poses`` (link index → its frame in the model's
    frame), ``frames`` (link index → [(motion, axis, anchor)] of its revolute and prismatic
    joints, axis and anchor in the model's frame where the joints before them leave them),
    ``frame`` the name of the frame totals are given in (``"root link NAME"`` for URDF and SDF,
    ``"world"`` for MJCF), ``to_frame`` model frame → that frame, and ``placed`` (link index →
    its frame in that frame)."""

    poses: dict[int, Pose]
    frames: dict[int, list]
    frame: str
    to_frame: Pose
    placed: dict[int, Pose]


def placement(model: RobotModel, joints: dict[str, float] | None = None) -> Placement:
    """Every link's pose at ``joints`` in one pass over the tree, parents first; InputError for a
    joint name the model has no revolute or prismatic joint of."""
    joints = dict(joints or {})
    _check_joint_names(model, joints)
    by_name = {link.key: link for link in model.links}
    poses: dict[int, Pose] = {}
    frames: dict[int, list] = {}
    for link in parents_first(model, by_name):
        pose = (Pose.identity() if link.parent is None else poses[by_name[link.parent].index]).then(
            link.origin
        )
        for motion in link.motions:
            if motion.kind in ("revolute", "prismatic"):
                frames.setdefault(link.index, []).append(
                    (motion, pose.rotation @ motion.axis, pose.apply(motion.anchor))
                )
            if motion.name in joints:
                pose = pose.then(_motion(motion, joints[motion.name]))
        poses[link.index] = pose
    frame, to_frame = "world", Pose.identity()
    if model.format != "mjcf":
        roots = [link for link in model.links if link.parent is None]
        if roots:
            to_frame = poses[roots[0].index].inverse()
            frame = f"root link {roots[0].name}"
    placed = {index: to_frame.then(pose) for index, pose in poses.items()}
    return Placement(poses, frames, frame, to_frame, placed)


def _check_joint_names(model: RobotModel, joints: dict[str, float]) -> None:
    movable = {
        m.name: m
        for link in model.links
        for m in link.motions
        if m.name is not None and m.kind in ("revolute", "prismatic")
    }
    unknown = [name for name in joints if name not in movable]
    if unknown:
        import difflib

        hint = difflib.get_close_matches(unknown[0], list(movable), n=1)
        raise InputError(
            f"--joints: {model.path} has no revolute or prismatic joint named {unknown[0]!r}"
            + (f" (did you mean {hint[0]!r}?)" if hint else "")
        )


def parents_first(model: RobotModel, by_name: dict) -> list:
    """The links ordered so each comes after its parent (depth first from the roots; a link
    whose parent is not in the model counts as a root)."""
    children: dict[str | None, list] = {}
    for link in model.links:
        children.setdefault(link.parent if link.parent in by_name else None, []).append(link)
    order, queue = [], list(children.get(None, []))
    while queue:
        link = queue.pop()
        order.append(link)
        queue.extend(children.get(link.key, []))
    return order


def _motion(motion, q: float) -> Pose:

    amount = q - motion.reference
    if motion.kind == "prismatic":
        return Pose(np.eye(3), motion.axis * amount)
    R = axis_angle_matrix(motion.axis, amount)
    return Pose(R, motion.anchor - R @ motion.anchor)


def totals(
    model: RobotModel, joints: dict[str, float] | None = None, at: Placement | None = None
) -> MassProperties:
    """Total mass, centre of mass and inertia about it at a configuration: in the root link's
    frame for URDF and SDF (``frame`` ``"root link NAME"``), in the world frame for MJCF
    (``"world"``). Links without mass add nothing; with no mass left, the zero value. ``at``:
    the links already placed at ``joints`` (:func:`placement`)."""
    placed = placement(model, joints) if at is None else at
    frame = placed.frame
    parts = []
    for link in model.links:
        if link.inertial is None or link.inertial.mass == 0.0:
            continue
        pose = placed.placed[link.index]
        parts.append(link.inertial.properties.transformed(pose.rotation, pose.translation, frame))
    try:
        total = MassProperties.sum(parts, frame)
    except ValueError:  # no link with mass, or negative masses (flagged unphysical) that leave none
        return MassProperties.zero(frame)
    if not (np.all(np.isfinite(total.center_of_mass)) and np.all(np.isfinite(total.inertia_about_com))):
        far = max(float(np.max(np.abs(part.center_of_mass))) for part in parts)
        raise InputError(
            f"{model.path}: the whole robot's mass properties overflow a double (a centre of mass "
            f"{far:.3g} m from the root); give lengths in metres"
        )
    return total
