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

import numpy as np

from rbi.core.mass import MassProperties, combine
from rbi.core.rotation import LARGEST_ANGLE_DEG, angle_is_kept, axis_angle_matrix
from rbi.errors import ArgumentError, InputError, literal
from rbi.formats.robot import Pose, RobotModel


def parse_joint_values(values: Mapping[str, float] | Sequence[str] | None) -> dict[str, float]:
    """``{NAME: VALUE}``, or ``NAME=VALUE`` strings (``--joints``), as a mapping of finite
    numbers (radians or metres); ArgumentError naming ``joints`` for a malformed one."""
    if isinstance(values, Mapping):
        pairs = [(name, number, f"{name}={number}") for name, number in values.items()]
    elif values is None or (isinstance(values, Sequence) and not isinstance(values, (str, bytes))):
        pairs = [(*str(value).rpartition("=")[::2], str(value)) for value in values or []]
    else:
        raise ArgumentError(
            "joints",
            f"expected a mapping of NAME to VALUE or NAME=VALUE strings, got {type(values).__name__}",
        )
    found: dict[str, float] = {}
    for name, number, shown in pairs:
        try:
            q = math.nan if isinstance(number, bool) else float(number)
        except (TypeError, ValueError):
            q = math.nan
        if not isinstance(name, str) or not name or not math.isfinite(q):
            raise ArgumentError(
                "joints",
                f"{literal(shown)}: give NAME=VALUE with VALUE a finite number (radians for a "
                "revolute joint, metres for a prismatic one)",
            )
        if name in found:
            raise ArgumentError(
                "joints", f"{literal(name)} is given twice ({found[name]:g} and {q:g}): give each joint once"
            )
        found[name] = q
    return found


def link_poses(model: RobotModel, joints: dict[str, float] | None = None) -> dict[int, Pose]:
    """Every link's frame in the model's frame (URDF: the root link's; SDF, MJCF: the world's)
    at the configuration ``joints`` (joint name → coordinate; others at the reference)."""
    return placement(model, joints).poses


@dataclass
class Placement:
    """The links placed at one configuration, as arrays (one row a link, ``rows``: link index →
    row): ``rotations`` (n, 3, 3) and ``translations`` (n, 3) each link's frame in the model's
    frame; ``joints`` [(link index, motion)] of the revolute and prismatic joints in file order
    of their links, with ``axes`` and ``anchors`` (k, 3) in the model's frame where the joints
    before them leave them; ``frame`` the name of the frame totals are given in (``"root link
    NAME"`` for URDF and SDF, ``"world"`` for MJCF), ``to_frame`` model frame → that frame, and
    ``placed_rotations``/``placed_translations`` each link's frame in that frame. :attr:`poses`
    and :attr:`placed` give them as :class:`Pose` values."""

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
    """(row, parent row) of each link in :func:`parents_first`'s order; a root's parent row is n."""

    @property
    def poses(self) -> dict[int, Pose]:
        """Link index → its frame in the model's frame."""
        return {i: Pose(self.rotations[r], self.translations[r]) for i, r in self.rows.items()}

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


def placement(model: RobotModel, joints: dict[str, float] | None = None) -> Placement:
    """Every link's pose at ``joints``, parents first (a link's pose is its parent's, then its
    origin, then its joints' motions), one level of the tree at a time on (n, 3, 3) stacks;
    InputError for a joint name the model has no revolute or prismatic joint of."""
    joints = dict(joints or {})
    _check_joints(model, joints)
    links = model.links
    n = len(links)
    rows = {link.index: row for row, link in enumerate(links)}
    R = np.empty((n + 1, 3, 3))  # row n: the identity, every root's parent
    t = np.empty((n + 1, 3))
    R[n], t[n] = np.eye(3), np.zeros(3)
    frames: dict[int, list] = {}
    order, levels = _levels(model)
    for level, parents in levels:
        level_R = stacked([links[row].origin.rotation for row in level], (3, 3))
        level_t = stacked([links[row].origin.translation for row in level], (3,))
        R[level] = np.matmul(R[parents], level_R)
        t[level] = stack_apply(R[parents], level_t) + t[parents]
        for row in level:
            if joints and any(motion.name in joints for motion in links[row].motions):
                R[row], t[row] = _moved(links[row], Pose(R[row], t[row]), joints, frames)
    R, t = R[:n], t[:n]
    joint_list, axes, anchors = _joint_frames(model, R, t, frames)
    frame, to_frame = "world", Pose.identity()
    if model.format != "mjcf":
        roots = [link for link in links if link.parent is None]
        if roots:
            root = rows[roots[0].index]
            to_frame = Pose(R[root], t[root]).inverse()
            frame = f"root link {roots[0].name}"
    to_R = np.broadcast_to(to_frame.rotation, R.shape)
    placed_R = np.matmul(to_R, R)
    placed_t = stack_apply(to_R, t) + to_frame.translation
    return Placement(rows, R, t, joint_list, axes, anchors, frame, to_frame, placed_R, placed_t, order)


def _levels(model: RobotModel) -> tuple[list[tuple[int, int]], list[tuple[list[int], list[int]]]]:
    """(row, parent row) in :func:`parents_first`'s order (a root's parent: row n, the identity),
    and the same rows grouped by depth in the tree with their parents' rows, shallowest first."""
    links = model.links
    n = len(links)
    by_name = {link.key: row for row, link in enumerate(links)}
    parents = [n if link.parent is None else by_name.get(link.parent, -1) for link in links]
    if len(by_name) == n and -1 not in parents:  # each key one link's, each parent a link
        children: list[list[int]] = [[] for _ in range(n + 1)]
        for row, parent in enumerate(parents):
            children[parent].append(row)
        rows = depth_first(children, n)  # parents_first's order, on rows
    else:
        row_of = {link.index: row for row, link in enumerate(links)}
        rows = [row_of[link.index] for link in parents_first(model, by_name)]
        parents = {row: n if links[row].parent is None else by_name[links[row].parent] for row in rows}
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


def depth_first(children: list[list[int]], root: int) -> list[int]:
    """The rows below ``root`` depth first, as :func:`parents_first` orders links: the last
    child first, each child list in file order."""
    order: list[int] = []
    queue = list(children[root])
    while queue:
        row = queue.pop()
        order.append(row)
        queue.extend(children[row])
    return order


def _moved(link, pose: Pose, joints: dict[str, float], frames: dict[int, list]) -> tuple:
    """A link whose joints have values: each joint's frame where the joints before it leave it
    (into ``frames``), and the link's pose after them all."""
    for motion in link.motions:
        if motion.kind in ("revolute", "prismatic"):
            frames.setdefault(link.index, []).append(
                (motion, pose.rotation @ motion.axis, pose.apply(motion.anchor))
            )
        if motion.name in joints:
            pose = pose.then(_motion(motion, joints[motion.name]))
    return pose.rotation, pose.translation


def _joint_frames(model: RobotModel, R: np.ndarray, t: np.ndarray, moved: dict[int, list]):
    """[(link index, motion)] of every revolute and prismatic joint in file order, and their axes
    and anchors (k, 3) in the model's frame: at the link's pose, or as :func:`_moved` found them."""
    found, rows, axes, anchors = [], [], [], []
    for row, link in enumerate(model.links):
        if link.index in moved:
            for motion, axis, anchor in moved[link.index]:
                found.append((link.index, motion))
                rows.append(-1)
                axes.append(axis)
                anchors.append(anchor)
            continue
        for motion in link.motions:
            if motion.kind in ("revolute", "prismatic"):
                found.append((link.index, motion))
                rows.append(row)
                axes.append(motion.axis)
                anchors.append(motion.anchor)
    axes_array = stacked(axes, (3,))
    anchors_array = stacked(anchors, (3,))
    at = np.array(rows, dtype=int)
    plain = at >= 0
    if np.any(plain):
        chosen = at[plain]
        axes_array[plain] = stack_apply(R[chosen], axes_array[plain])
        anchors_array[plain] = stack_apply(R[chosen], anchors_array[plain]) + t[chosen]
    return found, axes_array, anchors_array


def _check_joints(model: RobotModel, joints: dict[str, float]) -> None:
    """ArgumentError naming ``joints`` for a name no revolute or prismatic joint has, or a
    revolute value whose turn rounding loses."""
    movable = {
        m.name: m
        for link in model.links
        for m in link.motions
        if m.name is not None and m.kind in ("revolute", "prismatic")
    }
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
        if movable[name].kind == "revolute" and not angle_is_kept(math.degrees(value)):
            raise ArgumentError(
                "joints",
                literal(model.path, quoted=False)
                + f": joint {literal(name)}: {value:g} radians is too large to be a turn: rounding loses it "
                f"(at most {math.radians(LARGEST_ANGLE_DEG):.4g} radians)",
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
    chosen = [
        (placed.rows[link.index], link.inertial.properties)
        for link in model.links
        if link.inertial is not None and link.inertial.mass != 0.0
    ]
    try:
        if not chosen:
            raise ValueError("no link with mass")
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported just below
            masses, coms = _placed_parts(placed, chosen)
            inertias = _placed_inertias(placed, chosen)
            total = combine(masses, coms, inertias, frame)
    except ValueError:  # no link with mass, or negative masses (flagged unphysical) that leave none
        return MassProperties.zero(frame)
    if not (np.all(np.isfinite(total.center_of_mass)) and np.all(np.isfinite(total.inertia_about_com))):
        far = float(np.max(np.abs(coms)))
        moment = max(float(np.max(np.abs(props.inertia_about_com))) for _, props in chosen)
        raise InputError(
            f"{model.path}: the whole robot's mass properties overflow a double (centres of mass "
            f"up to {far:.3g} m from the root, moments up to {moment:.3g} kg·m²); give lengths in "
            "metres and moments in kg·m²"
        )
    return total


def _placed_parts(placed: Placement, chosen: list) -> tuple[np.ndarray, np.ndarray]:
    """The masses (kg) and centres of mass (m, in ``placed.frame``) of the ``chosen`` [(row,
    link-frame mass properties)]: each the value :meth:`MassProperties.transformed` gives."""
    rows = [row for row, _ in chosen]
    masses = np.array([props.mass for _, props in chosen], dtype=float)
    coms = stacked([props.center_of_mass for _, props in chosen], (3,))
    R = placed.placed_rotations[rows]
    return masses, stack_apply(R, coms) + placed.placed_translations[rows]


def _placed_inertias(placed: Placement, chosen: list) -> np.ndarray:
    """Each chosen link's inertia about its centre of mass in ``placed.frame``'s axes, kg·m²:
    ``R I Rᵀ`` made symmetric, as :meth:`MassProperties.transformed` gives it."""
    R = placed.placed_rotations[[row for row, _ in chosen]]
    inertias = stacked([props.inertia_about_com for _, props in chosen], (3, 3))
    turned = np.matmul(np.matmul(R, inertias), np.swapaxes(R, 1, 2))
    return 0.5 * (turned + np.swapaxes(turned, 1, 2))
