"""Joint holding torques: the generalised gravity force on each joint's coordinate at a
configuration, the effort the joint must exert to hold the robot still there, as Pinocchio's
``computeGeneralizedGravity`` and MuJoCo's ``qfrc_bias`` at zero velocity give it.

For a joint moving the links of its subtree (total mass ``M``, centre of mass ``c``, both in
the model's frame), with gravity ``g`` (m/s², model frame), ``V = −M g·c`` and

- revolute (hinge), axis ``a`` through ``p``: ``τ = ∂V/∂q = −M g·(a × (c − p))`` (N·m);
- prismatic (slide), along ``a``: ``τ = −M g·a`` (N).

Gravity: ``−9.81 z`` of the root link's frame for URDF and SDF, the model's ``<option gravity>``
for MJCF (world frame). Joints with several coordinates (ball, free, planar) have none listed.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rbi.formats.robot import Pose, RobotModel

STANDARD_GRAVITY = 9.81
"""m/s², along −z of the root link's frame for URDF and SDF."""


@dataclass
class JointTorque:
    """One joint coordinate: ``name``, ``type`` (``revolute`` or ``prismatic``), ``torque`` (N·m
    or N: the effort that holds the pose), ``effort_limit`` (declared, or None) and ``flags``."""

    name: str | None
    type: str
    torque: float
    effort_limit: float | None
    flags: list = field(default_factory=list)

    @property
    def margin(self) -> float | None:
        """``effort_limit − |torque|`` (negative: the joint cannot hold the pose), or None."""
        return None if self.effort_limit is None else self.effort_limit - abs(self.torque)


def joint_torques(model: RobotModel, joints: dict[str, float] | None = None) -> list[JointTorque]:
    """The holding torque of every revolute and prismatic joint at ``joints`` (name → value;
    the others at the reference configuration), in file order of their links."""
    joints = joints or {}
    frames, poses = _joint_frames(model, joints)
    gravity, to_frame = _gravity(model, poses)
    mass, moment = _subtree_sums(model, poses, to_frame)
    found = []
    for link in model.links:
        if model.format == "sdf" and link.parent is None:
            continue  # a joint to the world: SDF reads no axis for it here
        for motion, axis, anchor in frames.get(link.index, []):
            axis, anchor = to_frame.rotation @ axis, to_frame.apply(anchor)
            M, first = mass[link.index], moment[link.index]  # Σ m, Σ m c
            if motion.kind == "prismatic":
                torque = -M * float(gravity @ axis)
            else:
                torque = -float(gravity @ np.cross(axis, first - M * anchor))
            found.append(JointTorque(motion.name, motion.kind, torque + 0.0, motion.effort_limit))
    for each in found:
        if each.margin is not None and each.margin < 0:
            unit = "N·m" if each.type == "revolute" else "N"
            each.flags.append(
                {
                    "code": "effort",
                    "level": "warning",
                    "message": f"holding the pose takes {abs(each.torque):.4g} {unit}, more than the "
                    f"declared effort limit {each.effort_limit:.4g} {unit}",
                }
            )
    return found


def _joint_frames(model: RobotModel, joints: dict[str, float]):
    """(link index → [(motion, axis, anchor in the model frame)], link index → link pose), each
    joint's axis and anchor taken where the joints before it have left them."""
    from rbi.robot.tree import _motion

    by_name = {link.key: link for link in model.links}
    poses: dict[int, Pose] = {}
    frames: dict[int, list] = {}
    for link in _parents_first(model, by_name):
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
    return frames, poses


def _parents_first(model: RobotModel, by_name) -> list:
    """The links ordered so each comes after its parent (breadth first from the roots)."""
    children: dict[str | None, list] = {}
    for link in model.links:
        children.setdefault(link.parent if link.parent in by_name else None, []).append(link)
    order, queue = [], list(children.get(None, []))
    while queue:
        link = queue.pop()
        order.append(link)
        queue.extend(children.get(link.key, []))
    return order


def _gravity(model: RobotModel, poses: dict[int, Pose]) -> tuple[np.ndarray, Pose]:
    """(gravity in the frame the torques are computed in, model frame → that frame)."""
    if model.format == "mjcf":
        return np.asarray(model.options.get("gravity", [0.0, 0.0, -9.81]), dtype=float), Pose.identity()
    roots = [link for link in model.links if link.parent is None]
    to_frame = poses[roots[0].index].inverse() if roots else Pose.identity()
    return np.array([0.0, 0.0, -STANDARD_GRAVITY]), to_frame


def _subtree_sums(model: RobotModel, poses: dict[int, Pose], to_frame: Pose):
    """For each link: the mass of its subtree (kg) and its first moment Σ m c (kg·m)."""
    by_name = {link.key: link for link in model.links}
    mass = {link.index: 0.0 for link in model.links}
    moment = {link.index: np.zeros(3) for link in model.links}
    for link in model.links:
        inertial = link.inertial
        if inertial is not None and inertial.mass != 0.0:
            mass[link.index] = inertial.mass
            moment[link.index] = inertial.mass * to_frame.then(poses[link.index]).apply(
                inertial.properties.center_of_mass
            )
    for link in reversed(_parents_first(model, by_name)):
        if link.parent is not None and link.parent in by_name:
            parent = by_name[link.parent].index
            mass[parent] += mass[link.index]
            moment[parent] = moment[parent] + moment[link.index]
    return mass, moment
