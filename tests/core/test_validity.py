"""Physical validity of an inertia matrix: symmetric, moments ≥ 0, I1 + I2 ≥ I3, with a
tolerance relative to the matrix (so tiny SI inertias are judged like large ones)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbi.core.validity import inertia_problem


def turned(moments, rotvec=(0.4, -0.2, 0.9)):
    R = Rotation.from_rotvec(rotvec).as_matrix()
    return R @ np.diag(moments) @ R.T


@pytest.mark.parametrize("scale", [1e-12, 1e-6, 1.0, 1e6])
def test_valid_inertias_pass_at_every_scale(scale):
    for moments in ([1, 1, 1], [1, 2, 2.5], [1, 1, 2], [0, 1, 1]):  # [1,1,2]: a flat plate; [0,1,1]: a rod
        assert inertia_problem(turned(np.array(moments) * scale)) is None


@pytest.mark.parametrize("scale", [1e-12, 1e-6, 1.0])
def test_triangle_violation_is_caught_even_for_tiny_si_inertias(scale):
    # I3 exceeds I1 + I2 by 1e-6 relative: far above rounding, far below an absolute floor.
    problem = inertia_problem(turned(np.array([1.0, 1.0, 2.000002]) * scale))
    assert problem is not None and problem.kind == "triangle inequality"
    assert "I1 + I2 >= I3" in problem.message


def test_rounding_sized_triangle_excess_is_forgiven():
    assert inertia_problem(turned(np.array([1.0, 1.0, 2.0 + 1e-13]) * 1e-7)) is None


def test_negative_moment_and_asymmetry_and_nan_are_named():
    assert inertia_problem(np.diag([-1e-9, 1.0, 1.0])).kind == "negative moment"
    asymmetric = np.diag([1.0, 1.0, 1.0])
    asymmetric[0, 1] = 0.1
    problem = inertia_problem(asymmetric)
    assert problem.kind == "not symmetric" and "[0][1]" in problem.message
    assert inertia_problem(np.full((3, 3), np.nan)).kind == "not finite"


def test_given_scale_widens_the_tolerance_for_differences_of_large_numbers():
    tiny_negative = np.diag([-1e-8, 1.0, 1.0])
    assert inertia_problem(tiny_negative) is not None
    assert inertia_problem(tiny_negative, scale=1e3) is None


@settings(max_examples=60, deadline=None)
@given(
    st.lists(
        st.tuples(st.floats(1e-3, 1e3), st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5)),
        min_size=1,
        max_size=6,
    )
)
def test_any_set_of_point_masses_gives_a_valid_inertia(points):
    m = np.array([p[0] for p in points])
    r = np.array([p[1:] for p in points])
    r = r - m @ r / m.sum()
    second = (r * m[:, None]).T @ r
    assert inertia_problem(np.trace(second) * np.eye(3) - second) is None


def test_entries_whose_magnitudes_overflow_are_named_without_a_numpy_warning():
    import warnings

    from rbi.core.validity import overflowing_sum

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        message = overflowing_sum(np.diag([1e308, 1e308, 1.0]))
        assert message is not None and "largest 1e+308" in message and "1.8e+308" in message
        assert overflowing_sum(np.diag([8e307, 8e307, 1.0])) is None  # 1.6e308 still a double
        problem = inertia_problem(np.diag([1e308, 1e308, 1e308]))
    assert (
        problem is not None
        and problem.kind == "not finite"
        and problem.message.endswith("is the unit right?")
    )
