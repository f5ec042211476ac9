"""`rbi animate`: the body's motion as a self-contained 3D page (three.js) or a GIF."""

from __future__ import annotations

from typing import Annotated, Optional

import typer

from rbi.cli.options import SpecFile
from rbi.spec.errors import InputError


def animate(
    file: SpecFile,
    out: Annotated[str, typer.Option("--out", "-o", metavar="FILE.html|FILE.gif",
                                     help="The animation: .html (3D, plays offline in a browser) or .gif.")],
    spin: Annotated[Optional[float], typer.Option("--spin", "-s", metavar="W",
                                                  help="Spin about the body z axis, rad/s.")] = None,
    omega: Annotated[Optional[str], typer.Option("--omega", "-w", metavar="WX,WY,WZ",
                                                 help="Initial angular velocity in body axes, rad/s.")] = None,
    tilt: Annotated[float, typer.Option("--tilt", metavar="DEG", help="Initial tilt, degrees.")] = 0.0,
    tilt_axis: Annotated[str, typer.Option("--tilt-axis", metavar="x|y", help="World axis of the tilt.")] = "y",
    gravity: Annotated[Optional[float], typer.Option("--gravity", "-g", metavar="G",
                                                     help="Gravity in m/s² (default 9.81).")] = None,
    duration: Annotated[float, typer.Option("--duration", "-t", metavar="T", help="Simulated time, s.")] = 4.0,
    rtol: Annotated[Optional[float], typer.Option("--rtol", metavar="RTOL", help="Integrator tolerance (default 1e-12).")] = None,
    max_steps: Annotated[Optional[int], typer.Option("--max-steps", metavar="N",
                                                     help="Most integration steps the run may take.")] = None,
    yes: Annotated[bool, typer.Option("--yes", "-y", help="Run even past the estimated step budget.")] = False,
    speed: Annotated[float, typer.Option("--speed", metavar="X",
                                         help="Playback speed the page starts at (0.1–2; 1 = real time).")] = 1.0,
    fps: Annotated[int, typer.Option("--fps", metavar="N", help="Frames per second of a GIF.")] = 25,
) -> None:
    """Animate the body's motion, simulated as `rbi simulate` does.

    The HTML page draws the parts as solids, the pivot and the ground, and the path of the tip
    of the symmetry axis (or of the largest-moment axis); it plays in real time with
    play/pause, a speed control and a time slider. A GIF shows the same view as frames (it
    needs matplotlib and pillow: pip install '.[plot]').

    \b
    Examples:
      rbi animate top_bolted.yaml --spin 200 --out top.html
      rbi animate top_bolted.yaml --spin 200 --duration 2 --out top.gif
    """
    from rbi.cli.output import output_target, write_output
    from rbi.runs.prepare import prepare_run
    from rbi.runs.settings import check_run_options
    from rbi.spec.load import load_body

    check_run_options("default", spin, omega, tilt, duration, tilt_axis, gravity, max_steps, rtol)
    if not (0.1 <= speed <= 2.0):
        raise InputError(f"--speed: must be between 0.1 and 2 (got {speed!r})")
    if not 1 <= fps <= 60:
        raise InputError(f"--fps: must be between 1 and 60 (got {fps})")
    target = output_target(out, "--out", ("html", "gif"), inputs=[file])
    gif_frames = 0
    if target.format == "gif":
        from rbi.cli.plot import require_matplotlib
        from rbi.viz.frames import MAX_GIF_FRAMES

        require_matplotlib()
        gif_frames = int(duration * fps) + 1
        if gif_frames > MAX_GIF_FRAMES:
            raise InputError(f"--duration: a GIF of {duration:g} s at {fps} frames per second would have "
                             f"{gif_frames:.3g} frames, more than {MAX_GIF_FRAMES}: shorten --duration, lower --fps, "
                             "or write .html")
    prepared = prepare_run(load_body(file), spin=spin, omega=omega, tilt=tilt, tilt_axis=tilt_axis, gravity=gravity,
                           duration=duration, rtol=rtol, max_steps=max_steps, yes=yes)
    body, scene, q0, omega0, budget = prepared.body, prepared.scene, prepared.q0, prepared.omega0, prepared.budget
    import numpy as np

    from rbi.sim.api import SimulationError, simulate
    from rbi.sim.diagnostics import tilt_deg
    from rbi.spec.geometry import part_geometry
    from rbi.viz.motion import MAX_KEYFRAMES, MIN_KEYFRAMES, TRAIL_SECONDS, animation_data, keyframes_needed
    from rbi.viz.still import part_count

    try:
        probe = simulate(scene, q0, omega0, duration, MIN_KEYFRAMES, rtol=rtol, max_steps=budget)
        fastest = float(np.max(np.linalg.norm(probe.omega, axis=1)))
        needed = keyframes_needed(duration, fastest)
        if needed > MAX_KEYFRAMES:
            raise InputError(f"--duration: {duration:g} s of this motion needs {needed:.3g} keyframes to play "
                             f"smoothly, more than {MAX_KEYFRAMES}: shorten --duration")
        count = max(MIN_KEYFRAMES, needed, gif_frames)
        run = probe if count == MIN_KEYFRAMES else simulate(scene, q0, omega0, duration, count, rtol=rtol, max_steps=budget)
    except SimulationError as exc:
        raise InputError(f"{file}: {exc}") from None
    if not (np.all(np.isfinite(run.q)) and np.all(np.isfinite(run.omega))):
        raise InputError(f"{file}: the motion is not finite: the input values are too large for double precision")
    from rbi.viz.labels import label

    title = f"{label(body.name or file, 30)}: spin {float(np.linalg.norm(omega0)):g} rad/s, tilt {tilt:g}°"
    tilts = tilt_deg(run.q)
    data = animation_data(title, part_geometry(body), scene, run.t, run.q, run.omega, tilts, body.length_unit)
    data["legend"] = (f"{part_count(data['parts'])} parts · red line: path of the axis tip over the last {TRAIL_SECONDS:g} s · lengths in {body.length_unit}"
                      + (" · on a pivot" if scene.pivoted else " · free body, about its centre of mass"))
    if target.format == "html":
        from rbi.viz.page import html_page

        write_output(target, html_page(data, speed=speed))
        shown = f"{run.t.size} keyframes"
    else:
        from rbi.viz.frames import frame_indices, write_gif

        write_output(target, writer=lambda path: write_gif(data, path, fps=fps))
        shown = f"{frame_indices(run.t, fps).size} frames"
    print(f"{out}: {shown} over {duration:g} s, largest tilt {float(np.max(tilts)):.3g}°")
