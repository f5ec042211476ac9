"""The benchmark's baseline loop (rbi.sim._dop853.integrate_minimal) takes the same DOP853 steps
and gives the same samples as the kernel behind rbi.sim.api.simulate."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.sim.api import DEFAULT_RTOL, sample_times, simulate
from rbi.sim.scene import initial_state, scene_from_properties


def _scene(pivoted: bool):

    inertia = np.array([[3e-4, 1e-5, 0.0], [1e-5, 2.6e-4, -2e-6], [0.0, -2e-6, 1.9e-4]])
    props = MassProperties(mass=0.5, center_of_mass=np.array([0.001, 0.0, 0.05]), inertia_about_com=inertia)
    return scene_from_properties(props, np.zeros(3) if pivoted else None, 9.80665)


@pytest.mark.parametrize(
    "pivoted,tilt,omega,duration,samples,rtol",
    [
        (True, 0.0, (0.0, 0.0, 200.0), 2.0, 241, DEFAULT_RTOL),
        (True, 12.0, (1.0, -2.0, 150.0), 1.5, 7, 1e-9),
        (False, 0.0, (12.0, 16.0, 20.0), 3.0, 481, 1e-10),
        (True, 5.0, (0.0, 0.0, 80.0), 0.0, 1, DEFAULT_RTOL),
    ],
)
def test_same_steps_and_samples_as_simulate(pivoted, tilt, omega, duration, samples, rtol):
    from rbi.sim._dop853 import integrate_minimal

    scene = _scene(pivoted)
    q0, omega0 = initial_state(tilt, list(omega))
    run = simulate(scene, q0, omega0, duration, samples, rtol=rtol)
    t = sample_times(duration, samples)
    y = np.concatenate((q0 / np.linalg.norm(q0), omega0))
    out = np.empty((t.size, 7))
    steps = integrate_minimal(
        y,
        t,
        np.ascontiguousarray(scene.inertia),
        np.ascontiguousarray(scene.inertia_inv),
        np.ascontiguousarray(scene.gravity_moment, dtype=float),
        rtol,
        max(scene.natural_rate, 0.0),
        out,
    )
    assert steps == run.steps
    assert np.array_equal(out[:, :4], run.q) and np.array_equal(out[:, 4:], run.omega)
    if duration > 0:
        assert steps > 0
        # and the run moved: not a trivially equal pair of copies of the start
        assert not np.allclose(out[-1, :4], out[0, :4])


def test_shape_errors_raise():
    from rbi.sim._dop853 import integrate_minimal

    eye = np.eye(3)
    with pytest.raises(ValueError):
        integrate_minimal(
            np.zeros(6), np.array([0.0, 1.0]), eye, eye, np.zeros(3), 1e-9, 0.0, np.empty((2, 7))
        )
    with pytest.raises(ValueError):
        integrate_minimal(
            np.zeros(7), np.array([0.0, 1.0]), eye, eye, np.zeros(3), 1e-9, 0.0, np.empty((3, 7))
        )
