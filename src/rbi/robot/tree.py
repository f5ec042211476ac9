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
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from rbi.core.mass import MassProperties, combine
from rbi.core.rotation import angle_is_kept, axis_angle_matrix, turn_lost_to_rounding
from rbi.errors import ArgumentError, InputError, literal, shown
from rbi.formats.robot import LinkColumns, Pose, RobotModel, tree_rows


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
    """The links placed at one configuration, as arrays (one row a link, ``rows``: link index →
    row): ``rotations`` (n, 3, 3) and ``translations`` (n, 3) each link's frame in the model's
    frame; ``joints`` [(row, name, kind, effort limit)] of the revolute and prismatic joints in file order
    of their links, with ``axes`` and ``anchors`` (k, 3) in the model's frame where the joints
    before them leave them; ``frame`` the name of the frame totals are given in (``"root link
    NAME"`` for URDF and SDF, ``"world"`` for MJCF), ``to_frame`` model frame → that frame, and
    ``placed_rotations``/``placed_translations`` each link's frame in that frame, which
    :attr:`placed` gives as :class:`Pose` values."""

    rows: dict[int, int]
    rotations: np.ndarray
    translations: np.ndarray
    joints: list
    axes: np.ndarray
    anchors: np.ndarray
    frame: str
    to_frame: Pose
    placed_rotations: np.ndarray
    placed_translations: np.ndarray
    order: list[tuple[int, int]]
    """(row, parent row) of each link in :func:`~rbi.formats.robot.depth_first`'s order; a root's
    parent row is n."""
    levels: list[tuple[list[int], list[int]]]
    """The rows of each depth in the tree, shallowest first, in that order, with their parents' rows."""
    columns: LinkColumns | None = None
    """The model's links as arrays, when they were read in place of its links."""

    @property
    def placed(self) -> dict[int, Pose]:
        """Link index → its frame in :attr:`frame`."""
        return {i: Pose(self.placed_rotations[r], self.placed_translations[r]) for i, r in self.rows.items()}


def stacked(arrays: list, shape: tuple[int, ...]) -> np.ndarray:
    """The float arrays of ``shape`` in ``arrays`` as one (n, *shape) array: the values
    ``np.array(arrays, dtype=float)`` gives, made by one concatenation (numpy's discovery of a
    list's shape, element by element, takes twice as long for 100,000 links)."""
    if not arrays:
        return np.empty((0, *shape))
    return np.concatenate(arrays, dtype=float).reshape(-1, *shape)


def stack_apply(rotations: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """``rotations[i] @ vectors[i]`` for each row (numpy's matmul on the stack makes the same
    BLAS call per row as on one matrix, so each row equals the one-matrix product)."""
    return np.matmul(rotations, vectors[..., None])[..., 0]


class Joints(NamedTuple):
    """A model's joints, one entry a joint, in file order of their links (a link's in its own
    order): ``rows`` its link's row, ``names`` (None: unnamed), ``kinds`` (None: no joint, a root of
    link arrays), ``efforts`` the declared effort limits or None, ``axes`` and ``anchors`` (k, 3)
    in the link's frame at the reference pose."""

    rows: list[int]
    names: list[str | None]
    kinds: list[str | None]
    efforts: list[float | None]
    axes: np.ndarray
    anchors: np.ndarray


def joint_table(model: RobotModel, columns: LinkColumns | None = None) -> Joints:
    """The :class:`Joints` of ``model``: of its links' motions, or of ``columns`` (a row's joint)."""
    if columns is not None:
        n = len(columns)
        return Joints(
            list(range(n)),
            columns.joint_names,
            columns.joint_kinds,
            columns.efforts,
            columns.axes,
            np.zeros((n, 3)),
        )
    entries = [(row, motion) for row, link in enumerate(model.links) for motion in link.motions]
    motions = [motion for _, motion in entries]
    return Joints(
        [row for row, _ in entries],
        [motion.name for motion in motions],
        [motion.kind for motion in motions],
        [motion.effort_limit for motion in motions],
        stacked([motion.axis for motion in motions], (3,)),
        stacked([motion.anchor for motion in motions], (3,)),
    )


def placement(
    model: RobotModel, joints: dict[str, float] | None = None, columns: LinkColumns | None = None
) -> Placement:
    """Every link's pose at ``joints``, parents first (a link's pose is its parent's, then its
    origin, then its joints' motions), one level of the tree at a time on (n, 3, 3) stacks;
    InputError for a joint name the model has no revolute or prismatic joint of. ``columns``:
    the model's links as arrays (:attr:`RobotModel.in_columns`), read in place of its links."""
    joints = dict(joints or {})
    table = joint_table(model, columns)
    _check_joints(model, joints, table)
    moving = {row for row, name in zip(table.rows, table.names) if name in joints} if joints else set()
    n = len(model.links) if columns is None else len(columns)
    if columns is None:
        rows = {link.index: row for row, link in enumerate(model.links)}
    else:
        rows = dict(zip(range(n), range(n)))
    R = np.empty((n + 1, 3, 3))  # row n: the identity, every root's parent
    t = np.empty((n + 1, 3))
    R[n], t[n] = np.eye(3), np.zeros(3)
    frames: dict[int, list] = {}
    order, levels = _levels(model, columns)
    for level, parents in levels:
        level_R, level_t = _origins(model, columns, level)
        R[level] = np.matmul(R[parents], level_R)
        t[level] = stack_apply(R[parents], level_t) + t[parents]
        for row in [row for row in level if row in moving] if moving else ():
            link = model.links[row] if columns is None else columns.link(row)
            R[row], t[row] = _moved(link, row, Pose(R[row], t[row]), joints, frames)
    R, t = R[:n], t[:n]
    joint_list, axes, anchors = _joint_frames(table, R, t, frames)
    frame, to_frame = "world", Pose.identity()
    if model.format != "mjcf":
        root, name = _root(model, columns)
        if root is not None:
            to_frame = Pose(R[root], t[root]).inverse()
            frame = f"root link {name}"
    to_R = np.broadcast_to(to_frame.rotation, R.shape)
    placed_R = np.matmul(to_R, R)
    placed_t = stack_apply(to_R, t) + to_frame.translation
    return Placement(
        rows,
        R,
        t,
        joint_list,
        axes,
        anchors,
        frame,
        to_frame,
        placed_R,
        placed_t,
        order,
        levels,
        columns,
    )


def _origins(
    model: RobotModel, columns: LinkColumns | None, rows: list[int]
) -> tuple[np.ndarray, np.ndarray]:
    """The origins (rotations (k, 3, 3), translations (k, 3)) of the links of ``rows``."""
    if columns is not None:
        return columns.rotations[rows], columns.translations[rows]
    links = model.links
    return (
        stacked([links[row].origin.rotation for row in rows], (3, 3)),
        stacked([links[row].origin.translation for row in rows], (3,)),
    )


def _root(model: RobotModel, columns: LinkColumns | None) -> tuple[int | None, str | None]:
    """The row and name of the first root link (None, None: no root)."""
    if columns is not None:
        row = columns.parents.index(-1)
        return row, columns.names[row]
    for row, link in enumerate(model.links):
        if link.parent is None:
            return row, link.name
    return None, None


def _levels(
    model: RobotModel, columns: LinkColumns | None = None
) -> tuple[list[tuple[int, int]], list[tuple[list[int], list[int]]]]:
    """(row, parent row) in :func:`~rbi.formats.robot.depth_first`'s order (a root's parent:
    row n, the identity), and the same rows grouped by depth in the tree with their parents'
    rows, shallowest first. InputError for links that are no tree (:func:`tree_rows`)."""
    if columns is not None:
        n = len(columns)
        parents = [n if parent < 0 else parent for parent in columns.parents]
        return _grouped_levels(columns.order, parents, n)
    parents, rows = tree_rows(model.path, model.links)
    return _grouped_levels(rows, parents, len(parents))


def _grouped_levels(rows: list[int], parents, n: int) -> tuple[list[tuple[int, int]], list]:
    """:func:`_levels` of the ``rows`` in parents-first order, each with its parent's row
    (``parents[row]``; n for a root)."""
    depth = [0] * (n + 1)
    order: list[tuple[int, int]] = []
    groups: list[tuple[list[int], list[int]]] = []
    for row in rows:
        parent = parents[row]
        d = depth[row] = 0 if parent == n else depth[parent] + 1
        if d == len(groups):
            groups.append(([], []))
        groups[d][0].append(row)
        groups[d][1].append(parent)
        order.append((row, parent))
    return order, groups


def _moved(link, row: int, pose: Pose, joints: dict[str, float], frames: dict[int, list]) -> tuple:
    """A link (of ``row``) whose joints have values: each revolute and prismatic joint's axis and
    anchor where the joints before it leave them (into ``frames[row]``), and the link's pose after
    them all."""
    for motion in link.motions:
        if motion.kind in ("revolute", "prismatic"):
            frames.setdefault(row, []).append((pose.rotation @ motion.axis, pose.apply(motion.anchor)))
        if motion.name in joints:
            pose = pose.then(_motion(motion, joints[motion.name]))
    return pose.rotation, pose.translation


def _joint_frames(table: Joints, R: np.ndarray, t: np.ndarray, moved: dict[int, list]) -> tuple:
    """[(row, name, kind, effort limit)] of every revolute and prismatic joint of ``table``, and
    their axes and anchors (k, 3) in the model's frame: at the link's pose, or as :func:`_moved`
    found them (``moved``: row → each joint's (axis, anchor))."""
    chosen = [k for k, kind in enumerate(table.kinds) if kind in ("revolute", "prismatic")]
    rows = [table.rows[k] for k in chosen]
    found = [(row, table.names[k], table.kinds[k], table.efforts[k]) for row, k in zip(rows, chosen)]
    axes, anchors = table.axes[chosen], table.anchors[chosen]
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


def _check_joints(model: RobotModel, joints: dict[str, float], table: Joints) -> None:
    """ArgumentError naming ``joints`` for a name no revolute or prismatic joint of ``table`` has,
    or a revolute value whose turn rounding loses."""
    if not joints:
        return
    pairs = zip(table.names, table.kinds)
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
    rows, masses, own_coms, own_inertias = heavy_links(model, placed)
    try:
        if not rows:
            raise ValueError("no link with mass")
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported just below
            coms = stack_apply(placed.placed_rotations[rows], own_coms) + placed.placed_translations[rows]
            inertias = _placed_inertias(placed, rows, own_inertias)
            total = combine(masses, coms, inertias, frame)
    except ValueError:  # no link with mass, or negative masses (flagged unphysical) that leave none
        return MassProperties.zero(frame)
    if not (np.all(np.isfinite(total.center_of_mass)) and np.all(np.isfinite(total.inertia_about_com))):
        far = float(np.max(np.abs(coms)))
        moment = float(np.max(np.abs(own_inertias)))
        raise InputError(
            f"{model.path}: the whole robot's mass properties overflow a double (centres of mass "
            f"up to {far:.3g} m from the root, moments up to {moment:.3g} kg·m²); give lengths in "
            "metres and moments in kg·m²"
        )
    return total


def heavy_links(model: RobotModel, placed: Placement) -> tuple[list[int], np.ndarray, np.ndarray, np.ndarray]:
    """The links with a declared mass other than 0: their rows in ``placed``, masses (kg),
    centres of mass (m) and inertias about them (kg·m²) in their own frames."""
    columns = placed.columns
    if columns is not None:
        rows = np.flatnonzero(columns.declared & (columns.masses != 0.0)).tolist()
        return rows, columns.masses[rows], columns.coms[rows], columns.inertias[rows]
    chosen = [
        (placed.rows[link.index], link.inertial.properties)
        for link in model.links
        if link.inertial is not None and link.inertial.mass != 0.0
    ]
    return (
        [row for row, _ in chosen],
        np.array([props.mass for _, props in chosen], dtype=float),
        stacked([props.center_of_mass for _, props in chosen], (3,)),
        stacked([props.inertia_about_com for _, props in chosen], (3, 3)),
    )


def _placed_inertias(placed: Placement, rows: list[int], inertias: np.ndarray) -> np.ndarray:
    """The inertias (kg·m², about their centres of mass, in their links' axes) of the links of
    ``rows`` in ``placed.frame``'s axes: ``R I Rᵀ`` made symmetric, as
    :meth:`MassProperties.transformed` gives it."""
    R = placed.placed_rotations[rows]
    turned = np.matmul(np.matmul(R, inertias), np.swapaxes(R, 1, 2))
    return 0.5 * (turned + np.swapaxes(turned, 1, 2))
