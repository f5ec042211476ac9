"""Pictures: `show` a body, `animate` its motion (`Animation`)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rbi.api.body import Body, loaded_body
from rbi.api.outputs import checked_output
from rbi.core.validity import finite, require_callable
from rbi.errors import ArgumentError, literal
from rbi.files.output import Destination, write_output
from rbi.runs.animation import animation
from rbi.runs.run import RunSettings, prepare_run
from rbi.viz.frames import MAX_GIF_FRAMES, frame_indices, write_gif
from rbi.viz.page import html_page
from rbi.viz.still import draw_body


def show(body: Body, path: Destination, *, title: str | None = None) -> int:
    """Draw the body as specified at ``path``, as ``rbi show`` does: every part in place (holes
    red and translucent), the centre of mass, the principal axes about it (lengths in
    proportion to their moments, labelled with them) and the pivot, in the body frame with
    lengths in the spec's unit. ``.png`` or ``.svg`` (needs matplotlib), or ``.html`` (a 3D
    page that opens offline). The file is replaced atomically; ``title`` defaults to the
    spec's name, else its path. Returns the number of parts drawn.

    Raises:
        SpecError: ``path`` cannot be written, or its extension is none of those."""
    loaded = loaded_body(body, "body")
    return draw_body(loaded, checked_output(path, ("png", "svg", "html"), body), title)


@dataclass(frozen=True)
class Animation:
    """What `animate` wrote: ``path``; ``frames``, the pictures in it (a page's keyframes, a
    GIF's frames); ``max_tilt_deg``, the largest tilt of the spin axis from the upward
    vertical over the run, degrees."""

    path: str
    frames: int
    max_tilt_deg: float


def animate(
    body: Body,
    path: Destination,
    *,
    speed: float = 1.0,
    fps: int = 25,
    progress: Callable[[int, int], None] | None = None,
    **run: Any,
) -> Animation:
    """Animate the body's motion, simulated as `simulate` does, at ``path`` as ``rbi animate``
    does: ``.html``, a self-contained 3D page (parts as solids, pivot, ground, the path of the
    tip of the spin axis) that plays in real time, or ``.gif`` (needs matplotlib and pillow).

    Args:
        body: the `Body`.
        path: the file to write (replaced atomically).
        speed: playback speed the page starts at, 0.1 to 2 (1: real time).
        fps: frames per second of a GIF, 1 to 60.
        progress: called with (frames drawn, frames) as a GIF is drawn.
        run: `simulate`'s settings: ``spin``, ``omega``, ``tilt_deg``, ``tilt_axis``,
            ``gravity``, ``duration``, ``rtol``, ``max_steps``, ``check_budget``, ``spin_axis``.

    Raises:
        ValueError: a setting is out of range (named as this function's parameter), or the
            motion needs more keyframes (or GIF frames) than a file may hold.
        SpecError: ``path`` cannot be written; the run cannot be made."""
    loaded = loaded_body(body, "body")  # before the path: checked_output reads its files
    require_callable(progress=progress)
    target = checked_output(path, ("html", "gif"), body)
    prepared = prepare_run(loaded, RunSettings(**run))
    if not (finite(speed) and 0.1 <= speed <= 2.0):
        raise ArgumentError("speed", f"must be between 0.1 and 2 (got {literal(speed)})")
    if not (finite(fps) and 1 <= fps <= 60):
        raise ArgumentError("fps", f"must be between 1 and 60 (got {literal(fps)})")
    duration = prepared.settings.duration
    gif_frames = int(duration * fps) + 1 if target.format == "gif" else 0
    if gif_frames > MAX_GIF_FRAMES:
        raise ArgumentError(
            "duration",
            f"a GIF of {duration:g} s at {fps} frames per second would have {gif_frames:.3g} frames, more "
            f"than {MAX_GIF_FRAMES}: shorten {{duration}}, lower {{fps}}, or write .html",
        )
    data, trajectory, tilts = animation(prepared, gif_frames)
    if target.format == "html":
        write_output(target, html_page(data, speed=speed))
        return Animation(target.given, int(trajectory.t.size), float(tilts.max()))
    write_output(target, writer=lambda temp: write_gif(data, temp, fps=fps, progress=progress))
    return Animation(target.given, int(frame_indices(trajectory.t, fps).size), float(tilts.max()))
