"""The default spin axis, against bodies whose symmetry is known by construction."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.core.rotation import axis_angle_matrix, quaternion_to_matrix, unit_vector
from rbi.core.spin_axis import default_spin_axis, distinct_principal_axis, quaternion_from_z_to

ROD_ALONG_Y = np.diag([2.0, 1.0, 2.0])  # two equal moments: symmetry axis y


def test_the_symmetry_axis_points_from_the_pivot_towards_the_centre_of_mass():
    assert default_spin_axis(ROD_ALONG_Y, [0.0, 0.3, 0.0]).tolist() == [0.0, 1.0, 0.0]
    assert default_spin_axis(ROD_ALONG_Y, [0.0, -0.3, 0.0]).tolist() == [0.0, -1.0, 0.0]


def test_perpendicular_offset_or_free_body_takes_the_largest_component_positive():
    for offset in ([0.0, 0.0, 0.0], [0.2, 0.0, 0.0], [0.0, 0.0, -0.5]):
        assert default_spin_axis(ROD_ALONG_Y, offset).tolist() == [0.0, 1.0, 0.0]
    R = axis_angle_matrix(np.array([1.0, 0.0, 0.0]), np.radians(150.0))  # turns y to (0, -0.87, 0.5)
    axis = default_spin_axis(R @ ROD_ALONG_Y @ R.T, np.zeros(3))
    assert np.allclose(axis, -(R @ [0.0, 1.0, 0.0]), atol=1e-12) and axis[np.argmax(np.abs(axis))] > 0


def test_no_two_or_all_three_moments_equal_gives_body_z():
    assert default_spin_axis(np.diag([1.0, 2.0, 3.0]), [0.0, 0.0, 1.0]).tolist() == [0.0, 0.0, 1.0]
    assert default_spin_axis(np.eye(3), [1.0, 0.0, 0.0]).tolist() == [0.0, 0.0, 1.0]
    assert distinct_principal_axis(np.diag([1.0, 1.0 + 4e-9, 3.0])) is None  # 1.3e-9 of the largest
    assert distinct_principal_axis(np.diag([1.0, 1.0 + 1e-10, 3.0])) is not None


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 1e-3),
    st.floats(0.0, 3.0),
)
def test_an_axisymmetric_inertia_turned_anywhere_gives_its_turned_axis(axis, angle):
    R = axis_angle_matrix(np.array(axis), angle)
    inertia = R @ np.diag([1.0, 3.0, 3.0]) @ R.T  # symmetry axis: R x
    expected = R @ [1.0, 0.0, 0.0]
    found = default_spin_axis(inertia, 0.7 * expected)
    assert np.allclose(found, expected, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1e300, 1e300), min_size=3, max_size=3).filter(lambda v: max(map(abs, v)) > 1e-300))
def test_the_turn_from_z_carries_z_onto_the_axis_for_directions_of_any_size(vector):
    a = unit_vector(vector)
    assert abs(np.linalg.norm(a) - 1.0) < 1e-15
    assert np.allclose(quaternion_to_matrix(quaternion_from_z_to(a)) @ [0.0, 0.0, 1.0], a, atol=1e-15)


def test_body_z_is_turned_by_exactly_the_identity_and_minus_z_by_half_a_turn():
    assert quaternion_from_z_to([0.0, 0.0, 2.0]).tolist() == [1.0, 0.0, 0.0, 0.0]
    assert np.allclose(quaternion_to_matrix(quaternion_from_z_to([0.0, 0.0, -1.0])) @ [0, 0, 1], [0, 0, -1])


@pytest.mark.parametrize("bad", [[0.0, 0.0, 0.0], [np.nan, 0.0, 1.0], [np.inf, 0.0, 0.0]])
def test_a_direction_needs_a_finite_length(bad):
    with pytest.raises(ValueError):
        unit_vector(bad)
