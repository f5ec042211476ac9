"""Complete and incomplete elliptic integrals for scalars, in plain Python (``math`` only), so
that the closed-form facts ``rbi simulate`` reports (nutation period, mean precession rate of a
Lagrange top) need no scipy import, which costs more than the simulation itself.

Carlson's symmetric forms by the duplication theorem (B. C. Carlson, "Numerical computation of
real or complex elliptic integrals", Numer. Algorithms 10 (1995); DLMF §19.36(i)), iterated until
the remaining series is below double precision; then

- K(m) = R_F(0, 1 − m, 1)
- F(φ | m) = sin φ R_F(cos² φ, 1 − m sin² φ, 1) for |φ| ≤ π/2, extended by F(φ + kπ) = F(φ) + 2kK
- Π(n | m) = R_F(0, 1 − m, 1) + (n/3) R_J(0, 1 − m, 1, 1 − n) for n < 1 (p = 1 − n > 0)

``tests/sim/test_elliptic.py`` compares them with ``scipy.special``.
"""

from __future__ import annotations

import math

_RF_FACTOR = (3.0 * 2.0**-53) ** (-1.0 / 6.0)
_RJ_FACTOR = (0.25 * 2.0**-53) ** (-1.0 / 6.0)


def carlson_rf(x: float, y: float, z: float) -> float:
    """R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)), x, y, z ≥ 0 with at most one zero."""
    if min(x, y, z) < 0.0 or (x == 0.0) + (y == 0.0) + (z == 0.0) > 1:
        raise ValueError("carlson_rf: arguments must be >= 0 with at most one zero")
    x0, y0 = x, y
    a0 = a = (x + y + z) / 3.0
    q = _RF_FACTOR * max(abs(a0 - x), abs(a0 - y), abs(a0 - z))
    scale = 1.0
    while scale * q >= abs(a):
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * sy + sx * sz + sy * sz
        x, y, z, a = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (a + lam)
        scale *= 0.25
    dx, dy = (a0 - x0) * scale / a, (a0 - y0) * scale / a
    dz = -dx - dy
    e2, e3 = dx * dy - dz * dz, dx * dy * dz
    return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / math.sqrt(a)


def _rc_one(e: float) -> float:
    """R_C(1, 1 + e) for e > −1."""
    if e > 0.0:
        s = math.sqrt(e)
        return math.atan(s) / s
    if e < 0.0:
        s = math.sqrt(-e)
        return math.atanh(s) / s
    return 1.0


def carlson_rj(x: float, y: float, z: float, p: float) -> float:
    """R_J(x, y, z, p) = 3/2 ∫₀^∞ dt / ((t+p) √((t+x)(t+y)(t+z))), x, y, z ≥ 0 with at most one
    zero, p > 0."""
    if min(x, y, z) < 0.0 or (x == 0.0) + (y == 0.0) + (z == 0.0) > 1 or not p > 0.0:
        raise ValueError("carlson_rj: x, y, z must be >= 0 with at most one zero, and p > 0")
    x0, y0, z0 = x, y, z
    a0 = a = (x + y + z + 2.0 * p) / 5.0
    delta = (p - x) * (p - y) * (p - z)
    q = _RJ_FACTOR * max(abs(a0 - x), abs(a0 - y), abs(a0 - z), abs(a0 - p))
    scale = 1.0  # 4^-m
    total = 0.0
    while scale * q >= abs(a):
        sx, sy, sz, sp = math.sqrt(x), math.sqrt(y), math.sqrt(z), math.sqrt(p)
        lam = sx * sy + sx * sz + sy * sz
        d = (sp + sx) * (sp + sy) * (sp + sz)
        e = scale * scale * scale * delta / (d * d)
        total += scale * _rc_one(e) / d
        x, y, z = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam)
        p, a = 0.25 * (p + lam), 0.25 * (a + lam)
        scale *= 0.25
    dx, dy, dz = ((a0 - v) * scale / a for v in (x0, y0, z0))
    dp = -0.5 * (dx + dy + dz)
    e2 = dx * dy + dx * dz + dy * dz - 3.0 * dp * dp
    e3 = dx * dy * dz + 2.0 * e2 * dp + 4.0 * dp**3
    e4 = (2.0 * dx * dy * dz + e2 * dp + 3.0 * dp**3) * dp
    e5 = dx * dy * dz * dp * dp
    series = (
        1.0
        - 3.0 * e2 / 14.0
        + e3 / 6.0
        + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
    )
    return scale * series / (a * math.sqrt(a)) + 6.0 * total


def ellipk(m: float) -> float:
    """K(m), the complete elliptic integral of the first kind, parameter m < 1."""
    if not m < 1.0:
        raise ValueError(f"ellipk: parameter m must be < 1 (got {m!r})")
    return carlson_rf(0.0, 1.0 - m, 1.0)


def ellipkinc(phi: float, m: float) -> float:
    """F(φ | m), the incomplete elliptic integral of the first kind, 0 ≤ m < 1, any real φ."""
    half_turns = math.floor(phi / math.pi + 0.5)  # φ = kπ + r, |r| ≤ π/2
    r = phi - half_turns * math.pi
    s, c = math.sin(r), math.cos(r)
    value = s * carlson_rf(c * c, 1.0 - m * s * s, 1.0) if s != 0.0 else 0.0
    return value + (2.0 * half_turns * ellipk(m) if half_turns else 0.0)


def ellippi(n: float, m: float) -> float:
    """Π(n | m), the complete elliptic integral of the third kind, n < 1, m < 1."""
    value = carlson_rf(0.0, 1.0 - m, 1.0)
    if n != 0.0:
        value += n / 3.0 * carlson_rj(0.0, 1.0 - m, 1.0, 1.0 - n)
    return value
