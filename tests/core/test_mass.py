"""rbi.core.mass.MassProperties, the one mass-properties value type, against closed forms."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from rbi.core.mass import MassProperties, combine, inertia_shares


def test_two_point_masses_sum_to_a_dumbbell():
    # 1 kg at x = -1 m and 3 kg at x = +1 m: centre of mass at x = 0.5, moment about the
    # transverse axes through it Σ m d² = 1·1.5² + 3·0.5² = 3 kg·m², none about x.
    a = MassProperties.point(1.0, [-1.0, 0.0, 0.0], "link")
    b = MassProperties.point(3.0, [1.0, 0.0, 0.0], "link")
    total = MassProperties.sum([a, b])
    assert total.mass == 4.0 and total.frame == "link"
    np.testing.assert_allclose(total.center_of_mass, [0.5, 0.0, 0.0], rtol=0, atol=1e-16)
    np.testing.assert_allclose(total.inertia_about_com, np.diag([0.0, 3.0, 3.0]), rtol=0, atol=1e-15)
    np.testing.assert_allclose(inertia_shares([a, b], total), [0.75, 0.25], rtol=1e-15)


def test_the_sum_of_nothing_or_of_no_mass_is_refused():
    with pytest.raises(ValueError, match="positive"):
        MassProperties.sum([])
    with pytest.raises(ValueError, match="positive"):
        combine([1.0, -1.0], np.zeros((2, 3)))


def test_parallel_axis_of_a_rod_about_its_end():
    # thin rod of mass m, length L along z, about its end: m L²/3 about x and y (m L²/12 + m L²/4)
    m, L = 2.0, 3.0
    rod = MassProperties(m, [0.0, 0.0, L / 2], np.diag([m * L * L / 12, m * L * L / 12, 0.0]))
    np.testing.assert_allclose(rod.inertia_about([0, 0, 0]), np.diag([m * L * L / 3] * 2 + [0.0]), rtol=1e-15)
    np.testing.assert_allclose(rod.inertia_about(rod.center_of_mass), rod.inertia_about_com, rtol=0)


def test_transformed_turns_and_moves():
    # a box 1 × 2 × 3 m of 12 kg: moments (b² + c², a² + c², a² + b²) = 13, 10, 5 kg·m²; turned
    # 90° about z the x and y moments swap; the centre of mass (1, 0, 0) goes to (0, 1, 0) + t.
    box = MassProperties(12.0, [1.0, 0.0, 0.0], np.diag([13.0, 10.0, 5.0]), "part")
    quarter = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    moved = box.transformed(quarter, [0.0, 0.0, 2.0], "body")
    assert moved.frame == "body" and moved.mass == 12.0
    np.testing.assert_allclose(moved.center_of_mass, [0.0, 1.0, 2.0], rtol=0, atol=1e-16)
    np.testing.assert_allclose(moved.inertia_about_com, np.diag([10.0, 13.0, 5.0]), rtol=0, atol=1e-15)
    assert box.transformed().frame == "part"


def test_principal_moments_and_axes_of_a_turned_diagonal():
    c, s = math.cos(0.3), math.sin(0.3)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    body = MassProperties(1.0, np.zeros(3), R @ np.diag([1.0, 2.0, 4.0]) @ R.T)
    moments, axes = body.principal()
    np.testing.assert_allclose(moments, [1.0, 2.0, 4.0], rtol=1e-15)
    np.testing.assert_allclose(np.abs(axes[0] @ R[:, 0]), 1.0, rtol=1e-15)
    np.testing.assert_allclose(body.moments, moments, rtol=0)


def test_scaled_keeps_the_centre_and_scales_mass_and_inertia():
    unit = MassProperties(2.0, [1.0, 2.0, 3.0], np.eye(3))
    heavy = unit.scaled(500.0)
    assert heavy.mass == 1000.0
    np.testing.assert_array_equal(heavy.center_of_mass, unit.center_of_mass)
    np.testing.assert_array_equal(heavy.inertia_about_com, 500.0 * np.eye(3))
    exactly = unit.with_mass(0.3)  # 0.3 itself, not 2 × (0.3 / 2)
    assert exactly.mass == 0.3
    np.testing.assert_allclose(exactly.inertia_about_com, 0.15 * np.eye(3), rtol=1e-15)


def test_immutable():
    com = np.array([1.0, 2.0, 3.0])
    value = MassProperties(1.0, com, np.eye(3))
    com[0] = 9.0  # the value holds its own copy
    assert value.center_of_mass[0] == 1.0
    with pytest.raises(ValueError):
        value.center_of_mass[0] = 5.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        value.mass = 2.0  # type: ignore[misc]
    assert MassProperties.zero("world").mass == 0.0 and MassProperties.zero("world").frame == "world"
