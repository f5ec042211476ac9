"""Uncertainty of a body's mass properties from the uncertainty of its parts' inputs, as JCGM 100
(the GUM: the law of propagation, first order) and JCGM 101 (Monte Carlo) treat it.

A body's mass, first and second moments are sums over its parts, so an input of one part moves
only that part's term: :func:`body_derivatives` turns each input's derivative of its part's
``(mass, centre of mass, inertia)`` into the derivative of the body's mass, centre of mass and
inertia about a point (exact linear algebra), :func:`principal_derivatives` those of the
principal moments and axes (first-order eigen-perturbation). :func:`body_stack` sums n drawn
versions of the parts into n bodies at once. Units are the caller's (L, M, M·L²).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from rbi.core.inertia import principal_axes, symmetrize


def _shift_term(mass: np.ndarray, r: np.ndarray) -> np.ndarray:
    """``m (|r|² E − r rᵀ)`` for stacks: mass (...,), r (..., 3) → (..., 3, 3)."""
    rr = r[..., :, None] * r[..., None, :]
    return mass[..., None, None] * (np.einsum("...i,...i", r, r)[..., None, None] * np.eye(3) - rr)


def body_derivatives(
    masses: np.ndarray,
    coms: np.ndarray,
    part: np.ndarray,
    dm: np.ndarray,
    dc: np.ndarray,
    dI: np.ndarray,
    point: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(dM (k,), dC (k, 3), dJ (k, 3, 3))``: how the body's mass, centre of mass and inertia
    about the fixed ``point`` move with each of k inputs, from the parts' masses (P,) and
    centres of mass (P, 3) and, per input, the index of its part and that part's ``dm``, ``dc``
    (k, 3), ``dI`` (k, 3, 3) (a hole's mass and inertia counted negative). About the body's
    own centre of mass, ``point`` = that centre: its move changes the inertia only at second
    order, so dJ is then the derivative of the inertia about the centre of mass."""
    m, c = masses[part], coms[part]
    total = float(np.sum(masses))
    com = masses @ coms / total
    r = c - point
    rr = np.einsum("ki,ki->k", r, dc)
    dT = 2.0 * rr[:, None, None] * np.eye(3) - dc[:, :, None] * r[:, None, :] - r[:, :, None] * dc[:, None, :]
    dJ = dI + _shift_term(dm, r) + m[:, None, None] * dT
    dC = (dm[:, None] * (c - com) + m[:, None] * dc) / total
    return dm, dC, dJ


def principal_derivatives(
    inertia: np.ndarray, dI: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(moments (3,), axes (3, 3) rows, dmoments (k, 3), dturn (k, 3, 3))`` of the inertia and
    k derivatives of it: ``dλᵢ = eᵢᵀ dI eᵢ``, and ``dturn[:, i, j]`` the turn of axis i towards
    axis j, ``eⱼᵀ dI eᵢ / (λᵢ − λⱼ)`` (inf or nan for a pair of equal moments)."""
    moments, axes = principal_axes(inertia)
    projected = np.einsum("ia,kab,jb->kij", axes, dI, axes)
    gaps = moments[:, None] - moments[None, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        turn = projected / gaps
    turn[:, np.arange(3), np.arange(3)] = 0.0
    return moments, axes, np.einsum("kii->ki", projected), turn


def combined(sensitivities: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The law of propagation for independent inputs (GUM 5.1.2): ``√Σₖ (∂y/∂xₖ · u(xₖ))²``
    for each quantity; ``sensitivities`` (..., k), ``u`` (k,)."""
    return scale_safe(lambda terms: np.sqrt(np.sum(terms**2, axis=-1)), sensitivities * u)


def squares_lost(total: np.ndarray, largest: np.ndarray) -> np.ndarray:
    """Where a root of a sum of squares, ``total``, is not the true value: its largest term
    ``largest`` is a finite number other than 0, but ``total`` lies outside 1e-150..1e150 (the
    squares overflowed to inf or underflowed to 0 or subnormal numbers)."""
    return np.isfinite(largest) & (largest > 0) & ~((total > 1e-150) & (total < 1e150))


def scale_safe(root: Callable[[np.ndarray], np.ndarray], terms: np.ndarray) -> np.ndarray:
    """``root(terms)``, a root of a sum of squares over the last axis (so ``root(c x) = c
    root(x)``: a root-sum-square, a standard deviation), taken again on the terms divided by
    their largest where the squares leave a double (terms past 1e154 or below 1e-154), so it
    is the true value rather than inf or 0. Ordinary terms get the plain formula, bit for bit."""
    with np.errstate(over="ignore", under="ignore"):
        total = root(terms)
    largest = np.max(np.abs(terms), axis=-1, initial=0.0)
    lost = squares_lost(total, largest)
    if np.any(lost):
        scale = np.where(lost, largest, 1.0)
        total = np.where(lost, scale * root(terms / scale[..., None]), total)
    return total


def axis_uncertainty_deg(moments: np.ndarray, u_moments: np.ndarray, turn: np.ndarray, u: np.ndarray) -> list:
    """Each principal axis's standard angular uncertainty (degrees), the root of the variances
    of its turns towards the two other axes; None for an axis of a pair of moments closer than 3
    combined standard uncertainties (the data do not determine it there)."""
    found: list[float | None] = []
    for i in range(3):
        others = [j for j in range(3) if j != i]
        if any(abs(moments[i] - moments[j]) <= 3.0 * math.hypot(u_moments[i], u_moments[j]) for j in others):
            found.append(None)
            continue
        variance = sum(float(np.sum((turn[:, i, j] * u) ** 2)) for j in others)
        found.append(math.degrees(math.sqrt(variance)))
    return found


def body_stack(
    masses: np.ndarray, coms: np.ndarray, inertias: np.ndarray, point: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """n bodies at once from their parts: masses (n, P), centres of mass (n, P, 3), inertias
    about them (n, P, 3, 3) → mass (n,), centre of mass (n, 3), inertia about it (n, 3, 3).
    Moments are taken about ``point`` (near the body: the nominal centre of mass) so that only
    small offsets enter."""
    total = masses.sum(axis=1)
    r = coms - point
    first = np.einsum("np,npi->ni", masses, r) / total[:, None]
    about_point = inertias.sum(axis=1) + _shift_term(masses, r).sum(axis=1)
    inertia = about_point - _shift_term(total, first)
    return total, point + first, symmetrize(inertia)


def coverage_factor(coverage: float) -> float:
    """k of the interval value ± k·u holding ``coverage`` of a normal distribution."""
    from statistics import NormalDist  # not at top level: `rbi inertia` would load statistics too

    return NormalDist().inv_cdf(0.5 + coverage / 2.0)


def shortest_interval(samples: np.ndarray, coverage: float) -> tuple[float, float]:
    """The shortest interval holding ``coverage`` of the samples (JCGM 101 §7.7.2)."""
    ordered = np.sort(samples)
    n = len(ordered)
    q = min(max(int(coverage * n + 0.5), 1), n - 1)
    widths = ordered[q:] - ordered[: n - q]
    low = int(np.argmin(widths))
    return float(ordered[low]), float(ordered[low + q])


def validated(u: float, interval: tuple[float, float], mc: tuple[float, float]) -> bool:
    """Whether the linear result (standard uncertainty ``u``, coverage ``interval``) is
    validated by the Monte Carlo coverage interval ``mc`` (JCGM 101 §8.2; the probabilistically
    symmetric one, whose ends vary less from run to run than the shortest's): both ends within
    the numerical tolerance δ of u written to two significant digits (§7.9.2)."""
    delta = 0.5 * 10.0 ** (math.floor(math.log10(u)) - 1) if u > 0 else 0.0
    return abs(interval[0] - mc[0]) <= delta and abs(interval[1] - mc[1]) <= delta
