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
from rbi.robot.tree import parents_first, placement

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


def joint_torques(model: RobotModel, joints: dict[str, float] | None = None, at=None) -> list[JointTorque]:
    """The holding torque of every revolute and prismatic joint at ``joints`` (name → value;
    the others at the reference configuration), in file order of their links. ``at``: the links
    already placed there (:func:`rbi.robot.tree.placement`)."""

    placed = placement(model, joints) if at is None else at
    gravity = _gravity(model)
    to_frame = placed.to_frame
    mass, moment = _subtree_sums(model, placed.placed)
    found = []
    for link in model.links:
        if model.format == "sdf" and link.parent is None:
            continue  # a joint to the world: SDF reads no axis for it here
        for motion, axis, anchor in placed.frames.get(link.index, []):
            axis, anchor = to_frame.rotation @ axis, to_frame.apply(anchor)
            M, first = mass[link.index], moment[link.index]  # Σ m, Σ m c
            if motion.kind == "prismatic":
                torque = -M * float(gravity @ axis)
            else:
                torque = -float(gravity @ _cross(axis, first - M * anchor))
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


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.cross`` of two 3-vectors, the same products and differences without its set-up."""
    a0, a1, a2 = a.tolist()
    b0, b1, b2 = b.tolist()
    return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])


def _gravity(model: RobotModel) -> np.ndarray:
    """Gravity (m/s²) in the frame the torques are computed in: MJCF's ``<option gravity>`` in
    the world frame, else −9.81 z of the root link's frame."""
    if model.format == "mjcf":
        return np.asarray(model.options.get("gravity", [0.0, 0.0, -9.81]), dtype=float)
    return np.array([0.0, 0.0, -STANDARD_GRAVITY])


def _subtree_sums(model: RobotModel, placed: dict[int, Pose]):
    """For each link: the mass of its subtree (kg) and its first moment Σ m c (kg·m), from each
    link's pose in the torques' frame."""

    by_name = {link.key: link for link in model.links}
    mass = {link.index: 0.0 for link in model.links}
    moment = {link.index: np.zeros(3) for link in model.links}
    for link in model.links:
        inertial = link.inertial
        if inertial is not None and inertial.mass != 0.0:
            mass[link.index] = inertial.mass
            moment[link.index] = inertial.mass * placed[link.index].apply(inertial.properties.center_of_mass)
    for link in reversed(parents_first(model, by_name)):
        if link.parent is not None and link.parent in by_name:
            parent = by_name[link.parent].index
            mass[parent] += mass[link.index]
            moment[parent] = moment[parent] + moment[link.index]
    return mass, moment
