"""The compiled kernel (rbi.sim._dop853): its right-hand side (through integrate), agreement with the
numba kernel it replaced, and the batch entry against single runs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.sim import _dop853
from rbi.sim.baselines import python_rhs
from rbi.sim.compiled import STATUS_DONE, STATUS_MORE, integrator
from rbi.sim.scene import initial_state


@settings(max_examples=30, deadline=None)
@given(
    q=st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(lambda v: np.linalg.norm(v) > 0.1),
    w=st.lists(st.floats(-300, 300), min_size=3, max_size=3),
)
def test_compiled_rhs_equals_the_python_rhs(bolted_scene, q, w):
    y = np.concatenate((np.asarray(q) / np.linalg.norm(q), w))
    # a run asked for no step returns (STATUS_MORE) with the derivative at y in clock[2:]
    clock, scene = np.zeros(9), bolted_scene
    status = integrator().integrate(
        y.copy(),
        clock,
        np.array([1.0]),
        np.empty((1, 7)),
        np.ascontiguousarray(scene.inertia),
        np.ascontiguousarray(scene.inertia_inv),
        np.ascontiguousarray(scene.gravity_moment),
        np.array([1e-12, scene.natural_rate]),
        np.zeros(4, dtype=np.int64),
        0,
    )
    out = clock[2:]
    assert status == STATUS_MORE
    expected = np.asarray(python_rhs(bolted_scene)(0.0, y))
    np.testing.assert_allclose(out, expected, rtol=1e-12, atol=1e-12 * (1 + np.abs(expected).max()))


def _single(scene, q0, w0, t, rtol):
    y = np.concatenate((q0, w0))
    out = np.empty((t.size, 7))
    counts = np.zeros(4, dtype=np.int64)
    status = integrator().integrate(
        y,
        np.zeros(9),
        t,
        out,
        np.ascontiguousarray(scene.inertia),
        np.ascontiguousarray(scene.inertia_inv),
        np.ascontiguousarray(scene.gravity_moment),
        np.array([rtol, scene.natural_rate]),
        counts,
        10**9,
    )
    return status, out, counts


# Produced by the numba-compiled kernel this extension replaced (same algorithm), before it was
# removed: the first step counts and final states it gave for these runs.
NUMBA_RESULTS = {
    "bolted": (
        10.0,
        [0, 0, 200.0],
        1e-12,
        [3, 578, 0, 6940],
        [
            0.9523559900686119,
            -0.17267936022267305,
            -0.11154122375544334,
            0.22529638731382357,
            6.105956190202036,
            -7.71205698377497,
            199.8256510913953,
        ],
    ),
}


def test_results_agree_with_the_numba_kernel_it_replaced(bolted_scene):
    tilt, w, rtol, counts, final = NUMBA_RESULTS["bolted"]
    status, out, got_counts = _single(bolted_scene, *initial_state(tilt, w), np.linspace(0, 1.0, 3), rtol)
    assert status == STATUS_DONE and got_counts.tolist() == counts
    np.testing.assert_allclose(out[-1], final, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("threads", [1, 2])
def test_batch_rows_equal_single_runs_bit_for_bit(bolted_scene, top_scene, free_scene, threads):
    scenes = [bolted_scene, top_scene, free_scene, bolted_scene, top_scene]
    starts = [
        initial_state(10.0, [0, 0, 200.0]),
        initial_state(3.0, [0, 0, 150.0]),
        (np.array([1.0, 0, 0, 0]), np.array([0.1, 2.0, 0.05])),
        initial_state(0.0, [0, 0, 210.0]),
        initial_state(20.0, [1.0, 0, 90.0]),
    ]
    t = np.linspace(0.0, 1.5, 31)
    B = len(scenes)
    out = np.empty((B, t.size, 7))
    counts = np.zeros((B, 4), dtype=np.int64)
    status = np.full(B, -1, dtype=np.int64)
    integrator().integrate_batch(
        np.array([np.concatenate(s) for s in starts]),
        t,
        np.array([s.inertia for s in scenes]),
        np.array([s.inertia_inv for s in scenes]),
        np.array([s.gravity_moment for s in scenes]),
        np.array([s.natural_rate for s in scenes]),
        1e-12,
        10**9,
        out,
        counts,
        status,
        threads,
    )
    for r in range(B):
        single_status, single_out, single_counts = _single(scenes[r], *starts[r], t, 1e-12)
        assert status[r] == single_status == STATUS_DONE
        np.testing.assert_array_equal(out[r], single_out)
        np.testing.assert_array_equal(counts[r], single_counts)


def test_batch_run_past_its_step_budget_reports_more(bolted_scene):
    t = np.linspace(0.0, 4.0, 5)
    out = np.empty((1, t.size, 7))
    counts = np.zeros((1, 4), dtype=np.int64)
    status = np.zeros(1, dtype=np.int64)
    integrator().integrate_batch(
        np.array([np.concatenate(initial_state(5.0, [0, 0, 200.0]))]),
        t,
        bolted_scene.inertia[None],
        bolted_scene.inertia_inv[None],
        bolted_scene.gravity_moment[None],
        np.array([bolted_scene.natural_rate]),
        1e-12,
        100,
        out,
        counts,
        status,
        1,
    )
    assert status[0] == STATUS_MORE and counts[0, 1] == 100


def test_wrong_shapes_are_refused_not_read_out_of_bounds():
    with pytest.raises(ValueError):
        _dop853.integrate(
            np.zeros(6),
            np.zeros(9),
            np.linspace(0, 1, 3),
            np.empty((3, 7)),
            np.eye(3),
            np.eye(3),
            np.zeros(3),
            np.array([1e-8, 0.0]),
            np.zeros(4, dtype=np.int64),
            10,
        )
    with pytest.raises(ValueError):
        _dop853.integrate_batch(
            np.zeros((2, 7)),
            np.linspace(0, 1, 3),
            np.zeros((1, 3, 3)),
            np.zeros((2, 3, 3)),
            np.zeros((2, 3)),
            np.zeros(2),
            1e-8,
            10,
            np.empty((2, 3, 7)),
            np.zeros((2, 4), dtype=np.int64),
            np.zeros(2, dtype=np.int64),
        )


def test_the_kernel_is_a_built_extension_not_a_run_time_compilation():
    assert Path(_dop853.__file__).suffix in (".so", ".pyd")
    assert integrator().how.startswith("Cython")
