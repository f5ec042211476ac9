"""`rbi animate`: the body's motion as a self-contained 3D page (three.js) or a GIF."""

from __future__ import annotations

from typing import Annotated

import typer

from rbi import api
from rbi.cli.option_values import run_settings
from rbi.cli.options import SpecFile, require_matplotlib
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
from rbi.cli.terminal import terminal_safe

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
FpsOption = Annotated[
    int,
    typer.Option(
        "--fps",
        metavar="N",
        help="Frames per second of a GIF, 1–60; it plays in real time, so it has about --duration × N "
        "frames, at most 1500.",
    ),
]


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

    settings = run_settings(spin, omega, tilt, yes, spin_axis, tilt_axis=tilt_axis, gravity=gravity)
    settings |= dict(duration=duration, rtol=rtol, max_steps=max_steps, speed=speed, fps=fps)
    gif = out.lower().endswith(".gif")  # rbi.animate checks the path (and its format)
    if gif:
        require_matplotlib("--out")
    body = api.load(file)
    say_warnings(body.warnings)
    with progress_bar("gif", "frames", show=gif) as progress:
        made = api.animate(body, out, progress=progress.update if progress else None, **settings)
    shown = f"{made.frames} {'frames' if gif else 'keyframes'} over {duration:g} s"
    print(f"{terminal_safe(out)}: {shown}, largest tilt of the spin axis {made.max_tilt_deg:.3g}°")
