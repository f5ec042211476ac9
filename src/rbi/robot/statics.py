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

from rbi.errors import InputError
from rbi.formats.robot import RobotModel, short
from rbi.robot.flags import Flag
from rbi.robot.tree import dot_rows
from rbi.spec.units import STANDARD_GRAVITY_SI


@dataclass
class JointTorque:
    """One joint coordinate: ``name``, ``type`` (``revolute`` or ``prismatic``), ``torque`` (N·m
    or N: the effort that holds the pose), ``effort_limit`` (declared, or None) and ``flags``."""

    name: str | None
    type: str
    torque: float
    effort_limit: float | None
    flags: list[Flag] = field(default_factory=list)

    @property
    def margin(self) -> float | None:
        """``effort_limit − |torque|`` (negative: the joint cannot hold the pose), or None."""
        return None if self.effort_limit is None else self.effort_limit - abs(self.torque)


@np.errstate(over="ignore", invalid="ignore")  # an overflow is refused, naming the joint, below
def joint_torques(model: RobotModel, placed) -> list[JointTorque]:
    """The holding torque of every revolute and prismatic joint with the links ``placed`` at a
    configuration (:func:`rbi.robot.tree.placement`), in file order of their links; InputError,
    one line naming the joint, when one overflows a double."""
    gravity = _gravity(model)
    mass, moment = _subtree_sums(model, placed)
    to_frame = placed.to_frame
    to_R = np.broadcast_to(to_frame.rotation, (len(placed.joints), 3, 3))
    axes = np.matmul(to_R, placed.axes[..., None])[..., 0]
    anchors = np.matmul(to_R, placed.anchors[..., None])[..., 0] + to_frame.translation
    chosen = placed.joints
    if model.format == "sdf":  # only an SDF root link has joints to the world: SDF reads no axis for them
        roots = len(placed.columns)  # (a root's parent row)
        keep = [i for i, joint in enumerate(chosen) if placed.columns.parents[joint[0]] != roots]
        chosen, axes, anchors = [chosen[i] for i in keep], axes[keep], anchors[keep]
    rows = [row for row, *_ in chosen]
    M = mass[rows]  # Σ m of each joint's subtree
    lever = np.cross(axes, moment[rows] - M[:, None] * anchors)  # axis × (Σ m c − M p)
    prismatic = np.array([kind == "prismatic" for _, _, kind, _ in chosen], dtype=bool)
    torques = np.where(prismatic, -M * dot_rows(axes, gravity), -dot_rows(lever, gravity)) + 0.0
    if not np.all(np.isfinite(torques)):
        row, name, *_ = chosen[int(np.flatnonzero(~np.isfinite(torques))[0])]
        joint = f"joint {short(name)!r}" if name else "joint"
        raise InputError(
            f"{model.path}: {placed.columns.link(row).label}: {joint}: the torque that holds the pose "
            "overflows a double; give lengths in metres and masses in kg"
        )
    found = []
    for (_, name, kind, limit), torque in zip(chosen, torques.tolist()):
        flags = [] if limit is None or not limit - abs(torque) < 0 else [_effort_flag(kind, torque, limit)]
        found.append(JointTorque(name, kind, torque, limit, flags))
    return found


def _effort_flag(kind: str, torque: float, limit: float) -> Flag:
    """The warning for a joint whose holding torque exceeds its declared effort limit (a
    negative :attr:`JointTorque.margin`)."""
    unit = "N·m" if kind == "revolute" else "N"
    text = f"holding the pose takes {abs(torque):.4g} {unit}, more than the declared effort limit"
    return Flag("effort", "warning", f"{text} {limit:.4g} {unit}")


def _gravity(model: RobotModel) -> np.ndarray:
    """Gravity (m/s²) in the frame the torques are computed in: MJCF's ``<option gravity>`` in
    the world frame, else −9.81 z of the root link's frame."""
    if model.format == "mjcf":
        return np.asarray(model.options.get("gravity", [0.0, 0.0, -STANDARD_GRAVITY_SI]), dtype=float)
    return np.array([0.0, 0.0, -STANDARD_GRAVITY_SI])


def _subtree_sums(model: RobotModel, placed) -> tuple[np.ndarray, np.ndarray]:
    """For each link's row of ``placed``: the mass of its subtree (kg) and its first moment
    Σ m c (kg·m, in ``placed.frame``), each subtree added to its parent's in the reverse of
    :func:`rbi.formats.robot.depth_first`'s order: one level of the tree at a time, deepest
    first, each level's links in that reverse order (``np.add.at`` adds in the order given, so
    each parent receives the same sums in the same order as one link at a time)."""
    n = len(placed.placed_translations)
    mass = np.zeros(n + 1)  # row n: every root's parent, added to and dropped
    first = np.zeros((n + 1, 3))
    chosen, heavy = placed.heavy
    if chosen:
        first[chosen] = heavy.mass[:, None] * heavy.center_of_mass
        mass[chosen] = heavy.mass
    for rows, parents in reversed(placed.levels):
        rows, parents = rows[::-1], parents[::-1]
        np.add.at(mass, parents, mass[rows])
        np.add.at(first, parents, first[rows])
    return mass[:n], first[:n]
