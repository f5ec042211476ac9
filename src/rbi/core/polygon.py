"""Plane polygons with holes (the outline of ``shape: prism``): the area moments in closed form,
the checks that make an outline a simple polygon with holes inside it, and the trapezoids it is
drawn with.

A polygon is an ``(n, 2)`` array of vertices in order, either winding, its last edge closing back
to the first vertex. Every function takes the outline and a list of holes.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from rbi.core.rotation import numbers, scalar

MAX_VERTICES = 4096
"""Most vertices (outline and holes together) one polygon may have: the crossing check compares
every pair of edges, ~0.2 s at this size."""


def _rings(outline: ArrayLike, holes: list[ArrayLike]) -> list[np.ndarray]:
    return [numbers(r).reshape(-1, 2) for r in [outline, *holes]]


def ring_moments(ring: np.ndarray, origin: np.ndarray) -> np.ndarray:
    """``[A, ∫x, ∫y, ∫x², ∫y², ∫xy]`` over the area a ring encloses, x and y measured from
    ``origin``, positive whatever the winding (Green's theorem, edge by edge)."""
    x0, y0 = (ring - origin).T
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    c = x0 * y1 - x1 * y0
    moments = np.array(
        [
            c.sum() / 2,
            ((x0 + x1) * c).sum() / 6,
            ((y0 + y1) * c).sum() / 6,
            ((x0 * x0 + x0 * x1 + x1 * x1) * c).sum() / 12,
            ((y0 * y0 + y0 * y1 + y1 * y1) * c).sum() / 12,
            ((x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c).sum() / 24,
        ]
    )
    return moments if moments[0].real >= 0 else -moments


def area_moments(outline: ArrayLike, holes: Sequence[ArrayLike] = ()) -> tuple[float, np.ndarray, np.ndarray]:
    """``(area, centroid (2,), J)`` of the outline less its holes: ``J`` the second moments of
    area about the centroid, ``[[∫x'², ∫x'y'], [∫x'y', ∫y'²]]`` (x' = x − x̄)."""
    rings = _rings(outline, list(holes))
    origin = 0.5 * (rings[0].min(axis=0) + rings[0].max(axis=0))  # small offsets: little cancellation
    m = ring_moments(rings[0], origin) - sum((ring_moments(r, origin) for r in rings[1:]), np.zeros(6))
    area = m[0]
    cx, cy = m[1] / area, m[2] / area
    jxx, jyy, jxy = m[3] - area * cx * cx, m[4] - area * cy * cy, m[5] - area * cx * cy
    return scalar(area), origin + [cx, cy], np.array([[jxx, jxy], [jxy, jyy]])


def _edges(rings: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every edge's ends ``a``, ``b`` (E, 2), its ring and its place in the ring."""
    a = np.concatenate(rings)
    b = np.concatenate([np.roll(r, -1, axis=0) for r in rings])
    ring = np.concatenate([np.full(len(r), k) for k, r in enumerate(rings)])
    place = np.concatenate([np.arange(len(r)) for r in rings])
    return a, b, ring, place


def _cross(o: np.ndarray, p: np.ndarray, q: np.ndarray) -> np.ndarray:
    return (p[..., 0] - o[..., 0]) * (q[..., 1] - o[..., 1]) - (p[..., 1] - o[..., 1]) * (
        q[..., 0] - o[..., 0]
    )


NO_AREA = "encloses no area (its vertices are on one line, or too close for a double)"


def _ring_name(k: int) -> str:
    return "outline" if k == 0 else f"holes[{k - 1}]"


def polygon_problem(outline: ArrayLike, holes: Sequence[ArrayLike] = ()) -> str | None:
    """Why the outline and holes are not a simple polygon with holes inside it (``field: what``),
    or None: too many vertices, a vertex repeated, edges that cross or touch, no area, a hole
    outside the outline or inside another hole."""
    rings = _rings(outline, list(holes))
    if sum(len(r) for r in rings) > MAX_VERTICES:
        return f"outline, holes: more than {MAX_VERTICES} vertices together (too many to check and draw)"
    for k, r in enumerate(rings):
        if np.any(np.all(r == np.roll(r, -1, axis=0), axis=1)):
            return f"{_ring_name(k)}: a vertex is repeated (an edge of length 0)"
        if not np.any(_cross(r[0], r[1:-1], r[2:])):  # on one line: its edges overlap, but say why
            return f"{_ring_name(k)}: {NO_AREA}"
    a, b, ring, place = _edges(rings)
    n = len(a)
    sizes = np.bincount(ring)
    for start in range(0, n, 512):  # every pair of edges, a block of rows at a time
        i = np.arange(start, min(n, start + 512))[:, None]
        j = np.arange(n)[None, :]
        p1, p2, q1, q2 = a[i], b[i], a[j], b[j]
        d1, d2 = _cross(p1, p2, q1), _cross(p1, p2, q2)
        d3, d4 = _cross(q1, q2, p1), _cross(q1, q2, p2)
        boxes = np.all(
            (np.minimum(p1, p2) <= np.maximum(q1, q2)) & (np.minimum(q1, q2) <= np.maximum(p1, p2)), axis=-1
        )
        meet = (d1 * d2 <= 0) & (d3 * d4 <= 0) & boxes & (j > i)
        same = ring[i] == ring[j]
        step = (place[j] - place[i]) % sizes[ring[i]]
        next_to = same & ((step == 1) | (step == sizes[ring[i]] - 1))
        # edges meeting at their shared vertex are fine unless they fold back along one line
        folded = next_to & (d1 == 0) & (d2 == 0) & (np.sum((p2 - p1) * (q2 - q1), axis=-1) < 0)
        found = np.argwhere((meet & ~next_to) | folded)
        if len(found):
            e, f = int(i[found[0, 0], 0]), int(found[0, 1])
            if ring[e] == ring[f]:
                return f"{_ring_name(int(ring[e]))}: crosses itself (edges {place[e]} and {place[f]} meet)"
            other = "the outline" if ring[e] == 0 else _ring_name(int(ring[e]))
            return f"{_ring_name(int(ring[f]))}: crosses or touches {other}"
    for k, r in enumerate(rings):
        area, size = ring_moments(r, r[0])[0], np.ptp(r, axis=0).max()
        if not np.isfinite(area * size):
            return (
                f"{_ring_name(k)}: numbers too large: its area overflows (beyond {np.finfo(float).max:.3g})"
            )
        if area <= 1e-12 * size * size:
            return f"{_ring_name(k)}: {NO_AREA}"
    for k, r in enumerate(rings[1:], 1):
        if not inside(r[0], rings[0]):
            return f"{_ring_name(k)}: lies outside the outline"
        within = next((m for m in range(1, len(rings)) if m != k and inside(r[0], rings[m])), None)
        if within is not None:
            return f"{_ring_name(k)}: lies inside {_ring_name(within)} (holes may not overlap)"
    return None


def inside(point: np.ndarray, ring: np.ndarray) -> bool:
    """Whether ``point`` is inside the ring (even-odd rule; not on its edges)."""
    x0, y0 = ring.T
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    spans = (y0 > point[1]) != (y1 > point[1])
    with np.errstate(divide="ignore", invalid="ignore"):
        x = x0 + (point[1] - y0) * (x1 - x0) / (y1 - y0)
    return bool(np.count_nonzero(spans & (x > point[0])) % 2)


def trapezoids(outline: ArrayLike, holes: Sequence[ArrayLike] = ()) -> np.ndarray:
    """The polygon (outline less holes) cut into trapezoids ``(n, 4, 2)`` between the vertical
    lines through its vertices (even-odd rule: exact for a simple polygon with holes)."""
    a, b, _, _ = _edges(_rings(outline, list(holes)))
    xs = np.unique(a[:, 0])
    left, right = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    out: list[list[list[float]]] = []
    for x0, x1 in zip(xs[:-1], xs[1:]):
        k = np.flatnonzero((left <= x0) & (right >= x1) & (left < right))
        slope = (b[k, 1] - a[k, 1]) / (b[k, 0] - a[k, 0])
        y0, y1 = a[k, 1] + slope * (x0 - a[k, 0]), a[k, 1] + slope * (x1 - a[k, 0])
        order = np.argsort(y0 + y1)
        y0, y1 = y0[order].reshape(-1, 2), y1[order].reshape(-1, 2)
        out.extend([[x0, lo0], [x1, lo1], [x1, hi1], [x0, hi0]] for lo0, hi0, lo1, hi1 in zip(*y0.T, *y1.T))
    return np.asarray(out, dtype=np.float64).reshape(-1, 4, 2)
