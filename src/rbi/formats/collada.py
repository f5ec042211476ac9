"""Collada (``.dae``) meshes, the format of most ROS robot descriptions, read as RViz and MoveIt
read robot meshes: every triangle of the document, numbers at double precision, each geometry
placed by the node transforms of the scene that instances it, the file's ``<unit meter>``
applied, its ``<up_axis>`` ignored.

Read: ``<library_geometries>`` with ``<mesh>`` primitives ``<triangles>``, ``<polylist>``
(``<vcount>``), ``<polygons>`` (one ``<p>`` per polygon; ``<ph>`` holes are not cut),
``<trifans>`` and ``<tristrips>``; polygons are split into fans. Positions come from the
``<source>`` the ``VERTEX`` input's ``<vertices>`` names (its ``<float_array>`` and accessor
stride). The scene is ``<scene><instance_visual_scene url>`` (else the first visual scene):
its nodes, nested, with ``<matrix>`` (row-major 4×4), ``<translate>``, ``<rotate>`` (axis and
degrees), ``<scale>``, ``<instance_geometry>`` and ``<instance_node>`` (from
``<library_nodes>``). A document without a scene contributes each geometry once, unmoved.
Lines and points carry no volume and are skipped.

The XML is read by :mod:`rbi.formats.robot_xml` (no entities, no external references, bounded
depth), so a hostile file is refused as any robot file is. Errors are ``ValueError`` naming
what is wrong, never the file's content.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from rbi.core.rotation import axis_angle_matrix
from rbi.errors import InputError
from rbi.formats.robot_xml import read_xml

MAX_INSTANCES = 10_000
"""Most geometry instances placed by one scene (2.5 KB of nodes instancing each other place a
cube 10⁵ times)."""

MAX_NODE_VISITS = 100_000
"""Most nodes one scene is walked through (10 KB of nodes instancing each other 10 times a level
make 10³⁰ visits, without a geometry)."""

MAX_INPUT_OFFSET = 64
"""Largest ``offset`` of a primitive's ``<input>`` (a corner has one index per input)."""


def parse_collada(data: bytes, name: str = "mesh.dae", max_triangles: int = np.iinfo(np.int64).max):
    """(vertices (N, 3), faces (F, 3)) of every triangle the document's scene places, in
    metres (``<unit meter>`` applied), not welded. ``ValueError`` for a malformed document."""

    try:
        root = read_xml(name, data).root
    except InputError as exc:
        raise ValueError(str(exc).split(": ", 1)[-1]) from None
    if root.tag != "COLLADA":
        raise ValueError(f"not a Collada document (the root element is <{root.tag[:40]}>)")
    ids = {element.get("id"): element for element in root.iter() if element.get("id")}
    meter = _unit(root)
    geometries: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    placed: list[tuple[np.ndarray, np.ndarray]] = []
    total = 0
    for geometry_id, transform in _instances(root, ids):
        if geometry_id not in geometries:
            geometries[geometry_id] = _geometry(ids, ids[geometry_id], max_triangles)
        points, triangles = geometries[geometry_id]
        total += len(triangles)
        if total > max_triangles:
            raise ValueError(f"more than {max_triangles:,} triangles")
        if len(triangles):
            placed.append((points @ transform[:3, :3].T + transform[:3, 3], triangles))
    vertices, faces = joined(placed)
    return vertices * meter, faces


def joined(pieces: list[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """One mesh of (vertices, faces) pieces: each piece's faces renumbered past the vertices of
    the pieces before it."""
    if not pieces:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    offsets = np.cumsum([0] + [len(points) for points, _ in pieces[:-1]])
    faces = [triangles + offset for (_, triangles), offset in zip(pieces, offsets)]
    return np.concatenate([points for points, _ in pieces]), np.concatenate(faces)


def _unit(root) -> float:
    asset = root.child("asset")
    unit = asset.child("unit") if asset is not None else None
    if unit is None or unit.get("meter") is None:
        return 1.0
    try:
        meter = float(unit.get("meter"))
    except ValueError:
        raise ValueError("asset/unit: meter is not a number") from None
    if not (math.isfinite(meter) and meter > 0):
        raise ValueError("asset/unit: meter must be a finite number greater than 0")
    return meter


def _numbers(element, kind=float) -> np.ndarray:
    """The element's whitespace-separated numbers, parsed by numpy straight from the text (8
    bytes a number: never a Python object per number, so tens of millions stay small)."""
    text = (element.text or "").strip() if element is not None else ""
    words = "numbers" if kind is float else "integers"
    if not text:
        return np.zeros(0, dtype=np.float64 if kind is float else np.int64)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns, and stops, at the first word it cannot read
        try:
            values = np.fromstring(text, dtype=np.float64, sep=" ")
        except (ValueError, DeprecationWarning, OverflowError):
            raise ValueError(f"<{element.tag}>: not a list of {words}") from None
    if kind is float:
        return values
    if not np.all(np.isfinite(values) & (np.abs(values) < 2.0**53) & (values == np.round(values))):
        raise ValueError(f"<{element.tag}>: not a list of {words} (each below 2**53)")
    return values.astype(np.int64)


def _integer(element, attribute: str, default: int, least: int, most: int) -> int:
    """An integer attribute between ``least`` and ``most``; one line naming it otherwise."""
    text = element.get(attribute, str(default))
    try:
        value = int(text)
    except ValueError:
        value = None
    if value is None or not least <= value <= most:
        raise ValueError(f"<{element.tag}>: {attribute} must be an integer from {least:,} to {most:,}")
    return value


def _reference(ids, url: str | None, what: str):
    if not url or not url.startswith("#") or url[1:] not in ids:
        raise ValueError(f"{what}: {str(url)[:60]!r}: no element with that id in the document")
    return ids[url[1:]]


# --- the scene ----------------------------------------------------------------------------------


def _instances(root, ids):
    """(geometry id, 4×4 transform into the document's frame) for each geometry placed."""
    scenes = root.child("library_visual_scenes")
    chosen = None
    scene = root.child("scene")
    instance = scene.child("instance_visual_scene") if scene is not None else None
    if instance is not None:
        chosen = _reference(ids, instance.get("url"), "scene/instance_visual_scene")
    elif scenes is not None and scenes.child("visual_scene") is not None:
        chosen = scenes.child("visual_scene")
    if chosen is None:
        library = root.child("library_geometries")
        for geometry in library.all("geometry") if library is not None else []:
            if geometry.get("id"):
                yield geometry.get("id"), np.eye(4)
        return
    count = visits = 0
    stack = [(node, np.eye(4), 0) for node in reversed(chosen.all("node"))]
    while stack:
        node, parent, depth = stack.pop()
        if depth > 200:
            raise ValueError("nodes nested (or instanced) deeper than 200 levels")
        visits += 1
        if visits > MAX_NODE_VISITS:
            raise ValueError(f"more than {MAX_NODE_VISITS:,} node visits (nodes that instance each other)")
        transform = parent @ _node_transform(node)
        for child in node.children:
            if child.tag == "instance_geometry":
                count += 1
                if count > MAX_INSTANCES:
                    raise ValueError(f"more than {MAX_INSTANCES:,} geometry instances")
                target = _reference(ids, child.get("url"), "instance_geometry")
                yield target.get("id"), transform
        inner = [child for child in node.children if child.tag == "node"]
        inner += [
            _reference(ids, child.get("url"), "instance_node")
            for child in node.children
            if child.tag == "instance_node"
        ]
        stack.extend((child, transform, depth + 1) for child in reversed(inner))


def _node_transform(node) -> np.ndarray:
    """The node's transforms composed in document order (each applies in the frame the ones
    before it leave)."""
    result = np.eye(4)
    for child in node.children:
        step = None
        if child.tag == "matrix":
            step = _vector(child, 16).reshape(4, 4)
        elif child.tag == "translate":
            step = np.eye(4)
            step[:3, 3] = _vector(child, 3)
        elif child.tag == "scale":
            step = np.diag([*_vector(child, 3), 1.0])
        elif child.tag == "rotate":
            *axis, angle = _vector(child, 4)
            step = np.eye(4)
            if np.all(np.isfinite(axis)) and np.any(axis):  # about no axis: no turn
                step[:3, :3] = axis_angle_matrix(axis, math.radians(angle))
            elif np.any(axis):  # an axis that is not finite: refused below, never echoed
                step[:] = np.nan
        if step is not None:
            result = result @ step
    if not np.all(np.isfinite(result)):
        raise ValueError("a node transform is not finite")
    return result


def _vector(element, count: int) -> np.ndarray:
    values = _numbers(element)
    if values.size != count:
        raise ValueError(f"<{element.tag}>: needs {count} numbers")
    return values


# --- geometry ----------------------------------------------------------------------------------

PRIMITIVES = ("triangles", "polylist", "polygons", "trifans", "tristrips")


def _geometry(ids, geometry, limit: int) -> tuple[np.ndarray, np.ndarray]:
    """(positions, triangles indexing them) of one ``<geometry>``'s mesh."""
    mesh = geometry.child("mesh")
    pieces = []
    for primitive in mesh.children if mesh is not None else []:  # a spline or brep: no mesh
        if primitive.tag not in PRIMITIVES:
            continue
        positions, column, stride = _positions(ids, mesh, primitive)
        triangles = []
        for corners in _polygons(primitive, stride, limit):
            indices = corners[:, column].reshape(-1, 3)
            if indices.size and (indices.min() < 0 or indices.max() >= len(positions)):
                raise ValueError(f"<{primitive.tag}>: a vertex index is out of range")
            triangles.append(indices)
        if triangles:
            pieces.append((positions, np.concatenate(triangles)))
    return joined(pieces)


def _positions(ids, mesh, primitive) -> tuple[np.ndarray, int, int]:
    """(positions (N, 3), the column of the vertex index in each corner, corner stride)."""
    inputs = primitive.all("input")
    if not inputs:
        raise ValueError(f"<{primitive.tag}>: no <input>")
    offsets = [_integer(each, "offset", 0, 0, MAX_INPUT_OFFSET) for each in inputs]
    vertex = next((each for each in inputs if each.get("semantic") == "VERTEX"), None)
    if vertex is None:
        raise ValueError(f"<{primitive.tag}>: no VERTEX input")
    vertices = _reference(ids, vertex.get("source"), "input VERTEX")
    position = next((each for each in vertices.all("input") if each.get("semantic") == "POSITION"), None)
    if position is None:
        raise ValueError("<vertices>: no POSITION input")
    source = _reference(ids, position.get("source"), "input POSITION")
    return _source(source), offsets[inputs.index(vertex)], max(offsets) + 1


def _source(source) -> np.ndarray:
    array = source.child("float_array")
    if array is None:
        raise ValueError("<source>: no <float_array>")
    values = _numbers(array)
    technique = source.child("technique_common")
    accessor = technique.child("accessor") if technique is not None else None
    stride = _integer(accessor, "stride", 3, 3, max(values.size, 3)) if accessor is not None else 3
    offset = _integer(accessor, "offset", 0, 0, values.size) if accessor is not None else 0
    count = (values.size - offset) // stride
    return values[offset : offset + count * stride].reshape(count, stride)[:, :3]


def _polygons(primitive, stride: int, limit: int):
    """Each primitive's corners as triangles: arrays (3·T, stride) of index rows; ValueError as
    soon as the triangles would pass ``limit``, counted before they are made."""
    kind = primitive.tag
    if kind in ("triangles", "polylist"):
        corners = _corners(primitive.child("p"), stride, limit)
        if kind == "triangles":
            usable = len(corners) - len(corners) % 3
            yield corners[:usable]
            return
        counts = _numbers(primitive.child("vcount"), int) if primitive.child("vcount") is not None else None
        if (
            counts is None
            or np.any(counts < 0)
            or np.any(counts > len(corners))
            or counts.sum() != len(corners)
        ):
            raise ValueError("<polylist>: <vcount> does not match the indices in <p>")
        if int(np.maximum(counts - 2, 0).sum()) > limit:
            raise ValueError(f"more than {limit:,} triangles")
        yield from _fans(corners, counts)
        return
    for p in primitive.all("p"):
        corners = _corners(p, stride, limit)
        if kind == "tristrips":
            order = np.arange(max(len(corners) - 2, 0))
            flip = order % 2  # every other triangle of a strip runs the other way round
            yield corners[np.stack([order + flip, order + 1 - flip, order + 2], axis=1).ravel()]
        else:
            yield from _fans(corners, np.array([len(corners)]))


def _corners(p, stride: int, limit: int) -> np.ndarray:
    if p is None:
        return np.zeros((0, stride), dtype=np.int64)
    values = _numbers(p, int)
    if values.size // stride > 3 * limit:
        raise ValueError(f"more than {limit:,} triangles")
    usable = values.size - values.size % stride
    return values[:usable].reshape(-1, stride)


def _fans(corners: np.ndarray, counts: np.ndarray):
    """Polygons of ``counts`` corners each, split into triangle fans from their first corner."""
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    big = counts >= 3
    starts, counts = starts[big], counts[big]
    if not len(counts):
        return
    triangles = counts - 2
    first = np.repeat(starts, triangles)
    step = np.arange(int(triangles.sum())) - np.repeat(np.cumsum(triangles) - triangles, triangles)
    order = np.stack([first, first + step + 1, first + step + 2], axis=1).ravel()
    yield corners[order]
