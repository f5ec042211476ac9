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

The model it returns holds its links as columns (:class:`rbi.formats.robot.LinkColumns`), which
:mod:`rbi.robot` audits as they are; its :class:`Link` values are made when first asked for.
They have no XML ``element``: :func:`attach_elements` reads the document the careful way and
attaches them, for ``rbi audit --fix`` (which edits the file at their spans).
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np

from rbi.core.validity import SMALLEST_NORMAL
from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.robot import (
    MAX_ANGLE_RAD,
    GeomColumn,
    Inertial,
    Link,
    LinkColumns,
    RobotModel,
    Where,
    depth_first,
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
        fields = _links(document.path, links, geometry, package_paths)
        fields.update(_joints(fields["names"], joints, document.path))
        return RobotModel(document.path, "urdf", name, document=document, columns=LinkColumns(**fields))
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
    values, blank = _values(text)
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
    name = values.one(root.index(b"name")).decode() if b"name" in root else None
    return name, groups[b"<link"], groups[b"<joint"]


def _values(text: bytes) -> tuple[_Values, bytes]:
    """The attribute values of ``text`` (in double quotes: with no character data, comment or
    single-quoted value, every double quote opens or closes one) and the text with each value
    emptied; _Doubt for a value holding a line end or tab, which XML reads as a space."""
    codes = np.frombuffer(text, dtype=np.uint8)
    quotes = np.flatnonzero(codes == 34)
    if len(quotes) % 2:
        raise _Doubt
    starts, ends = quotes[0::2] + 1, quotes[1::2]
    if np.any(np.searchsorted(quotes, np.flatnonzero(codes < 32)) % 2):  # \t, \n or \r in a value
        raise _Doubt  # (expat lets no other control character through)
    bounds = np.empty(2 * len(starts) + 2, dtype=np.int64)  # outside, inside, outside, ...
    bounds[0], bounds[1:-1:2], bounds[2:-1:2], bounds[-1] = 0, starts, ends, len(codes)
    outside = np.ones(len(bounds) - 1, dtype=bool)
    outside[1::2] = False
    return _Values(codes, starts, ends), codes[np.repeat(outside, np.diff(bounds))].tobytes()


class _Values:
    """A document's attribute values, in document order: value k is ``codes[starts[k]:ends[k]]``."""

    def __init__(self, codes: np.ndarray, starts: np.ndarray, ends: np.ndarray):
        self.codes, self.starts, self.ends = codes, starts, ends

    def __len__(self) -> int:
        return len(self.starts)

    def one(self, k: int) -> bytes:
        return self.codes[self.starts[k] : self.ends[k]].tobytes()

    def texts(self, which: np.ndarray) -> list[bytes]:
        """The values of the indices ``which``."""
        found = self._rows(which)
        if found is None:
            return [b""] * len(which)
        return found.view(f"S{found.shape[1]}").reshape(-1).tolist()

    def distinct(self, which: np.ndarray) -> tuple[list[bytes], np.ndarray]:
        """The distinct values of the indices ``which`` (in order of first appearance) and where
        each index's value is among them."""
        found = self._rows(which)
        if found is None:
            return ([b""] if len(which) else []), np.zeros(len(which), dtype=int)
        if np.all(found == found[0]):  # one text throughout (a generated file's column)
            return [found[0].tobytes().rstrip(b"\0")], np.zeros(len(which), dtype=int)
        texts = found.view(f"S{found.shape[1]}").reshape(-1).tolist()
        places: dict[bytes, int] = {}
        inverse = np.array([places.setdefault(text, len(places)) for text in texts], dtype=int)
        return list(places), inverse

    def _rows(self, which: np.ndarray) -> np.ndarray | None:
        """The values of the indices ``which`` as rows of a (k, width) array of bytes, each
        padded with NULs (no value holds one: expat refuses it); None when all are empty."""
        starts, lengths = self.starts[which], self.ends[which] - self.starts[which]
        width = int(lengths.max()) if len(lengths) else 0
        if width == 0:
            return None
        codes = self.codes
        if len(codes) < width + int(starts.max()):
            codes = np.concatenate([codes, np.zeros(width, dtype=np.uint8)])
        windows = np.lib.stride_tricks.as_strided(
            codes, shape=(len(codes) - width + 1, width), strides=(1, 1)
        )
        found = windows[starts]
        found[np.arange(width) >= lengths[:, None]] = 0
        return found


def _grouped(blank: bytes, begins, stops, lows, highs, values: _Values) -> dict[bytes, _Rows]:
    """Signature → its elements (:class:`_Rows`) of the elements spanning ``begins:stops`` of
    the emptied text, whose values are ``values[lows:highs]``."""
    found: dict[bytes, tuple[list[int], list[int]]] = {}
    spans = zip(begins.tolist(), stops.tolist(), lows.tolist())
    for index, (begin, end, low) in enumerate(spans):
        indices, firsts = found.setdefault(blank[begin:end], ([], []))
        indices.append(index)
        firsts.append(low)
    return {
        signature: _Rows(indices, np.array(firsts, dtype=np.int64), values)
        for signature, (indices, firsts) in found.items()
    }


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
    return {signature: _Rows(list(range(count)), first + spacing * np.arange(count, dtype=np.int64), values)}


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
    and ``firsts`` (where each one's values start in the document's :class:`_Values`)."""

    def __init__(self, indices: list[int], firsts: np.ndarray, values: _Values):
        self.indices, self.firsts, self.values = indices, firsts, values

    def __len__(self) -> int:
        return len(self.indices)

    def column(self, place: int | None, default: bytes) -> list[bytes]:
        """The text at ``place`` of each element (``default`` where the attribute is not written)."""
        if place is None:
            return [default] * len(self)
        return self.values.texts(self.firsts + place)

    def distinct(self, place: int | None, default: bytes) -> tuple[list[bytes], np.ndarray]:
        """:meth:`column` as its distinct texts and where each element's is among them."""
        if place is None:
            return [default], np.zeros(len(self), dtype=int)
        return self.values.distinct(self.firsts + place)

    def numbers(self, place: int | None, default: bytes, count: int) -> np.ndarray:
        """:func:`_numbers` of :meth:`column`, each distinct text read once."""
        distinct, inverse = self.distinct(place, default)
        return _numbers(distinct, count)[inverse]

    def words(self, place: int | None) -> list[str]:
        """The text at ``place`` of each element as str (``""`` where the attribute is not written)."""
        if place is None:
            return [""] * len(self)
        # one decoding for all: no value holds a line end (_values leaves those to the careful reader)
        return b"\n".join(self.column(place, b"")).decode().split("\n")


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


def _poses(rows: _Rows, origin: _Node | None) -> tuple[np.ndarray, np.ndarray]:
    """The poses :func:`rbi.formats.urdf._origin` reads from each row's ``origin`` element:
    rotations (k, 3, 3) and translations (k, 3)."""
    at = {} if origin is None else origin.at
    xyz = rows.numbers(at.get("xyz"), b"0 0 0", 3)
    rpy = _angles(rows.numbers(at.get("rpy"), b"0 0 0", 3))
    turned = np.any(rpy != 0, axis=1).tolist()
    R = np.empty((len(rows), 3, 3))
    R[:] = np.eye(3)
    for k in np.flatnonzero(turned).tolist():
        R[k] = rpy_matrix(rpy[k].tolist())
    return R, xyz


class _Inertials:
    """The links' inertials as :class:`rbi.formats.robot.LinkColumns` holds them, for ``n`` links."""

    def __init__(self, n: int):
        self.declared = np.zeros(n, dtype=bool)
        self.masses = np.zeros(n)
        self.coms = np.zeros((n, 3))
        self.inertias = np.zeros((n, 3, 3))
        self.written = np.zeros((n, 3, 3))
        self.turned: dict[int, Inertial] = {}

    def read(self, rows: _Rows, inertial: _Node) -> None:
        """The inertials :func:`rbi.formats.urdf._inertial` reads from each row, into the columns."""
        origin, mass, block = inertial.child("origin"), inertial.child("mass"), inertial.child("inertia")
        if mass is None or block is None or "value" not in mass.at:
            raise _Doubt
        at = {} if origin is None else origin.at
        com = rows.numbers(at.get("xyz"), b"0 0 0", 3)
        rpy = _angles(rows.numbers(at.get("rpy"), b"0 0 0", 3))
        masses = rows.numbers(mass.at["value"], b"", 1)[:, 0]
        six = []
        for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            if key not in block.at:
                raise _Doubt
            six.append(rows.numbers(block.at[key], b"", 1)[:, 0])
        ixx, ixy, ixz, iyy, iyz, izz = six
        written = np.stack([ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz], axis=1).reshape(-1, 3, 3)
        if np.any(np.abs(written) >= 1e300):
            raise _Doubt  # check_inertia_range's sum might overflow: the careful reader words it
        where = np.array(rows.indices, dtype=int)
        self.declared[where] = True
        self.masses[where], self.coms[where] = masses, com
        self.inertias[where] = self.written[where] = written
        for k in np.flatnonzero(np.any(rpy != 0, axis=1)).tolist():
            angles = tuple(rpy[k].tolist())
            found = Inertial.read(
                float(masses[k]), com[k].tolist(), written[k], rotation=rpy_matrix(angles), rpy=angles
            )
            row = rows.indices[k]
            self.turned[row] = found
            self.coms[row] = found.properties.center_of_mass
            self.inertias[row] = found.properties.inertia_about_com


def _geoms(rows: _Rows, top: _Node, tag: str, links: list[tuple], packages) -> list[GeomColumn]:
    """The rows' ``tag`` (collision or visual) geoms as :func:`rbi.formats.urdf._geoms` reads
    them, one column per element (``links``: each row's (path, link label) for a mesh's lookup)."""
    found = []
    for number, element in enumerate(each for each in top.children if each.tag == tag):
        holder = element.child("geometry")
        if holder is None or not holder.children:
            raise _Doubt
        shape = holder.children[0]
        label = f"{tag}[{number}]/geometry/{shape.tag}"
        R, t = _poses(rows, element.child("origin"))
        column = GeomColumn(tag, label, shape.tag, rows.indices, R, t)
        if shape.tag == "mesh":
            column.meshes = _meshes(rows, shape, label, links, packages)
        else:
            column.sizes = _sizes(rows, shape)
        found.append(column)
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


def _sizes(rows: _Rows, shape: _Node) -> np.ndarray:
    """Each row's shape size (k, m), as :func:`rbi.formats.urdf._geom` reads it; m = 0 for a
    kind with no volume."""
    names = _SHAPES.get(shape.tag, ())
    if any(name not in shape.at for name in names):
        raise _Doubt
    if not names:
        return np.empty((len(rows), 0))
    count = 3 if shape.tag == "box" else 1
    parts = [rows.numbers(shape.at[name], b"", count) for name in names]
    sizes = np.concatenate(parts, axis=1)
    if np.any(sizes < 0):
        raise _Doubt
    return sizes


def _links(path: str, elements: dict, geometry: bool, packages) -> dict:
    """The links of ``elements`` (signature → :class:`_Rows`: :func:`_elements`) as the
    :class:`rbi.formats.robot.LinkColumns` fields they give: names, inertials and geometry."""
    if not elements:
        raise _Doubt  # no link: the careful reader words it
    n = sum(len(group) for group in elements.values())
    names: list[str] = [""] * n
    inertials = _Inertials(n)
    geoms: list[GeomColumn] = []
    for signature, rows in elements.items():
        top = _tree(signature)
        if "name" not in top.at:
            raise _Doubt
        words = rows.words(top.at["name"])
        if not all(words):
            raise _Doubt
        for index, word in zip(rows.indices, words):
            names[index] = word
        inertial = top.child("inertial")
        if inertial is not None:
            inertials.read(rows, inertial)
        if geometry:
            labels = [(path, index, words[k]) for k, index in enumerate(rows.indices)]
            geoms += _geoms(rows, top, "collision", labels, packages)
            geoms += _geoms(rows, top, "visual", labels, packages)
    if len(set(names)) != n:
        raise _Doubt  # check_unique_names would refuse it: the careful reader words it
    fields = {key: value for key, value in vars(inertials).items()}
    return {"names": names, "geoms": geoms, **fields}


def _joints(names: list[str], elements, path: str) -> dict:
    """The joints of ``elements`` (signature → :class:`_Rows`: :func:`_elements`) as the
    :class:`rbi.formats.robot.LinkColumns` fields they give, each in its child link's row, as
    :func:`rbi.formats.urdf._joints` reads them; _Doubt (or its InputError) where that reader
    would refuse the file."""
    n = len(names)
    rows_of = {name: row for row, name in enumerate(names)}
    parents = np.full(n, -1)
    joint_names, kinds, efforts = np.full(n, "", dtype=object), np.full(n, None), np.full(n, None)
    rotations, translations, axes = np.empty((n, 3, 3)), np.zeros((n, 3)), np.zeros((n, 3))
    rotations[:] = np.eye(3)
    count = 0
    for signature, rows in elements.items():
        top = _tree(signature)
        parent, child = top.child("parent"), top.child("child")
        if "name" not in top.at or parent is None or child is None:
            raise _Doubt
        if "link" not in parent.at or "link" not in child.at:
            raise _Doubt
        kinds_read = [MOVING.get(kind) for kind in rows.words(top.at.get("type"))]
        if None in kinds_read:
            raise _Doubt
        words = rows.words(top.at["name"])
        parent_rows = [rows_of.get(name, -1) for name in rows.words(parent.at["link"])]
        children = [rows_of.get(name, -1) for name in rows.words(child.at["link"])]
        if not all(words) or -1 in parent_rows or -1 in children:
            raise _Doubt
        R, t = _poses(rows, top.child("origin"))
        found_axes = _axes(path, rows, top.child("axis"), kinds_read)
        found_efforts = _efforts(rows, top.child("limit"))
        at = np.array(children, dtype=int)
        if np.any(parents[at] != -1) or len(np.unique(at)) != len(at):
            raise _Doubt  # a link with a second parent: the careful reader words it
        parents[at], joint_names[at], kinds[at], efforts[at] = parent_rows, words, kinds_read, found_efforts
        rotations[at], translations[at], axes[at] = R, t, found_axes
        count += len(rows)
    order = _one_tree(parents.tolist())
    named = joint_names.tolist()
    if len({name for name in named if name}) != count or order is None:
        raise _Doubt  # check_unique_joint_names or check_tree would refuse it: the careful reader words it
    return {
        "parents": parents.tolist(),
        "order": order,
        "rotations": rotations,
        "translations": translations,
        "joint_names": named,
        "joint_kinds": kinds.tolist(),
        "axes": axes,
        "efforts": efforts.tolist(),
    }


def _one_tree(parents: list[int]) -> list[int] | None:
    """The links' rows parents first, as :func:`rbi.formats.robot.depth_first` orders them, when
    they form one tree (one root, every link reached from it), as
    :func:`rbi.formats.urdf.check_tree` asks (``parents``: each link's parent row, -1 for none);
    None when they do not."""
    n = len(parents)
    if parents.count(-1) != 1:
        return None
    order = depth_first([n if parent < 0 else parent for parent in parents], n)
    return order if len(order) == n else None


def _axes(path: str, rows: _Rows, axis: _Node | None, kinds: list) -> np.ndarray:
    """Each joint's axis (k, 3) as :func:`rbi.formats.urdf._axis` reads it: a unit vector for
    revolute and prismatic joints (worked out once per distinct text, as there), else as written."""
    distinct, inverse = rows.distinct(None if axis is None else axis.at.get("xyz"), b"1 0 0")
    written = _numbers(distinct, 3)
    values = written[inverse]
    turned = np.array([kind in UNIT_AXIS_KINDS for kind in kinds], dtype=bool)
    if np.any(turned):
        units = written.copy()
        for k in np.unique(inverse[turned]).tolist():
            units[k] = unit(Where(path), written[k].tolist(), "axis: xyz")
        values[turned] = units[inverse[turned]]
    return values


def _efforts(rows: _Rows, limit: _Node | None) -> list[float | None]:
    """Each joint's ``<limit effort>`` as a magnitude, or None where it is not written."""
    if limit is None or "effort" not in limit.at:
        return [None] * len(rows)
    return np.abs(rows.numbers(limit.at["effort"], b"", 1)[:, 0]).tolist()


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
