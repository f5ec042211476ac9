"""Momentum, energy and Newton–Euler against sums over the particles of a rigid cloud: each
particle moves with v = v_c + ω × ρ and a = a_c + α × ρ + ω × (ω × ρ), and the sums of
m v, ρ × m v, m a and ρ × m a are the independent answers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.core.dynamics import (
    angle_between_deg,
    angular_momentum,
    angular_momentum_about_point,
    kinetic_energy,
    newton_euler_about,
)
from rbi.core.mass import MassProperties


def newton_euler_com(mass, inertia_com, omega, alpha, com_acceleration):
    """Inverse dynamics about the centre of mass: the force and the torque about it."""
    props = MassProperties(mass, np.zeros(3), inertia_com)
    given = dict(alpha=alpha, point_acceleration=com_acceleration)
    return newton_euler_about(props, inertia_com, np.zeros(3), omega, about_com=True, **given)[1]


def newton_euler_point(mass, inertia_point, com_from_point, omega, alpha, point_acceleration):
    """Inverse dynamics about a body point o: the force and the torque about o."""
    props = MassProperties(mass, com_from_point, inertia_point)  # only the mass is read
    given = dict(alpha=alpha, point_acceleration=point_acceleration)
    return newton_euler_about(props, inertia_point, com_from_point, omega, about_com=False, **given)[1]


def newton_euler_point_forward(mass, inertia_point, com_from_point, omega, force, torque):
    """Forward dynamics about a body point o given the force: ``a_o`` and ``α``."""
    props = MassProperties(mass, com_from_point, inertia_point)  # only the mass is read
    given = dict(force=np.asarray(force, dtype=float), torque=np.asarray(torque, dtype=float))
    return newton_euler_about(props, inertia_point, com_from_point, omega, about_com=False, **given)[0]


class Cloud:
    """Point masses of a rigid body, with its mass, CoM and inertia summed directly."""

    def __init__(self, seed: int):
        rng = np.random.default_rng(seed)
        self.m = rng.uniform(0.2, 1.5, size=6)
        self.r = rng.uniform(-1.0, 1.0, size=(6, 3)) + [0.3, -0.1, 0.6]
        self.mass = float(self.m.sum())
        self.com = (self.m @ self.r) / self.mass
        self.rng = rng

    def inertia_about(self, point):
        d = self.r - point
        return sum(m * (x @ x * np.eye(3) - np.outer(x, x)) for m, x in zip(self.m, d))

    def vector(self, scale=1.0):
        return self.rng.normal(size=3) * scale

    def accelerations(self, a_point, point, omega, alpha):
        """Each particle's acceleration from that of a body point."""
        d = self.r - point
        return a_point + np.cross(alpha, d) + np.cross(omega, np.cross(omega, d))

    def wrench_about(self, point, accelerations):
        forces = self.m[:, None] * accelerations
        return forces.sum(axis=0), np.cross(self.r - point, forces).sum(axis=0)


SEEDS = [1, 2, 3, 4]


@pytest.mark.parametrize("seed", SEEDS)
def test_newton_euler_about_the_com_equals_particle_sums(seed):
    b = Cloud(seed)
    w, alpha, a_c = b.vector(3.0), b.vector(2.0), b.vector()
    force, torque = b.wrench_about(b.com, b.accelerations(a_c, b.com, w, alpha))
    out = newton_euler_com(b.mass, b.inertia_about(b.com), w, alpha, a_c)
    np.testing.assert_allclose(out.force, force, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(out.torque, torque, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_newton_euler_about_a_point_equals_particle_sums(seed):
    b = Cloud(seed)
    o = b.vector()
    w, alpha, a_o = b.vector(3.0), b.vector(2.0), b.vector()
    force, torque = b.wrench_about(o, b.accelerations(a_o, o, w, alpha))
    out = newton_euler_point(b.mass, b.inertia_about(o), b.com - o, w, alpha, a_o)
    np.testing.assert_allclose(out.force, force, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(out.torque, torque, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_point_form_is_the_com_form_plus_transport(seed):
    b = Cloud(seed)
    o = b.vector()
    r = b.com - o
    w, alpha, a_o = b.vector(3.0), b.vector(2.0), b.vector()
    a_c = a_o + np.cross(alpha, r) + np.cross(w, np.cross(w, r))
    at_com = newton_euler_com(b.mass, b.inertia_about(b.com), w, alpha, a_c)
    at_point = newton_euler_point(b.mass, b.inertia_about(o), r, w, alpha, a_o)
    np.testing.assert_allclose(at_point.force, b.mass * a_c, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(
        at_point.torque, at_com.torque + np.cross(r, at_com.force), rtol=1e-12, atol=1e-12
    )


@pytest.mark.parametrize("seed", SEEDS)
def test_forward_and_inverse_round_trip(seed):
    b = Cloud(seed)
    o = b.vector()
    w, force, torque = b.vector(3.0), b.vector(), b.vector()
    acc = newton_euler_point_forward(b.mass, b.inertia_about(b.com), np.zeros(3), w, force, torque)
    back = newton_euler_com(b.mass, b.inertia_about(b.com), w, acc.angular, acc.linear)
    np.testing.assert_allclose(back.force, force, rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(back.torque, torque, rtol=1e-12, atol=1e-13)
    acc = newton_euler_point_forward(b.mass, b.inertia_about(o), b.com - o, w, force, torque)
    back = newton_euler_point(b.mass, b.inertia_about(o), b.com - o, w, acc.angular, acc.linear)
    np.testing.assert_allclose(back.force, force, rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(back.torque, torque, rtol=1e-11, atol=1e-12)


def test_forward_about_the_com_is_eulers_equation_for_a_principal_body():
    # Torque-free, principal axes: α = ((I2 − I3) ω2 ω3 / I1, ...).
    I = np.diag([1.0, 2.0, 4.0])
    w = np.array([0.5, -1.0, 2.0])
    acc = newton_euler_point_forward(3.0, I, np.zeros(3), w, [3.0, 0.0, -6.0], [0.0, 0.0, 0.0])
    expected = [
        (2.0 - 4.0) * w[1] * w[2] / 1.0,
        (4.0 - 1.0) * w[2] * w[0] / 2.0,
        (1.0 - 2.0) * w[0] * w[1] / 4.0,
    ]
    np.testing.assert_allclose(acc.angular, expected, rtol=1e-15)
    np.testing.assert_allclose(acc.linear, [1.0, 0.0, -2.0], rtol=1e-15)


@pytest.mark.parametrize("seed", SEEDS)
def test_angular_momentum_about_a_point_with_the_extra_term(seed):
    b = Cloud(seed)
    o = b.vector()
    w, v_c = b.vector(3.0), b.vector()
    v = v_c + np.cross(w, b.r - b.com)
    h_direct = np.cross(b.r - o, b.m[:, None] * v).sum(axis=0)
    h = angular_momentum_about_point(b.inertia_about(b.com), b.mass, b.com - o, w, v_c)
    np.testing.assert_allclose(h, h_direct, rtol=1e-12, atol=1e-12)
    # About the CoM the extra term vanishes: h = I_c ω.
    h_c = np.cross(b.r - b.com, b.m[:, None] * v).sum(axis=0)
    np.testing.assert_allclose(angular_momentum(b.inertia_about(b.com), w), h_c, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_kinetic_energy_equals_half_sum_m_v_squared(seed):
    b = Cloud(seed)
    w, v_c = b.vector(3.0), b.vector()
    v = v_c + np.cross(w, b.r - b.com)
    direct = 0.5 * float(b.m @ np.einsum("ij,ij->i", v, v))
    assert kinetic_energy(b.inertia_about(b.com), w, b.mass, v_c) == pytest.approx(direct, rel=1e-13)
    rotation_only = 0.5 * float(b.m @ np.einsum("ij,ij->i", v - v_c, v - v_c))
    assert kinetic_energy(b.inertia_about(b.com), w) == pytest.approx(rotation_only, rel=1e-13)


@pytest.mark.parametrize("t", [1e-12, 1e-9, 1e-6, 0.3, 1.5])
def test_angle_between_is_accurate_near_0_and_180(t):
    a = np.array([2.0, 0.0, 0.0])
    close = np.array([math.cos(t), math.sin(t), 0.0]) * 5.0
    opposite = np.array([-math.cos(t), math.sin(t), 0.0]) * 0.5
    assert angle_between_deg(a, close) == pytest.approx(math.degrees(t), rel=1e-12)
    assert 180.0 - angle_between_deg(a, opposite) == pytest.approx(
        math.degrees(t), rel=1e-12 if t > 1e-6 else 1e-3
    )
    assert angle_between_deg(a, a) == 0.0
    assert angle_between_deg(a, -a) == 180.0


def test_angle_with_a_zero_vector_is_undefined():
    assert angle_between_deg([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]) is None
    assert angle_between_deg([1.0, 0.0, 0.0], [0.0, 0.0, 0.0]) is None
