"""Inertia matrices: moving the reference point, turning the frame, principal axes (the value
type that carries them with a mass and a centre of mass is :class:`rbi.core.mass.MassProperties`).

Conventions: ``I = ∫ (|r|² E − r rᵀ) dm`` (products of inertia carry a minus sign);
``R`` always maps body coordinates to world coordinates.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from rbi.core.rotation import numbers, unit_vector

OFF_DIAGONAL = ~np.eye(3, dtype=bool)
"""The mask of a (3, 3) matrix's products of inertia (its off-diagonal entries)."""


def point_mass_inertia(mass: ArrayLike, offset: np.ndarray) -> np.ndarray:
    """Inertia ``m (|r|² E − r rᵀ)`` of a point mass at ``offset`` from the reference point
    (masses (...,) and offsets (..., 3) give (..., 3, 3))."""
    r = numbers(offset)
    r2 = np.sum(r * r, axis=-1)[..., None, None]
    return numbers(mass)[..., None, None] * (r2 * np.eye(3) - r[..., :, None] * r[..., None, :])


def parallel_axis(inertia_com: np.ndarray, mass: ArrayLike, offset: np.ndarray) -> np.ndarray:
    """Inertia about a point ``offset`` away from the centre of mass (parallel-axis theorem).

    ``inertia_com`` is about the centre of mass; the result has the same axes. Only the length
    and direction of the offset matter, not its sign. Stacks broadcast: (..., 3, 3), (...,),
    (..., 3).
    """
    return numbers(inertia_com) + point_mass_inertia(mass, offset)


def parallel_axis_to_com(inertia_about_point: np.ndarray, mass: float, offset: np.ndarray) -> np.ndarray:
    """Inverse of :func:`parallel_axis`: inertia about the centre of mass from that about a
    point ``offset`` away from it."""
    return numbers(inertia_about_point) - point_mass_inertia(mass, offset)


def centre_of_mass(masses: np.ndarray, positions: np.ndarray) -> np.ndarray:
    """Mass-weighted mean of ``positions`` (N×3), accurate far from the origin.

    Positions are averaged relative to the heaviest part, then one correction pass removes
    the rounding left over, so that a small body 1 km from the origin keeps its digits.
    """
    m = numbers(masses)
    p = numbers(positions).reshape(-1, 3)
    total = m.sum()
    reference = p[int(np.argmax(np.abs(m)))]
    com = reference + (m @ (p - reference)) / total
    return com + (m @ (p - com)) / total


def re_express(inertia: np.ndarray, R: np.ndarray) -> np.ndarray:
    """Inertia in world axes, ``R I Rᵀ``, for a body turned by ``R`` (body -> world)."""
    R = numbers(R)
    return symmetrize(R @ numbers(inertia) @ R.T)


def symmetrize(matrix: np.ndarray) -> np.ndarray:
    """``(A + Aᵀ)/2``: removes the rounding asymmetry of a computed symmetric matrix (or of
    each of a stack (..., 3, 3))."""
    return 0.5 * (matrix + np.swapaxes(matrix, -1, -2))


# --- principal axes ------------------------------------------------------------------------

DEGENERATE_RTOL = 1e-9
"""Moments closer than this (relative to the largest) are treated as equal: their axes are
then any orthonormal pair of the shared plane, and rbi picks a canonical one."""


def principal_axes(inertia: np.ndarray, rtol: float = DEGENERATE_RTOL) -> tuple[np.ndarray, np.ndarray]:
    """Principal moments (ascending) and axes of a symmetric inertia matrix.

    Returns ``moments`` (3,) and ``axes`` (3, 3) with ``axes[i]`` the unit axis of
    ``moments[i]``, in the same frame as ``inertia``. The axes always form a right-handed
    orthonormal set and are chosen deterministically: each axis of a distinct moment points
    with its largest component positive; where two moments coincide (to ``rtol``) the pair is
    built from the coordinate axis closest to their shared plane; where all three coincide
    the axes are the coordinate axes.
    """
    moments, vectors = symmetric_eigen(np.asarray(inertia, dtype=float))
    return moments, _chosen_axes(moments[None], vectors.T[None], rtol)[0]


def symmetric_eigen(matrix: np.ndarray, max_sweeps: int = 30) -> tuple[np.ndarray, np.ndarray]:
    """Eigenvalues (ascending) and eigenvectors (columns) of a symmetric 3×3 matrix by cyclic
    Jacobi rotations.

    Chosen over LAPACK's ``eigh`` for two reasons: an off-diagonal entry that is exactly zero
    is never touched, so a body symmetric about a coordinate plane gets axes with exact zeros
    instead of 1e-16 noise; and Jacobi's stopping rule ``|a_pq| ≤ ε·sqrt(a_pp·a_qq)`` keeps
    small eigenvalues of positive definite matrices accurate relative to themselves.
    """
    A = symmetrize(np.array(matrix, dtype=float))
    V = np.eye(3)
    eps = np.finfo(float).eps
    for _ in range(max_sweeps):
        rotated = False
        for p, q in ((0, 1), (0, 2), (1, 2)):
            apq = A[p, q]
            if apq == 0.0:
                continue
            if abs(apq) <= eps * np.sqrt(abs(A[p, p])) * np.sqrt(abs(A[q, q])):  # no overflow
                A[p, q] = A[q, p] = 0.0
                continue
            gap = A[q, q] - A[p, p]
            if abs(apq) <= 1e-150 * abs(gap):  # θ² would overflow; t = 1/(2θ) to full precision
                t = apq / gap
            else:
                theta = gap / (2.0 * apq)
                t = np.copysign(1.0, theta) / (abs(theta) + np.sqrt(theta * theta + 1.0))
            c = 1.0 / np.sqrt(t * t + 1.0)
            s = t * c
            J = np.eye(3)
            J[p, p] = J[q, q] = c
            J[p, q] = s
            J[q, p] = -s
            A = J.T @ A @ J
            A[p, q] = A[q, p] = 0.0
            V = V @ J
            rotated = True
        if not rotated:
            break
    values = np.diag(A).copy()
    order = np.argsort(values, kind="stable")
    return values[order], V[:, order]


def principal_axes_of_stack(
    inertias: np.ndarray, rtol: float = DEGENERATE_RTOL
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`principal_axes` of each of a stack of inertias (n, 3, 3), at once: moments (n, 3)
    and axes (n, 3, 3), chosen by the same rules, from LAPACK's ``eigh`` of the whole stack
    (the single body's Jacobi rotations keep a little more of the smallest moments' digits)."""
    moments, vectors = np.linalg.eigh(symmetrize(np.asarray(inertias, dtype=float)))
    return moments, _chosen_axes(moments, np.swapaxes(vectors, -1, -2), rtol)


def _chosen_axes(moments: np.ndarray, axes: np.ndarray, rtol: float) -> np.ndarray:
    """The axes :func:`principal_axes` chooses, for each of a stack of ascending moments (n, 3)
    and unit eigenvectors (rows, (n, 3, 3))."""
    scale = np.max(np.abs(moments), axis=-1, keepdims=True)
    close: np.ndarray = np.diff(moments, axis=-1) <= rtol * np.where(scale > 0.0, scale, 1.0)
    first, second = _canonical_sign(axes[:, 0]), _canonical_sign(axes[:, 1])
    third = np.cross(first, second)
    distinct = np.stack([first, second, third / np.linalg.norm(third, axis=-1, keepdims=True)], axis=1)
    lone_last = close[:, 0, None]  # moments 0 and 1 coincide: moment 2 stands alone
    u = _canonical_sign(np.where(lone_last, axes[:, 2], axes[:, 0]))
    a = _closest_coordinate_axis_in_plane(u)
    b = np.cross(u, a)
    pair = np.where(lone_last[..., None], np.stack([a, b, u], axis=1), np.stack([u, a, b], axis=1))
    chosen = np.where(np.any(close, axis=-1)[:, None, None], pair, distinct)
    return np.where(np.all(close, axis=-1)[:, None, None], np.eye(3), chosen)


def _canonical_sign(v: np.ndarray) -> np.ndarray:
    """``v`` or ``-v`` (each of a stack (..., 3)): the one whose largest-magnitude component is
    positive (earliest component wins near-ties, so rounding noise cannot flip the choice)."""
    magnitudes = np.abs(v)
    k = np.argmax(magnitudes >= magnitudes.max(axis=-1, keepdims=True) * (1.0 - 1e-9), axis=-1)
    return np.where(np.take_along_axis(v, k[..., None], axis=-1) > 0, v, -v)


def _closest_coordinate_axis_in_plane(normal: np.ndarray) -> np.ndarray:
    """Unit projection, onto the plane ⟂ ``normal`` (each of a stack (..., 3)), of the
    coordinate axis that lies most in that plane (earliest axis wins near-ties)."""
    projections = np.eye(3) - normal[..., :, None] * normal[..., None, :]  # row k: e_k projected
    norms = np.linalg.norm(projections, axis=-1)
    k = np.argmax(norms >= norms.max(axis=-1, keepdims=True) * (1.0 - 1e-9), axis=-1)[..., None]
    row = np.take_along_axis(projections, k[..., None], axis=-2)[..., 0, :]
    return row / np.take_along_axis(norms, k, axis=-1)


# --- one axis, radii of gyration, the sign of products --------------------------------------


def unit_axis(axis: ArrayLike) -> np.ndarray:
    """``axis`` scaled to unit length; ValueError when it is zero or not finite."""
    try:
        n = np.asarray(axis, dtype=float).reshape(3)
    except (OverflowError, TypeError):  # an integer no double holds (10**400), no number (None, object())
        raise ValueError(f"the axis must be a non-zero finite direction, got {axis!r:.60}") from None
    return unit_vector(n)  # any size: 1e200 or 1e-200 components are still a direction; refuses 0 and inf


def moment_about_axis(inertia_about_point: np.ndarray, axis: Sequence[float]) -> float:
    """Scalar moment of inertia ``nᵀ I n`` (M·L²) about the line through the reference point
    of ``inertia_about_point`` along ``axis`` (any non-zero length, same axes as the matrix).

    It equals ``∫ d² dm`` with ``d`` the distance of each mass element from that line.
    """
    n = unit_axis(axis)
    return float(n @ np.asarray(inertia_about_point, dtype=float) @ n)


def radii_of_gyration(moments: Sequence[float], mass: float) -> np.ndarray:
    """Radius of gyration ``k = sqrt(I / m)`` (L) for each moment (M·L²): the distance from
    the axis at which the whole mass would have the same moment. A moment that rounding made
    slightly negative gives 0."""
    I = np.asarray(moments, dtype=float)
    return np.sqrt(np.clip(I, 0.0, None) / float(mass))
