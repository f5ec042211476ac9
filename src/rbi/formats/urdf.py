"""URDF: ``<robot><link name><inertial>…</inertial><collision>…<visual>…</link><joint …/>``.

- ``<inertial><origin xyz rpy/><mass value/><inertia ixx ixy ixz iyy iyz izz/>``; ``rpy`` is
  roll, pitch, yaw about the fixed x, y, z axes (``R = Rz(yaw) Ry(pitch) Rx(roll)``); the
  inertia is about the centre of mass in the inertial frame's axes, off-diagonal entries the
  matrix's own (``ixy = −∫xy dm``).
- ``<collision>``/``<visual>``: ``<origin/>`` and ``<geometry>`` holding one of ``<box size>``,
  ``<cylinder radius length>`` (along z), ``<sphere radius>``, ``<capsule radius length>`` (as
  pybullet and ROS 2 read it: ``length`` the cylindrical part) or ``<mesh filename scale>``.
- ``<joint type><origin/><parent link/><child link/><axis xyz/>``: the child link's frame in the
  parent's at zero, and the motion (revolute and continuous turn about the axis, prismatic
  slides along it, in the child's frame).

One reader, on columns (issue 25: a 100,000-link file in seconds, without a Python object and
two handler calls per XML element). The top-level ``<link>`` and ``<joint>`` elements are put
in groups of the same *signature* (the same elements and attribute names: their values at the
same places), so each field (an origin's ``xyz``, a mass, a box's ``size``) is one column of
strings, checked and turned into numbers at once; the model holds its links as those columns
(:class:`rbi.formats.robot.LinkColumns`).

One path for every file (:func:`read_urdf`): the groups are found on the document's text with
every attribute value emptied and the values apart, as arrays. A plain text (:func:`plain_text`:
UTF-8 with no DTD, entity or character reference, CDATA, processing instruction, character
data or single-quoted value) is taken apart so in one pass on arrays, without an element tree;
any other file is parsed and its tree written out in that form (:func:`_tree_text`). A refusal
is worded for the first thing wrong in document order (link by link, then joint by joint, each
field in the order above): the elements of groups that refuse are read again
:data:`~rbi.formats.xml_columns.CHUNK` at a time, and a chunk that refuses one element a group.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from rbi.core.mass import MassProperties
from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.robot import (
    MAX_ANGLE_RAD,
    SHAPES,
    GeomColumn,
    Inertial,
    LinkColumns,
    RobotModel,
    check_unique_joint_names,
    depth_first,
    element_label,
    from_six,
    on_loop,
    refuse_shared_keys,
    rpy_matrix,
    short,
)
from rbi.formats.robot_paths import resolve_mesh
from rbi.formats.xml_columns import CHUNK, Doubt, Node, Rows, Values, in_order

MOVING = {
    "revolute": "revolute",
    "continuous": "revolute",
    "prismatic": "prismatic",
    "floating": "floating",
    "planar": "planar",
    "fixed": "fixed",
    "spherical": "ball",
    "ball": "ball",
}

UNIT_AXIS_KINDS = ("revolute", "prismatic")
"""The motions whose ``<axis xyz>`` is made a unit vector (the others keep it as written)."""


def read_urdf(
    document, package_paths=None, geometry: bool = True, plain: Elements | None = None
) -> RobotModel:
    """The model of the URDF ``document``: of its plain text when ``plain`` gives its elements
    (:func:`plain_text`), else of its parsed tree; InputError, one line naming the file, the
    link or joint and the attribute, for the first thing wrong in document order."""
    found = plain if plain is not None else _elements(*_tree_text(document.root))
    fields = _links(document.path, found.links, geometry, package_paths, found.line)
    fields.update(_joints(document.path, fields["names"], found.joints))
    return RobotModel(document.path, "urdf", found.name, LinkColumns(**fields), document=document)


class Elements(NamedTuple):
    """A URDF's root ``name`` and its top-level ``links`` and ``joints`` as chunks for
    :func:`~rbi.formats.xml_columns.in_order`; ``line`` gives a link's line in the text."""

    name: str | None
    links: list
    joints: list
    line: Callable[[int], int]


# --- the groups of a plain text -----------------------------------------------------------------

_COMMENT = re.compile(rb"<!--.*?-->", re.S)
_TEXT = re.compile(rb">\s*[^\s<]")
"""Character data inside an element (or a ``>`` inside a value): not plain."""

_SINGLE_QUOTED = re.compile(rb"=\s*'")
_NAMES = re.compile(rb'([^\s=<>/]+)\s*=\s*""')


def _plain_xml(text: bytes) -> bool:
    """Is ``text`` well-formed XML (as expat, the tree's parser, reads it) with no document
    type declaration, entity or character reference, CDATA section or processing instruction
    (but the XML declaration)?"""
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


def plain_text(document) -> Elements | None:
    """The elements of a URDF document's text (:func:`_elements`) when it is plain: UTF-8 with
    no DTD, entity or character reference, CDATA, processing instruction, character data or
    single-quoted value, well-formed as expat reads it, its values taken out in one pass on
    arrays; None otherwise (then its tree is read)."""
    text = document.text
    try:
        if document.encoding != "utf-8" or not _plain_xml(text):
            return None
        if text.startswith(b"<?xml"):  # (the declaration's line ends kept, so lines count as in the file)
            end = text.index(b"?>") + 2
            text = b"\n" * text.count(b"\n", 0, end) + text[end:]
        if b"<!--" in text:
            text = _COMMENT.sub(lambda comment: b"\n" * comment.group().count(b"\n"), text)
        if _TEXT.search(text):
            return None
        values, blank = _values(text)
        if _SINGLE_QUOTED.search(blank):
            return None
        return _elements(blank, values)
    except Doubt:
        return None


def _tree_text(root) -> tuple[bytes, Values]:
    """A parsed document as :func:`plain_text` takes a text apart: its tags with each value
    emptied (each top-level element on its own line of the file) and its values in document
    order."""
    pieces: list[str] = ["\n" * (root.line - 1)]
    texts: list[bytes] = []
    reached = [root.line]  # the line the text has reached

    def write(element, top: bool) -> None:
        if top:
            pieces.append("\n" * (element.line - reached[0]))
            reached[0] = element.line
        pairs = element.pairs
        pieces.append("<" + element.tag + "".join(f' {name}=""' for name in pairs[::2]))
        texts.extend(value.encode() for value in pairs[1::2])
        if not element.children:
            pieces.append("/>")
            return
        pieces.append(">")
        for child in element.children:
            write(child, element is root)
        pieces.append(f"</{element.tag}>")

    write(root, False)
    lengths = np.array([len(text) for text in texts], dtype=np.int64)
    ends = np.cumsum(lengths)
    return "".join(pieces).encode(), Values(
        np.frombuffer(b"".join(texts), dtype=np.uint8), ends - lengths, ends
    )


def _elements(blank: bytes, values: Values) -> Elements:
    """The root's name and the top-level links and joints of a URDF text with every value
    emptied (``blank``; ``values`` the values), each kind as chunks for
    :func:`~rbi.formats.xml_columns.in_order` (:func:`_chunks`). The element boundaries are found
    on the arrays of its ``<``, ``>`` and ``=`` (with no text, comment or value left, each starts
    or ends a tag, or gives a value); Doubt for a text not so made."""
    codes = np.frombuffer(blank, dtype=np.uint8)
    marks = np.flatnonzero(codes - 60 <= 2)  # where a <, = or > is (bytes below 60 wrap around)
    kinds = codes[marks]
    opens, equals, closes = marks[kinds == 60], marks[kinds == 61], marks[kinds == 62]
    if len(opens) != len(closes) or len(equals) != len(values) or not len(opens):
        raise Doubt
    if np.any(closes < opens) or np.any(opens[1:] < closes[:-1]):
        raise Doubt
    ending, empty = codes[opens + 1] == 47, codes[closes - 1] == 47
    step = np.where(ending, -1, np.where(empty, 0, 1))
    after = np.cumsum(step)
    if after.max() > robot_xml.MAX_DEPTH or not _named(codes, opens[:1], b"<robot")[0]:
        raise Doubt
    starts = np.flatnonzero((after - step == 1) & ~ending)
    ends = np.flatnonzero((after == 1) & (ending | empty))
    groups, firsts = {}, {}
    for opening in (b"<link", b"<joint"):
        chosen = _named(codes, opens[starts], opening)
        begins, stops = opens[starts][chosen], closes[ends][chosen] + 1
        lows = np.searchsorted(equals, begins)
        groups[opening] = _chunks(codes, blank, begins, stops, lows, np.searchsorted(equals, stops), values)
        firsts[opening] = begins
    root = _NAMES.findall(blank[: closes[0] + 1])
    name = values.one(root.index(b"name")).decode() if b"name" in root else None
    links = firsts[b"<link"]
    return Elements(
        name, groups[b"<link"], groups[b"<joint"], lambda index: blank.count(b"\n", 0, int(links[index])) + 1
    )


def _chunks(codes: np.ndarray, blank: bytes, begins, stops, lows, highs, values: Values) -> list:
    """The elements spanning ``begins:stops`` of ``blank`` (their values ``values[lows:highs]``)
    as chunks for :func:`~rbi.formats.xml_columns.in_order`: all of them in groups of one
    signature; on a refusal read again :data:`~rbi.formats.xml_columns.CHUNK` at a time, and a
    chunk refused one element a group, so that the refusal names the first wrong element."""

    def part(low: int, high: int, single: bool) -> list[Rows]:
        spans = begins[low:high], stops[low:high], lows[low:high]
        return list(_grouped(blank, *spans, values, low, single).values())

    def chunks() -> list:
        steps = range(0, len(begins), CHUNK)
        return [(part(a, a + CHUNK, False), lambda a=a: [(part(a, a + CHUNK, True), None)]) for a in steps]

    whole = _alike(codes, blank, begins, stops, lows, highs, values) or _grouped(
        blank, begins, stops, lows, values
    )
    return [(list(whole.values()), chunks)]


def _values(text: bytes) -> tuple[Values, bytes]:
    """The attribute values of ``text`` (in double quotes: with no character data, comment or
    single-quoted value, every double quote opens or closes one) and the text with each value
    emptied; Doubt for a value holding a line end or tab, which XML reads as a space."""
    codes = np.frombuffer(text, dtype=np.uint8)
    quotes = np.flatnonzero(codes == 34)
    if len(quotes) % 2:
        raise Doubt
    starts, ends = quotes[0::2] + 1, quotes[1::2]
    if np.any(np.searchsorted(quotes, np.flatnonzero(codes < 32)) % 2):  # \t, \n or \r in a value
        raise Doubt  # (expat lets no other control character through)
    bounds = np.empty(2 * len(starts) + 2, dtype=np.int64)  # outside, inside, outside, ...
    bounds[0], bounds[1:-1:2], bounds[2:-1:2], bounds[-1] = 0, starts, ends, len(codes)
    outside = np.ones(len(bounds) - 1, dtype=bool)
    outside[1::2] = False
    return Values(codes, starts, ends), codes[np.repeat(outside, np.diff(bounds))].tobytes()


def _grouped(blank: bytes, begins, stops, lows, values: Values, first: int = 0, single: bool = False) -> dict:
    """Signature → its elements (:class:`Rows`) of the elements spanning ``begins:stops`` of
    the emptied text, whose values start at ``lows``; ``first``: the first one's index;
    ``single``: each element a group of its own."""
    found: dict[bytes | int, tuple[bytes, list[int], list[int]]] = {}
    spans = zip(begins.tolist(), stops.tolist(), lows.tolist())
    for index, (begin, end, low) in enumerate(spans, first):
        signature = blank[begin:end]
        _, indices, firsts = found.setdefault(index if single else signature, (signature, [], []))
        indices.append(index)
        firsts.append(low)
    return {
        key: Rows(_tree(signature), indices, np.array(firsts, dtype=np.int64), values)
        for key, (signature, indices, firsts) in found.items()
    }


def _alike(codes: np.ndarray, blank: bytes, begins, stops, lows, highs, values) -> dict[bytes, Rows] | None:
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
    firsts = first + spacing * np.arange(count, dtype=np.int64)
    return {signature: Rows(_tree(signature), list(range(count)), firsts, values)}


def _named(codes: np.ndarray, at: np.ndarray, opening: bytes) -> np.ndarray:
    """Which of the tags starting at ``at`` open with ``opening`` (``<`` and a name) and that
    name alone."""
    size = len(opening)
    inside = at + size < len(codes)
    chosen = inside.copy()
    for k, byte in enumerate(opening):
        chosen[inside] &= codes[at[inside] + k] == byte
    chosen[inside] &= np.isin(codes[at[inside] + size], _NAME_ENDS)
    return chosen


_NAME_ENDS = np.frombuffer(b" \t\n\r>/", dtype=np.uint8)


@functools.lru_cache(maxsize=4096)
def _tree(signature: bytes) -> Node:
    """The element tree a signature describes (read as the file is: names as written)."""
    return Node.of(robot_xml.parse("(signature)", signature), [0])


# --- links --------------------------------------------------------------------------------------


def _links(path: str, chunks: list, geometry: bool, packages, line: Callable[[int], int]) -> dict:
    """The links of ``chunks`` (:func:`in_order`) as the :class:`LinkColumns` fields they give:
    names, inertials and geometry."""
    n = sum(len(rows) for groups, _ in chunks for rows in groups)
    if not n:
        raise InputError(f"{path}: no <link>: a URDF needs at least one (urdfdom and pybullet refuse it)")
    names: list[str] = [""] * n
    declared, masses, coms = np.zeros(n, dtype=bool), np.zeros(n), np.zeros((n, 3))
    written, records = np.zeros((n, 3, 3)), {}
    geoms: list[GeomColumn] = []

    def read(rows: Rows) -> None:
        words = rows.words(rows.top.at.get("name"))
        for k, word in enumerate(words):
            if not word:
                raise InputError(
                    f"{path}: link[{rows.indices[k]}] (line {line(rows.indices[k])}): name: missing; every link needs a "
                    "name (urdfdom and pybullet refuse it)"
                )
            names[rows.indices[k]] = word
        rows.path = path
        rows.label = lambda k, rows=rows, words=words: element_label("link", rows.indices[k], words[k])
        inertial = rows.top.child("inertial")
        if inertial is not None:
            at = rows.indices
            declared[at] = True
            masses[at], coms[at], written[at], rpy = _inertials(rows, inertial)
            for k in np.flatnonzero(np.any(rpy != 0, axis=1)).tolist():
                turn = tuple(rpy[k].tolist())
                records[at[k]] = Inertial.read(
                    masses[at[k]], coms[at[k]], written[at[k]], rotation=rpy_matrix(turn), rpy=turn
                )
        if geometry:
            geoms.extend(_geoms(rows, "collision", packages) + _geoms(rows, "visual", packages))

    in_order(chunks, read)
    if len(set(names)) != n:
        refuse_shared_keys(path, "link", names)
    inertias = written.copy()
    for row, each in records.items():
        coms[row], inertias[row] = each.properties.center_of_mass, each.properties.inertia_about_com
    inertials = MassProperties(masses, coms, inertias, "link")
    return {
        "names": names,
        "geoms": geoms,
        "declared": declared,
        "inertials": inertials,
        "written": written,
        "records": records,
    }


def _origins(rows: Rows, origin: Node | None, what: str, turn: str = "") -> tuple[np.ndarray, np.ndarray]:
    """Each row's ``origin`` element (``what``: whose) as its ``xyz`` (k, 3) and ``rpy`` (k, 3),
    zero where not written; ``turn`` names the angles when one is refused (:meth:`Where.angles`),
    else ``what/origin: rpy``."""
    at = {} if origin is None else origin.at
    xyz = rows.numbers(at.get("xyz"), b"0 0 0", 3, f"{what}/origin: xyz")
    rpy = rows.numbers(at.get("rpy"), b"0 0 0", 3, f"{what}/origin: rpy")
    for k in np.flatnonzero(np.any(np.abs(rpy) > MAX_ANGLE_RAD, axis=1)).tolist():
        rows.where(k).angles(rpy[k].tolist(), turn or f"{what}/origin: rpy")
    return xyz, rpy


def _poses(rows: Rows, origin: Node | None, what: str) -> tuple[np.ndarray, np.ndarray]:
    """Each row's ``origin`` element (``what``: whose) as rotations (k, 3, 3) and translations
    (k, 3); the identity where there is none."""
    xyz, rpy = _origins(rows, origin, what)
    R = np.empty((len(rows), 3, 3))
    R[:] = np.eye(3)
    for k in np.flatnonzero(np.any(rpy != 0, axis=1)).tolist():
        R[k] = rpy_matrix(rpy[k].tolist())
    return R, xyz


def _inertials(rows: Rows, inertial: Node) -> tuple[np.ndarray, ...]:
    """Each row's ``<inertial>``: masses (k,) kg, centres of mass (k, 3) m, the inertias as
    written (k, 3, 3) kg·m² and the inertial frames' roll, pitch, yaw (k, 3) rad."""
    com, rpy = _origins(rows, inertial.child("origin"), "inertial", "inertial rpy")
    mass, block = inertial.child("mass"), inertial.child("inertia")
    if mass is None:
        raise rows.where(0).error("inertial/mass: missing")
    masses = rows.numbers(mass.at.get("value"), None, 1, "inertial/mass: value")[:, 0]
    if block is None:
        raise rows.where(0).error("inertial/inertia: missing")
    six = {
        key: rows.numbers(block.at.get(key), None, 1, f"inertial/inertia: {key}")[:, 0]
        for key in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
    }
    written = from_six(**six)
    for k in np.flatnonzero(np.any(np.abs(written) >= 1e300, axis=(1, 2))).tolist():
        rows.where(k).check_inertia_range(written[k])  # (a sum of smaller entries cannot overflow)
    return masses, com, written, rpy


def _geoms(rows: Rows, tag: str, packages) -> list[GeomColumn]:
    """The rows' ``tag`` (collision or visual) geoms, one column per element."""
    found = []
    for number, element in enumerate(each for each in rows.top.children if each.tag == tag):
        label = f"{tag}[{number}]"
        R, t = _poses(rows, element.child("origin"), label)
        holder = element.child("geometry")
        if holder is None or not holder.children:
            raise rows.where(0).error(
                f"{label}/geometry: missing (give a box, cylinder, sphere, capsule or mesh)"
            )
        shape = holder.children[0]
        label = f"{label}/geometry/{shape.tag}"
        column = GeomColumn(tag, label, shape.tag, rows.indices, R, t)
        if shape.tag == "mesh":
            column.meshes = _meshes(rows, shape, label, packages)
        else:
            column.sizes = _sizes(rows, shape, label)
        found.append(column)
    return found


def _meshes(rows: Rows, shape: Node, label: str, packages) -> list[tuple]:
    """(file, scale) of each row's mesh."""
    filenames = rows.words(shape.at.get("filename"))
    for k, filename in enumerate(filenames):
        if not filename:
            raise rows.where(k).error(f"{label}: filename: missing")
    scales = rows.numbers(shape.at.get("scale"), b"1 1 1", (1, 3), f"{label}: scale")
    return [
        (resolve_mesh(rows.where(k), filename, label, packages), scales[k].copy())
        for k, filename in enumerate(filenames)
    ]


def _sizes(rows: Rows, shape: Node, label: str) -> np.ndarray:
    """Each row's shape size (k, m) in m; m = 0 for a kind with no volume."""
    fields = SHAPES.get(shape.tag, ()) if shape.tag != "ellipsoid" else ()
    if not fields:
        return np.empty((len(rows), 0))
    default = b"" if shape.tag == "box" else None  # (a box's missing size is 0 numbers, not missing)
    sizes = np.concatenate(
        [rows.numbers(shape.at.get(name), default, count, f"{label}: {name}") for name, count in fields],
        axis=1,
    )
    what = f"{label}: {' and '.join(name for name, _ in fields)}"
    for k in np.flatnonzero(np.any(sizes < 0, axis=1)).tolist():
        rows.where(k).positive(sizes[k].tolist(), what, allow_zero=True)
    return sizes


# --- joints -------------------------------------------------------------------------------------


def _joints(path: str, names: list[str], chunks: list) -> dict:
    """The joints of ``chunks`` (:func:`in_order`) as the :class:`LinkColumns` fields they
    give, each in its child link's row."""
    n = len(names)
    rows_of = {name: row for row, name in enumerate(names)}
    parents, joint_names, kinds, efforts = [-1] * n, [""] * n, [None] * n, [None] * n
    rotations, translations, axes = np.empty((n, 3, 3)), np.zeros((n, 3)), np.zeros((n, 3))
    rotations[:] = np.eye(3)

    def read(rows: Rows) -> None:
        at, found = _joint_links(path, names, rows_of, parents, rows)
        words = rows.words(rows.top.at.get("type"))
        for k, word in enumerate(words):
            if word not in MOVING:
                raise rows.where(k).error(
                    f"type: {short(word)!r} is not a URDF joint type (revolute, continuous, prismatic, "
                    "fixed, floating, planar)"
                )
        motions = [MOVING[word] for word in words]
        rotations[at], translations[at] = _poses(rows, rows.top.child("origin"), "joint")
        axes[at] = _axes(rows, rows.top.child("axis"), motions)
        limit = rows.top.child("limit")
        for row, k, name in zip(at, range(len(rows)), found):
            joint_names[row], kinds[row] = name, motions[k]
        if limit is not None and "effort" in limit.at:
            magnitudes = np.abs(rows.numbers(limit.at["effort"], None, 1, "limit: effort")[:, 0]).tolist()
            for row, effort in zip(at, magnitudes):
                efforts[row] = effort

    in_order(chunks, read, parents)
    rows = [n if parent < 0 else parent for parent in parents]  # a root's parent: n
    order = depth_first(rows, n)
    unique = len({name for name in joint_names if name}) == sum(map(bool, joint_names))
    if not unique or parents.count(-1) != 1 or len(order) != n:  # (one tree: one root, reaching every link)
        _refuse_tree(path, names, rows, order, joint_names)
    return {
        "parents": rows,
        "order": order,
        "rotations": rotations,
        "translations": translations,
        "joint_rows": list(range(n)),
        "joint_names": joint_names,
        "joint_kinds": kinds,
        "axes": axes,
        "anchors": np.zeros((n, 3)),
        "efforts": efforts,
        "references": [0.0] * n,
    }


def _joint_links(path: str, names: list[str], rows_of: dict, parents: list[int], rows: Rows):
    """The rows of the joints' child links (each given its parent in ``parents``) and the
    joints' names; InputError for a joint with no name, no parent or child, or a child that
    has a parent already."""
    top = rows.top
    words = rows.words(top.at.get("name"))
    shown = words if "name" in top.at else [None] * len(rows)
    rows.path = path
    rows.label = lambda k: element_label("joint", rows.indices[k], shown[k])
    parent, child = top.child("parent"), top.child("child")
    ends = [rows.words(None if node is None else node.at.get("link")) for node in (parent, child)]
    found = [[rows_of.get(name, -1) for name in names_of] for names_of in ends]
    for k, (word, above, row) in enumerate(zip(words, *found)):
        if not word or parent is None or child is None or min(above, row) < 0 or parents[row] != -1:
            where = rows.where(k)
            if not word:
                raise where.error("name: missing; every joint needs a name (urdfdom refuses it)")
            if parent is None or child is None:
                raise where.error("needs <parent link=…/> and <child link=…/>")
            for role, link_names in zip(("parent", "child"), ends):
                if link_names[k] not in rows_of:
                    raise where.error(f"{role}: no link named {short(link_names[k])!r}")
            raise where.error(
                f"child: link {short(ends[1][k])!r} is already the child of link "
                f"{short(names[parents[row]])!r}: two joints close a loop, and a URDF's links form a "
                "tree (model a closed chain in SDF or MJCF)"
            )
        parents[row] = above
    at = found[1]
    return at, words


def _axes(rows: Rows, axis: Node | None, motions: list[str]) -> np.ndarray:
    """Each joint's axis (k, 3) in its child link's frame: ``xyz`` as written (default 1 0 0),
    a unit vector for revolute and prismatic joints (worked out once per distinct text)."""
    place = None if axis is None else axis.at.get("xyz")
    values = rows.numbers(place, b"1 0 0", 3, "axis: xyz")
    turned = np.array([motion in UNIT_AXIS_KINDS for motion in motions], dtype=bool)
    if not np.any(turned):
        return values
    texts = rows.distinct(place, b"1 0 0")[1][turned]
    at = np.flatnonzero(turned)
    distinct, firsts = np.unique(texts, return_index=True)  # each text and where it is first
    units = np.empty((int(texts.max()) + 1, 3))
    for d, row in zip(distinct.tolist(), at[firsts].tolist()):  # each text's unit vector worked out once
        units[d] = rows.where(row).unit(values[row], "axis: xyz")
    values[at] = units[texts]
    return values


def _refuse_tree(
    path: str, names: list[str], parents: list[int], order: list[int], joint_names: list[str]
) -> None:
    """InputError for joints that share a name, links no joint joins to the one root, or
    joints that form a loop (``parents``: each link's parent row, n for none; ``order``: the
    rows reached from the roots, :func:`depth_first`)."""
    labels = [element_label("link", row, name) for row, name in enumerate(names)]
    check_unique_joint_names(path, list(zip(labels, joint_names)), "urdfdom")
    roots = [row for row, parent in enumerate(parents) if parent == len(names)]
    if len(roots) > 1:
        shown = ", ".join(repr(short(names[row])) for row in roots[:4]) + (", ..." if len(roots) > 4 else "")
        raise InputError(
            f"{path}: {len(roots)} root links ({shown}): no joint joins them; a URDF has one root "
            "link that every other hangs from (urdfdom and pybullet refuse it)"
        )
    row, at = on_loop(parents, order)
    raise InputError(
        f"{path}: {labels[row]}: the joints form a loop through link {short(names[at])!r}; a "
        "URDF's links form a tree"
    )


def attach_elements(model: RobotModel) -> None:
    """The XML elements of a URDF model (its links are read from columns, which hold none): the
    document parsed if it was not, each link given its ``<link>`` and its inertial its
    ``<inertial>`` (their spans are where ``rbi audit --fix`` edits)."""
    document = model.document
    if model.format != "urdf" or document is None:
        return
    if document.root is None:
        document.root = robot_xml.parse(model.path, document.text)
    columns = model.columns
    columns.elements = document.root.all("link")
    for row, each in columns.records.items():
        columns.records[row] = dataclasses.replace(each, element=columns.elements[row].child("inertial"))
