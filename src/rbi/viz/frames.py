"""The animation page's view drawn with matplotlib, frame by frame, and written as a GIF (pillow).

Same world as :mod:`rbi.viz.motion`: z up, the pivot (or a free body's centre of mass) at the
origin; the camera looks from the same direction as the page's. matplotlib and pillow are
imported inside the functions (the ``plot`` extra).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.core.rotation import quaternion_to_matrix
from rbi.viz.labels import label, plain, pyplot
from rbi.viz.solids import MAX_POINT_SPHERES, part_quads, segments_for, shade

PALETTE = (
    "#3f7fbf #d08a2a #4f9f5f #9a5fb0 #6b8e23 #2aa0a0 #8c7b4f #5a6b8c #c9a227 #d46fa8 #a0522d #7fb8e0"
).split()
"""Colours of solid parts, by the part's index in the spec (:func:`part_colour`): twelve, so a
body of up to twelve parts has no two parts of one colour. The HTML page draws with this list
too (``palette`` in :func:`rbi.viz.motion.page_data`), and the legends name parts in it."""
AXIS_COLOURS = ["#d62728", "#2ca02c", "#1f77b4"]
"""Colours of the principal axes of the smallest, middle and largest moment (``rbi show``, and the
angle panel of a free body's ``simulate --plot``)."""
HOLE_RGBA = (0.88, 0.19, 0.19, 0.35)
POINT_RGBA = (0.2, 0.2, 0.2, 1.0)
VIEW_ELEVATION_DEG = 24.0
VIEW_AZIMUTH_DEG = -48.0
GIF_PIXELS = 400
GIF_COLOURS = 64
GIF_OPTIONS = {"format": "GIF", "save_all": True, "loop": 0, "optimize": True, "disposal": 1}
"""How a GIF is written (pillow's options): every frame, looping forever, each frame drawn over the last."""
MAX_TITLE_CHARS = 60
"""Longest title drawn on a GIF frame (its name part is cut to :data:`rbi.viz.labels.MAX_LABEL_CHARS`)."""
MAX_GIF_FRAMES = 1500
"""Most frames a GIF may have (a minute at 25 frames per second, some tens of MB)."""


def part_colour(part: int) -> str:
    """The colour (``#rrggbb``) a solid part is drawn with, from its index in the spec."""
    return PALETTE[part % len(PALETTE)]


def body_mesh(
    parts: list[dict[str, Any]], size: float, holes: bool = True, stripes: bool = True
) -> tuple[np.ndarray, np.ndarray]:
    """The parts as quads ``(n, 4, 3)`` with an RGBA colour each (stripes darker; holes red and
    translucent, or left out when ``holes`` is false; point masses dark grey, or dots of
    :func:`cloud_points` when there are many); thousands of round solids get fewer facets each
    (:func:`rbi.viz.solids.segments_for`)."""
    from matplotlib.colors import to_rgba  # optional extra `plot`, loaded only to draw

    dots = _points_as_dots(parts)
    drawn = [
        (i, p) for i, p in enumerate(parts) if (holes or not p.get("hole")) and not (dots and _is_point(p))
    ]
    segments = segments_for([item["kind"] for _, item in drawn])
    all_quads, all_colours = [], []
    for index, item in drawn:
        quads, banded = part_quads(item, size, segments)
        solid = not item.get("hole") and not _is_point(item)
        rgba = HOLE_RGBA if item.get("hole") else POINT_RGBA
        if solid:
            rgba = to_rgba(part_colour(item.get("part", index)), 0.55 if item.get("stand_in") else 1.0)
        colours = np.tile(rgba, (len(quads), 1))
        if solid and stripes:
            colours[banded, :3] *= 0.62
        all_quads.append(quads)
        all_colours.append(colours)
    if not all_quads:
        return np.zeros((0, 4, 3)), np.zeros((0, 4))
    return np.concatenate(all_quads), np.concatenate(all_colours)


def _is_point(item: dict[str, Any]) -> bool:
    return item["kind"] == "point"


def _points_as_dots(parts: list[dict[str, Any]]) -> bool:
    """Whether the point masses are drawn as dots: more than :data:`MAX_POINT_SPHERES` of them."""
    return sum(map(_is_point, parts)) > MAX_POINT_SPHERES


def cloud_points(parts: list[dict[str, Any]]) -> np.ndarray:
    """Every point drawn as a dot, ``(n, 3)``: the points of point clouds, and the point masses
    when there are too many to draw as spheres (:func:`body_mesh`)."""
    dots = _points_as_dots(parts)
    clouds = [
        np.asarray(item["positions" if item["kind"] == "points" else "position"], dtype=float).reshape(-1, 3)
        for item in parts
        if item["kind"] == "points" or (dots and _is_point(item))
    ]
    return np.concatenate(clouds) if clouds else np.zeros((0, 3))


def _scene_axes(fig, data: dict[str, Any]):
    """3D axes framed on the heights the body reaches, ground disc (just below the lowest point
    the body reaches, see :func:`rbi.viz.motion.height_range`) and pivot drawn for a top, axes
    hidden."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # optional extra `plot`, loaded only to draw

    size = float(data["size"])
    ax = fig.add_axes((0.0, 0.0, 1.0, 0.9), projection="3d")
    ax.computed_zorder = False
    ax.view_init(elev=VIEW_ELEVATION_DEG, azim=VIEW_AZIMUTH_DEG)
    reach = 1.05 * size
    high = (data.get("height_range") or (-size, size))[1]
    if data["pivoted"]:
        ground = float(data.get("ground_z") or 0.0) - 0.002 * size
        z_low, z_high = ground - 0.05 * size, max(high, 0.0) + 0.1 * size
        angles = np.linspace(0, 2 * np.pi, 97)
        disc = np.column_stack(
            (1.2 * size * np.cos(angles), 1.2 * size * np.sin(angles), np.full_like(angles, ground))
        )
        ax.add_collection3d(
            Poly3DCollection([disc], facecolors=(0.85, 0.86, 0.89, 1.0), edgecolors="none", zorder=0)
        )
        ax.scatter([0], [0], [0], color="black", s=14, zorder=3)
    else:
        z_low, z_high = -reach, reach
    ax.set(xlim=(-reach, reach), ylim=(-reach, reach), zlim=(z_low, z_high))
    ax.set_box_aspect((2 * reach, 2 * reach, z_high - z_low))
    ax.set_axis_off()
    return ax


def frame_indices(times, fps: float) -> np.ndarray:
    """Indices of the samples nearest to the frame times 0, 1/fps, 2/fps, … (real time)."""
    times = np.asarray(times, dtype=float)
    wanted = np.arange(0.0, times[-1] + 0.5 / fps, 1.0 / fps)
    return np.unique(np.clip(np.searchsorted(times, wanted - 1e-12), 0, times.size - 1))


def render_frames(data: dict[str, Any], indices, pixels: int = GIF_PIXELS):
    """Yield one RGB image (``(pixels, pixels, 3)`` uint8 array) per sample index in ``indices``;
    the trace of the axis tip is drawn through every sample of the last ``data['trail_seconds']``."""
    plt = pyplot()
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # optional extra `plot`, loaded only to draw

    size = float(data["size"])
    quads, colours = body_mesh(data["parts"], size)
    points = cloud_points(data["parts"])
    trace = np.asarray(data["trace"], dtype=float)
    dpi = 100
    fig = plt.figure(figsize=(pixels / dpi, pixels / dpi), dpi=dpi)
    try:
        ax = _scene_axes(fig, data)

        title = label(data.get("title", ""), MAX_TITLE_CHARS)
        plain(fig.text(0.02, 0.965, title, fontsize=8.5, weight="bold", va="top"))
        readout = fig.text(0.02, 0.915, "", fontsize=8, va="top", family="monospace")
        for index in indices:
            t = data["times"][index]
            rotation = quaternion_to_matrix(np.roll(data["quaternions"][index], 1))  # from [x, y, z, w]
            faces = quads @ rotation.T
            body = Poly3DCollection(faces, facecolors=shade(faces, colours), edgecolors="none", zorder=2)
            ax.add_collection3d(body)
            turned = points @ rotation.T
            dots = ax.scatter(*turned.T, s=4, color="#333333", depthshade=False, zorder=2)
            first = int(np.searchsorted(data["times"], t - data["trail_seconds"]))
            recent = trace[first : index + 1]
            (path,) = ax.plot(recent[:, 0], recent[:, 1], recent[:, 2], color="#c03030", lw=0.9, zorder=1)
            readout.set_text(
                f"t = {t:6.3f} s   tilt = {data['tilt_deg'][index]:6.2f}°   "
                f"|ω| = {data['omega'][index]:.2f} rad/s"
            )
            fig.canvas.draw()
            yield np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()
            body.remove()
            path.remove()
            dots.remove()
    finally:
        plt.close(fig)


def write_gif(data: dict[str, Any], path: str, fps: int = 25, progress=None) -> None:
    """A looping GIF that plays ``data`` in real time at ``fps`` frames per second.
    ``progress(done, total)``, if given, is called after each frame is drawn."""
    from PIL import Image  # ships with matplotlib (extra `plot`), loaded only to write a GIF

    indices = frame_indices(data["times"], fps)
    images = []
    for frame in render_frames(data, indices):
        images.append(Image.fromarray(frame).quantize(colors=GIF_COLOURS, method=Image.Quantize.MEDIANCUT))
        if progress is not None:
            progress(len(images), len(indices))
    images[0].save(path, append_images=images[1:], duration=round(1000 / fps), **GIF_OPTIONS)
