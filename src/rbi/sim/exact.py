"""Closed-form motions, used as ``--method exact`` and to test the integrators.

:func:`solve` ``(scene, q0, omega0)`` picks the one that applies (or raises
:class:`NotIntegrable`): :class:`UniformRotation` (a steady spin about a principal axis, also the
sleeping top), :class:`SymmetricFreeBody`, :class:`EulerPoinsot` (torque-free asymmetric body;
near the intermediate axis it flips every half period of ω) or :class:`LagrangeTop`. Each has
``state_at(t) -> (q (N, 4), omega (N, 3))``, ``description`` and ``facts()`` (characteristic
numbers); its docstring gives its formulas.

Frames: q = [w, x, y, z] body -> world, ω in body axes (rad/s); the world's z is up. Times in
seconds. The scene's inertia is about its fixed point (pivot, or centre of mass of a free
body), so a pivoted body without gravity torque is a free body about its pivot.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import Any

import numpy as np

from rbi.core.rotation import (
    Z_AXIS,
    matrix_to_quaternion,
    quaternion_to_matrix,
    rotate,
    rotate_into_body,
    unit_vector,
)
from rbi.core.rotation import quaternion_conjugate as _conj
from rbi.core.rotation import quaternion_from_axis_angle as turn
from rbi.core.rotation import quaternion_multiply as qmul
from rbi.sim.diagnostics import AXISYMMETRY_RTOL, axial_and_transverse, symmetry_axis
from rbi.sim.elliptic import ellipk, ellipkinc, ellippi
from rbi.sim.scene import Scene

PARALLEL_RTOL = 1e-14
"""ω within this (relative) of a principal axis is a steady spin about it."""

VERTICAL_MARGIN = 1e-12
"""A Lagrange top whose cos(tilt) comes this close to ±1 passes through the vertical: no
closed form here (the Euler angles are singular there)."""


class NotIntegrable(ValueError):
    """The scene or the initial state has no closed form that rbi implements."""


# --- quaternion helpers (rows are samples) ---------------------------------------------------


_X = np.array([1.0, 0.0, 0.0])


def _zxz(phi, theta, psi) -> np.ndarray:
    """Quaternion of ``Rz(φ) Rx(θ) Rz(ψ)``."""
    return qmul(qmul(turn(Z_AXIS, phi), turn(_X, theta)), turn(Z_AXIS, psi))


# --- elliptic integrals ----------------------------------------------------------------------


def _pi_incomplete(n: float, phi: np.ndarray, m: float) -> np.ndarray:
    """Π(n; φ | m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ)) for |φ| ≤ π/2 (Carlson form)."""
    # not at top level: `rbi simulate` would load scipy.special too
    from scipy.special import elliprf, elliprj

    s = np.sin(phi)
    c2 = np.cos(phi) ** 2
    d2 = 1.0 - m * s * s
    value = s * elliprf(c2, d2, 1.0)
    if n != 0.0:
        value = value + (n / 3.0) * s**3 * elliprj(c2, d2, 1.0, 1.0 - n * s * s)
    return value


class _Elliptic:
    """Jacobi elliptic functions of a parameter m evaluated with argument reduction, and the
    integral ``G(n; u) = ∫₀^u du' / (1 − n sn²u')`` for any real u."""

    def __init__(self, m: float) -> None:
        if not 0.0 <= m < 1.0:
            raise NotIntegrable(
                f"elliptic parameter m = {m!r} outside [0, 1) (the motion is on a separatrix)"
            )
        self.m = m
        self.K = ellipk(m)  # scalars in plain Python: the facts of a run need no scipy import

    def functions(self, u: np.ndarray):
        """(sn, cn, dn, am_reduced, j) with u = 2K j + r, r in [−K, K); am_reduced = am(r)."""
        # not at top level: `rbi simulate` would load scipy.special too
        from scipy.special import ellipj

        u = np.asarray(u, dtype=float)
        j = np.floor((u + self.K) / (2.0 * self.K))
        r = u - 2.0 * self.K * j
        sn, cn, dn, am = ellipj(r, self.m)
        sign = np.where(j % 2 == 0, 1.0, -1.0)  # sn(u + 2K) = −sn u, cn(u + 2K) = −cn u
        return sign * sn, sign * cn, dn, am, j

    def G(self, n: float, u: np.ndarray) -> np.ndarray:
        _, _, _, am, j = self.functions(u)
        return 2.0 * j * ellippi(n, self.m) + _pi_incomplete(n, am, self.m)


# --- solutions ---------------------------------------------------------------------------------


class UniformRotation:
    """Steady rotation with constant body ω about a principal axis (that axis then stays
    fixed in space; for a top it must be vertical)."""

    def __init__(self, q0: np.ndarray, omega0: np.ndarray, description: str) -> None:
        self.q0 = np.asarray(q0, dtype=float)
        self.omega0 = np.asarray(omega0, dtype=float)
        self.description = description

    def state_at(self, t: np.ndarray):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        rate = float(np.linalg.norm(self.omega0))
        axis = self.omega0 / rate if rate > 0 else Z_AXIS
        q = unit_vector(qmul(self.q0, turn(axis, rate * t)))
        return q, np.tile(self.omega0, (t.size, 1))

    def facts(self) -> dict[str, Any]:
        return {"kind": "uniform rotation"}


class SymmetricFreeBody:
    """Torque-free body with two equal principal moments I_t and axis moment I_a about the
    symmetry axis ``a`` (body frame): the body turns at |h|/I_t about the fixed angular
    momentum h and at Ω = −(I_a − I_t) ω_a / I_t about its own axis,
    ``q(t) = exp(ĥ |h| t / I_t) q0 exp(a Ω t)``."""

    def __init__(self, scene: Scene, q0, omega0, axis: np.ndarray) -> None:

        self.q0 = np.asarray(q0, dtype=float)
        self.axis = np.asarray(axis, dtype=float)
        I_axis, self.I_t = axial_and_transverse(scene, self.axis)
        h_body = scene.inertia @ omega0
        self.h_world = rotate(self.q0, h_body)
        self.h = float(np.linalg.norm(self.h_world))
        self.spin_rate = -(I_axis - self.I_t) * float(omega0 @ self.axis) / self.I_t
        self.description = "torque-free symmetric body (elementary functions)"

    def state_at(self, t: np.ndarray):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        h_dir = self.h_world / self.h if self.h > 0 else Z_AXIS
        q = qmul(qmul(turn(h_dir, self.h / self.I_t * t), self.q0), turn(self.axis, self.spin_rate * t))
        q = unit_vector(q)
        # ω_body = R(t)ᵀ h_world / I_t + Ω a
        h_body = rotate_into_body(q, self.h_world)
        omega = h_body / self.I_t + self.spin_rate * self.axis
        return q, omega

    def facts(self) -> dict[str, Any]:
        return {
            "kind": "symmetric free body",
            "precession_rate_rad_s": self.h / self.I_t,
            "body_spin_rate_rad_s": self.spin_rate,
        }


class EulerPoinsot:
    """Torque-free asymmetric body (I₁ < I₂ < I₃ about the fixed point).

    With 2T = Σ Iᵢωᵢ² and M² = Σ Iᵢ²ωᵢ²: when M² > 2T I₂ the angular velocity circulates
    about axis 3 (ω₁ ∝ cn, ω₂ ∝ sn, ω₃ ∝ dn), otherwise about axis 1 (ω₃ ∝ cn, ω₂ ∝ sn,
    ω₁ ∝ dn), argument τ = λ t + τ₀. The orientation is ``Rz(φ) Rx(θ) Rz(ψ)`` in a frame
    whose z is the fixed angular momentum, with θ, ψ read from ω and φ the integral of
    φ̇ = M (I_a ω_a² + I_b ω_b²)/(I_a² ω_a² + I_b² ω_b²).
    """

    def __init__(self, scene: Scene, q0, omega0) -> None:
        moments, axes = scene.principal_moments, scene.principal_axes
        I1, I2, I3 = (float(v) for v in moments)
        p, q, r = axes @ omega0
        self.axes = axes
        self.moments = moments
        a3 = I1 * (I3 - I1) * p * p + I2 * (I3 - I2) * q * q  # 2T I3 − M²
        a1 = I2 * (I2 - I1) * q * q + I3 * (I3 - I1) * r * r  # M² − 2T I1
        b = I1 * (I2 - I1) * p * p - I3 * (I3 - I2) * r * r  # 2T I2 − M²
        self.M = math.sqrt(I1 * I1 * p * p + I2 * I2 * q * q + I3 * I3 * r * r)
        A1, A3 = math.sqrt(a3 / (I1 * (I3 - I1))), math.sqrt(a1 / (I3 * (I3 - I1)))
        if b < 0.0:  # about axis 3: ω = (s A1 cn, A2 sn, s A3 dn)
            self.polar = 3
            A2 = math.sqrt(a3 / (I2 * (I3 - I2)))
            self.lam = math.sqrt((I3 - I2) * a1 / (I1 * I2 * I3))
            m = (I2 - I1) * a3 / ((I3 - I2) * a1)
            s = math.copysign(1.0, r)
            sn0, cn0 = q / A2, p / (s * A1)
            # triad (a, b, c) = (1, 2, 3): cn carries axis 1, sn axis 2
            self.triad = (0, 1, 2)
            I_cn, A_cn, n1_over_d1 = I1, A1, 1.0 / I3
        else:  # about axis 1: ω = (s A1 dn, A2 sn, s A3 cn)
            self.polar = 1
            A2 = math.sqrt(a1 / (I2 * (I2 - I1)))
            self.lam = math.sqrt((I2 - I1) * a3 / (I1 * I2 * I3))
            m = (I3 - I2) * a1 / ((I2 - I1) * a3) if a3 > 0 else 0.0
            s = math.copysign(1.0, p)
            sn0, cn0 = q / A2, r / (s * A3)
            # triad (a, b, c) = (2, 3, 1), right-handed: sn carries axis 2 (a), cn axis 3 (b)
            self.triad = (1, 2, 0)
            I_cn, A_cn, n1_over_d1 = I3, A3, 1.0 / I1
        self.amplitudes = np.array([s * A1, A2, s * A3])
        I_sn, A_sn = I2, A2
        self.ell = _Elliptic(m)
        self.tau0 = ellipkinc(math.atan2(sn0, cn0), self.ell.m)
        # φ̇ = M [n1/d1 + (n0 d1 − n1 d0)/(d0 d1) / (1 − ν sn²)], ν = −d1/d0
        d0 = (I_cn * A_cn) ** 2
        d1 = (I_sn * A_sn) ** 2 - d0
        self.nu = -d1 / d0
        self.h_cn, self.h_sn = I_cn * A_cn, I_sn * A_sn
        self.rate_mean_part = self.M * n1_over_d1
        self.rate_periodic = (
            self.M * I_cn * I_sn * (A_cn * A_sn) ** 2 * (I_sn - I_cn) / (d0 * d1) if d1 != 0 else 0.0
        )
        self.G0 = float(self.ell.G(self.nu, np.array([self.tau0]))[0])
        self._fix_frame(q0)
        self.description = "torque-free asymmetric body (Jacobi elliptic functions, elliptic integrals)"

    def _fix_frame(self, q0) -> None:
        """The constant turns of q_wb(t) = q_wH ⊗ zxz(φ, θ, ψ) ⊗ q_tb that make t = 0 give ``q0``."""
        # the matrix whose rows are the triad in body coordinates maps body to triad coordinates
        self.q_tb = matrix_to_quaternion(self.axes[list(self.triad)])
        phi0, theta0, psi0, _ = self._angles(np.array([0.0]))
        self.q_wH = qmul(
            qmul(np.asarray(q0, dtype=float), _conj(self.q_tb)), _conj(_zxz(phi0, theta0, psi0))
        )[0]

    def _psi(self, am: np.ndarray) -> np.ndarray:
        """ψ = atan2(I_a ω_a, I_b ω_b) as a continuous function of the amplitude am(τ), so
        that the quaternions come out continuous in time. With X, Y > 0 the amplitudes of
        the cn and sn components of h: g(am) = am + atan2((Y − X) sin cos, X cos² + Y sin²)
        has tan g = (Y/X) tan am and never jumps."""
        s = math.copysign(1.0, self.amplitudes[0] if self.polar == 3 else self.amplitudes[2])
        X, Y = self.h_cn, self.h_sn
        c, n = np.cos(am), np.sin(am)
        g = am + np.arctan2((Y - X) * n * c, X * c * c + Y * n * n)
        if self.polar == 3:  # ψ = atan2(s X cn, Y sn)
            return s * (0.5 * np.pi - g)
        return 0.5 * (1.0 - s) * np.pi + s * g  # ψ = atan2(Y sn, s X cn)

    def _omega(self, sn, cn, dn) -> np.ndarray:
        if self.polar == 3:
            return np.stack((cn, sn, dn), axis=-1) * self.amplitudes
        return np.stack((dn, sn, cn), axis=-1) * self.amplitudes

    def _angles(self, t: np.ndarray):
        """The Euler angles φ, θ, ψ at times ``t`` and ω in principal axes (N, 3), rad/s."""
        t = np.asarray(t, dtype=float)
        sn, cn, dn, am, j = self.ell.functions(self.lam * t + self.tau0)
        w = self._omega(sn, cn, dn)
        h = w * self.moments
        ha, hb, hc = (h[..., i] for i in self.triad)
        theta = np.arctan2(np.hypot(ha, hb), hc)
        psi = self._psi(am + np.pi * j)
        phi = self.rate_mean_part * t
        if self.rate_periodic != 0.0:
            phi = phi + self.rate_periodic / self.lam * (
                self.ell.G(self.nu, self.lam * t + self.tau0) - self.G0
            )
        return phi, theta, psi, w

    def state_at(self, t: np.ndarray):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        phi, theta, psi, w = self._angles(t)
        q = qmul(qmul(self.q_wH, _zxz(phi, theta, psi)), self.q_tb)
        return unit_vector(q), w @ self.axes

    @property
    def period(self) -> float:
        """Period of ω in the body, 4K(m)/λ (s)."""
        return 4.0 * self.ell.K / self.lam

    def facts(self) -> dict[str, Any]:
        return {
            "kind": "asymmetric free body",
            "circulates_about_axis": self.polar,
            "elliptic_parameter": self.ell.m,
            "omega_period_s": self.period,
            "half_period_s": 0.5 * self.period,
        }


def _triad(axis: np.ndarray, principal_axes: np.ndarray) -> np.ndarray:
    """Rows (a, b, c = ``axis``) of a right-handed triad whose transverse pair is taken from the
    principal axis most nearly perpendicular to ``axis``."""
    first = principal_axes[0] if abs(principal_axes[0] @ axis) < 0.5 else principal_axes[1]
    first = first - (first @ axis) * axis
    first /= np.linalg.norm(first)
    return np.array([first, np.cross(axis, first), axis])


class LagrangeTop:
    """Heavy symmetric top, centre of mass at distance l > 0 along its axis from the pivot.

    Euler angles ``R_world_triad = Rz(φ) Rx(θ) Rz(ψ)``; constants ω₃ (spin), h_z (vertical
    angular momentum) and E. With u = cos θ, α = (2E − I₃ω₃²)/I₁, β = 2mgl/I₁, a = h_z/I₁,
    b = I₃ω₃/I₁: u̇² = f(u) = (α − βu)(1 − u²) − (a − bu)², φ̇ = (a − bu)/(1 − u²),
    ψ̇ = ω₃ − φ̇ u. u moves between the two lower roots u₁ ≤ u₂ of the cubic f:
    u = u₁ + (u₂ − u₁) sn²(σ, m), m = (u₂ − u₁)/(u₃ − u₁) (u₁ = u₂: steady precession); φ and
    ψ in closed form through elliptic integrals of the third kind.
    """

    def __init__(self, scene: Scene, q0, omega0, axis: np.ndarray) -> None:

        self.axis = np.asarray(axis, dtype=float)
        self.I3, self.I1 = axial_and_transverse(scene, self.axis)
        self.rows = rows = _triad(self.axis, scene.principal_axes)
        self.q_tb = matrix_to_quaternion(rows)
        self.mgl = scene.mass * scene.gravity * float(np.linalg.norm(scene.com_from_pivot))
        w_t = rows @ np.asarray(omega0, dtype=float)
        R = quaternion_to_matrix(q0) @ rows.T  # triad -> world
        self.u0 = float(R[2, 2])
        sin_theta0 = math.hypot(R[0, 2], R[1, 2])
        self.phi0 = math.atan2(R[0, 2], -R[1, 2]) if sin_theta0 > 0 else 0.0
        self.psi0 = math.atan2(R[2, 0], R[2, 1]) if sin_theta0 > 0 else 0.0
        theta_dot0 = w_t[0] * math.cos(self.psi0) - w_t[1] * math.sin(self.psi0)
        self.w3 = float(w_t[2])
        h_t = np.array([self.I1 * w_t[0], self.I1 * w_t[1], self.I3 * w_t[2]])
        hz = float(R[2] @ h_t)
        energy = 0.5 * (self.I1 * (w_t[0] ** 2 + w_t[1] ** 2) + self.I3 * self.w3**2) + self.mgl * self.u0
        self.alpha = (2.0 * energy - self.I3 * self.w3**2) / self.I1
        self.beta = 2.0 * self.mgl / self.I1
        self.a = hz / self.I1
        self.b = self.I3 * self.w3 / self.I1
        transverse = math.hypot(w_t[0], w_t[1])
        if sin_theta0 == 0.0:
            if transverse == 0.0:
                raise _Sleeping()
            raise NotIntegrable(
                "the top starts exactly upright with a transverse ω: its axis passes through the "
                "vertical, where the Euler angles of the closed form break down"
            )
        u_dot0 = -sin_theta0 * theta_dot0
        self.u1, self.u2, self.u3 = self._roots(u_dot0)
        self.delta = self.u2 - self.u1
        if 1.0 - self.u2 <= VERTICAL_MARGIN or 1.0 + self.u1 <= VERTICAL_MARGIN:
            raise NotIntegrable(
                "the top's axis passes through the vertical (straight up or down), where the "
                "Euler angles of the closed form break down"
            )
        self.sigma_rate = 0.5 * math.sqrt(self.beta * (self.u3 - self.u1))
        self.ell = _Elliptic(self.delta / (self.u3 - self.u1))
        ratio = min(max((self.u0 - self.u1) / self.delta, 0.0), 1.0) if self.delta > 0 else 0.0
        self.sigma0 = math.copysign(
            ellipkinc(math.asin(math.sqrt(ratio)), self.ell.m),
            u_dot0 if u_dot0 != 0 else (1.0 if ratio > 0.5 else -1.0),
        )
        self.n_plus = self.delta / (1.0 - self.u1)
        self.n_minus = -self.delta / (1.0 + self.u1)
        self.description = "Lagrange top (Jacobi elliptic functions, elliptic integrals)"

    def _roots(self, u_dot0: float) -> tuple[float, float, float]:
        """u₁ ≤ u₂ ≤ u₃ of the cubic, polished by Newton steps; the starting u is kept exact
        when it is a turning point (u̇ = 0)."""
        beta, alpha, a, b = self.beta, self.alpha, self.a, self.b
        coeffs = np.array([beta, -(alpha + b * b), 2.0 * a * b - beta, alpha - a * a])
        roots = np.sort(np.roots(coeffs).real)
        polished = []
        for u in roots:
            for _ in range(3):
                slope = np.polyval(np.polyder(coeffs), u)
                if slope == 0.0:
                    break
                u = u - np.polyval(coeffs, u) / slope
            polished.append(float(u))
        if u_dot0 == 0.0:
            # u0 is a root: the other two from the deflated quadratic β u² + c1 u + c0
            c1 = coeffs[1] + beta * self.u0
            c0 = coeffs[2] + c1 * self.u0
            disc = max(c1 * c1 - 4.0 * beta * c0, 0.0)
            r1 = (-c1 - math.copysign(math.sqrt(disc), c1)) / (2.0 * beta)
            r2 = c0 / (beta * r1) if r1 != 0.0 else -c1 / beta
            polished = [self.u0, r1, r2]
        polished.sort()
        return polished[0], polished[1], polished[2]

    @cached_property
    def J0(self) -> tuple[float, float]:
        """G(n±; σ₀): the third-kind integrals at the start (computed when a state is asked for,
        so that :meth:`facts` needs no scipy)."""
        s0 = np.array([self.sigma0])
        return float(self.ell.G(self.n_plus, s0)[0]), float(self.ell.G(self.n_minus, s0)[0])

    def _angles(self, t: np.ndarray):
        sigma = self.sigma_rate * t + self.sigma0
        sn, cn, dn, _, _ = self.ell.functions(sigma)
        one_minus_u = (1.0 - self.u1) - self.delta * sn * sn
        one_plus_u = (1.0 + self.u1) + self.delta * sn * sn
        u = self.u1 + self.delta * sn * sn
        sin_theta = np.sqrt(one_minus_u * one_plus_u)
        theta = np.arctan2(sin_theta, u)
        jp = (self.ell.G(self.n_plus, sigma) - self.J0[0]) / (self.sigma_rate * (1.0 - self.u1))
        jm = (self.ell.G(self.n_minus, sigma) - self.J0[1]) / (self.sigma_rate * (1.0 + self.u1))
        half_minus, half_plus = 0.5 * (self.a - self.b), 0.5 * (self.a + self.b)
        phi = self.phi0 + half_minus * jp + half_plus * jm
        psi = self.psi0 + (self.w3 - self.b) * t - half_minus * jp + half_plus * jm
        u_dot = 2.0 * self.delta * sn * cn * dn * self.sigma_rate
        phi_dot = (self.a - self.b * u) / (one_minus_u * one_plus_u)
        theta_dot = -u_dot / sin_theta
        return phi, theta, psi, phi_dot, theta_dot

    def state_at(self, t: np.ndarray):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        phi, theta, psi, phi_dot, theta_dot = self._angles(t)
        q = unit_vector(qmul(_zxz(phi, theta, psi), self.q_tb))
        st = np.sin(theta)
        w_t = np.stack(
            (
                phi_dot * st * np.sin(psi) + theta_dot * np.cos(psi),
                phi_dot * st * np.cos(psi) - theta_dot * np.sin(psi),
                np.full_like(t, self.w3),
            ),
            axis=-1,
        )
        return q, w_t @ self.rows

    @property
    def nutation_period(self) -> float:
        """Period of θ: 2K(m)/σ̇ = 4K(m)/√(β(u₃ − u₁)) (s)."""
        return 2.0 * self.ell.K / self.sigma_rate

    @property
    def tilt_bounds_deg(self) -> tuple[float, float]:
        """Smallest and largest tilt of the axis from vertical (deg): arccos u₂, arccos u₁."""
        return math.degrees(math.acos(min(self.u2, 1.0))), math.degrees(math.acos(max(self.u1, -1.0)))

    @property
    def mean_precession_rate(self) -> float:
        """Mean of φ̇ over a nutation period (rad/s)."""
        period_sigma = 2.0 * self.ell.K
        jp = 2.0 * ellippi(self.n_plus, self.ell.m) / (self.sigma_rate * (1.0 - self.u1))
        jm = 2.0 * ellippi(self.n_minus, self.ell.m) / (self.sigma_rate * (1.0 + self.u1))
        return (0.5 * (self.a - self.b) * jp + 0.5 * (self.a + self.b) * jm) / (
            period_sigma / self.sigma_rate
        )

    def facts(self) -> dict[str, Any]:
        low, high = self.tilt_bounds_deg
        return {
            "kind": "Lagrange top",
            "nutation_tilt_min_deg": low,
            "nutation_tilt_max_deg": high,
            "nutation_period_s": self.nutation_period,
            "mean_precession_rate_deg_s": math.degrees(self.mean_precession_rate),
            "cos_tilt_roots": [self.u1, self.u2, self.u3],
        }


class _Sleeping(Exception):
    pass


def solve(scene: Scene, q0, omega0):
    """The closed-form solution of ``scene`` from ``(q0, omega0)``; NotIntegrable when there
    is none (a heavy top that is not a Lagrange top, or a degenerate start)."""
    q0 = np.asarray(q0, dtype=float) / np.linalg.norm(q0)
    omega0 = np.asarray(omega0, dtype=float).reshape(3)
    torque_free = not scene.pivoted or scene.gravity == 0.0 or not np.any(scene.com_from_pivot)
    if torque_free:
        return _free(scene, q0, omega0)
    axis = symmetry_axis(scene)
    if axis is None:
        raise NotIntegrable(
            "a heavy top has a closed form only when it is axisymmetric about the pivot with its "
            "centre of mass on the axis (Lagrange top); this one is not"
        )
    try:
        return LagrangeTop(scene, q0, omega0, axis)
    except _Sleeping:
        return UniformRotation(q0, omega0, "sleeping top: steady spin about the vertical axis")


def _free(scene: Scene, q0, omega0):
    rate = float(np.linalg.norm(omega0))
    moments, axes = scene.principal_moments, scene.principal_axes
    if rate == 0.0:
        return UniformRotation(q0, omega0, "at rest")
    components = axes @ omega0
    for i in range(3):
        others = np.delete(components, i)
        if np.all(np.abs(others) <= PARALLEL_RTOL * rate):
            return UniformRotation(q0, omega0, f"steady spin about principal axis {i + 1}")
    scale = moments[-1]
    if moments[1] - moments[0] <= AXISYMMETRY_RTOL * scale:
        return SymmetricFreeBody(scene, q0, omega0, axes[2])
    if moments[2] - moments[1] <= AXISYMMETRY_RTOL * scale:
        return SymmetricFreeBody(scene, q0, omega0, axes[0])
    return EulerPoinsot(scene, q0, omega0)
