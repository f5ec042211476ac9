"""Angular momentum, kinetic energy and the Newton–Euler equations of a rigid body.

All vectors and matrices passed to one call must be expressed in the same frame (any frame,
for instance body axes). Units: whatever consistent set the caller uses, with angular
velocity in rad/s and angular acceleration in rad/s².
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from rbi.core.mass import MassProperties
from rbi.core.rotation import skew


def angular_momentum(inertia: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """``h = I ω`` about the point the inertia is taken about."""
    return np.asarray(inertia, dtype=float) @ np.asarray(omega, dtype=float)


def angular_momentum_about_point(
    inertia_com: np.ndarray,
    mass: float,
    com_from_point: np.ndarray,
    omega: np.ndarray,
    com_velocity: np.ndarray,
) -> np.ndarray:
    """``h_o = I_c ω + m r_{c/o} × v_c``: angular momentum about a point o.

    ``com_from_point`` is the centre of mass relative to o; ``com_velocity`` the velocity of
    the centre of mass in the inertial frame (expressed in the common frame).
    """
    r = np.asarray(com_from_point, dtype=float)
    return angular_momentum(inertia_com, omega) + mass * np.cross(r, np.asarray(com_velocity, dtype=float))


def kinetic_energy(
    inertia_com: np.ndarray, omega: np.ndarray, mass: float = 0.0, com_velocity: ArrayLike = (0.0, 0.0, 0.0)
) -> float:
    """``T = ½ ωᵀ I_c ω + ½ m |v_c|²``."""
    w = np.asarray(omega, dtype=float)
    v = np.asarray(com_velocity, dtype=float)
    return 0.5 * float(w @ np.asarray(inertia_com, dtype=float) @ w) + 0.5 * mass * float(v @ v)


def angle_between_deg(a: np.ndarray, b: np.ndarray) -> float | None:
    """Angle between two vectors in degrees (``atan2`` form, accurate near 0 and 180);
    None when either vector is zero."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    if not (np.any(a) and np.any(b)):
        return None
    return math.degrees(math.atan2(float(np.linalg.norm(np.cross(a, b))), float(a @ b)))


# --- Newton–Euler ----------------------------------------------------------------------------


class Wrench(NamedTuple):
    """A force (M·L/s²) and a torque (M·L²/s²) about a stated point."""

    force: np.ndarray
    torque: np.ndarray


class Acceleration(NamedTuple):
    """A point's linear acceleration (L/s²) and the body's angular acceleration (rad/s²)."""

    linear: np.ndarray
    angular: np.ndarray


def newton_euler_about(
    props: MassProperties,
    inertia_point: np.ndarray,
    com_from_point: np.ndarray,
    omega: np.ndarray,
    *,
    about_com: bool,
    alpha: np.ndarray | None = None,
    point_acceleration: np.ndarray | None = None,
    force: np.ndarray | None = None,
    torque: np.ndarray | None = None,
) -> tuple[Acceleration, Wrench, bool]:
    """Newton–Euler about a body point o (the centre of mass when ``about_com``), inverse when
    ``alpha`` is given, else forward: ``(acceleration of o and α, force on the body and torque
    about o, held)``. Forward without ``force`` about a point other than the centre of mass,
    o is held (a pivot, accelerating at ``point_acceleration``, default 0) and the force
    holding it is found (``held`` True); otherwise ``point_acceleration`` is what the loads
    give. ``inertia_point``: the inertia about o; ``com_from_point``: ``r_{c/o}``.

    About the centre of mass ``F = m a_c``, ``τ_c = I α + ω × I ω``; about a point o
    ``[F; τ_o] = [[m E, −m[r]×], [m[r]×, I_o]] [a_o; α] + [m ω×(ω×r); ω × I_o ω]`` with
    ``r = r_{c/o}``, solved for ``a_o`` and ``α`` when forward."""
    m, w, r = props.mass, omega, com_from_point
    acc = np.zeros(3) if point_acceleration is None else point_acceleration
    S = skew(r)
    block = np.block([[m * np.eye(3), -m * S], [m * S, inertia_point]])  # acting on [a_o; α]
    bias = np.concatenate((m * np.cross(w, np.cross(w, r)), np.cross(w, inertia_point @ w)))  # velocity terms
    if alpha is not None:
        if about_com:  # F = m a_c, τ_c = I α + ω × I ω
            I = props.inertia_about_com
            return Acceleration(acc, alpha), Wrench(m * acc, I @ alpha + np.cross(w, I @ w)), False
        out = block @ np.concatenate((acc, alpha)) + bias
        return Acceleration(acc, alpha), Wrench(out[:3], out[3:]), False
    t = np.zeros(3) if torque is None else torque
    if force is None and not about_com:
        a = np.linalg.solve(inertia_point, t - np.cross(w, inertia_point @ w) - m * np.cross(r, acc))
        held = block @ np.concatenate((acc, a)) + bias
        return Acceleration(acc, a), Wrench(held[:3], t), True
    f = np.zeros(3) if force is None else force  # about the centre of mass r is 0: a_c = F/m
    solved = np.linalg.solve(block, np.concatenate((f, t)) - bias)
    return Acceleration(solved[:3], solved[3:]), Wrench(f, t), False
