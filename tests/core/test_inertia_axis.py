"""Moment about an arbitrary axis, radii of gyration and the CAD sign of products, against
closed forms and the defining integrals."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.core.inertia import moment_about_axis, parallel_axis, radii_of_gyration, unit_axis
from rbi.core.mass import combine
from tests.core import built


def test_cylinder_about_a_diameter_through_its_end_face():
    # Solid cylinder, mass m, radius r, length L: about a diameter of an end face,
    # I = m (r²/4 + L²/3) (perpendicular-axis moment m(3r² + L²)/12 shifted by m(L/2)²).
    m, r, L = 2.5, 0.04, 0.3
    direction = np.array([1.0, 2.0, 2.0]) / 3.0
    start = np.array([0.1, -0.2, 0.3])
    element = built.cylinder(m, r, start, start + L * direction)
    about_start = parallel_axis(element.inertia_about_com, m, start - element.center_of_mass)
    across = np.cross(direction, [0.0, 0.0, 1.0])  # perpendicular to the cylinder's axis
    assert moment_about_axis(about_start, 7.0 * across) == pytest.approx(m * (r**2 / 4 + L**2 / 3), rel=1e-13)
    assert moment_about_axis(about_start, direction) == pytest.approx(m * r**2 / 2, rel=1e-13)


def test_point_mass_moment_is_mass_times_squared_distance_from_the_line():
    # m at (3, 4, 0) about the z axis through the origin: m · 5²; about x: m · 4².
    I = combine(np.array([2.0]), np.array([[3.0, 4.0, 0.0]]), None).inertia_about_com
    I_origin = parallel_axis(I, 2.0, [3.0, 4.0, 0.0])
    assert moment_about_axis(I_origin, [0, 0, 1]) == pytest.approx(50.0, rel=1e-15)
    assert moment_about_axis(I_origin, [2, 0, 0]) == pytest.approx(32.0, rel=1e-15)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(
        st.tuples(st.floats(0.1, 10), st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5)),
        min_size=2,
        max_size=8,
    ),
    st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1)).filter(lambda v: np.linalg.norm(v) > 0.1),
)
def test_moment_equals_the_sum_of_mass_times_squared_distance(points, axis):
    masses = np.array([p[0] for p in points])
    positions = np.array([p[1:] for p in points])
    props = combine(masses, positions, None)
    n = np.asarray(axis) / np.linalg.norm(axis)
    d = positions - props.center_of_mass
    distance_squared = np.sum(np.cross(d, n) ** 2, axis=1)  # |d × n|² is the squared distance to the line
    expected = float(masses @ distance_squared)
    assert moment_about_axis(props.inertia_about_com, axis) == pytest.approx(expected, rel=1e-10, abs=1e-10)


@pytest.mark.parametrize("axis", [[0, 0, 0], [np.nan, 0, 1], [np.inf, 0, 0]])
def test_an_axis_without_direction_is_refused(axis):
    with pytest.raises(ValueError):
        unit_axis(axis)


def test_radius_of_gyration_of_a_sphere():
    m, r = 3.0, 0.2
    element = built.sphere(m, r, np.zeros(3))
    k = radii_of_gyration(np.diag(element.inertia_about_com), m)
    assert k**2 == pytest.approx([2 * r**2 / 5] * 3, rel=1e-14)


def test_radius_of_gyration_of_a_thin_ring_is_its_radius():
    # Eight equal point masses on a circle of radius 0.5 about z: I_z = m R², so k_z = R.
    angles = np.arange(8) * np.pi / 4
    positions = np.c_[0.5 * np.cos(angles), 0.5 * np.sin(angles), np.zeros(8)]
    props = combine(np.full(8, 0.25), positions, None)
    assert radii_of_gyration([props.inertia_about_com[2, 2]], props.mass)[0] == pytest.approx(0.5, rel=1e-14)
