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

import difflib
import functools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.rotation import angle_is_kept, axis_angle_matrix, turn_lost_to_rounding
from rbi.errors import ArgumentError, InputError, literal, shown
from rbi.formats.robot import LinkColumns, Pose, RobotModel


def parse_joint_values(values: Mapping[str, float] | Sequence[str] | None) -> dict[str, float]:
    """``{NAME: VALUE}``, or ``NAME=VALUE`` strings (``--joints``), as a mapping of finite
    numbers (radians or metres); ArgumentError naming ``joints`` for a malformed one."""
    if isinstance(values, Mapping):
        pairs = [
            (name, number, f"{name}={number if isinstance(number, str) else shown(number)}")
            for name, number in values.items()
        ]
    elif values is None or (isinstance(values, Sequence) and not isinstance(values, (str, bytes))):
        pairs = [(*str(value).rpartition("=")[::2], str(value)) for value in values or []]
    else:
        raise ArgumentError(
            "joints",
            f"expected a mapping of NAME to VALUE or NAME=VALUE strings, got {type(values).__name__}",
        )
    found: dict[str, float] = {}
    for name, number, written in pairs:
        try:
            q = math.nan if isinstance(number, bool) else float(number)
        except (TypeError, ValueError, OverflowError):
            q = math.nan
        if not isinstance(name, str) or not name or not math.isfinite(q):
            raise ArgumentError(
                "joints",
                f"{literal(written)}: give NAME=VALUE with VALUE a finite number (radians for a "
                "revolute joint, metres for a prismatic one)",
            )
        if name in found:
            raise ArgumentError(
                "joints", f"{literal(name)} is given twice ({found[name]:g} and {q:g}): give each joint once"
            )
        found[name] = q
    return found


@dataclass
class Placement:
    """The links placed at one configuration, as arrays (one row a link): ``joints``
    [(row, name, kind, effort limit)] of the revolute and prismatic joints in file order of
    their links, with ``axes`` and ``anchors`` (k, 3) in the model's frame where the joints
    before them leave them; ``frame`` the name of the frame totals are given in (``"root link
    NAME"`` for URDF and SDF, ``"world"`` for MJCF), ``to_frame`` model frame → that frame, and
    ``placed_rotations`` (n, 3, 3) and ``placed_translations`` (n, 3) each link's frame in that
    frame."""

    joints: list
    axes: np.ndarray
    anchors: np.ndarray
    frame: str
    to_frame: Pose
    placed_rotations: np.ndarray
    placed_translations: np.ndarray
    levels: list[tuple[list[int], list[int]]]
    """The rows of each depth in the tree, shallowest first, in
    :func:`~rbi.formats.robot.depth_first`'s order, with their parents' rows (a root's: n)."""
    columns: LinkColumns
    """The model's links as arrays (:meth:`RobotModel.link_columns`)."""

    @functools.cached_property
    def heavy(self) -> tuple[list[int], MassProperties]:
        """The links with a declared mass other than 0: their rows, and their mass properties
        in :attr:`frame` (made once: the totals and the joint torques both ask)."""
        inertials = self.columns.inertials
        rows = np.flatnonzero(self.columns.declared & (inertials.mass != 0.0)).tolist()
        R, t = self.placed_rotations[rows], self.placed_translations[rows]
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported by totals
            return rows, inertials[rows].transformed(R, t, self.frame)


def stack_apply(rotations: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """``rotations[i] @ vectors[i]`` for each row (numpy's matmul on the stack makes the same
    BLAS call per row as on one matrix, so each row equals the one-matrix product)."""
    return np.matmul(rotations, vectors[..., None])[..., 0]


def dot_rows(rows: np.ndarray, other: np.ndarray) -> np.ndarray:
    """``row @ other`` (a 3-vector, or the matching row of a (k, 3) array) for each row of a
    (k, 3) array, as a stack of one-row products (numpy makes the same BLAS call per row as for
    two 3-vectors, so each equals the one-vector product)."""
    return np.matmul(rows[:, None, :], other[..., None])[:, 0, 0]


def placement(
    model: RobotModel, joints: dict[str, float] | None = None, columns: LinkColumns | None = None
) -> Placement:
    """Every link's pose at ``joints``, parents first (a link's pose is its parent's, then its
    origin, then its joints' motions), one level of the tree at a time on (n, 3, 3) stacks;
    InputError for a joint name the model has no revolute or prismatic joint of. ``columns``:
    the model's links as arrays, when already made (:meth:`RobotModel.link_columns`)."""
    joints = dict(joints or {})
    columns = model.link_columns() if columns is None else columns
    _check_joints(model, joints, columns)
    names = zip(columns.joint_rows, columns.joint_names)
    moving = {row for row, name in names if name in joints} if joints else set()
    n = len(columns)
    R = np.empty((n + 1, 3, 3))  # row n: the identity, every root's parent
    t = np.empty((n + 1, 3))
    R[n], t[n] = np.eye(3), np.zeros(3)
    frames: dict[int, list] = {}
    levels = _levels(columns)
    for level, parents in levels:
        level_R, level_t = columns.rotations[level], columns.translations[level]
        R[level] = np.matmul(R[parents], level_R)
        t[level] = stack_apply(R[parents], level_t) + t[parents]
        for row in [row for row in level if row in moving] if moving else ():
            R[row], t[row] = _moved(columns, row, Pose(R[row], t[row]), joints, frames)
    R, t = R[:n], t[:n]
    joint_list, axes, anchors = _joint_frames(columns, R, t, frames)
    frame, to_frame = "world", Pose.identity()
    if model.format != "mjcf" and n:  # the first root link's frame (links that form a tree have one)
        root = columns.parents.index(n)
        to_frame = Pose(R[root], t[root]).inverse()
        frame = f"root link {columns.names[root]}"
    to_R = np.broadcast_to(to_frame.rotation, R.shape)
    placed_R = np.matmul(to_R, R)
    placed_t = stack_apply(to_R, t) + to_frame.translation
    return Placement(joint_list, axes, anchors, frame, to_frame, placed_R, placed_t, levels, columns)


def _levels(columns: LinkColumns) -> list[tuple[list[int], list[int]]]:
    """The rows of each depth in the tree, shallowest first, in
    :func:`~rbi.formats.robot.depth_first`'s order, with their parents' rows (a root's: n)."""
    parents = columns.parents
    depth = [0] * (len(parents) + 1)
    groups: list[tuple[list[int], list[int]]] = []
    for row in columns.order:
        parent = parents[row]
        d = depth[row] = 0 if parent == len(parents) else depth[parent] + 1
        if d == len(groups):
            groups.append(([], []))
        groups[d][0].append(row)
        groups[d][1].append(parent)
    return groups


def _moved(columns: LinkColumns, row: int, pose: Pose, joints: dict[str, float], frames: dict) -> tuple:
    """The link of ``row``, whose joints have values: each revolute and prismatic joint's axis
    and anchor where the joints before it leave them (into ``frames[row]``), and the link's pose
    after them all."""
    for k in columns.joints_of(row):
        kind, axis, anchor = columns.joint_kinds[k], columns.axes[k], columns.anchors[k]
        if kind in ("revolute", "prismatic"):
            frames.setdefault(row, []).append((pose.rotation @ axis, pose.apply(anchor)))
        if columns.joint_names[k] in joints:
            pose = pose.then(
                _motion(kind, axis, anchor, joints[columns.joint_names[k]] - columns.references[k])
            )
    return pose.rotation, pose.translation


def _joint_frames(columns: LinkColumns, R: np.ndarray, t: np.ndarray, moved: dict[int, list]) -> tuple:
    """[(row, name, kind, effort limit)] of every revolute and prismatic joint of ``columns``,
    and their axes and anchors (k, 3) in the model's frame: at the link's pose, or as
    :func:`_moved` found them (``moved``: row → each joint's (axis, anchor))."""
    chosen = [k for k, kind in enumerate(columns.joint_kinds) if kind in ("revolute", "prismatic")]
    rows = [columns.joint_rows[k] for k in chosen]
    found = [
        (row, columns.joint_names[k], columns.joint_kinds[k], columns.efforts[k])
        for row, k in zip(rows, chosen)
    ]
    axes, anchors = columns.axes[chosen], columns.anchors[chosen]
    left = {row: iter(frames) for row, frames in moved.items()}
    for i, row in enumerate(rows):
        if row in left:
            axes[i], anchors[i] = next(left[row])
    at = np.array(rows, dtype=int)
    plain = np.array([row not in left for row in rows], dtype=bool)
    if np.any(plain):
        placed = at[plain]
        axes[plain] = stack_apply(R[placed], axes[plain])
        anchors[plain] = stack_apply(R[placed], anchors[plain]) + t[placed]
    return found, axes, anchors


def _check_joints(model: RobotModel, joints: dict[str, float], columns: LinkColumns) -> None:
    """ArgumentError naming ``joints`` for a name no revolute or prismatic joint of ``columns``
    has, or a revolute value whose turn rounding loses."""
    if not joints:
        return
    pairs = zip(columns.joint_names, columns.joint_kinds)
    movable = {name: kind for name, kind in pairs if name and kind in ("revolute", "prismatic")}
    unknown = [name for name in joints if name not in movable]
    if unknown:
        hint = difflib.get_close_matches(unknown[0], list(movable), n=1)
        raise ArgumentError(
            "joints",
            literal(model.path, quoted=False)
            + f" has no revolute or prismatic joint named {literal(unknown[0])}"
            + (f" (did you mean {literal(hint[0])}?)" if hint else ""),
        )
    for name, value in joints.items():
        if movable[name] == "revolute" and not angle_is_kept(math.degrees(value)):
            raise ArgumentError(
                "joints",
                literal(model.path, quoted=False)
                + f": joint {literal(name)}: {turn_lost_to_rounding(f'{value:g}', 'radians')}",
            )


def _motion(kind: str | None, axis: np.ndarray, anchor: np.ndarray, amount: float) -> Pose:
    """A joint's motion by ``amount`` from its reference (radians turning about ``axis``
    through ``anchor``, metres sliding along it)."""
    if kind == "prismatic":
        return Pose(np.eye(3), axis * amount)
    R = axis_angle_matrix(axis, amount)
    return Pose(R, anchor - R @ anchor)


def totals(
    model: RobotModel, joints: dict[str, float] | None = None, at: Placement | None = None
) -> MassProperties:
    """Total mass, centre of mass and inertia about it at a configuration: in the root link's
    frame for URDF and SDF (``frame`` ``"root link NAME"``), in the world frame for MJCF
    (``"world"``). Links without mass add nothing; with no mass left, the zero value. ``at``:
    the links already placed at ``joints`` (:func:`placement`)."""
    placed = placement(model, joints) if at is None else at
    rows, heavy = placed.heavy
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported just below
            total = heavy.sum()
    except ValueError:  # no link with mass, or negative masses (flagged unphysical) that leave none
        return MassProperties.zero(placed.frame)
    if not (np.all(np.isfinite(total.center_of_mass)) and np.all(np.isfinite(total.inertia_about_com))):
        far = float(np.max(np.abs(heavy.center_of_mass)))
        moment = float(np.max(np.abs(placed.columns.inertials.inertia_about_com[rows])))
        raise InputError(
            f"{model.path}: the whole robot's mass properties overflow a double (centres of mass "
            f"up to {far:.3g} m from the root, moments up to {moment:.3g} kg·m²); give lengths in "
            "metres and moments in kg·m²"
        )
    return total
