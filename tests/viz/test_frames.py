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


# --- bodies of thousands of parts: bounded drawing -------------------------------------------


def _positions(count: int) -> np.ndarray:
    i = np.arange(count)
    return np.stack(((i % 100) * 0.01, (i // 100) * 0.01, (i % 7) * 0.01), axis=1)


def test_many_point_masses_are_drawn_as_dots_at_their_positions():
    """2000 point masses: no 512-quad sphere each (a 117 MB SVG for 1000), but one dot each,
    exactly at the positions the spec gives."""
    from rbi.viz.frames import body_mesh, cloud_points

    positions = _positions(2000)
    parts = [{"kind": "point", "position": list(p), "hole": False} for p in positions]
    quads, colours = body_mesh(parts, 1.0)
    assert len(quads) == 0 and len(colours) == 0
    np.testing.assert_array_equal(cloud_points(parts), positions)


def test_a_few_point_masses_stay_spheres():
    from rbi.viz.frames import body_mesh, cloud_points

    parts = [{"kind": "point", "position": [0.0, 0.0, float(k)], "hole": False} for k in range(3)]
    quads, _ = body_mesh(parts, 1.0)
    # each a sphere of radius 0.035 × size about its position
    centres = quads.reshape(3, -1, 4, 3).mean(axis=(1, 2))
    np.testing.assert_allclose(centres, [[0, 0, 0], [0, 0, 1], [0, 0, 2]], atol=1e-12)
    assert len(cloud_points(parts)) == 0


def test_many_cylinders_keep_a_bounded_mesh_with_their_surface_area():
    """2000 cylinders of radius 0.01 and length 0.05: at most 100,000 quads in all, and the drawn
    area still within 10 % of 2000 × (2πrh + 2πr²)."""
    from rbi.viz.frames import body_mesh
    from rbi.viz.solids import QUAD_BUDGET

    r, h = 0.01, 0.05
    parts = [
        {
            "kind": "frustum",
            "start": list(p),
            "end": list(p + [0, 0, h]),
            "start_radius": r,
            "end_radius": r,
            "hole": False,
        }
        for p in _positions(2000)
    ]
    quads, colours = body_mesh(parts, 1.0)
    assert len(quads) <= QUAD_BUDGET == 100_000 and len(colours) == len(quads)
    a = np.cross(quads[:, 1] - quads[:, 0], quads[:, 2] - quads[:, 0])
    b = np.cross(quads[:, 2] - quads[:, 0], quads[:, 3] - quads[:, 0])
    area = 0.5 * (np.linalg.norm(a, axis=1) + np.linalg.norm(b, axis=1)).sum()
    assert area == pytest.approx(2000 * (2 * np.pi * r * h + 2 * np.pi * r * r), rel=0.10)
