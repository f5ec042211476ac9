"""The run behind `rbi animate`: the motion sampled densely enough to play smoothly, and the
plain data the page and the GIF are drawn from."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.errors import ArgumentError
from rbi.runs.run import PreparedRun, refuse_non_finite
from rbi.sim.diagnostics import tilt_deg
from rbi.spec.geometry import part_geometry
from rbi.viz.labels import motion_title
from rbi.viz.motion import MAX_KEYFRAMES, MIN_KEYFRAMES, TRAIL_SECONDS, animation_data, keyframes_needed
from rbi.viz.still import part_count


def animation(run: PreparedRun, gif_frames: int = 0) -> tuple[dict[str, Any], Any, np.ndarray]:
    """Simulate ``run`` at as many keyframes as its fastest turning needs (at least
    ``gif_frames``) and assemble the animation's data (:func:`rbi.viz.motion.animation_data`,
    with its title and legend). Returns ``(data, trajectory, tilt of body z in degrees)``.

    :class:`InputError` when the motion would need more keyframes than a page can play, or is
    not finite."""
    body, scene, duration = run.body, run.scene, run.settings.duration
    probe = run.integrate(MIN_KEYFRAMES)
    fastest = float(np.max(np.linalg.norm(probe.omega, axis=1)))
    needed = keyframes_needed(duration, fastest)
    if needed > MAX_KEYFRAMES:
        raise ArgumentError(
            "duration",
            f"{duration:g} s of this motion needs {needed:.3g} keyframes to play "
            f"smoothly, more than {MAX_KEYFRAMES}: shorten {{duration}}",
        )
    count = max(MIN_KEYFRAMES, needed, gif_frames)
    trajectory = probe if count == MIN_KEYFRAMES else run.integrate(count)
    refuse_non_finite(body.path, {"q": trajectory.q, "omega": trajectory.omega})
    title = motion_title(
        body.name or body.path,
        run.omega0,
        None if run.omega_given else scene.spin_axis,
        run.settings.tilt_deg,
        limit=30,
    )
    tilts = tilt_deg(trajectory.q, scene.spin_frame)
    data = animation_data(
        title,
        part_geometry(body),
        scene,
        trajectory.t,
        trajectory.q,
        trajectory.omega,
        tilts,
        body.length_unit,
    )
    data["legend"] = (
        f"{part_count(data['parts'])} parts · red line: path of the axis tip over the last "
        f"{TRAIL_SECONDS:g} s · lengths in {body.length_unit}"
        + (" · on a pivot" if scene.pivoted else " · free body, about its centre of mass")
    )
    return data, trajectory, tilts
