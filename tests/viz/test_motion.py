"""The data an animation plays, checked against the motion itself: unit keyframes, the path
of the axis tip of a sleeping top and of a tilted fast top, keyframes close enough for slerp."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.sim.api import simulate
from rbi.sim.diagnostics import tilt_deg
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.spec.geometry import part_geometry
from rbi.spec.load import load_body
from rbi.viz.motion import MAX_TURN_PER_KEYFRAME, MIN_KEYFRAMES, animation_data, keyframes_needed


def _run(bodies, name, spin, tilt, duration=0.5, samples=None):
    body = load_body(bodies / name)
    scene = scene_from_properties(body.props, body.pivot, 9.81)
    q0, w0 = initial_state(tilt, [0.0, 0.0, spin])
    count = samples or max(MIN_KEYFRAMES, keyframes_needed(duration, abs(spin) * 1.05))
    run = simulate(scene, q0, w0, duration, count)
    data = animation_data(
        "t", part_geometry(body), scene, run.t, run.q, run.omega, tilt_deg(run.q), body.length_unit
    )
    return body, scene, run, data


def test_keyframes_are_unit_quaternions_in_xyzw_order(bodies):
    _, _, run, data = _run(bodies, "top_bolted.yaml", 200.0, 5.0)
    q = np.array(data["quaternions"])
    np.testing.assert_allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-9)
    np.testing.assert_allclose(q[:, 3], run.q[:, 0])  # w last, as three.js wants
    assert len(data["times"]) == len(q) == len(data["trace"]) == len(data["tilt_deg"]) == len(data["omega"])


def test_keyframes_turn_little_enough_for_slerp(bodies):
    _, _, run, data = _run(bodies, "top_bolted.yaml", 200.0, 5.0)
    q = np.array(data["quaternions"])
    turns = 2 * np.arccos(np.clip(np.abs(np.sum(q[1:] * q[:-1], axis=1)), 0, 1))
    assert turns.max() <= 1.1 * MAX_TURN_PER_KEYFRAME


def test_sleeping_top_trace_stays_at_the_top(bodies):
    # 1000 rad/s is far above the sleeping threshold (about 208 rad/s) and the top starts exactly upright
    _, _, _, data = _run(bodies, "top.yaml", 1000.0, 0.0)
    trace = np.array(data["trace"])
    np.testing.assert_allclose(
        trace, np.tile([0.0, 0.0, data["size"]], (len(trace), 1)), atol=1e-9 * data["size"]
    )


def test_tilted_fast_top_trace_is_tilted_by_the_start_angle_towards_x(bodies):
    _, _, _, data = _run(bodies, "top.yaml", 1000.0, 10.0)
    trace = np.array(data["trace"])
    angle = np.degrees(np.arccos(trace[:, 2] / np.linalg.norm(trace, axis=1)))
    assert angle[0] == pytest.approx(10.0, abs=1e-9)
    # a tilt about world y turns the body's z axis towards world +x
    assert trace[0, 0] == pytest.approx(data["size"] * math.sin(math.radians(10.0)), rel=1e-9)
    assert abs(trace[0, 1]) < 1e-12
    # a fast top nods only slightly below its start (nutation of order m g l I1 / (I3 ω)², a fraction of a degree)
    assert angle.min() >= 10.0 - 1e-6 and angle.max() <= 10.5
    # and it precesses: the tip goes round the vertical
    assert np.ptp(np.arctan2(trace[:, 1], trace[:, 0])) > 0.01


def test_the_traced_axis_of_a_top_without_symmetry_points_near_its_centre_of_mass(bodies):
    body, scene, _, _ = _run(bodies, "top_bolted.yaml", 200.0, 0.0, samples=2)
    axis = np.asarray(scene.spin_axis)  # the axis the animation traces
    offset = np.asarray(scene.com_from_pivot)
    assert np.degrees(np.arccos(axis @ offset / np.linalg.norm(offset))) < 10.0


@pytest.mark.parametrize("duration, rate, expected", [(0.0, 5.0, 1), (1.0, 0.0, 1), (4.0, 200.0, 1601)])
def test_keyframes_needed(duration, rate, expected):
    # no interval between keyframes turns the body more than MAX_TURN_PER_KEYFRAME rad
    assert keyframes_needed(duration, rate) == expected
