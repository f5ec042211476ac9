"""The drawable primitives of :mod:`rbi.spec.geometry` as flat quadrilaterals, for the matplotlib
pictures (``rbi animate --out F.gif``, ``rbi show --out F.png``).

Every solid becomes an array of quads ``(n, 4, 3)`` in the coordinates of its primitive (body
frame, file length unit) and, for each quad, a stripe flag (alternate bands around the part's
axis, so a turn about that axis can be seen). Nothing here draws; numpy only.
"""

from __future__ import annotations

from collections import Counter
from itertools import product
from typing import Any

import numpy as np

from rbi.core.rotation import unit_vector

SEGMENTS = 32
"""Facets around a round solid (even, so stripes alternate all the way round)."""
STRIPES = 8
POINT_RADIUS_FRACTION = 0.035
"""Radius of the small sphere drawn for a point mass, as a fraction of the body's size."""
QUAD_BUDGET = 100_000
"""Most quads a picture of the round solids may take: a body of thousands of parts is drawn with
fewer facets each (at least 4 around), so a picture stays some MB and some seconds (512 quads a
sphere made a 117 MB SVG of 1000 point masses)."""
MAX_POINT_SPHERES = 64
"""Point masses beyond this many are drawn as dots (one marker each) rather than as spheres."""


def _perpendiculars(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = unit_vector(np.cross(axis, helper))
    return u, np.cross(axis, u)


def _grid_quads(points: np.ndarray) -> np.ndarray:
    """Quads of a grid of points ``(rows, columns, 3)``."""
    return np.stack((points[:-1, :-1], points[:-1, 1:], points[1:, 1:], points[1:, :-1]), axis=2).reshape(
        -1, 4, 3
    )


def _stripe_flags(rows: int, columns: int) -> np.ndarray:
    band = (np.arange(columns) * STRIPES // columns) % 2 == 1
    return np.tile(band, rows)


def frustum_quads(
    start, end, start_radius: float, end_radius: float, inner_radius: float = 0.0, segments: int = SEGMENTS
):
    """Side, end caps (annuli when ``inner_radius`` > 0) and inner wall of a frustum, ``segments``
    facets around."""
    a, b = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    axis = unit_vector(b - a) if np.any(b != a) else np.array([0.0, 0.0, 1.0])
    u, v = _perpendiculars(axis)
    angles = np.linspace(0.0, 2 * np.pi, segments + 1)
    ring = np.cos(angles)[:, None] * u + np.sin(angles)[:, None] * v  # (S+1, 3)

    def surface(r0, p0, r1, p1):
        points = np.stack((p0 + r0 * ring, p1 + r1 * ring))
        return _grid_quads(points), _stripe_flags(1, segments)

    pieces = [
        surface(start_radius, a, end_radius, b),
        surface(inner_radius, a, start_radius, a),
        surface(end_radius, b, inner_radius, b),
    ]
    if inner_radius > 0:
        pieces.append(surface(inner_radius, b, inner_radius, a))
    return _join(pieces)


def ellipsoid_quads(center, semi_axes, rotation, segments: int = SEGMENTS):
    """A latitude-longitude mesh of the ellipsoid (stripes around the part's z axis)."""
    rows = segments // 2
    polar = np.linspace(0.0, np.pi, rows + 1)[:, None]
    azimuth = np.linspace(0.0, 2 * np.pi, segments + 1)[None, :]
    sine, cosine = np.sin(polar), np.cos(polar)
    unit = np.stack((sine * np.cos(azimuth), sine * np.sin(azimuth), cosine * np.ones_like(azimuth)), axis=-1)
    local = unit * np.asarray(semi_axes, dtype=float)
    points = local @ np.asarray(rotation, dtype=float).T + np.asarray(center, dtype=float)
    return _grid_quads(points), _stripe_flags(rows, segments)


def box_quads(center, size, rotation):
    """The six faces of a box (no stripes)."""
    half = 0.5 * np.asarray(size, dtype=float)
    corners = np.array(list(product((-1, 1), repeat=3)), dtype=float) * half  # x slowest, z fastest
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    quads = corners[np.array(faces)] @ np.asarray(rotation, dtype=float).T + np.asarray(center, dtype=float)
    return quads, np.zeros(6, dtype=bool)


def torus_quads(center, axis, major_radius: float, minor_radius: float, segments: int = SEGMENTS):
    """A ring mesh; stripes around the ring's axis."""
    axis = unit_vector(axis)
    u, v = _perpendiculars(axis)
    around = np.linspace(0.0, 2 * np.pi, segments + 1)[None, :]
    tube = np.linspace(0.0, 2 * np.pi, segments // 2 + 1)[:, None]
    radial = np.cos(around)[..., None] * u + np.sin(around)[..., None] * v  # (1, S+1, 3)
    points = (
        np.asarray(center, dtype=float)
        + (major_radius + minor_radius * np.cos(tube))[..., None] * radial
        + (minor_radius * np.sin(tube))[..., None] * axis
    )
    return _grid_quads(points), _stripe_flags(segments // 2, segments)


def hemisphere_quads(center, axis, radius: float, segments: int = SEGMENTS):
    """Dome and flat face; stripes around the axis."""
    axis = unit_vector(axis)
    u, v = _perpendiculars(axis)
    rows = max(1, segments // 4)
    polar = np.linspace(0.0, np.pi / 2, rows + 1)[:, None]
    azimuth = np.linspace(0.0, 2 * np.pi, segments + 1)[None, :]
    points = np.asarray(center, dtype=float) + radius * (
        (np.sin(polar) * np.cos(azimuth))[..., None] * u
        + (np.sin(polar) * np.sin(azimuth))[..., None] * v
        + np.cos(polar)[..., None] * axis
    )
    dome = (_grid_quads(points), _stripe_flags(rows, segments))
    ring = np.cos(azimuth[0])[:, None] * u + np.sin(azimuth[0])[:, None] * v
    centre = np.asarray(center, dtype=float)
    face = (_grid_quads(np.stack((centre + 0.0 * ring, centre + radius * ring))), _stripe_flags(1, segments))
    return _join([dome, face])


def capsule_quads(start, end, radius: float, segments: int = SEGMENTS):
    """Cylinder from ``start`` to ``end`` with a hemispherical cap on each end."""
    a, b = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    side = frustum_quads(a, b, radius, radius, segments=segments)
    caps = [hemisphere_quads(b, b - a, radius, segments), hemisphere_quads(a, a - b, radius, segments)]
    return _join([side, *caps])


def mesh_quads(vertices, faces):
    """Triangles as quads with the last corner repeated; no stripes."""
    triangles = np.asarray(vertices, dtype=float)[np.asarray(faces, dtype=int)]
    return np.concatenate((triangles, triangles[:, 2:3]), axis=1), np.zeros(len(triangles), dtype=bool)


def _join(pieces):
    return np.concatenate([p[0] for p in pieces]), np.concatenate([p[1] for p in pieces])


def _round_quads(kind: str, segments: int) -> int:
    """How many quads a round solid of ``kind`` takes at ``segments`` facets around."""
    ring = segments // 4 * segments + segments  # a dome and its flat face
    return {
        "frustum": 4 * segments,
        "ellipsoid": segments * segments // 2,
        "point": segments * segments // 2,
        "torus": segments * segments // 2,
        "hemisphere": ring,
        "capsule": 3 * segments + 2 * ring,
    }.get(kind, 0)


def segments_for(kinds: list[str]) -> int:
    """Facets around each round solid of a picture of parts of these ``kinds``: the most (even,
    at most :data:`SEGMENTS`, at least 4) that keeps them within :data:`QUAD_BUDGET` quads."""
    counts = Counter(kinds)
    for segments in range(SEGMENTS, 4, -2):
        if sum(n * _round_quads(kind, segments) for kind, n in counts.items()) <= QUAD_BUDGET:
            return segments
    return 4


ROUND_SOLIDS = {
    "frustum": (frustum_quads, ("start", "end", "start_radius", "end_radius", "inner_radius")),
    "ellipsoid": (ellipsoid_quads, ("center", "semi_axes", "rotation")),
    "torus": (torus_quads, ("center", "axis", "major_radius", "minor_radius")),
    "hemisphere": (hemisphere_quads, ("center", "axis", "radius")),
    "capsule": (capsule_quads, ("start", "end", "radius")),
}
"""Each round solid's quads function and the fields of its item it takes, in order (a frustum
without ``inner_radius`` is solid)."""


def part_quads(item: dict[str, Any], size: float, segments: int = SEGMENTS) -> tuple[np.ndarray, np.ndarray]:
    """Quads and stripe flags of one primitive; ``size``: the body's size (for point masses);
    ``segments``: facets around a round solid."""
    kind = item["kind"]
    if kind in ROUND_SOLIDS:
        build, fields = ROUND_SOLIDS[kind]
        return build(*(item[field] for field in fields if field in item), segments=segments)
    if kind == "mesh":
        return mesh_quads(item["vertices"], item["faces"])
    if kind == "points":  # drawn as dots, not as surfaces
        return np.zeros((0, 4, 3)), np.zeros(0, dtype=bool)
    if kind == "box":
        floor = 1e-3 * size
        return box_quads(
            item["center"], np.maximum(np.asarray(item["size"], dtype=float), floor), item["rotation"]
        )
    radius = POINT_RADIUS_FRACTION * size
    return ellipsoid_quads(item["position"], [radius] * 3, np.eye(3), segments)


def shade(quads: np.ndarray, colors: np.ndarray, light=(0.35, -0.45, 0.82)) -> np.ndarray:
    """RGBA colours lit by a distant light (Lambert, two-sided, with an ambient floor)."""
    normals = np.cross(quads[:, 2] - quads[:, 0], quads[:, 3] - quads[:, 1])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, lengths, out=np.zeros_like(normals), where=lengths > 0)
    direction = np.asarray(light, dtype=float) / np.linalg.norm(light)
    intensity = 0.55 + 0.45 * np.abs(normals @ direction)
    out = np.array(colors, dtype=float, copy=True)
    out[:, :3] *= intensity[:, None]
    return out
