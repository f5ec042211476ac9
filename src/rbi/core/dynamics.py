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


# --- Newton–Euler about the centre of mass -------------------------------------------------


class Wrench(NamedTuple):
    """A force (M·L/s²) and a torque (M·L²/s²) about a stated point."""

    force: np.ndarray
    torque: np.ndarray


class Acceleration(NamedTuple):
    """A point's linear acceleration (L/s²) and the body's angular acceleration (rad/s²)."""

    linear: np.ndarray
    angular: np.ndarray


def newton_euler_com(
    mass: float, inertia_com: np.ndarray, omega: np.ndarray, alpha: np.ndarray, com_acceleration: np.ndarray
) -> Wrench:
    """Inverse dynamics about the centre of mass: ``F = m a_c``, ``τ_c = I α + ω × I ω``."""
    I = np.asarray(inertia_com, dtype=float)
    w = np.asarray(omega, dtype=float)
    force = mass * np.asarray(com_acceleration, dtype=float)
    torque = I @ np.asarray(alpha, dtype=float) + np.cross(w, I @ w)
    return Wrench(force, torque)


# --- Newton–Euler about a point o ----------------------------------------------------------


def spatial_inertia_about_point(
    mass: float, inertia_point: np.ndarray, com_from_point: np.ndarray
) -> np.ndarray:
    """The 6×6 block matrix ``[[m E, −m[r]×], [m[r]×, I_o]]`` acting on ``[a_o; α]``.

    ``inertia_point`` is the inertia about o; ``com_from_point`` is r_{c/o}.
    """
    S = skew(np.asarray(com_from_point, dtype=float))
    block = np.zeros((6, 6))
    block[:3, :3] = mass * np.eye(3)
    block[:3, 3:] = -mass * S
    block[3:, :3] = mass * S
    block[3:, 3:] = np.asarray(inertia_point, dtype=float)
    return block


def velocity_terms_about_point(
    mass: float, inertia_point: np.ndarray, com_from_point: np.ndarray, omega: np.ndarray
) -> np.ndarray:
    """The velocity-dependent 6-vector ``[m ω × (ω × r_{c/o}); ω × I_o ω]``."""
    w = np.asarray(omega, dtype=float)
    r = np.asarray(com_from_point, dtype=float)
    I = np.asarray(inertia_point, dtype=float)
    return np.concatenate((mass * np.cross(w, np.cross(w, r)), np.cross(w, I @ w)))


def newton_euler_point(
    mass: float,
    inertia_point: np.ndarray,
    com_from_point: np.ndarray,
    omega: np.ndarray,
    alpha: np.ndarray,
    point_acceleration: np.ndarray,
) -> Wrench:
    """Inverse dynamics about a body point o: force on the body and torque about o.

    ``[F; τ_o] = [[m E, −m[r]×], [m[r]×, I_o]] [a_o; α] + [m ω×(ω×r); ω × I_o ω]``
    with ``r = r_{c/o}``.
    """
    block = spatial_inertia_about_point(mass, inertia_point, com_from_point)
    acc = np.concatenate((np.asarray(point_acceleration, dtype=float), np.asarray(alpha, dtype=float)))
    out = block @ acc + velocity_terms_about_point(mass, inertia_point, com_from_point, omega)
    return Wrench(out[:3], out[3:])


def newton_euler_point_forward(
    mass: float,
    inertia_point: np.ndarray,
    com_from_point: np.ndarray,
    omega: np.ndarray,
    force: np.ndarray,
    torque_point: np.ndarray,
) -> Acceleration:
    """Forward dynamics about a body point o: ``a_o`` and ``α`` from the force and the torque
    about o, solving the block system of :func:`newton_euler_point`."""
    block = spatial_inertia_about_point(mass, inertia_point, com_from_point)
    rhs = np.concatenate((np.asarray(force, dtype=float), np.asarray(torque_point, dtype=float)))
    rhs = rhs - velocity_terms_about_point(mass, inertia_point, com_from_point, omega)
    acc = np.linalg.solve(block, rhs)
    return Acceleration(acc[:3], acc[3:])


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
    give. ``inertia_point``: the inertia about o; ``com_from_point``: ``r_{c/o}``."""
    m, w, r = props.mass, omega, com_from_point
    acc = np.zeros(3) if point_acceleration is None else point_acceleration
    if alpha is not None:
        if about_com:
            return (
                Acceleration(acc, alpha),
                newton_euler_com(m, props.inertia_about_com, w, alpha, acc),
                False,
            )
        return Acceleration(acc, alpha), newton_euler_point(m, inertia_point, r, w, alpha, acc), False
    t = np.zeros(3) if torque is None else torque
    if force is None and not about_com:
        a = np.linalg.solve(inertia_point, t - np.cross(w, inertia_point @ w) - m * np.cross(r, acc))
        held = newton_euler_point(m, inertia_point, r, w, a, acc).force
        return Acceleration(acc, a), Wrench(held, t), True
    f = (
        np.zeros(3) if force is None else force
    )  # about the centre of mass r is 0: a_c = F/m, I α = τ − ω × I ω
    return newton_euler_point_forward(m, inertia_point, r, w, f, t), Wrench(f, t), False
