"""``rbi show``: a picture of the body as specified — every part in place (holes red and
translucent), the centre of mass, the principal axes about it drawn with lengths in proportion
to their moments, and the pivot.

:func:`view_data` gathers what to draw in the spec's own coordinates (body frame, file units,
the spec's origin: the ticks read as the YAML does); :func:`draw_still` draws it with
matplotlib (PNG, SVG); the HTML form is the animation page with a single time
(:func:`rbi.viz.page.html_page`), with the same legend of parts (:func:`part_legend`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.files.output import write_output
from rbi.spec.geometry import part_geometry
from rbi.viz.frames import AXIS_COLOURS, HOLE_RGBA, body_mesh, cloud_points, part_colour
from rbi.viz.labels import label, plain, plain_legend, pyplot
from rbi.viz.motion import body_size, drawn_points, page_data, shifted
from rbi.viz.page import html_page
from rbi.viz.solids import shade

AXIS_NAME_BOX = {"boxstyle": "round,pad=0.15", "facecolor": "white", "edgecolor": "none", "alpha": 0.8}
"""The white box behind the name of a principal axis (I1, I2, I3) at its tip."""
MAX_LEGEND_PARTS = 14
STILL_SUBTITLE = (
    "body axes and coordinates as in the spec; principal axes about the centre of mass, lengths in "
    "proportion to their moments"
)
"""The line under a still's title."""
LONGEST_AXIS_FRACTION = 0.75
"""Half-length of the axis of the largest moment, as a fraction of the body's reach from its
centre of mass."""


def view_data(title: str, body: Any) -> dict[str, Any]:
    """What :func:`draw_still` and the page draw of a loaded ``body`` (its parts from
    :func:`rbi.spec.geometry.part_geometry`, centre of mass, inertia about it and pivot),
    JSON-ready. Every coordinate is the spec's own (body frame, file units, not shifted or
    turned), so a picture's ticks match the YAML; ``size``, the scale the page's camera and
    markers are set by, is the body's reach from the pivot (or, without one, from the centre of
    mass); ``axes_length`` the length of the drawn x, y, z axes from the spec's origin."""

    geometry, pivot, inertia_unit = part_geometry(body), body.pivot, body.labels["inertia"]
    com = np.asarray(body.props.center_of_mass, dtype=float)
    parts = [dict(item) for item in geometry]
    centre = com if pivot is None else np.asarray(pivot, dtype=float)
    size = body_size(
        [shifted(item, centre) for item in geometry]
        + [{"kind": "point", "position": (com - centre).tolist()}]
    )
    moments, axes = principal_axes(np.asarray(body.props.inertia_about_com, dtype=float))
    largest = float(np.max(np.abs(moments))) or 1.0
    reach_from_com = body_size([shifted(item, com) for item in geometry])
    axes_length = 1.15 * float(np.max(np.abs(drawn_points(parts, size)))) or size
    principal = [
        {
            "moment": float(m),
            "direction": axis.tolist(),
            "half_length": LONGEST_AXIS_FRACTION * reach_from_com * max(abs(float(m)) / largest, 0.08),
            "label": f"I{k + 1} = {float(m):.4g} {inertia_unit}",
            "colour": AXIS_COLOURS[k],
        }
        for k, (m, axis) in enumerate(zip(moments, axes))
    ]
    return page_data(label(title), body.length_unit, parts, size, com, trace=[com]) | {
        "view_center": com.tolist(),
        "pivot": None if pivot is None else np.asarray(pivot, dtype=float).tolist(),
        "principal_axes": principal,
        "spec_axes": axes_length,
        "part_legend": part_legend(parts),
    }


def part_legend(parts: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """One entry per written part, in spec order: ``name`` (as a label: escaped, cut),
    ``shape``, ``colour`` (as drawn), ``copies`` (a pattern), ``hole``, ``stand_in`` (a custom
    part drawn as the box of equal inertia). The copies of a pattern are one entry."""

    entries: dict[int, dict[str, Any]] = {}
    for index, item in enumerate(parts):
        part = item.get("part", index)
        if part in entries:  # a sub-assembly's parts are one copy
            seen = entries[part]["copies"]
            entries[part]["copies"] = max(seen, item.get("copy", seen) + 1)
            continue
        colour = "#333333" if item["kind"] in ("point", "points") else part_colour(part)
        entries[part] = {
            "name": label(item.get("name") or f"parts[{part}]"),
            "shape": str(item.get("shape", "")),
            "colour": HOLE_COLOUR if item.get("hole") else colour,
            "copies": 1,
            "hole": bool(item.get("hole")),
            "stand_in": bool(item.get("stand_in")),
        }
    return list(entries.values())


HOLE_COLOUR = "#e03030"


def legend_text(entry: dict[str, Any]) -> str:
    """``name: shape ×copies (hole)`` for one :func:`part_legend` entry."""
    return (
        f"{entry['name']}: {entry['shape']}"
        + (f" ×{entry['copies']}" if entry["copies"] > 1 else "")
        + (" (hole, subtracted)" if entry["hole"] else "")
        + (" (box of equal inertia)" if entry["stand_in"] else "")
    )


def part_count(parts: list[dict[str, Any]]) -> int:
    """Written parts among the primitives (the copies of a pattern count once)."""
    return len({item.get("part", index) for index, item in enumerate(parts)})


def draw_body(body: Any, target: Any, title: str | None = None) -> int:
    """Draw a loaded body (:class:`~rbi.spec.load.LoadedBody`, spec units, body frame) at the
    checked output ``target`` (:func:`rbi.files.output.output_target`): a 3D page for
    ``.html``, else a still (:func:`draw_still`); ``title`` defaults to the spec's name, else
    its path. Returns the number of parts drawn."""

    data = view_data(title or body.name or body.path, body)
    if target.format == "html":
        data["legend"] = (
            f"{part_count(data['parts'])} parts · black dot: centre of mass · coloured lines: principal "
            f"axes (below) · grey arrows: the spec's x, y, z from its origin · lengths in {body.length_unit}"
        )
        write_output(target, html_page(data))
    else:
        write_output(target, writer=lambda path: draw_still(data, path, format=target.format))
    return part_count(data["parts"])


def draw_still(data: dict[str, Any], path: str, format: str = "png") -> None:
    """The body in 3D (matplotlib), saved at ``path`` as ``format`` (png or svg)."""
    plt = pyplot()

    size = float(data["size"])
    quads, colours = body_mesh(data["parts"], size, holes=False, stripes=False)
    holes = [item for item in data["parts"] if item.get("hole")]
    hole_quads, hole_colours = body_mesh(holes, size)
    fig = plt.figure(figsize=(10, 7))
    ax = fig.add_axes((0.0, 0.02, 0.6, 0.9), projection="3d")
    ax.computed_zorder = False  # holes, axes and markers stay in front of the solids
    ax.view_init(elev=22, azim=-55)
    _draw_solids(ax, quads, colours, hole_quads, hole_colours)
    quads = np.concatenate((quads, hole_quads)) if len(hole_quads) else quads
    points = cloud_points(data["parts"])
    if len(points):
        ax.scatter(points[:, 0], points[:, 1], points[:, 2], s=6, color="#333333", depthshade=False, zorder=3)
    com = np.asarray(data["com"], dtype=float)
    handles = _draw_axes_and_points(ax, com, data)
    plain_legend(
        fig.legend(
            handles=handles, loc="center left", bbox_to_anchor=(0.62, 0.5), fontsize=8.5, frameon=False
        )
    )
    _frame(ax, quads, com, data)
    unit = data["length_unit"]
    ax.set(xlabel=f"x [{unit}]", ylabel=f"y [{unit}]", zlabel=f"z [{unit}]")
    plain(fig.suptitle(f"{label(data['title'])}\n{STILL_SUBTITLE}", fontsize=10))
    fig.savefig(path, format=format, dpi=110)
    plt.close(fig)


def _draw_solids(ax, quads, colours, hole_quads, hole_colours) -> None:
    """The parts' faces, shaded; holes in red, the solids made see-through where there are any."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # optional extra `plot`, loaded only to draw

    if len(quads) and len(hole_quads):
        colours[:, 3] = np.minimum(colours[:, 3], 0.75)  # so that holes inside a part show through
    layers = [  # faces, their fill, edges and edge width: the solids shaded, then the holes over them
        (quads, shade(quads, colours), (0, 0, 0, 0.06), 0.2),
        (hole_quads, hole_colours, (0.75, 0.1, 0.1, 0.5), 0.3),
    ]
    for z, (faces, fill, edges, width) in enumerate(layers, start=1):
        if len(faces):
            layer = Poly3DCollection(faces, facecolors=fill, edgecolors=edges, linewidths=width, zorder=z)
            ax.add_collection3d(layer)


def _draw_axes_and_points(ax, com: np.ndarray, data: dict[str, Any]) -> list:
    """The principal axes through the centre of mass, the centre of mass, the pivot and the
    parts, each with its legend handle (returned in legend order)."""
    from matplotlib.lines import Line2D  # optional extra `plot`, loaded only to draw
    from matplotlib.patches import Patch  # optional extra `plot`, loaded only to draw

    handles = []
    for k, axis in enumerate(data["principal_axes"]):
        direction = np.asarray(axis["direction"]) * axis["half_length"]
        ends = np.stack((com - direction, com + direction))
        ax.plot(ends[:, 0], ends[:, 1], ends[:, 2], color=axis["colour"], lw=2.2, zorder=10)
        tip = com + 1.08 * direction
        ax.text(
            *tip, f"I{k + 1}", color=axis["colour"], fontsize=10, weight="bold", zorder=11, bbox=AXIS_NAME_BOX
        )
        handles.append(Line2D([], [], color=axis["colour"], lw=2.2, label=axis["label"]))
    ax.scatter(*com, color="black", s=40, marker="o", depthshade=False, zorder=12)
    handles.append(Line2D([], [], color="black", marker="o", ls="none", label="centre of mass"))
    if data.get("pivot") is not None:
        ax.scatter(*data["pivot"], color="black", s=70, marker="^", depthshade=False, zorder=12)
        handles.append(Line2D([], [], color="black", marker="^", ls="none", label="pivot"))
    entries = data["part_legend"]
    for entry in entries[:MAX_LEGEND_PARTS]:
        if entry["hole"]:
            handles.append(Patch(facecolor=HOLE_RGBA, edgecolor="#b02020", label=legend_text(entry)))
        else:
            alpha = 0.55 if entry["stand_in"] else 1.0
            handles.append(Patch(facecolor=entry["colour"], alpha=alpha, label=legend_text(entry)))
    if len(entries) > MAX_LEGEND_PARTS:
        handles.append(Patch(facecolor="white", label=f"… {len(entries)} parts in all"))
    return handles


def _frame(ax, quads: np.ndarray, com: np.ndarray, data: dict[str, Any]) -> None:
    """Equal scales on the three axes, framing every part, the CoM, the axes and the pivot."""

    points = [quads.reshape(-1, 3)] if len(quads) else []
    points.append(com[None, :])
    points.append(cloud_points(data["parts"]))
    for axis in data["principal_axes"]:
        direction = np.asarray(axis["direction"]) * axis["half_length"] * 1.1
        points.append(np.stack((com - direction, com + direction)))
    if data.get("pivot") is not None:
        points.append(np.asarray(data["pivot"], dtype=float)[None, :])
    cloud = np.concatenate(points)
    low, high = cloud.min(axis=0), cloud.max(axis=0)
    centre = 0.5 * (low + high)
    half = 0.5 * float(np.max(high - low)) or 1.0
    lower, upper = centre - half, centre + half
    ax.set(xlim=(lower[0], upper[0]), ylim=(lower[1], upper[1]), zlim=(lower[2], upper[2]))
    ax.set_box_aspect((1, 1, 1))
    # seen from azimuth -55°, x's upper end and y's lower end meet at the front corner: ticks at
    # both would print into one another ('100-100' under a wheel of 100 mm radius), so x keeps
    # its ticks there and y drops the one at its lower limit
    ax.set_yticks([v for v in ax.get_yticks() if v > lower[1] + 0.02 * half and v <= upper[1]])
