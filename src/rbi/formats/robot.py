"""The plain data a robot file reader returns (URDF, SDF and MJCF alike): links with their
inertial element, their geometry and their place in the kinematic tree.

Frames: every pose is a rotation matrix and a translation turning coordinates in a child frame
into its parent's (``x_parent = R x_child + p``). A link's ``origin`` places it in its parent
link's frame at the reference configuration (URDF/SDF: every joint at zero; MJCF: ``qpos0``);
its ``motions`` move it from there (a joint's own coordinate: radians for revolute/hinge, metres
for prismatic/slide). Geometry poses are in the link frame. SI units throughout (m, kg, kg·m²).
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from rbi.core.inertia import re_express
from rbi.core.mass import MassProperties
from rbi.core.rotation import euler_matrix, quaternion_to_matrix, unit_vector, without_rounding_noise
from rbi.core.validity import overflowing_sum, subnormal_problem
from rbi.errors import InputError
from rbi.text import visible

_NUMBER = re.compile(r"^[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?$")

MAX_ANGLE_RAD = 1e9
"""Largest angle read (rad): beyond it a double cannot place the angle within a microradian."""


@dataclass(frozen=True)
class Pose:
    """Child frame → parent frame: ``x_parent = rotation @ x_child + translation``."""

    rotation: np.ndarray
    translation: np.ndarray

    @staticmethod
    def identity() -> Pose:
        return Pose(np.eye(3), np.zeros(3))

    def then(self, inner: Pose) -> Pose:
        """This pose applied after ``inner`` (``inner`` is expressed in this pose's child frame)."""
        return Pose(self.rotation @ inner.rotation, self.rotation @ inner.translation + self.translation)

    def inverse(self) -> Pose:
        return Pose(self.rotation.T, -self.rotation.T @ self.translation)

    def apply(self, point) -> np.ndarray:
        return self.rotation @ np.asarray(point, dtype=float) + self.translation


@dataclass(frozen=True)
class Inertial:
    """A link's declared mass properties: ``properties`` in the link frame (``mass`` kg, the
    centre of mass in m, the inertia about it in the link frame's axes, kg·m²). The file's own
    record: ``written_inertia`` the inertia as the file wrote it, in the inertial frame's axes
    (kg·m²), ``rotation`` the inertial frame's axes → link axes (None: the same axes), ``rpy`` and
    ``quaternion`` the rotation as the file gave it (URDF/SDF roll-pitch-yaw, MJCF/SDF quaternion
    ``w x y z``). ``element`` is the XML element it was read from (None when MJCF's compiler
    inferred it from the geoms); ``source`` says which: ``"inertial"`` or ``"geoms"``."""

    properties: MassProperties
    written_inertia: np.ndarray
    rotation: np.ndarray | None = None
    rpy: tuple[float, float, float] | None = None
    quaternion: np.ndarray | None = None
    element: Any = None
    source: str = "inertial"

    @staticmethod
    def read(mass: float, com, inertia, *, rotation: np.ndarray | None = None, **record: Any) -> Inertial:
        """The inertial a file declares: ``mass`` (kg), ``com`` (m, link frame), ``inertia``
        about it in the inertial frame's axes (kg·m²), turned into the link's by ``rotation``;
        ``record``: the rest of the file's record (``rpy``, ``quaternion``, ``element``,
        ``source``), as the fields above."""
        written = np.array(inertia, dtype=float)
        in_link = written if rotation is None else re_express(written, rotation)
        return Inertial(MassProperties(mass, com, in_link, "link"), written, rotation, **record)

    @property
    def mass(self) -> float:
        """The declared mass, kg."""
        return self.properties.mass


@dataclass
class Geom:
    """One piece of a link's geometry, placed in the link frame by ``pose`` (the shape's own
    frame: centred on its centre, cylinder and capsule along z).

    ``kind`` and ``size`` (m): ``box`` (x, y, z full edge lengths), ``cylinder`` (radius, length),
    ``capsule`` (radius, length of the cylindrical part), ``sphere`` (radius,), ``ellipsoid``
    (three semi-axes), ``mesh`` (``mesh_file`` scaled by ``mesh_scale`` about the mesh origin),
    or a kind with no volume (``plane``, ``hfield``, …), which carries nothing.
    MJCF only: ``mass`` or ``density`` (kg/m³, or kg/m² with ``shell``), ``mesh_inertia`` the mesh
    asset's ``inertia`` mode."""

    kind: str
    size: tuple[float, ...]
    pose: Pose
    label: str
    mesh_file: Path | None = None
    mesh_scale: np.ndarray | None = None
    mass: float | None = None
    density: float | None = None
    shell: bool = False
    mesh_inertia: str | None = None


@dataclass
class Motion:
    """One joint's motion of a link relative to its reference pose: ``kind`` ``revolute``
    (about ``axis`` through ``anchor``, radians) or ``prismatic`` (along ``axis``, metres), or
    ``fixed``/``free``/``ball``/``planar``/``floating`` (left at the reference pose). ``axis`` and
    ``anchor`` are in the link's frame at the reference pose (default: x through the origin, as a
    world or free joint has them); ``reference`` the coordinate at
    which the link is at that pose (MJCF ``ref``, else 0); ``effort_limit`` the declared limit on
    the joint's effort (URDF/SDF ``<limit effort>``, MJCF ``actuatorfrcrange`` or its actuators'
    force range times their gear), or None."""

    name: str | None
    kind: str
    axis: np.ndarray = field(default_factory=lambda: np.array([1.0, 0, 0]))
    anchor: np.ndarray = field(default_factory=lambda: np.zeros(3))
    reference: float = 0.0
    effort_limit: float | None = None
    """The declared limit of the joint's effort (N·m revolute, N prismatic), or None."""


def element_label(tag: str, index: int, name: str | None) -> str:
    """How a message names the ``index``-th element of a kind: ``tag[index]``, then its
    ``(name)`` when it has one (None: none)."""
    return f"{tag}[{index}]" + (f" ({short(name)})" if name is not None else "")


def link_key(word: str, index: int, name: str | None) -> str:
    """How other links refer to a link (its parent's key): its name, or for an unnamed MJCF
    body its place in the file (with a NUL, so no name can equal it)."""
    return name if name is not None else f"\0{word}[{index}]"


@dataclass(frozen=True, eq=False)
class Link:
    """One link (MJCF: body) of a model: row ``index`` (file order) of its :class:`LinkColumns`
    seen alone, each value read from the columns when asked for: ``name``, ``inertial`` (None
    when it declares none), ``collisions`` and ``visuals``, the XML ``element`` and whether a
    joint ``moves`` it."""

    columns: LinkColumns
    index: int

    @property
    def name(self) -> str | None:
        return self.columns.names[self.index]

    @property
    def label(self) -> str:
        return element_label(self.columns.word, self.index, self.name)

    @property
    def element(self) -> Any:
        elements = self.columns.elements
        return None if elements is None else elements[self.index]

    @property
    def inertial(self) -> Inertial | None:
        columns, row = self.columns, self.index
        found = columns.records.get(row)
        if found is not None or not columns.declared[row]:
            return found
        element = self.element
        inertial = None if element is None else element.child("inertial")
        return Inertial(columns.inertials[row], columns.written[row], element=inertial)

    @functools.cached_property
    def collisions(self) -> list[Geom]:
        return self.columns.geoms_of(self.index, "collision")

    @functools.cached_property
    def visuals(self) -> list[Geom]:
        return self.columns.geoms_of(self.index, "visual")

    @property
    def moves(self) -> bool:
        """Does a joint move this link relative to its parent (a root that is not MJCF's free
        body counts as fixed)?"""
        columns = self.columns
        return columns.parents[self.index] != len(columns) and any(
            columns.joint_kinds[k] != "fixed" for k in columns.joints_of(self.index)
        )


@dataclass
class GeomColumn:
    """One ``<collision>`` or ``<visual>`` element (``tag``, ``label`` as :class:`Geom` gives it)
    of links alike: ``rows`` the links' rows, their shape ``kind``, poses (``rotations`` (k, 3, 3),
    ``translations`` (k, 3), link frame), ``sizes`` ((k, m) in m, a row's the :class:`Geom`'s
    ``size``) or ``meshes`` ((file, scale) a row); ``pieces``: the :class:`Geom` of each row,
    when a reader made them (SDF, MJCF)."""

    tag: str
    label: str
    kind: str
    rows: list[int]
    rotations: np.ndarray
    translations: np.ndarray
    sizes: np.ndarray | None = None
    meshes: list[tuple[Path, np.ndarray]] | None = None
    pieces: list[Geom] | None = None

    def geom(self, k: int) -> Geom:
        """The :class:`Geom` of the k-th row."""
        if self.pieces is not None:
            return self.pieces[k]
        pose = Pose(self.rotations[k], self.translations[k])
        if self.meshes is not None:
            mesh, scale = self.meshes[k]
            return Geom("mesh", (), pose, self.label, mesh_file=mesh, mesh_scale=scale)
        return Geom(
            self.kind, tuple(self.sizes[k].tolist()) if self.sizes is not None else (), pose, self.label
        )


@dataclass
class LinkColumns:
    """A model's links as columns, one row a link in file order (its ``index``): the one form
    of a model's links. :mod:`rbi.formats.urdf` reads a URDF into them; the SDF and MJCF
    readers fill a :class:`LinkTable`, stacked into them once. Names, ``parents`` (the parent's
    row, n for a root), ``order`` (the rows parents first, as :func:`depth_first` gives them;
    without the rows on a loop, :meth:`RobotModel.link_columns`), origins (``rotations`` (n, 3,
    3), ``translations`` (n, 3), in the parent's frame), the declared inertials (``declared``
    (n,) which links have one; ``inertials`` their mass properties in the link frame, one
    :class:`~rbi.core.mass.MassProperties` stack of n, zero where none is declared; ``written``
    (n, 3, 3) the inertias as written; ``records``: row → the :class:`Inertial` as read when it
    holds more than these arrays: a rotated inertial frame, its element or its source), the
    joints, one entry a joint in file order of their links (``joint_rows`` its link's row; a
    URDF's: one a row, a root's of kind None; names, kinds, unit ``axes`` and ``anchors`` (k, 3)
    in the link frame, effort limits or None, ``references``), the geometry, the ``word`` for a
    link and the links' XML ``elements`` (None: not at hand). :meth:`link` is a row's
    :class:`Link`."""

    names: list[str | None]
    parents: list[int]
    order: list[int]
    rotations: np.ndarray
    translations: np.ndarray
    declared: np.ndarray
    inertials: MassProperties
    written: np.ndarray
    records: dict[int, Inertial]
    joint_rows: list[int]
    joint_names: list[str | None]
    joint_kinds: list[str | None]
    axes: np.ndarray
    anchors: np.ndarray
    efforts: list[float | None]
    references: list[float]
    geoms: list[GeomColumn]
    word: str = "link"
    elements: list | None = None
    _at: dict[str, list] = field(default_factory=dict, repr=False)

    def __len__(self) -> int:
        return len(self.names)

    def link(self, row: int) -> Link:
        """The :class:`Link` of ``row``."""
        return Link(self, row)

    def links(self) -> list[Link]:
        """Every row's :class:`Link`, in file order."""
        return [Link(self, row) for row in range(len(self.names))]

    def joints_of(self, row: int) -> list[int]:
        """The joints (their places in the joint columns) of the link of ``row``."""
        if "joints" not in self._at:  # row → its joints, made once
            self._at["joints"] = found = [[] for _ in self.names]
            for k, each in enumerate(self.joint_rows):
                found[each].append(k)
        return self._at["joints"][row]

    def geoms_of(self, row: int, tag: str) -> list[Geom]:
        """The ``tag`` (collision or visual) geoms of the link of ``row``, in file order."""
        if "geoms" not in self._at:  # row → its geoms' (column, place), made once
            self._at["geoms"] = found = [[] for _ in self.names]
            for column in self.geoms:
                for k, each in enumerate(column.rows):
                    found[each].append((column, k))
        return [column.geom(k) for column, k in self._at["geoms"][row] if column.tag == tag]


class LinkTable:
    """The links of the SDF or MJCF file at ``path`` as its reader finds them, one row a link: plain lists
    (``names``; ``parents``, the parent's key, :func:`link_key`, None for a root; ``origins``,
    ``inertials``, ``motions``, ``collisions``, ``visuals`` and ``elements``, as
    :class:`LinkColumns` describes them), stacked into :class:`LinkColumns` once by
    :meth:`columns`."""

    def __init__(self, path: str, word: str):
        self.path, self.word = path, word
        self.names: list[str | None] = []
        self.parents: list[str | None] = []
        self.origins: list[Pose] = []
        self.inertials: list[Inertial | None] = []
        self.motions: list[list[Motion]] = []
        self.collisions: list[list[Geom]] = []
        self.visuals: list[list[Geom]] = []
        self.elements: list[Any] = []

    def add(self, name: str | None, element: Any) -> int:
        """A new link's row: a root at the origin, with nothing declared."""
        self.names.append(name)
        self.elements.append(element)
        for each in (self.parents, self.inertials):
            each.append(None)
        self.origins.append(Pose.identity())
        for each in (self.motions, self.collisions, self.visuals):
            each.append([])
        return len(self.names) - 1

    def label(self, row: int) -> str:
        return element_label(self.word, row, self.names[row])

    def key(self, row: int) -> str:
        return link_key(self.word, row, self.names[row])

    def columns(self) -> LinkColumns:
        """The rows as :class:`LinkColumns` (geoms in one column per tag, place in the link and
        kind: kind ``other``, without sizes, for a mesh, a shell or a kind with no volume)."""
        parents, order = tree_rows(self.path, self.word, self.names, self.parents)
        none = Inertial(MassProperties.zero("link"), np.zeros((3, 3)))
        inertials = [none if each is None else each for each in self.inertials]
        joints = [(row, motion) for row, motions in enumerate(self.motions) for motion in motions]
        return LinkColumns(
            self.names,
            parents,
            order,
            stacked([origin.rotation for origin in self.origins], (3, 3)),
            stacked([origin.translation for origin in self.origins], (3,)),
            np.array([each is not None for each in self.inertials], dtype=bool),
            MassProperties(
                np.array([each.mass for each in inertials], dtype=float),
                stacked([each.properties.center_of_mass for each in inertials], (3,)),
                stacked([each.properties.inertia_about_com for each in inertials], (3, 3)),
                "link",
            ),
            stacked([each.written_inertia for each in inertials], (3, 3)),
            {row: each for row, each in enumerate(self.inertials) if each is not None},
            [row for row, _ in joints],
            [motion.name for _, motion in joints],
            [motion.kind for _, motion in joints],
            stacked([motion.axis for _, motion in joints], (3,)),
            stacked([motion.anchor for _, motion in joints], (3,)),
            [motion.effort_limit for _, motion in joints],
            [motion.reference for _, motion in joints],
            self._geom_columns(),
            self.word,
            self.elements,
        )

    def _geom_columns(self) -> list[GeomColumn]:
        found: dict[tuple[int, str, str], list] = {}
        for row, pair in enumerate(zip(self.collisions, self.visuals)):
            for tag, geoms in zip(("collision", "visual"), pair):
                for place, geom in enumerate(geoms):
                    kind = geom.kind if geom.kind in SOLID_KINDS and not geom.shell else "other"
                    found.setdefault((place, tag, kind), []).append((row, geom))
        return [
            GeomColumn(
                tag,
                "",
                kind,
                [row for row, _ in pairs],
                stacked([geom.pose.rotation for _, geom in pairs], (3, 3)),
                stacked([geom.pose.translation for _, geom in pairs], (3,)),
                None if kind == "other" else stacked([g.size for _, g in pairs], (len(pairs[0][1].size),)),
                pieces=[geom for _, geom in pairs],
            )
            for (_, tag, kind), pairs in sorted(found.items(), key=lambda item: item[0][0])
        ]


def refuse_shared_keys(path: str, word: str, names: list[str | None]) -> dict[str, int]:
    """Each link's key (:func:`link_key`) → its row; InputError, one line naming the first link
    whose key an earlier link has. The one check of a model's link names: every reader and the
    tree (:func:`tree_rows`) go through it, so that a parent names one link."""
    rows: dict[str, int] = {}
    for row, name in enumerate(names):
        first = rows.setdefault(link_key(word, row, name), row)
        if first != row:
            raise InputError(
                f"{path}: {element_label(word, row, name)}: duplicate {word} name {short(name)!r} "
                f"(also {element_label(word, first, names[first])}); every {word} needs its own name"
            )
    return rows


def tree_rows(path: str, word: str, names: list[str | None], parents: list[str | None]) -> tuple:
    """The links' tree (``parents``: each link's parent key, None for a root): each one's
    parent row (``len(names)`` for a root) and the rows parents first (:func:`depth_first`;
    without the links on a loop). InputError, one line, when two links share a key
    (:func:`refuse_shared_keys`) or a parent is none of the links."""
    rows = refuse_shared_keys(path, word, names)
    n = len(names)
    found = [n if key is None else rows.get(key, -1) for key in parents]
    if -1 in found:
        row = found.index(-1)
        raise InputError(
            f"{path}: {element_label(word, row, names[row])}: parent {short(parents[row])!r}: no {word} has that name"
        )
    return found, depth_first(found, n)


def depth_first(parents: list[int], root: int) -> list[int]:
    """The rows below ``root`` depth first (``parents``: each row's parent row, ``root`` for a
    top-level one): the last child first, each child list in file order. Rows not reached from ``root`` are left out."""
    children: list[list[int]] = [[] for _ in range(len(parents) + 1)]
    for row, parent in enumerate(parents):
        children[parent].append(row)
    order: list[int] = []
    queue = list(children[root])
    while queue:
        row = queue.pop()
        order.append(row)
        queue.extend(children[row])
    return order


def on_loop(parents: list[int], order: list[int]) -> tuple[int, int]:
    """The first row no root reaches (``parents``: each row's parent row; ``order``: the rows
    reached, :func:`depth_first`) and the first row on the loop its chain of parents runs into."""
    first = at = min(set(range(len(parents))) - set(order))
    seen = set()
    while at not in seen:
        seen.add(at)
        at = parents[at]
    return first, at


def stacked(arrays: list, shape: tuple[int, ...]) -> np.ndarray:
    """The float arrays of ``shape`` in ``arrays`` as one (n, *shape) array: the values
    ``np.array(arrays, dtype=float)`` gives, made by one concatenation (numpy's discovery of a
    list's shape, element by element, takes twice as long for 100,000 links)."""
    if not arrays:
        return np.empty((0, *shape))
    return np.concatenate(arrays, dtype=float).reshape(-1, *shape)


SOLID_KINDS = ("box", "sphere", "cylinder", "capsule", "ellipsoid")
"""The kinds of geometry that are one solid primitive."""

SHAPES = {
    "box": (("size", 3),),
    "cylinder": (("radius", 1), ("length", 1)),
    "capsule": (("radius", 1), ("length", 1)),
    "sphere": (("radius", 1),),
    "ellipsoid": (("radii", 3),),
}
"""URDF's and SDF's primitive shapes: their attributes (URDF) or child elements (SDF) and how
many numbers each holds (m). URDF has no ellipsoid (one is a shape with no volume)."""


@dataclass
class RobotModel:
    """A parsed robot file: ``format`` (``urdf``, ``sdf``, ``mjcf``), ``name``, ``links`` in file
    order, ``notes`` (what was read but not checked: unresolved includes, kinds of geometry
    without volume), and ``document`` (the XML with element spans, for a fixed copy).
    ``columns``: the links as arrays (:class:`LinkColumns`), whose rows are :attr:`links`."""

    path: str
    format: str
    name: str | None
    columns: LinkColumns = field(repr=False)
    notes: list[str] = field(default_factory=list)
    unchecked: list[str] = field(default_factory=list)
    document: Any = None
    options: dict[str, Any] = field(default_factory=dict)

    @functools.cached_property
    def links(self) -> list[Link]:
        """The links in file order (:meth:`LinkColumns.links`, made once)."""
        return self.columns.links()

    def link_columns(self) -> LinkColumns:
        """:attr:`columns` as rbi.robot reads them: InputError, one line, when the joints form
        a loop (a link no root reaches: on a loop, or below one)."""
        columns = self.columns
        if len(columns.order) < len(columns):
            _, at = on_loop(columns.parents, columns.order)
            raise InputError(
                f"{self.path}: {columns.link(at).label}: the joints form a loop through it; the links "
                "of a robot form a tree (each hangs from one parent, down from a root)"
            )
        return columns

    @property
    def link_word(self) -> str:
        return self.columns.word

    @property
    def inertial_links(self) -> list[Link]:
        """The links with mass properties (an inertial element; MJCF: or geoms with mass)."""
        return [each for each in self.links if each.inertial is not None]

    @property
    def skipped(self) -> list[tuple[str, str]]:
        """(label, reason) for each link without mass properties."""
        reason = "no <inertial> element" + (" and no geoms with mass" if self.format == "mjcf" else "")
        return [(each.label, reason) for each in self.links if each.inertial is None]


# --- reading numbers ----------------------------------------------------------------------------


class Where:
    """Where a value was read, for error messages: ``file: link[i] (name): what``, and the
    readers of the values found there, each refusing a bad one with an error naming the place.
    ``label`` may be given as a function returning the text, worked out only when asked for (a
    large robot file reads a million values and errs on none of them)."""

    def __init__(self, path: str, label: Any = None):
        self.path, self._label = path, label

    @property
    def label(self) -> str | None:
        label = self._label
        return label() if callable(label) else label

    def error(self, what: str) -> InputError:
        return InputError(f"{self.path}: {self.label}: {what}" if self.label else f"{self.path}: {what}")

    def numbers(self, text: str | None, what: str, count: int | tuple[int, ...]) -> list[float]:
        """Whitespace-separated plain finite decimals (no NaN, inf, hex or underscores)."""
        values = _plain_numbers(text or "")
        if values is not None and (len(values) == count if isinstance(count, int) else len(values) in count):
            return list(values)
        pieces = (text or "").split()
        if len(pieces) != count if isinstance(count, int) else len(pieces) not in count:
            expected = " or ".join(str(c) for c in ((count,) if isinstance(count, int) else count))
            raise self.error(f"{what}: expected {expected} number(s), got {len(pieces)} ({short(text)!r})")
        raise self._number_error(what, pieces)

    def _number_error(self, what: str, pieces: list[str]) -> InputError:
        """The error for the first of ``pieces`` that is not a plain finite decimal."""
        for piece in pieces:
            if not _NUMBER.match(piece):
                return self.error(f"{what}: must be a finite number (got {short(piece)!r})")
            value = float(piece)
            if not math.isfinite(value):
                return self.error(f"{what}: must be a finite number (got {short(piece)!r}, too large)")
            if problem := subnormal_problem(value):
                return self.error(f"{what}: {problem}")
        raise AssertionError(f"{what}: every number is fine")  # only called when one is not

    def number(self, text: str | None, what: str, default: float | None = None) -> float:
        if text is None:
            if default is None:
                raise self.error(f"{what}: missing")
            return default
        return self.numbers(text, what, 1)[0]

    def positive(self, values, what: str, allow_zero: bool = False) -> None:
        for value in values:
            if value < 0 or (value == 0 and not allow_zero):
                raise self.error(
                    f"{what}: must be {'zero or ' if allow_zero else ''}greater than 0 (got {value!r})"
                )

    def angles(self, values, what: str) -> None:
        for axis, angle in zip(("roll", "pitch", "yaw"), values):
            if abs(angle) > MAX_ANGLE_RAD:
                raise self.error(
                    f"{what}: {axis} = {angle:.6g} rad is not an angle a double can hold to a "
                    f"microradian: give it within one turn (between -{math.pi:.5f} and {math.pi:.5f})"
                )

    def check_inertia_range(self, inertia: np.ndarray) -> None:
        too_large = overflowing_sum(inertia)
        if too_large:
            raise self.error(f"inertia: {too_large}; give the inertia in kg·m²")

    def quaternion_matrix(self, wxyz, what: str) -> np.ndarray:
        """Rotation of the quaternion ``w x y z`` (MJCF's order; SDF's ``x y z w`` reordered by its
        reader) of any finite non-zero size: :func:`~rbi.core.rotation.quaternion_to_matrix`
        normalises it, once."""
        if not np.any(wxyz):
            raise self.error(f"{what}: the quaternion must not be zero")
        return without_rounding_noise(quaternion_to_matrix(wxyz))

    def unit(self, vector, what: str) -> np.ndarray:
        try:
            return unit_vector(vector)
        except ValueError:  # (numbers read are finite: only the zero vector is refused)
            raise self.error(f"{what}: must not be the zero vector") from None


def _plain_numbers(text: str) -> tuple[float, ...] | None:
    """The numbers of ``text`` when each is a plain finite decimal, not subnormal, else None; short texts are
    remembered (robot files repeat ``0 0 0``, ``1 0 0`` and their like many times over)."""
    if len(text) <= 64:
        return _remembered_numbers(text)
    return _read_numbers(text)


def _read_numbers(text: str) -> tuple[float, ...] | None:
    pieces = text.split()
    if all(map(_NUMBER.match, pieces)):
        values = tuple(map(float, pieces))
        if all(map(math.isfinite, values)) and not any(map(subnormal_problem, values)):
            return values
    return None


_remembered_numbers = functools.lru_cache(maxsize=4096)(_read_numbers)


def from_six(ixx, iyy, izz, ixy, ixz, iyz) -> np.ndarray:
    """The symmetric inertia matrix (3, 3) of its six entries; (k, 3, 3) of k of each."""
    return np.stack([ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz], axis=-1).reshape(*np.shape(ixx), 3, 3)


def rpy_matrix(rpy) -> np.ndarray:
    """URDF/SDF roll, pitch, yaw (rad) about the fixed x, y, z axes: ``Rz(yaw) Ry(pitch) Rx(roll)``."""

    return without_rounding_noise(euler_matrix(np.asarray(rpy, dtype=float), "xyz"))


def short(text: Any, limit: int = 40) -> str:
    """A name or value from a robot file as a message shows it: hidden characters escaped by the
    one terminal escaper (:func:`rbi.text.visible`; letters such as ``ü`` shown as they are),
    cut to ``limit`` characters."""
    text = visible("" if text is None else str(text))
    return text if len(text) <= limit else text[: limit - 3] + "..."


def check_unique_joint_names(path: str, joints: list[tuple[str, str | None]], reader: str) -> None:
    """InputError naming the first joint name two of ``joints`` ((its link's label, its name)
    in file order) share (``reader``: the program that refuses such a file, e.g. urdfdom or
    MuJoCo's compiler), so that a joint named in ``--joints`` and in the report is one joint."""
    seen: dict[str, str] = {}
    for link, name in joints:
        if not name:
            continue
        if name in seen:
            raise InputError(
                f"{path}: {link}: duplicate joint name {short(name)!r} (also a joint of "
                f"{seen[name]}); every joint needs its own name ({reader} refuses the file)"
            )
        seen[name] = link
