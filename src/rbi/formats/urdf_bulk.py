"""URDF read in bulk (issue 25: a 100,000-link file in seconds, not a quarter of a minute,
without a Python object and two handler calls per XML element).

expat (the careful reader's parser) checks that the document is well-formed with no handler
at all. Then the text of a plain document (no DTD, entity or character reference, comment
inside an element, CDATA, processing instruction, character data or single-quoted value) is
read on arrays: its attribute values taken out in one pass, and the top-level ``<link>`` and
``<joint>`` elements found from where its ``<``, ``>`` and ``/`` are. Elements whose text is the
same once their values are emptied (their *signature*) hold their values at the same places,
so each field (an origin's ``xyz``, a mass, a box's ``size``) is one column of strings, checked
and turned into numbers at once; each signature is read once, by expat, into the element tree
that tells which value is which.

The careful reader decides every error: :func:`read_urdf_bulk` returns None, and
:func:`rbi.formats.robot_files.read_robot` then reads the file with
:mod:`rbi.formats.robot_xml` and :func:`rbi.formats.urdf.read_urdf`, for anything it is not
certain that reader reads without complaint: another encoding than UTF-8, XML that is not
plain as above or not well-formed, a missing or malformed value, a number out of range,
duplicate names, a joint naming no link, a loop, a mesh that cannot be found. So every
refusal and every message stays that reader's. The numbers are its too: the same text read by
``float``, the same functions (:func:`rpy_matrix`, :func:`unit`, :meth:`Inertial.read`) for
rotated frames and axes, and for the rest the same values laid into stacked arrays (each
link's arrays are rows of them).

The links it returns have no XML ``element``: :func:`attach_elements` reads the document the
careful way and attaches them, for ``rbi audit --fix`` (which edits the file at their spans).
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.validity import SMALLEST_NORMAL
from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.robot import (
    MAX_ANGLE_RAD,
    Geom,
    Inertial,
    Link,
    Motion,
    Pose,
    RobotModel,
    Where,
    check_unique_names,
    rpy_matrix,
    short,
    unit,
)
from rbi.formats.robot_paths import resolve_mesh
from rbi.formats.urdf import MOVING, UNIT_AXIS_KINDS

_PLAIN = re.compile(rb"[0-9eE+\-. \n]*")
"""The characters of texts of plain decimals apart by spaces, one text a line: with them, a
token ``float`` reads is one :data:`rbi.formats.robot._NUMBER` matches (``float`` alone would
also take ``nan``, ``inf``, ``1_0`` and other digits than 0-9)."""

_QUOTED = re.compile(rb'"([^"]*)"')
"""An attribute's value in double quotes (in a document with no character data, comment or
single-quoted value, every double quote opens or closes one; a file with a value in single
quotes goes the careful way)."""

_COMMENT = re.compile(rb"<!--.*?-->", re.S)
_TEXT = re.compile(rb">\s*[^\s<]")
"""Character data inside an element (or a ``>`` inside a value): left to the careful reader."""

_SINGLE_QUOTED = re.compile(rb"=\s*'")
_NAMES = re.compile(rb'([^\s=<>/]+)\s*=\s*""')

_SHAPES = {
    "box": ("size",),
    "cylinder": ("radius", "length"),
    "capsule": ("radius", "length"),
    "sphere": ("radius",),
}
"""The primitive shapes read here and their attributes (a mesh goes the careful way)."""

_UNPLACED = Pose(np.eye(3), np.zeros(3))
"""A link's origin until a joint places it (the root then gets one of its own)."""


class _Doubt(Exception):
    """Something the bulk reader leaves to the careful one."""


def read_urdf_bulk(path: str, data: bytes, package_paths=None, geometry: bool = True) -> RobotModel | None:
    """The model :func:`rbi.formats.urdf.read_urdf` reads from ``data`` (the file's bytes), or
    None when it is not certain to be the same (see the module's docstring)."""
    try:
        document = robot_xml.decoded(path, data)
        if document.encoding != "utf-8" or not _plain_xml(document.text):
            return None
        name, links, joints = _elements(document.text)
        model = RobotModel(document.path, "urdf", name, document=document)
        model.links = _links(document.path, links, geometry, package_paths)
        check_unique_names(document.path, model.links, "link")
        _joints(model, joints)
        return model
    except (_Doubt, InputError):
        return None


def _plain_xml(text: bytes) -> bool:
    """Is ``text`` well-formed XML (as expat, the careful reader's parser, reads it) with no
    document type declaration, entity or character reference, CDATA section or processing
    instruction (but the XML declaration)?"""
    if b"&" in text or b"<!DOCTYPE" in text or b"<![CDATA[" in text or text.find(b"<?", 1) >= 0:
        return False
    # not at top level: `rbi validate` would load xml.parsers.expat too
    from xml.parsers import expat

    parser = expat.ParserCreate(encoding="utf-8")
    try:
        parser.Parse(text, True)
    except expat.ExpatError:
        return False
    return True


def _elements(text: bytes) -> tuple[str | None, dict, dict]:
    """The root's name and the top-level links and joints of a URDF :func:`_plain_xml` passed,
    each grouped by signature (its text with every attribute value emptied): signature →
    [(index among the links or joints, its attribute values in document order)]. The values
    are taken out of the text and the element boundaries found on the arrays of its ``<``,
    ``>`` and ``=`` (with no text, comment or value left, each starts or ends a tag, or gives
    a value)."""
    if text.startswith(b"<?xml"):
        text = text[text.index(b"?>") + 2 :]
    if b"<!--" in text:
        text = _COMMENT.sub(b"", text)
    if _TEXT.search(text):
        raise _Doubt
    pieces = _QUOTED.split(text)  # between values, a value, between values, ...
    values = pieces[1::2]
    blank = b'""'.join(pieces[::2])
    if any(space in text and text.count(space) != blank.count(space) for space in (b"\n", b"\t", b"\r")):
        raise _Doubt  # a value holding a line end or tab, which XML reads as a space
    if _SINGLE_QUOTED.search(blank):
        raise _Doubt
    codes = np.frombuffer(blank, dtype=np.uint8)
    marks = np.flatnonzero(codes - 60 <= 2)  # where a <, = or > is (bytes below 60 wrap around)
    kinds = codes[marks]
    opens, equals, closes = marks[kinds == 60], marks[kinds == 61], marks[kinds == 62]
    if len(opens) != len(closes) or len(equals) != len(values) or not len(opens):
        raise _Doubt
    if np.any(closes < opens) or np.any(opens[1:] < closes[:-1]):
        raise _Doubt
    ending, empty = codes[opens + 1] == 47, codes[closes - 1] == 47
    step = np.where(ending, -1, np.where(empty, 0, 1))
    after = np.cumsum(step)
    if after.max() >= robot_xml.MAX_DEPTH or not _starts(blank, int(opens[0]), b"<robot"):
        raise _Doubt
    starts = np.flatnonzero((after - step == 1) & ~ending)
    ends = np.flatnonzero((after == 1) & (ending | empty))
    groups = {}
    for opening in (b"<link", b"<joint"):
        chosen = _named(codes, opens[starts], opening)
        begins, stops = opens[starts][chosen], closes[ends][chosen] + 1
        lows, highs = np.searchsorted(equals, begins), np.searchsorted(equals, stops)
        groups[opening] = _alike(codes, blank, begins, stops, lows, highs, values) or _grouped(
            blank, begins, stops, lows, highs, values
        )
    root = _NAMES.findall(blank[: closes[0] + 1])
    name = values[root.index(b"name")].decode() if b"name" in root else None
    return name, groups[b"<link"], groups[b"<joint"]


def _grouped(blank: bytes, begins, stops, lows, highs, values: list[bytes]) -> dict[bytes, _Rows]:
    """Signature → its elements (:class:`_Rows`) of the elements spanning ``begins:stops`` of
    the emptied text, whose values are ``values[lows:highs]``."""
    found: dict[bytes, tuple[list[int], list[list[bytes]]]] = {}
    spans = zip(begins.tolist(), stops.tolist(), lows.tolist(), highs.tolist())
    for index, (begin, end, low, high) in enumerate(spans):
        indices, rows = found.setdefault(blank[begin:end], ([], []))
        indices.append(index)
        rows.append(values[low:high])
    return {signature: _Rows(indices, rows) for signature, (indices, rows) in found.items()}


def _alike(codes: np.ndarray, blank: bytes, begins, stops, lows, highs, values) -> dict[bytes, _Rows] | None:
    """The one group of :func:`_grouped` when the elements are alike (a generated file): the
    same emptied text at even steps through it, their values at even steps through the values;
    None otherwise. The texts are compared as rows of one strided view of the bytes."""
    count = len(begins)
    if count < 2:
        return None
    length, step, first = int(stops[0] - begins[0]), int(begins[1] - begins[0]), int(lows[0])
    width, spacing = int(highs[0] - lows[0]), int(lows[1] - lows[0])
    if (
        np.any(stops - begins != length)
        or np.any(np.diff(begins) != step)
        or np.any(highs - lows != width)
        or np.any(np.diff(lows) != spacing)
        or step < length
    ):
        return None
    texts = np.lib.stride_tricks.as_strided(codes[int(begins[0]) :], shape=(count, length), strides=(step, 1))
    if not np.all(texts == texts[0]):
        return None
    signature = blank[int(begins[0]) : int(stops[0])]
    return {signature: _Rows(list(range(count)), spaced=(first, spacing), values=values)}


def _named(codes: np.ndarray, at: np.ndarray, opening: bytes) -> np.ndarray:
    """Which of the tags starting at ``at`` open with ``opening`` (``<`` and a name) and that
    name alone."""
    size = len(opening)
    inside = at + size < len(codes)
    chosen = inside.copy()
    for k, byte in enumerate(opening):
        chosen[inside] &= codes[at[inside] + k] == byte
    chosen[inside] &= np.isin(codes[at[inside] + size], np.frombuffer(bytes(_NAME_ENDS), dtype=np.uint8))
    return chosen


def _starts(blank: bytes, at: int, opening: bytes) -> bool:
    """Does the tag at ``at`` open with ``opening`` (``<`` and a name) and that name alone?"""
    return blank.startswith(opening, at) and blank[at + len(opening)] in _NAME_ENDS


_NAME_ENDS = frozenset(b" \t\n\r>/")


class _Node:
    """One element of a signature: ``tag``, ``at`` (attribute name → place in the values list)
    and its child elements (comments left out)."""

    __slots__ = ("tag", "at", "children")

    def __init__(self, tag: str, at: dict[str, int]):
        self.tag, self.at, self.children = tag, at, []

    def child(self, tag: str) -> _Node | None:
        for each in self.children:
            if each.tag == tag:
                return each
        return None


def _tree(signature: bytes) -> _Node:
    """The element tree a signature describes (expat reads it as the careful reader reads the
    file: names as written), each attribute at its place among the element's values."""
    # not at top level: `rbi validate` would load xml.parsers.expat too
    from xml.parsers import expat

    parser = expat.ParserCreate(encoding="utf-8")
    parser.ordered_attributes = True
    stack: list[_Node] = []
    found: list[_Node] = []
    count = [0]

    def start(tag: str, attributes: list[str]) -> None:
        names = attributes[::2]
        node = _Node(tag, {name: count[0] + k for k, name in enumerate(names)})
        count[0] += len(names)
        (stack[-1].children if stack else found).append(node)
        stack.append(node)

    parser.StartElementHandler = start
    parser.EndElementHandler = lambda _tag: stack.pop()
    parser.Parse(signature, True)
    return found[0]


class _Rows:
    """The elements of one signature: ``indices`` (each one's place among the links or joints)
    and their values, as a list per element, or (``spaced``: the first element's first value's
    place, the step between elements) at even steps in the document's list of values."""

    def __init__(self, indices: list[int], rows: list[list[bytes]] | None = None, spaced=None, values=None):
        self.indices, self.rows, self.spaced, self.values = indices, rows, spaced, values

    def __len__(self) -> int:
        return len(self.indices)

    def column(self, place: int | None, default: bytes) -> list[bytes]:
        """The text at ``place`` of each element (``default`` where the attribute is not written)."""
        if place is None:
            return [default] * len(self)
        if self.rows is not None:
            return [row[place] for row in self.rows]
        first, step = self.spaced
        return self.values[first + place : first + place + step * (len(self) - 1) + 1 : step]

    def words(self, place: int | None) -> list[str]:
        """The text at ``place`` of each element as str (``""`` where the attribute is not written)."""
        if place is None:
            return [""] * len(self)
        return [each.decode() for each in self.column(place, b"")]


def _numbers(texts: list[bytes], count: int) -> np.ndarray:
    """(len(texts), count) floats of texts each of ``count`` plain finite decimals (what
    :func:`rbi.formats.robot.numbers` reads: signs, digits, a point and an exponent, apart by
    spaces), none subnormal; _Doubt otherwise. Each distinct text is read once."""
    if not texts:
        return np.empty((0, count))
    distinct = dict.fromkeys(texts)
    joined = b"\n".join(distinct)
    if _PLAIN.fullmatch(joined) is None:
        raise _Doubt
    codes = np.frombuffer(joined, dtype=np.uint8)
    blank = (codes == 32) | (codes == 10)
    starts = ~blank
    starts[1:] &= blank[:-1]
    per_text = np.bincount(np.cumsum(codes == 10)[starts], minlength=len(distinct))
    if np.any(per_text != count):
        raise _Doubt
    try:
        values = np.array(list(map(float, joined.split())), dtype=float).reshape(-1, count)
    except ValueError:  # "1-2", "1e": characters of numbers that make none
        raise _Doubt from None
    if not np.all(np.isfinite(values)) or np.any((values != 0) & (np.abs(values) < SMALLEST_NORMAL)):
        raise _Doubt
    if len(distinct) == len(texts):
        return values
    if len(distinct) == 1:  # a generated file's column: one text throughout
        return np.repeat(values, len(texts), axis=0)
    place = {text: k for k, text in enumerate(distinct)}
    return values[[place[text] for text in texts]]


def _angles(rpy: np.ndarray) -> np.ndarray:
    """``rpy`` (k, 3), _Doubt when :func:`rbi.formats.robot.angles` would refuse one."""
    if np.any(np.abs(rpy) > MAX_ANGLE_RAD):
        raise _Doubt
    return rpy


def _poses(rows: _Rows, origin: _Node | None) -> list[Pose]:
    """The poses :func:`rbi.formats.urdf._origin` reads from each row's ``origin`` element."""
    at = {} if origin is None else origin.at
    xyz = _numbers(rows.column(at.get("xyz"), b"0 0 0"), 3)
    rpy = _angles(_numbers(rows.column(at.get("rpy"), b"0 0 0"), 3))
    turned = np.any(rpy != 0, axis=1).tolist()
    R = np.empty((len(rows), 3, 3))
    R[:] = np.eye(3)
    for k in np.flatnonzero(turned).tolist():
        R[k] = rpy_matrix(rpy[k].tolist())
    return [Pose(R[k], xyz[k]) for k in range(len(rows))]


def _inertials(rows: _Rows, inertial: _Node) -> list[Inertial]:
    """The inertials :func:`rbi.formats.urdf._inertial` reads from each row."""
    origin, mass, block = inertial.child("origin"), inertial.child("mass"), inertial.child("inertia")
    if mass is None or block is None or "value" not in mass.at:
        raise _Doubt
    at = {} if origin is None else origin.at
    com = _numbers(rows.column(at.get("xyz"), b"0 0 0"), 3)
    rpy = _angles(_numbers(rows.column(at.get("rpy"), b"0 0 0"), 3))
    masses = _numbers(rows.column(mass.at["value"], b""), 1)[:, 0].tolist()
    six = []
    for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
        if key not in block.at:
            raise _Doubt
        six.append(_numbers(rows.column(block.at[key], b""), 1)[:, 0])
    ixx, ixy, ixz, iyy, iyz, izz = six
    written = np.stack([ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz], axis=1).reshape(-1, 3, 3)
    if np.any(np.abs(written) >= 1e300):
        raise _Doubt  # check_inertia_range's sum might overflow: the careful reader words it
    turned = np.any(rpy != 0, axis=1)
    level = np.flatnonzero(~turned).tolist()
    made = MassProperties.rows([masses[k] for k in level], com[level], written[level], "link")
    found: list[Inertial | None] = [None] * len(rows)
    for k, properties in zip(level, made):
        found[k] = Inertial(properties, written[k])
    for k in np.flatnonzero(turned).tolist():
        angles = tuple(rpy[k].tolist())
        found[k] = Inertial.read(
            masses[k], com[k].tolist(), written[k], rotation=rpy_matrix(angles), rpy=angles
        )
    return found


def _geoms(rows: _Rows, top: _Node, tag: str, links: list[tuple], packages) -> list[list[Geom]]:
    """Each row's ``tag`` (collision or visual) geoms as :func:`rbi.formats.urdf._geoms` reads
    them (``links``: each row's (path, link label) for a mesh's lookup)."""
    found: list[list[Geom]] = [[] for _ in range(len(rows))]
    for number, element in enumerate(each for each in top.children if each.tag == tag):
        holder = element.child("geometry")
        if holder is None or not holder.children:
            raise _Doubt
        shape = holder.children[0]
        label = f"{tag}[{number}]/geometry/{shape.tag}"
        poses = _poses(rows, element.child("origin"))
        if shape.tag == "mesh":
            for k, (pose, mesh) in enumerate(zip(poses, _meshes(rows, shape, label, links, packages))):
                found[k].append(Geom("mesh", (), pose, label, mesh_file=mesh[0], mesh_scale=mesh[1]))
            continue
        sizes = _sizes(rows, shape)
        for k, pose in enumerate(poses):
            found[k].append(Geom(shape.tag, sizes[k], pose, label))
    return found


def _meshes(rows: _Rows, shape: _Node, label: str, links: list[tuple], packages) -> list[tuple]:
    """(file, scale) of each row's mesh, as :func:`rbi.formats.urdf._geom` finds them."""
    if "filename" not in shape.at:
        raise _Doubt
    texts = rows.column(shape.at.get("scale"), b"1 1 1")
    try:
        scales = _numbers(texts, 3)
    except _Doubt:
        scales = np.repeat(_numbers(texts, 1), 3, axis=1)
    found = []
    for k, filename in enumerate(rows.words(shape.at["filename"])):
        if not filename:
            raise _Doubt
        path, index, name = links[k]
        shown = f"{path}: {Link(index, name).label}: {label}: {short(filename, 1000)}"
        found.append((resolve_mesh(path, filename, shown, packages), scales[k].copy()))
    return found


def _sizes(rows: _Rows, shape: _Node) -> list[tuple[float, ...]]:
    """Each row's shape size, as :func:`rbi.formats.urdf._geom` reads it; () for a kind with no
    volume."""
    names = _SHAPES.get(shape.tag, ())
    if any(name not in shape.at for name in names):
        raise _Doubt
    if not names:
        return [()] * len(rows)
    count = 3 if shape.tag == "box" else 1
    parts = [_numbers(rows.column(shape.at[name], b""), count) for name in names]
    sizes = np.concatenate(parts, axis=1)
    if np.any(sizes < 0):
        raise _Doubt
    return [tuple(row) for row in sizes.tolist()]


def _links(path: str, elements: dict, geometry: bool, packages) -> list[Link]:
    """The links of ``elements`` (signature → [(index, values)]: :func:`_elements`), in file order."""
    if not elements:
        raise _Doubt  # no link: the careful reader words it
    links: list[Link] = [None] * sum(len(group) for group in elements.values())  # type: ignore[list-item]
    for signature, group in elements.items():
        top = _tree(signature)
        if "name" not in top.at:
            raise _Doubt
        rows = group
        names = rows.words(top.at["name"])
        if not all(names):
            raise _Doubt
        inertial = top.child("inertial")
        inertials = [None] * len(rows) if inertial is None else _inertials(rows, inertial)
        empty: list[list[Geom]] = [[] for _ in range(len(rows))]
        labels = [(path, index, names[k]) for k, index in enumerate(group.indices)]
        collisions = _geoms(rows, top, "collision", labels, packages) if geometry else empty
        visuals = _geoms(rows, top, "visual", labels, packages) if geometry else empty
        for k, index in enumerate(group.indices):
            links[index] = Link(index, names[k], inertials[k], collisions[k], visuals[k], origin=_UNPLACED)
    return links


def _joints(model: RobotModel, elements) -> None:
    """Each joint of ``elements`` (signature → [(index, values)]: :func:`_elements`) into its
    child link, as :func:`rbi.formats.urdf._joints` reads it; _Doubt (or its InputError) where
    that reader would refuse the file."""
    by_name = {link.name: link for link in model.links}
    found: list[tuple] = [()] * sum(len(group) for group in elements.values())
    for signature, group in elements.items():
        top = _tree(signature)
        parent, child = top.child("parent"), top.child("child")
        if "name" not in top.at or parent is None or child is None:
            raise _Doubt
        if "link" not in parent.at or "link" not in child.at:
            raise _Doubt
        rows = group
        kinds = [MOVING.get(kind) for kind in rows.words(top.at.get("type"))]
        if None in kinds:
            raise _Doubt
        names, parents = rows.words(top.at["name"]), rows.words(parent.at["link"])
        children = rows.words(child.at["link"])
        poses = _poses(rows, top.child("origin"))
        axes = _axes(model.path, rows, top.child("axis"), kinds)
        efforts = _efforts(rows, top.child("limit"))
        for k, index in enumerate(group.indices):
            found[index] = (names[k], kinds[k], parents[k], children[k], poses[k], axes[k], efforts[k])
    anchors = np.zeros((len(found), 3))
    for k, (name, kind, parent_name, child_name, pose, axis, effort) in enumerate(found):
        link = by_name.get(child_name)
        if not name or parent_name not in by_name or link is None or link.parent is not None:
            raise _Doubt
        link.parent, link.origin = parent_name, pose
        link.motions = [Motion(name, kind, axis, anchors[k], effort_limit=effort)]
    if len({name for name, *_ in found}) != len(found) or not _one_tree(model.links):
        raise _Doubt  # check_unique_joint_names or check_tree would refuse it: the careful reader words it
    for link in model.links:
        if link.origin is _UNPLACED:
            link.origin = Pose.identity()  # the root's, as the careful reader leaves it


def _one_tree(links: list[Link]) -> bool:
    """Do the links form one tree (one root, every link reached from it), as
    :func:`rbi.formats.urdf.check_tree` asks (each link has one parent here, a link of the model)?"""
    rows = {link.name: row for row, link in enumerate(links)}
    children: list[list[int]] = [[] for _ in links]
    roots = []
    for row, link in enumerate(links):
        if link.parent is None:
            roots.append(row)
        else:
            children[rows[link.parent]].append(row)
    if len(roots) != 1:
        return False
    reached, queue = 0, roots
    while queue:
        reached += 1
        queue.extend(children[queue.pop()])
    return reached == len(links)


def _axes(path: str, rows: _Rows, axis: _Node | None, kinds: list) -> list[np.ndarray]:
    """Each joint's axis as :func:`rbi.formats.urdf._axis` reads it: a unit vector for revolute
    and prismatic joints (worked out once per distinct text, as there), else as written."""
    texts = [b"1 0 0"] * len(rows) if axis is None else rows.column(axis.at.get("xyz"), b"1 0 0")
    values = _numbers(texts, 3)
    units: dict[str, np.ndarray] = {}
    found = []
    for k, kind in enumerate(kinds):
        if kind not in UNIT_AXIS_KINDS:
            found.append(values[k].copy())
            continue
        known = units.get(texts[k])
        if known is None:
            known = units[texts[k]] = unit(Where(path), values[k].tolist(), "axis: xyz")
        found.append(known.copy())
    return found


def _efforts(rows: _Rows, limit: _Node | None) -> list[float | None]:
    """Each joint's ``<limit effort>`` as a magnitude, or None where it is not written."""
    if limit is None or "effort" not in limit.at:
        return [None] * len(rows)
    return np.abs(_numbers(rows.column(limit.at["effort"], b""), 1)[:, 0]).tolist()


def attach_elements(model: RobotModel) -> None:
    """The XML elements of a model :func:`read_urdf_bulk` read (it leaves them out): the document
    parsed the careful way, each link given its ``<link>`` and its inertial its ``<inertial>``
    (their spans are where ``rbi audit --fix`` edits)."""
    document = model.document
    if model.format != "urdf" or document is None or document.root is not None:
        return
    document.root = robot_xml.parse(model.path, document.text)
    for link, element in zip(model.links, document.root.all("link")):
        link.element = element
        if link.inertial is not None:
            link.inertial = dataclasses.replace(link.inertial, element=element.child("inertial"))
