"""`rbi animate`: the body's motion as a self-contained 3D page (three.js) or a GIF."""

from __future__ import annotations

from typing import Annotated

import typer

from rbi.cli.options import SpecFile
from rbi.cli.render import progress_bar, say_warnings
from rbi.cli.run_options import (
    DurationOption,
    GravityOption,
    MaxStepsOption,
    OmegaOption,
    RtolOption,
    SpinAxisOption,
    SpinOption,
    TiltAxisOption,
    TiltOption,
    YesOption,
)
from rbi.spec.errors import InputError

OutOption = Annotated[
    str,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE.html|FILE.gif",
        help="The animation: .html (3D, plays offline in a browser) or .gif.",
    ),
]
SpeedOption = Annotated[
    float,
    typer.Option("--speed", metavar="X", help="Playback speed the page starts at (0.1–2; 1 = real time)."),
]
FpsOption = Annotated[int, typer.Option("--fps", metavar="N", help="Frames per second of a GIF.")]


def animate(
    file: SpecFile,
    out: OutOption,
    spin: SpinOption = None,
    omega: OmegaOption = None,
    tilt: TiltOption = 0.0,
    tilt_axis: TiltAxisOption = "y",
    gravity: GravityOption = None,
    duration: DurationOption = 4.0,
    rtol: RtolOption = None,
    max_steps: MaxStepsOption = None,
    yes: YesOption = False,
    speed: SpeedOption = 1.0,
    fps: FpsOption = 25,
    spin_axis: SpinAxisOption = None,
) -> None:
    """Animate the body's motion, simulated as `rbi simulate` does.

    The HTML page draws the parts as solids, the pivot and the ground, and the path of the tip
    of the spin axis (see --spin-axis); it plays in real time with
    play/pause, a speed control and a time slider. A GIF shows the same view as frames (it
    needs matplotlib and pillow: pip install '.[plot]' in rbi's source folder).

    \b
    Examples:
      rbi animate top_bolted.yaml --spin 200 --out top.html
      rbi animate top_bolted.yaml --spin 200 --duration 2 --out top.gif
    """
    from rbi.cli.option_values import run_settings
    from rbi.cli.output import output_target
    from rbi.runs.animation import animation
    from rbi.runs.run import check_run_options, prepare_run
    from rbi.spec.load import load_body

    settings = run_settings(spin, omega, tilt, yes, spin_axis, tilt_axis=tilt_axis, gravity=gravity)
    settings |= dict(duration=duration, rtol=rtol, max_steps=max_steps)
    check_run_options("default", **settings)
    _check_playback(speed, fps)
    target = output_target(out, "--out", ("html", "gif"), inputs=[file])
    gif_frames = _gif_frames(duration, fps) if target.format == "gif" else 0
    body = load_body(file)
    say_warnings(body.warnings)
    prepared = prepare_run(body, **settings)
    data, run, tilts = animation(prepared, gif_frames)
    if target.format == "html":
        shown = _write_page(target, data, run, speed)
    else:
        shown = _write_gif(target, data, run, fps)
    print(f"{out}: {shown} over {duration:g} s, largest tilt of the spin axis {float(tilts.max()):.3g}°")


def _gif_frames(duration: float, fps: int) -> int:
    """Frames of a GIF of ``duration`` s at ``fps``; refused past what a GIF may hold."""
    from rbi.viz.frames import MAX_GIF_FRAMES
    from rbi.viz.plots import require_matplotlib

    require_matplotlib("--out")
    frames = int(duration * fps) + 1
    if frames > MAX_GIF_FRAMES:
        raise InputError(
            f"--duration: a GIF of {duration:g} s at {fps} frames per second would have "
            f"{frames:.3g} frames, more than {MAX_GIF_FRAMES}: shorten --duration, lower --fps, "
            "or write .html"
        )
    return frames


def _check_playback(speed: float, fps: int) -> None:
    if not (0.1 <= speed <= 2.0):
        raise InputError(f"--speed: must be between 0.1 and 2 (got {speed!r})")
    if not 1 <= fps <= 60:
        raise InputError(f"--fps: must be between 1 and 60 (got {fps})")


def _write_page(target, data: dict, run, speed: float) -> str:
    """Write the 3D page at ``target``; what it holds (``N keyframes``)."""
    from rbi.cli.output import write_output
    from rbi.viz.page import html_page

    write_output(target, html_page(data, speed=speed))
    return f"{run.t.size} keyframes"


def _write_gif(target, data: dict, run, fps: int) -> str:
    """Write the GIF at ``target`` with a progress bar on a terminal; what it holds (``N frames``)."""
    from rbi.cli.output import write_output
    from rbi.viz.frames import frame_indices, write_gif

    progress = progress_bar("gif", "frames")
    try:
        write_output(
            target,
            writer=lambda path: write_gif(
                data, path, fps=fps, progress=progress.update if progress else None
            ),
        )
    finally:
        if progress is not None:
            progress.close()
    return f"{frame_indices(run.t, fps).size} frames"
