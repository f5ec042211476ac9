"""`rbi animate`: the body's motion as a self-contained 3D page (three.js) or a GIF."""

from __future__ import annotations

import rbi
from rbi.cli.options import REQUIRED, SpecFile, command, option, out_option, require_matplotlib
from rbi.cli.render import progress_bar, say_warnings
from rbi.cli.run_options import RUN, budget
from rbi.cli.terminal import terminal_safe

OPTIONS = (
    *(each for name, each in RUN.items() if name != "samples"),
    out_option(
        "FILE.html|FILE.gif",
        "The animation: .html (3D, plays offline in a browser) or .gif.",
        default=REQUIRED,
    ),
    option(
        float,
        "--speed",
        default=1.0,
        metavar="X",
        help="Playback speed the page starts at (0.1–2; 1 = real time).",
    ),
    option(
        int,
        "--fps",
        default=25,
        metavar="N",
        help="Frames per second of a GIF, 1–60; it plays in real time, so it has about --duration × N "
        "frames, at most 1500.",
    ),
)


@command(*OPTIONS, api=rbi.simulate)
def animate(file: SpecFile, *, out: str, **settings) -> None:
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

    gif = out.lower().endswith(".gif")  # rbi.animate checks the path (and its format)
    if gif:
        require_matplotlib("--out")
    body = rbi.load(file)
    say_warnings(body.warnings)
    with progress_bar("gif", "frames", show=gif) as progress:
        made = rbi.animate(body, out, progress=progress.update if progress else None, **budget(settings))
    shown = f"{made.frames} {'frames' if gif else 'keyframes'} over {settings['duration']:g} s"
    print(f"{terminal_safe(out)}: {shown}, largest tilt of the spin axis {made.max_tilt_deg:.3g}°")
