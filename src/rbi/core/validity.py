"""Can a number be computed with (:func:`finite`, :func:`whole`, :func:`subnormal_problem`), and is a
3×3 matrix a physically possible inertia matrix?

The tests follow MuJoCo's compiler and Drake's ``RotationalInertia::CouldBePhysicallyValid``:
finite, symmetric, principal moments not negative, and the triangle inequality
``I1 + I2 ≥ I3`` on the principal moments (no real mass distribution violates it: each
moment is a sum of two of the three second moments ∫x² dm, ∫y² dm, ∫z² dm).

Rounding is forgiven relative to the size of the matrix, never with an absolute floor:
a tolerance of ``rtol · scale`` where ``scale`` defaults to the largest moment the matrix
could have (half its trace). Inertias of small parts in SI (10⁻⁹ kg·m² and less) are thus
judged exactly as strictly as large ones.
"""

from __future__ import annotations

import math
import numbers
import sys
from typing import Any, NamedTuple

import numpy as np

SMALLEST_NORMAL = sys.float_info.min
"""The smallest positive double with all its digits (2.2e-308): a mass, size or density below
it is subnormal, and the moments computed from it lose their digits or vanish to 0."""


def finite(value: Any) -> bool:
    """True for a finite real number a double holds (a bool is not one, nor an integer such as
    10**400, which ``float`` cannot convert)."""
    if isinstance(value, bool):
        return False
    try:
        return math.isfinite(value)
    except (TypeError, OverflowError):
        return False


def require_flags(**values: Any) -> None:
    """TypeError naming the parameter when one of ``values``, a public function's switch, is not
    True or False (the text ``"no"`` would be taken as true)."""
    for name, value in values.items():
        if not isinstance(value, (bool, np.bool_)):
            raise TypeError(f"{name}: must be True or False (got {type(value).__name__} {value!r:.60})")


def require_callable(**values: Any) -> None:
    """TypeError naming the parameter when one of ``values`` (a callback: ``progress``) is neither
    None nor callable, before any work (not at its first call)."""
    for name, value in values.items():
        if value is not None and not callable(value):
            raise TypeError(f"{name}: must be a function or None (got {type(value).__name__} {value!r:.60})")


def whole(value: Any) -> bool:
    """True for a whole number (a bool is not one)."""
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def subnormal_problem(value: float) -> str | None:
    """Why ``value`` (any input number) cannot be computed with: it is subnormal (not 0, and
    smaller in size than :data:`SMALLEST_NORMAL`); None when it is fine."""
    if value != 0 and abs(value) < SMALLEST_NORMAL:
        return (
            f"{value!r} is subnormal (smaller than {SMALLEST_NORMAL:.3g}, the smallest double with "
            "all its digits): the moments computed from it would lose their digits or vanish"
        )
    return None


INERTIA_RTOL = 1e-9
"""Default relative tolerance: well above the rounding of any double computation on the
matrix (Drake uses 16 ε ≈ 3.6·10⁻¹⁵), well below any physical difference."""


def overflowing_sum(inertia: np.ndarray) -> str | None:
    """Why the finite entries of ``inertia`` (any units) cannot be computed with: their
    magnitudes add up beyond the largest double (so every sum of moments, such as a trace or
    a parallel-axis shift, overflows); None when they do not."""
    with np.errstate(over="ignore"):  # the overflow is the answer, not a warning to print
        total = np.sum(np.abs(inertia))
    if np.isfinite(total):
        return None
    return (
        f"numbers too large: the entries (largest {float(np.max(np.abs(inertia))):.3g}) "
        f"add up beyond the largest double, {np.finfo(float).max:.3g}"
    )


class InertiaProblem(NamedTuple):
    """Why a matrix is not a valid inertia: ``kind`` is ``'not finite'``, ``'not symmetric'``,
    ``'negative moment'`` or ``'triangle inequality'`` (``'not finite'`` also when the entries
    are so large that their sum overflows); ``message`` says it in words with the
    numbers."""

    kind: str
    message: str


def inertia_problem(
    inertia: np.ndarray, rtol: float = INERTIA_RTOL, scale: float | None = None
) -> InertiaProblem | None:
    """The first reason ``inertia`` (M·L², any axes, about any point) is not physically
    possible, or None when it is.

    ``scale`` (M·L²) sets the size against which ``rtol`` forgives rounding; give the gross
    size when the matrix is a small difference of large ones (a body with holes).
    """
    I = np.asarray(inertia, dtype=float)
    if I.shape != (3, 3) or not np.all(np.isfinite(I)):
        return InertiaProblem("not finite", "inertia must be a finite 3×3 matrix")
    too_large = overflowing_sum(I)
    if too_large:
        return InertiaProblem("not finite", f"{too_large}; is the unit right?")
    size = 0.5 * abs(float(np.trace(I))) if scale is None else float(scale)
    tol = rtol * size
    asymmetry = float(np.max(np.abs(I - I.T)))
    if asymmetry > tol:
        row, col = np.unravel_index(int(np.argmax(np.abs(I - I.T))), (3, 3))
        i, j = sorted((int(row), int(col)))
        return InertiaProblem(
            "not symmetric",
            f"not symmetric: entry [{i}][{j}] = {I[i, j]:.6g} but [{j}][{i}] = {I[j, i]:.6g}; an inertia matrix "
            f"equals its transpose: give both the same value",
        )
    moments = np.linalg.eigvalsh(0.5 * I + 0.5 * I.T)  # ascending; I + I.T could overflow
    I1, I2, I3 = (float(m) for m in moments)
    if I1 < -tol:
        return InertiaProblem(
            "negative moment",
            f"not positive definite: principal moment I1 = {I1:.6g} < 0 "
            f"(principal moments {I1:.6g}, {I2:.6g}, {I3:.6g}); no real body has a negative moment: check the "
            f"signs (products are the matrix entries, −∫xy dm: a tool listing +∫xy dm needs them negated)",
        )
    if I1 + I2 < I3 - tol:
        return InertiaProblem(
            "triangle inequality",
            f"violates the triangle inequality I1 + I2 >= I3 on the principal moments: "
            f"{I1:.6g} + {I2:.6g} = {I1 + I2:.6g} < {I3:.6g}; no mass distribution has these moments (the largest "
            f"is at most the sum of the other two): check that all are about one point and in one unit",
        )
    return None


NOISE_LENGTH = 1e-6
"""A declared inertia's rounding noise may reach its mass times this length squared (1 µm)²."""


def declared_inertia_problem(mass: float, inertia: np.ndarray) -> InertiaProblem | None:
    """:func:`inertia_problem` for an inertia a file declares with a mass: a negative moment or
    triangle-inequality deficit smaller than ``INERTIA_RTOL`` of the largest moment, or than
    ``mass × (1 µm)²``, is rounding noise (a CAD export's ``ixx = -5.4e-20`` on a 0.53 kg link)."""
    I = np.asarray(inertia, dtype=float)
    if I.shape == (3, 3) and np.all(np.isfinite(I)) and np.isfinite(np.sum(np.abs(I))):
        largest = float(np.max(np.abs(np.linalg.eigvalsh(0.5 * I + 0.5 * I.T))))
        floor = max(float(mass), 0.0) * NOISE_LENGTH**2 / INERTIA_RTOL
        return inertia_problem(I, scale=max(largest, floor, 0.5 * abs(float(np.trace(I)))))
    return inertia_problem(I)
