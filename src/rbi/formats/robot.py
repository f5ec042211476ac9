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
from rbi.core.rotation import euler_matrix, quaternion_to_matrix, without_rounding_noise
from rbi.core.validity import overflowing_sum, subnormal_problem
from rbi.errors import InputError
from rbi.text import visible

LINK_WORD = {"urdf": "link", "sdf": "link", "mjcf": "body"}

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
    def read(
        mass: float,
        com,
        inertia,
        *,
        rotation: np.ndarray | None = None,
        rpy: tuple[float, float, float] | None = None,
        quaternion: np.ndarray | None = None,
        element: Any = None,
        source: str = "inertial",
    ) -> Inertial:
        """The inertial a file declares: ``mass`` (kg), ``com`` (m, link frame), ``inertia``
        about it in the inertial frame's axes (kg·m²), turned into the link's by ``rotation``."""
        written = np.array(inertia, dtype=float)
        in_link = written if rotation is None else re_express(written, rotation)
        properties = MassProperties(mass, com, in_link, "link")
        return Inertial(properties, written, rotation, rpy, quaternion, element, source)

    @property
    def mass(self) -> float:
        """The declared mass, kg."""
        return self.properties.mass

    def spec_rotation(self) -> dict[str, Any] | None:
        """The rotation (inertial frame → link frame) as a spec ``rotation:`` mapping: URDF/SDF
        roll, pitch, yaw as Euler angles about the fixed x, y, z axes, a quaternion as the file
        gave it; None when the frames coincide."""
        if self.rpy is not None:
            return {"euler_deg": [math.degrees(a) for a in self.rpy], "sequence": "xyz"}
        if self.quaternion is not None:
            return {"quaternion": [float(v) for v in self.quaternion]}
        return None


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
    ``anchor`` are in the link's frame at the reference pose; ``reference`` the coordinate at
    which the link is at that pose (MJCF ``ref``, else 0); ``effort_limit`` the declared limit on
    the joint's effort (URDF/SDF ``<limit effort>``, MJCF ``actuatorfrcrange`` or its actuators'
    force range times their gear), or None."""

    name: str | None
    kind: str
    axis: np.ndarray
    anchor: np.ndarray
    reference: float = 0.0
    effort_limit: float | None = None
    """The declared limit of the joint's effort (N·m revolute, N prismatic), or None."""


@dataclass
class Link:
    """A link (MJCF: body): ``index`` in file order, ``name``, ``inertial`` (None when it
    declares none), ``collisions`` and ``visuals``, ``parent`` (a link's :attr:`key`, None for a root),
    ``origin`` (its frame in the parent's at the reference configuration; for a root, in the
    model frame), ``motions`` (the joints between it and its parent; empty when fixed) and the
    XML ``element``."""

    index: int
    name: str | None
    inertial: Inertial | None = None
    collisions: list[Geom] = field(default_factory=list)
    visuals: list[Geom] = field(default_factory=list)
    parent: str | None = None
    origin: Pose = field(default_factory=Pose.identity)
    motions: list[Motion] = field(default_factory=list)
    element: Any = None
    word: str = "link"

    @property
    def label(self) -> str:
        return f"{self.word}[{self.index}]" + (f" ({short(self.name)})" if self.name is not None else "")

    @property
    def key(self) -> str:
        """How other links refer to this one (``parent``): its name, or for an unnamed MJCF body
        its place in the file (with a NUL, so no name can equal it)."""
        return self.name if self.name is not None else f"\0{self.word}[{self.index}]"

    @property
    def moves(self) -> bool:
        """Does a joint move this link relative to its parent (a root that is not MJCF's free
        body counts as fixed)?"""
        return self.parent is not None and any(m.kind not in ("fixed",) for m in self.motions)


@dataclass
class GeomColumn:
    """One ``<collision>`` or ``<visual>`` element (``tag``, ``label`` as :class:`Geom` gives it)
    of links alike: ``rows`` the links' rows, their shape ``kind``, poses (``rotations`` (k, 3, 3),
    ``translations`` (k, 3), link frame), ``sizes`` ((k, m) in m, a row's the :class:`Geom`'s
    ``size``) or ``meshes`` ((file,
    scale) a row)."""

    tag: str
    label: str
    kind: str
    rows: list[int]
    rotations: np.ndarray
    translations: np.ndarray
    sizes: np.ndarray | None = None
    meshes: list[tuple[Path, np.ndarray]] | None = None

    def geom(self, k: int) -> Geom:
        """The :class:`Geom` of the k-th row."""
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
    rbi.robot reads them in. :mod:`rbi.formats.urdf` reads a URDF into them;
    :meth:`of_links` lays any links into them. Names, ``parents`` (the parent's row, n for a
    root), ``order`` (the rows parents first, as :func:`depth_first` gives them), origins
    (``rotations`` (n, 3, 3), ``translations`` (n, 3), in the parent's frame), the declared
    inertials (``declared`` (n,) which links have one; ``inertials`` their mass properties in
    the link frame, one :class:`~rbi.core.mass.MassProperties` stack of n, zero where none is
    declared; ``written`` (n, 3, 3) the inertias as written; ``turned``: row → the
    :class:`Inertial` of a rotated inertial frame), the joints,
    one entry a joint in file order of their links (``joint_rows`` its link's row; a URDF's:
    one a row, a root's of kind None; names, kinds, unit ``axes`` and ``anchors`` (k, 3) in the
    link frame, effort limits or None) and the geometry. :meth:`link` makes a row's
    :class:`Link` (once; of :meth:`of_links`, the link laid in)."""

    names: list[str | None]
    parents: list[int]
    order: list[int]
    rotations: np.ndarray
    translations: np.ndarray
    declared: np.ndarray
    inertials: MassProperties
    written: np.ndarray
    turned: dict[int, Inertial]
    joint_rows: list[int]
    joint_names: list[str | None]
    joint_kinds: list[str | None]
    axes: np.ndarray
    anchors: np.ndarray
    efforts: list[float | None]
    geoms: list[GeomColumn]
    made: dict[int, Link] = field(default_factory=dict)
    geoms_at: list[list[tuple[GeomColumn, int]]] | None = field(default=None, repr=False)

    @classmethod
    def of_links(cls, path: str, links: list[Link]) -> LinkColumns:
        """The columns of ``links`` (an SDF or MJCF reader's, a URDF's once made), each link
        its row's :meth:`link`; geoms in one column per tag and kind (kind ``other``, without
        sizes: a mesh, a shell or a kind with no volume). InputError for links that are no
        tree (:func:`tree_rows`)."""
        parents, order = tree_rows(path, links)
        none = Inertial(MassProperties.zero("link"), np.zeros((3, 3)))
        inertials = [none if link.inertial is None else link.inertial for link in links]
        joints = [(row, motion) for row, link in enumerate(links) for motion in link.motions]
        return cls(
            [link.name for link in links],
            parents,
            order,
            stacked([link.origin.rotation for link in links], (3, 3)),
            stacked([link.origin.translation for link in links], (3,)),
            np.array([link.inertial is not None for link in links], dtype=bool),
            MassProperties(
                np.array([each.mass for each in inertials], dtype=float),
                stacked([each.properties.center_of_mass for each in inertials], (3,)),
                stacked([each.properties.inertia_about_com for each in inertials], (3, 3)),
                "link",
            ),
            stacked([each.written_inertia for each in inertials], (3, 3)),
            {},
            [row for row, _ in joints],
            [motion.name for _, motion in joints],
            [motion.kind for _, motion in joints],
            stacked([motion.axis for _, motion in joints], (3,)),
            stacked([motion.anchor for _, motion in joints], (3,)),
            [motion.effort_limit for _, motion in joints],
            _geom_columns(links),
            dict(enumerate(links)),
        )

    def __len__(self) -> int:
        return len(self.names)

    def link(self, row: int) -> Link:
        """The :class:`Link` of ``row`` (the same object each time)."""
        found = self.made.get(row)
        if found is None:
            found = self.made[row] = self._link(row)
        return found

    def links(self) -> list[Link]:
        """Every row's :class:`Link`, in file order."""
        return [self.link(row) for row in range(len(self.names))]

    def _link(self, row: int) -> Link:
        """A URDF's link of ``row`` (its joint: the row's)."""
        if self.geoms_at is None:  # row → its geoms' (column, place), made once
            self.geoms_at = [[] for _ in self.names]
            for column in self.geoms:
                for k, each in enumerate(column.rows):
                    self.geoms_at[each].append((column, k))
        geoms: dict[str, list[Geom]] = {"collision": [], "visual": []}
        for column, k in self.geoms_at[row]:
            geoms[column.tag].append(column.geom(k))
        inertial = self.turned.get(row)
        if inertial is None and self.declared[row]:
            inertial = Inertial(self.inertials[row], self.written[row])
        parent = self.parents[row]
        link = Link(row, self.names[row], inertial, geoms["collision"], geoms["visual"])
        if parent == len(self.names):
            return link
        link.parent = self.names[parent]
        link.origin = Pose(self.rotations[row], self.translations[row])
        axis = self.axes[row].copy()
        link.motions = [
            Motion(
                self.joint_names[row],
                self.joint_kinds[row],
                axis,
                np.zeros(3),
                effort_limit=self.efforts[row],
            )
        ]
        return link


def refuse_shared_keys(path: str, links: list[Link]) -> dict[str, int]:
    """Each link's :attr:`Link.key` → its row; InputError, one line naming the first link whose
    key an earlier link has. The one check of a model's link names: every reader and the tree
    (:func:`tree_rows`) go through it, so that a parent names one link."""
    rows = {link.key: row for row, link in enumerate(links)}
    if len(rows) == len(links):
        return rows
    seen: dict[str, Link] = {}
    for each in links:
        first = seen.setdefault(each.key, each)
        if first is not each:
            raise InputError(
                f"{path}: {each.label}: duplicate {each.word} name {short(each.name)!r} "
                f"(also {first.label}); every {each.word} needs its own name"
            )
    raise AssertionError("two links share a key")  # the count above says so


def tree_rows(path: str, links: list[Link]) -> tuple[list[int], list[int]]:
    """The links' tree: each one's parent row (``len(links)`` for a root) and the rows parents
    first (:func:`depth_first`). InputError, one line, when two links share a key
    (:func:`refuse_shared_keys`), a parent is none of the links, or the joints form a loop."""
    rows = refuse_shared_keys(path, links)
    n = len(links)
    parents = [n if link.parent is None else rows.get(link.parent, -1) for link in links]
    if -1 in parents:
        link = links[parents.index(-1)]
        raise InputError(f"{path}: {link.label}: parent {short(link.parent)!r}: no {link.word} has that name")
    order = depth_first(parents, n)
    if len(order) < n:  # a link no root reaches: on a loop, or below one
        at, seen = min(set(range(n)) - set(order)), set()
        while at not in seen:
            seen.add(at)
            at = parents[at]
        raise InputError(
            f"{path}: {links[at].label}: the joints form a loop through it; the links of a robot "
            "form a tree (each hangs from one parent, down from a root)"
        )
    return parents, order


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


def stacked(arrays: list, shape: tuple[int, ...]) -> np.ndarray:
    """The float arrays of ``shape`` in ``arrays`` as one (n, *shape) array: the values
    ``np.array(arrays, dtype=float)`` gives, made by one concatenation (numpy's discovery of a
    list's shape, element by element, takes twice as long for 100,000 links)."""
    if not arrays:
        return np.empty((0, *shape))
    return np.concatenate(arrays, dtype=float).reshape(-1, *shape)


SOLID_KINDS = ("box", "sphere", "cylinder", "capsule", "ellipsoid")
"""The kinds of geometry that are one solid primitive."""


def _geom_columns(links: list[Link]) -> list[GeomColumn]:
    """The links' ``<collision>`` and ``<visual>`` geoms as :class:`GeomColumn` values, one per
    tag and kind (a mesh, a shell or a kind with no volume: kind ``other``, without sizes)."""
    found: dict[tuple[str, str], list] = {}
    for row, link in enumerate(links):
        for tag, geoms in (("collision", link.collisions), ("visual", link.visuals)):
            for geom in geoms:
                kind = geom.kind if geom.kind in SOLID_KINDS and not geom.shell else "other"
                found.setdefault((tag, kind), []).append((row, geom))
    return [
        GeomColumn(
            tag,
            "",
            kind,
            [row for row, _ in pairs],
            stacked([geom.pose.rotation for _, geom in pairs], (3, 3)),
            stacked([geom.pose.translation for _, geom in pairs], (3,)),
            None if kind == "other" else stacked([geom.size for _, geom in pairs], (len(pairs[0][1].size),)),
        )
        for (tag, kind), pairs in found.items()
    ]


@dataclass
class RobotModel:
    """A parsed robot file: ``format`` (``urdf``, ``sdf``, ``mjcf``), ``name``, ``links`` in file
    order, ``notes`` (what was read but not checked: unresolved includes, kinds of geometry
    without volume), and ``document`` (the XML with element spans, for a fixed copy).
    ``columns``: the links as arrays (:class:`LinkColumns`, a URDF), from which
    :attr:`links` are made when first asked for."""

    path: str
    format: str
    name: str | None
    notes: list[str] = field(default_factory=list)
    unchecked: list[str] = field(default_factory=list)
    document: Any = None
    options: dict[str, Any] = field(default_factory=dict)
    columns: LinkColumns | None = field(default=None, repr=False)
    _links: list[Link] | None = field(default=None, repr=False)

    @property
    def links(self) -> list[Link]:
        """The links in file order (made from :attr:`columns` the first time, when given)."""
        if self._links is None:
            self._links = [] if self.columns is None else self.columns.links()
        return self._links

    @property
    def in_columns(self) -> LinkColumns | None:
        """:attr:`columns` while they are all there is of the links (no :class:`Link` made yet,
        so none changed): what rbi.robot reads in place of the links; None otherwise."""
        columns = self.columns
        return columns if columns is not None and self._links is None and not columns.made else None

    def link_columns(self) -> LinkColumns:
        """The links as rbi.robot reads them: :attr:`in_columns`, else laid into columns
        (:meth:`LinkColumns.of_links`)."""
        columns = self.in_columns
        return LinkColumns.of_links(self.path, self.links) if columns is None else columns

    @property
    def link_word(self) -> str:
        return LINK_WORD[self.format]

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
    """Where a value was read, for error messages: ``file: link[i] (name): what``. ``label``
    may be given as a :class:`Link` or a function returning the text, worked out only when
    asked for (a large robot file reads a million values and errs on none of them)."""

    def __init__(self, path: str, label: Any = None):
        self.path, self._label = path, label

    @property
    def label(self) -> str | None:
        label = self._label
        if label is None or isinstance(label, str):
            return label
        return label() if callable(label) else label.label

    def error(self, what: str) -> InputError:
        return InputError(f"{self.path}: {self.label}: {what}" if self.label else f"{self.path}: {what}")


def numbers(where: Where, text: str | None, what: str, count: int | tuple[int, ...]) -> list[float]:
    """Whitespace-separated plain finite decimals (no NaN, inf, hex or underscores)."""
    values = _plain_numbers(text or "")
    if values is not None and (len(values) == count if isinstance(count, int) else len(values) in count):
        return list(values)
    pieces = (text or "").split()
    if len(pieces) != count if isinstance(count, int) else len(pieces) not in count:
        expected = " or ".join(str(c) for c in ((count,) if isinstance(count, int) else count))
        raise where.error(f"{what}: expected {expected} number(s), got {len(pieces)} ({short(text)!r})")
    raise _number_error(where, what, pieces)


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


def _number_error(where: Where, what: str, pieces: list[str]) -> InputError:
    """The error for the first of ``pieces`` that is not a plain finite decimal."""
    for piece in pieces:
        if not _NUMBER.match(piece):
            return where.error(f"{what}: must be a finite number (got {short(piece)!r})")
        value = float(piece)
        if not math.isfinite(value):
            return where.error(f"{what}: must be a finite number (got {short(piece)!r}, too large)")
        if problem := subnormal_problem(value):
            return where.error(f"{what}: {problem}")
    raise AssertionError(f"{what}: every number is fine")  # only called when one is not


def number(where: Where, text: str | None, what: str, default: float | None = None) -> float:
    if text is None:
        if default is None:
            raise where.error(f"{what}: missing")
        return default
    return numbers(where, text, what, 1)[0]


def positive(where: Where, values, what: str, allow_zero: bool = False) -> None:
    for value in values:
        if value < 0 or (value == 0 and not allow_zero):
            raise where.error(
                f"{what}: must be {'zero or ' if allow_zero else ''}greater than 0 (got {value!r})"
            )


def angles(where: Where, values, what: str) -> list[float]:
    for axis, angle in zip(("roll", "pitch", "yaw"), values):
        if abs(angle) > MAX_ANGLE_RAD:
            raise where.error(
                f"{what}: {axis} = {angle:.6g} rad is not an angle a double can hold to a "
                f"microradian: give it within one turn (between -{math.pi:.5f} and {math.pi:.5f})"
            )
    return list(values)


def from_six(ixx, iyy, izz, ixy, ixz, iyz) -> np.ndarray:
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], dtype=float)


def check_inertia_range(where: Where, inertia: np.ndarray) -> None:
    too_large = overflowing_sum(inertia)
    if too_large:
        raise where.error(f"inertia: {too_large}; give the inertia in kg·m²")


def rpy_matrix(rpy) -> np.ndarray:
    """URDF/SDF roll, pitch, yaw (rad) about the fixed x, y, z axes: ``Rz(yaw) Ry(pitch) Rx(roll)``."""

    return without_rounding_noise(euler_matrix(np.asarray(rpy, dtype=float), "xyz"))


def quaternion_matrix(where: Where, wxyz, what: str) -> np.ndarray:
    """Rotation of the quaternion ``w x y z`` (MJCF's order; SDF's ``x y z w`` reordered by its
    reader) of any finite non-zero size: :func:`~rbi.core.rotation.quaternion_to_matrix`
    normalises it, once."""
    if not np.any(wxyz):
        raise where.error(f"{what}: the quaternion must not be zero")
    return without_rounding_noise(quaternion_to_matrix(wxyz))


def unit(where: Where, vector, what: str) -> np.ndarray:
    v = np.asarray(vector, dtype=float)
    largest = float(np.abs(v).max())
    if largest == 0.0:
        raise where.error(f"{what}: must not be the zero vector")
    v = v / largest
    return v / np.sqrt(v.dot(v))  # np.linalg.norm's own arithmetic for a vector


def short(text: Any, limit: int = 40) -> str:
    """A name or value from a robot file as a message shows it: hidden characters escaped by the
    one terminal escaper (:func:`rbi.text.visible`; letters such as ``ü`` shown as they are),
    cut to ``limit`` characters."""
    text = visible("" if text is None else str(text))
    return text if len(text) <= limit else text[: limit - 3] + "..."


def check_unique_joint_names(path: str, links: list[Link], reader: str) -> None:
    """InputError naming the first joint name two joints of ``links`` share (``reader``: the
    program that refuses such a file, e.g. urdfdom or MuJoCo's compiler), so that a joint named
    in ``--joints`` and in the report is one joint."""
    seen: dict[str, Link] = {}
    for link in links:
        for motion in link.motions:
            if not motion.name:
                continue
            if motion.name in seen:
                raise InputError(
                    f"{path}: {link.label}: duplicate joint name {short(motion.name)!r} (also a joint of "
                    f"{seen[motion.name].label}); every joint needs its own name ({reader} refuses the file)"
                )
            seen[motion.name] = link
