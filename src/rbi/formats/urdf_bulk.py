"""URDF read in bulk (issue 25: a 100,000-link file in a second or two, not a quarter of a
minute): libxml2 (lxml) builds the tree in C; each ``<link>`` and ``<joint>`` is walked once into
a *signature* (the tags, child counts and attribute names of its elements in document order)
and the list of its attribute values. Elements that share a signature hold their values at the
same places, so each field (an origin's ``xyz``, a mass, a box's ``size``) is a column of
strings, checked and turned into numbers at once.

The careful reader decides every error: :func:`read_urdf_bulk` returns None, and
:func:`rbi.formats.robot_files.read_robot` then reads the file with
:mod:`rbi.formats.robot_xml` and :func:`rbi.formats.urdf.read_urdf`, for anything it is not
certain that reader reads without complaint: an encoding other than UTF-8, a document type
declaration, a namespace, any XML lxml refuses, a link with a mesh, a missing or malformed value,
a number out of range, duplicate names, a joint naming no link, a loop. So every refusal and
every message stays that reader's. The numbers are its too: the same text read by ``float``,
the same functions (:func:`rpy_matrix`, :func:`unit`, :meth:`Inertial.read`) for rotated frames
and axes, and for the rest the same values laid into stacked arrays (each link's arrays are
rows of them).

The links it returns have no XML ``element``: :func:`attach_elements` reads the document the
careful way and attaches them, for ``rbi audit --fix`` (which edits the file at their spans).
"""

from __future__ import annotations

import dataclasses
import re
from typing import Any

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
    check_unique_joint_names,
    check_unique_names,
    rpy_matrix,
    short,
    unit,
)
from rbi.formats.robot_paths import resolve_mesh
from rbi.formats.urdf import MOVING, check_tree

_PLAIN = re.compile(r"[0-9eE+\-. \n]*")
"""The characters of texts of plain decimals apart by spaces, one text a line: with them, a
token ``float`` reads is one :data:`rbi.formats.robot._NUMBER` matches (``float`` alone would
also take ``nan``, ``inf``, ``1_0`` and other digits than 0-9)."""

_DECLARATION = re.compile(
    rb"<\?xml\s+version\s*=\s*([\"'])1\.0\1(?:\s+encoding\s*=\s*([\"'])[A-Za-z0-9._-]+\2)?"
    rb"(?:\s+standalone\s*=\s*([\"'])(?:yes|no)\3)?\s*\?>"
)

_DEFAULT_NAMESPACE = re.compile(rb"xmlns\s*=")
"""A default namespace: lxml would give every tag under it a ``{uri}`` the careful reader does
not (it reads names as written). Prefixed ones are fine: a prefixed name is no URDF name."""

_SHAPES = {
    "box": ("size",),
    "cylinder": ("radius", "length"),
    "capsule": ("radius", "length"),
    "sphere": ("radius",),
}
"""The primitive shapes read here and their attributes (a mesh goes the careful way)."""

_MOVING_UNIT = ("revolute", "prismatic")

_UNPLACED = Pose(np.eye(3), np.zeros(3))
"""A link's origin until a joint places it (the root then gets one of its own)."""


class _Doubt(Exception):
    """Something the bulk reader leaves to the careful one."""


def read_urdf_bulk(path: str, data: bytes, package_paths=None, geometry: bool = True) -> RobotModel | None:
    """The model :func:`rbi.formats.urdf.read_urdf` reads from ``data`` (the file's bytes), or
    None when it is not certain to be the same (see the module's docstring)."""
    try:
        document = robot_xml.decoded(path, data)
    except InputError:
        return None
    if (
        document.encoding != "utf-8"
        or b"<!DOCTYPE" in document.text
        or _DEFAULT_NAMESPACE.search(document.text)
    ):
        return None
    if document.text.startswith(b"<?xml") and _DECLARATION.match(document.text) is None:
        return None
    root = _lxml_root(document.text)
    if root is None or root.tag != "robot":
        return None
    try:
        return _model(document, root, geometry, package_paths)
    except (_Doubt, InputError):
        return None


def _lxml_root(text: bytes):
    """The root element as lxml parses ``text`` with nothing loaded from outside, or None."""
    # not at top level: `rbi validate` on a spec would load lxml too
    from lxml import etree

    parser = etree.XMLParser(
        resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False, collect_ids=False
    )
    try:
        return etree.fromstring(text, parser)
    except Exception:  # any refusal: the careful reader words it
        return None


def _model(document, root, geometry: bool, packages) -> RobotModel:
    links, joints = [], []
    for element in root:
        tag = element.tag
        if tag == "link":
            links.append(element)
        elif tag == "joint":
            joints.append(element)
    if not links:
        raise _Doubt
    model = RobotModel(document.path, "urdf", root.get("name"), document=document)
    model.links = _links(document.path, links, geometry, packages)
    check_unique_names(document.path, model.links, "link")
    _joints(model, joints)
    return model


def _signed(elements) -> dict[tuple, list[tuple[int, list[str]]]]:
    """Signature → [(index, values)] of ``elements``: the signature holds each node's tag (lxml's
    function for a comment), its number of child nodes and its attribute names, in document
    order; the values, its attribute values in the same order."""
    groups: dict[tuple, list[tuple[int, list[str]]]] = {}
    for index, element in enumerate(elements):
        signature: list[Any] = []
        values: list[str] = []
        add, more, take = signature.append, signature.extend, values.extend
        for node in element.iter():
            keys = node.keys()
            add(node.tag)
            add(len(node))
            add(len(keys))
            more(keys)
            take(node.values())
        groups.setdefault(tuple(signature), []).append((index, values))
    return groups


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


def _tree(signature: tuple) -> _Node:
    """The element tree a signature describes."""
    cursor = {"sig": 0, "value": 0}

    def node() -> _Node | None:
        at = cursor["sig"]
        tag, count, keys = signature[at], signature[at + 1], signature[at + 2]
        names = signature[at + 3 : at + 3 + keys]
        cursor["sig"] = at + 3 + keys
        first = cursor["value"]
        cursor["value"] = first + keys
        made = _Node(tag, {name: first + k for k, name in enumerate(names)}) if isinstance(tag, str) else None
        for _ in range(count):
            child = node()
            if child is not None and made is not None:
                made.children.append(child)
        return made

    top = node()
    if top is None or any(":" in name or "{" in name for name in signature if isinstance(name, str)):
        raise _Doubt
    return top


def column(rows: list[list[str]], place: int | None, default: str) -> list[str]:
    """The text at ``place`` of each row (``default`` where the attribute is not written)."""
    if place is None:
        return [default] * len(rows)
    return [row[place] for row in rows]


def _numbers(texts: list[str], count: int) -> np.ndarray:
    """(len(texts), count) floats of texts each of ``count`` plain finite decimals (what
    :func:`rbi.formats.robot.numbers` reads: signs, digits, a point and an exponent, apart by
    spaces), none subnormal; _Doubt otherwise. Each distinct text is read once."""
    if not texts:
        return np.empty((0, count))
    distinct = dict.fromkeys(texts)
    joined = "\n".join(distinct)
    if _PLAIN.fullmatch(joined) is None:
        raise _Doubt
    codes = np.frombuffer(joined.encode("ascii"), dtype=np.uint8)
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
    place = {text: k for k, text in enumerate(distinct)}
    return values[[place[text] for text in texts]]


def _angles(rpy: np.ndarray) -> np.ndarray:
    """``rpy`` (k, 3), _Doubt when :func:`rbi.formats.robot.angles` would refuse one."""
    if np.any(np.abs(rpy) > MAX_ANGLE_RAD):
        raise _Doubt
    return rpy


def _poses(rows: list[list[str]], origin: _Node | None) -> list[Pose]:
    """The poses :func:`rbi.formats.urdf._origin` reads from each row's ``origin`` element."""
    at = {} if origin is None else origin.at
    xyz = _numbers(column(rows, at.get("xyz"), "0 0 0"), 3)
    rpy = _angles(_numbers(column(rows, at.get("rpy"), "0 0 0"), 3))
    turned = np.any(rpy != 0, axis=1).tolist()
    R = np.empty((len(rows), 3, 3))
    R[:] = np.eye(3)
    for k in np.flatnonzero(turned).tolist():
        R[k] = rpy_matrix(rpy[k].tolist())
    return [Pose(R[k], xyz[k]) for k in range(len(rows))]


def _inertials(rows: list[list[str]], inertial: _Node) -> list[Inertial]:
    """The inertials :func:`rbi.formats.urdf._inertial` reads from each row."""
    origin, mass, block = inertial.child("origin"), inertial.child("mass"), inertial.child("inertia")
    if mass is None or block is None or "value" not in mass.at:
        raise _Doubt
    at = {} if origin is None else origin.at
    com = _numbers(column(rows, at.get("xyz"), "0 0 0"), 3)
    rpy = _angles(_numbers(column(rows, at.get("rpy"), "0 0 0"), 3))
    masses = _numbers(column(rows, mass.at["value"], ""), 1)[:, 0].tolist()
    six = []
    for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
        if key not in block.at:
            raise _Doubt
        six.append(_numbers(column(rows, block.at[key], ""), 1)[:, 0])
    ixx, ixy, ixz, iyy, iyz, izz = six
    written = np.stack([ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz], axis=1).reshape(-1, 3, 3)
    if np.any(np.abs(written) >= 1e300):
        raise _Doubt  # check_inertia_range's sum might overflow: the careful reader words it
    in_link = written.copy()
    found = []
    for k, turned in enumerate(np.any(rpy != 0, axis=1).tolist()):
        if turned:
            angles = tuple(rpy[k].tolist())
            found.append(
                Inertial.read(masses[k], com[k].tolist(), written[k], rotation=rpy_matrix(angles), rpy=angles)
            )
        else:
            properties = MassProperties.of_arrays(masses[k], com[k], in_link[k], "link")
            found.append(Inertial(properties, written[k]))
    return found


def _geoms(rows: list[list[str]], top: _Node, tag: str, links: list[tuple], packages) -> list[list[Geom]]:
    """Each row's ``tag`` (collision or visual) geoms as :func:`rbi.formats.urdf._geoms` reads
    them (``links``: each row's (path, link label) for a mesh's lookup)."""
    found: list[list[Geom]] = [[] for _ in rows]
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


def _meshes(rows: list[list[str]], shape: _Node, label: str, links: list[tuple], packages) -> list[tuple]:
    """(file, scale) of each row's mesh, as :func:`rbi.formats.urdf._geom` finds them."""
    if "filename" not in shape.at:
        raise _Doubt
    texts = column(rows, shape.at.get("scale"), "1 1 1")
    try:
        scales = _numbers(texts, 3)
    except _Doubt:
        scales = np.repeat(_numbers(texts, 1), 3, axis=1)
    found = []
    for k, filename in enumerate(column(rows, shape.at["filename"], "")):
        if not filename:
            raise _Doubt
        path, index, name = links[k]
        shown = f"{path}: {Link(index, name).label}: {label}: {short(filename, 1000)}"
        found.append((resolve_mesh(path, filename, shown, packages), scales[k].copy()))
    return found


def _sizes(rows: list[list[str]], shape: _Node) -> list[tuple[float, ...]]:
    """Each row's shape size, as :func:`rbi.formats.urdf._geom` reads it; () for a kind with no
    volume."""
    names = _SHAPES.get(shape.tag, ())
    if any(name not in shape.at for name in names):
        raise _Doubt
    if not names:
        return [()] * len(rows)
    count = 3 if shape.tag == "box" else 1
    parts = [_numbers(column(rows, shape.at[name], ""), count) for name in names]
    sizes = np.concatenate(parts, axis=1)
    if np.any(sizes < 0):
        raise _Doubt
    return [tuple(row) for row in sizes.tolist()]


def _links(path: str, elements, geometry: bool, packages) -> list[Link]:
    """The links of ``elements`` (lxml), in file order."""
    links: list[Link] = [None] * len(elements)  # type: ignore[list-item]
    for signature, group in _signed(elements).items():
        top = _tree(signature)
        if "name" not in top.at:
            raise _Doubt
        rows = [values for _, values in group]
        names = column(rows, top.at["name"], "")
        if not all(names):
            raise _Doubt
        inertial = top.child("inertial")
        inertials = [None] * len(rows) if inertial is None else _inertials(rows, inertial)
        empty: list[list[Geom]] = [[] for _ in rows]
        labels = [(path, index, names[k]) for k, (index, _) in enumerate(group)]
        collisions = _geoms(rows, top, "collision", labels, packages) if geometry else empty
        visuals = _geoms(rows, top, "visual", labels, packages) if geometry else empty
        for k, (index, _) in enumerate(group):
            links[index] = Link(index, names[k], inertials[k], collisions[k], visuals[k], origin=_UNPLACED)
    return links


def _joints(model: RobotModel, elements) -> None:
    """Each joint of ``elements`` (lxml) into its child link, as :func:`rbi.formats.urdf._joints`
    reads it; _Doubt (or its InputError) where that reader would refuse the file."""
    by_name = {link.name: link for link in model.links}
    found: list[tuple] = [()] * len(elements)
    for signature, group in _signed(elements).items():
        top = _tree(signature)
        parent, child = top.child("parent"), top.child("child")
        if "name" not in top.at or parent is None or child is None:
            raise _Doubt
        if "link" not in parent.at or "link" not in child.at:
            raise _Doubt
        rows = [values for _, values in group]
        kinds = [MOVING.get(kind) for kind in column(rows, top.at.get("type"), "")]
        if None in kinds:
            raise _Doubt
        names, parents = column(rows, top.at["name"], ""), column(rows, parent.at["link"], "")
        children = column(rows, child.at["link"], "")
        poses = _poses(rows, top.child("origin"))
        axes = _axes(model.path, rows, top.child("axis"), kinds)
        efforts = _efforts(rows, top.child("limit"))
        for k, (index, _) in enumerate(group):
            found[index] = (names[k], kinds[k], parents[k], children[k], poses[k], axes[k], efforts[k])
    anchors = np.zeros((len(found), 3))
    for k, (name, kind, parent_name, child_name, pose, axis, effort) in enumerate(found):
        link = by_name.get(child_name)
        if not name or parent_name not in by_name or link is None or link.parent is not None:
            raise _Doubt
        link.parent, link.origin = parent_name, pose
        link.motions = [Motion(name, kind, axis, anchors[k], effort_limit=effort)]
    check_unique_joint_names(model, "urdfdom")
    check_tree(model)
    for link in model.links:
        if link.origin is _UNPLACED:
            link.origin = Pose.identity()  # the root's, as the careful reader leaves it


def _axes(path: str, rows: list[list[str]], axis: _Node | None, kinds: list) -> list[np.ndarray]:
    """Each joint's axis as :func:`rbi.formats.urdf._axis` reads it: a unit vector for revolute
    and prismatic joints (worked out once per distinct text, as there), else as written."""
    texts = ["1 0 0"] * len(rows) if axis is None else column(rows, axis.at.get("xyz"), "1 0 0")
    values = _numbers(texts, 3)
    units: dict[str, np.ndarray] = {}
    found = []
    for k, kind in enumerate(kinds):
        if kind not in _MOVING_UNIT:
            found.append(values[k].copy())
            continue
        known = units.get(texts[k])
        if known is None:
            known = units[texts[k]] = unit(Where(path), values[k].tolist(), "axis: xyz")
        found.append(known.copy())
    return found


def _efforts(rows: list[list[str]], limit: _Node | None) -> list[float | None]:
    """Each joint's ``<limit effort>`` as a magnitude, or None where it is not written."""
    if limit is None or "effort" not in limit.at:
        return [None] * len(rows)
    return np.abs(_numbers(column(rows, limit.at["effort"], ""), 1)[:, 0]).tolist()


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
