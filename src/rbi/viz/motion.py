"""The data an animation plays: the parts placed about the point the body turns about, the
orientation keyframes, and the path of the tip of the body's spin axis.

World axes: z up (gravity along −z); the pivot of a top (or the centre of mass of a free body)
at the origin. Quaternions are given in three.js order ``[x, y, z, w]``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike
from scipy.spatial import ConvexHull, QhullError

from rbi.core.rotation import rotate, up_in_body
from rbi.spec.geometry import moved
from rbi.viz.frames import PALETTE
from rbi.viz.solids import part_quads, segments_for

MAX_TURN_PER_KEYFRAME = 0.5
"""Largest turn (rad) between two keyframes, so that slerp between them follows the motion."""

TRAIL_SECONDS = 0.5
"""How far back the drawn path of the axis tip reaches (the whole path would hide the body)."""

MIN_KEYFRAMES = 481
MAX_KEYFRAMES = 40_000


def keyframes_needed(duration: float, fastest_rate: float) -> int:
    """Samples needed so that no keyframe interval turns the body more than
    :data:`MAX_TURN_PER_KEYFRAME` (``fastest_rate``: the largest |ω|, rad/s)."""
    if duration <= 0:
        return 1
    return int(math.ceil(duration * max(fastest_rate, 0.0) / MAX_TURN_PER_KEYFRAME)) + 1


def animation_data(
    title: str,
    geometry: list[dict[str, Any]],
    scene,
    t: np.ndarray,
    q: np.ndarray,
    omega: np.ndarray,
    tilt_deg: np.ndarray,
    length_unit: str,
) -> dict[str, Any]:
    """Everything the page needs, as JSON-ready lists. ``geometry``: from
    :func:`rbi.spec.geometry.part_geometry` (body frame); ``q`` (N, 4) [w, x, y, z] body → world;
    ``omega`` (N, 3) body frame, rad/s."""

    origin = np.asarray(scene.pivot if scene.pivoted else scene.com, dtype=float)
    parts = [shifted(item, origin) for item in geometry]
    size = body_size(parts)
    tip = np.asarray(scene.spin_axis, dtype=float) * size  # the axis the run reports the tilt of
    low, high = height_range(parts, size, q)
    com = np.asarray(scene.com, dtype=float) - origin
    speeds = np.linalg.norm(omega, axis=1)
    return page_data(title, length_unit, parts, size, com, rotate(q, tip), t, q, tilt_deg, speeds) | {
        "pivoted": bool(scene.pivoted),
        "axis_tip": tip.tolist(),
        "trail_seconds": TRAIL_SECONDS,
        # the ground (a top only) just below the lowest point the body reaches: a hanging
        # pendulum hangs above it, a top stands on it at its pivot
        "ground_z": min(0.0, low) if scene.pivoted else None,
        "height_range": [low, high],
    }


def page_data(
    title: str,
    length_unit: str,
    parts: list[dict[str, Any]],
    size: float,
    com: ArrayLike,
    trace: ArrayLike,
    t: ArrayLike = (0.0,),
    q: ArrayLike = ((1.0, 0.0, 0.0, 0.0),),
    tilt_deg: ArrayLike = (0.0,),
    omega: ArrayLike = (0.0,),
) -> dict[str, Any]:
    """What every page (:func:`rbi.viz.page.html_page`) draws, JSON-ready: at each time ``t`` (s)
    the turn ``q`` ((N, 4) [w, x, y, z] body → world; the page's order is [x, y, z, w]), tilt
    (deg), |ω| (rad/s) and axis tip (``trace``, (N, 3)); by default one unturned time (a still)."""
    return {
        "title": title,
        "length_unit": length_unit,
        "pivoted": False,
        "size": size,
        "parts": parts,
        "com": np.asarray(com, dtype=float).tolist(),
        "axis_tip": None,
        "times": np.asarray(t, dtype=float).tolist(),
        "quaternions": np.asarray(q, dtype=float)[:, [1, 2, 3, 0]].tolist(),
        "tilt_deg": np.asarray(tilt_deg, dtype=float).tolist(),
        "omega": np.asarray(omega, dtype=float).tolist(),
        "trace": np.asarray(trace, dtype=float).tolist(),
        "trail_seconds": 0.0,
        "palette": PALETTE,  # the page draws each solid part in the colour the PNG and legend give it
    }


def drawn_points(parts: list[dict[str, Any]], size: float) -> np.ndarray:
    """Every corner of the drawn solids (a point mass drawn as its small sphere) and every cloud
    point, ``(n, 3)``, reduced to the corners of their convex hull (the extreme heights of a
    turned body are there). Holes add nothing: they lie inside their solid. Thousands of round
    solids are taken with the facets a picture draws them with (:func:`segments_for`)."""

    pieces = [np.zeros((1, 3))]
    segments = segments_for([item["kind"] for item in parts if not item.get("hole")])
    for item in parts:
        if item["kind"] == "points":
            pieces.append(np.asarray(item["positions"], dtype=float).reshape(-1, 3))
        elif not item.get("hole"):
            quads, _ = part_quads(item, size, segments)
            pieces.append(quads.reshape(-1, 3))
    points = np.unique(np.concatenate(pieces), axis=0)
    if len(points) > 64:
        try:
            points = points[ConvexHull(points).vertices]
        except (QhullError, ValueError):  # flat or degenerate: every point stays
            pass
    return points


def height_range(parts: list[dict[str, Any]], size: float, q: np.ndarray) -> tuple[float, float]:
    """Lowest and highest world z any drawn point of the body reaches over the motion ``q``
    ((N, 4), [w, x, y, z] body → world; parts placed about the origin the body turns about)."""
    points = drawn_points(parts, size)
    heights_of_axes = up_in_body(q)  # a body point's world height is its dot product with this
    low, high = np.inf, -np.inf
    chunk = max(1, 2_000_000 // len(points))  # bounded memory for long runs of large meshes
    for start in range(0, len(heights_of_axes), chunk):
        heights = points @ heights_of_axes[start : start + chunk].T
        low, high = min(low, float(heights.min())), max(high, float(heights.max()))
    return low, high


def shifted(item: dict[str, Any], origin: np.ndarray) -> dict[str, Any]:

    return moved(item, np.eye(3), -np.asarray(origin, dtype=float))


def body_size(parts: list[dict[str, Any]]) -> float:
    """A length the scene is drawn at: the farthest reach of any part from the origin."""

    reach = 0.0
    for item in parts:
        if item["kind"] == "point":
            reach = max(reach, float(np.linalg.norm(item["position"])))
        elif item["kind"] == "points":
            reach = max(reach, float(np.max(np.linalg.norm(item["positions"], axis=1), initial=0.0)))
        else:
            quads, _ = part_quads(item, 0.0)
            if len(quads):
                reach = max(reach, float(np.max(np.linalg.norm(quads.reshape(-1, 3), axis=1))))
    return float(reach) if reach > 0 else 1.0
