"""GIF frames (matplotlib + pillow) and rbi show's still picture, read back as images."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")
from PIL import Image  # noqa: E402

from rbi.sim.api import simulate  # noqa: E402
from rbi.sim.diagnostics import tilt_deg  # noqa: E402
from rbi.sim.scene import initial_state, scene_from_properties  # noqa: E402
from rbi.spec.geometry import part_geometry  # noqa: E402
from rbi.spec.load import load_body  # noqa: E402
from rbi.viz.frames import frame_indices, write_gif  # noqa: E402
from rbi.viz.motion import animation_data  # noqa: E402


def test_frame_indices_follow_real_time():
    times = np.linspace(0.0, 2.0, 801)
    indices = frame_indices(times, 10)
    np.testing.assert_allclose(times[indices], np.arange(0.0, 2.0001, 0.1), atol=1e-12)


def test_gif_plays_the_motion_in_real_time(tmp_path, bodies):
    body = load_body(bodies / "top_bolted.yaml")
    scene = scene_from_properties(body.props, body.pivot, 9.81)
    q0, w0 = initial_state(0.0, [0, 0, 200.0])
    run = simulate(scene, q0, w0, 1.0, 401)
    data = animation_data("t", part_geometry(body), scene, run.t, run.q, run.omega, tilt_deg(run.q), "m")
    out = tmp_path / "top.gif"
    write_gif(data, str(out), fps=10)
    gif = Image.open(out)
    assert gif.n_frames == 11
    assert gif.info["duration"] == 100  # ms per frame at 10 frames per second
    frames = []
    for k in (0, 10):
        gif.seek(k)
        frames.append(np.asarray(gif.convert("RGB"), dtype=int))
    coloured = [(f.max(axis=2) - f.min(axis=2) > 60).sum() for f in frames]
    assert min(coloured) > 500  # the parts are drawn
    assert (np.abs(frames[0] - frames[1]).max(axis=2) > 40).sum() > 300  # and they moved (the wobble grew)
