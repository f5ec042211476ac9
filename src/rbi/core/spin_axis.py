"""The spin axis of a body: the body-frame direction `--spin` turns about, whose tilt from the
vertical and azimuth (precession) a run reports.

Public names:

- :func:`distinct_principal_axis`: the axis of an axisymmetric inertia (exactly two equal moments).
- :func:`default_spin_axis`: the rule every command uses when no axis is given.
- :func:`quaternion_from_z_to`: the turn that carries body z onto a spin axis, so that code
  written for "the body z axis" measures the spin axis instead.

Vectors are in the body frame; the inertia is about the fixed point (the pivot of a top, the
centre of mass of a free body), in mass·length².
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from rbi.core.inertia import principal_axes
from rbi.core.rotation import Z_AXIS, unit_vector

EQUAL_MOMENTS_RTOL = 1e-9
"""Two principal moments this close (relative to the largest) count as equal."""


def distinct_principal_axis(inertia: np.ndarray, rtol: float = EQUAL_MOMENTS_RTOL) -> np.ndarray | None:
    """The unit principal axis whose moment differs from the other two, when exactly two of
    the three principal moments of ``inertia`` agree to ``rtol`` (relative to the largest);
    None when no two agree or all three do (a sphere has no distinguished axis). Its sign is
    not fixed here."""
    moments, axes = principal_axes(np.asarray(inertia, dtype=float))
    scale = float(moments[-1])
    low_equal = moments[1] - moments[0] <= rtol * scale
    high_equal = moments[2] - moments[1] <= rtol * scale
    if low_equal == high_equal:
        return None
    return np.array(axes[2] if low_equal else axes[0], dtype=float)


def default_spin_axis(inertia: np.ndarray, com_from_fixed_point: ArrayLike) -> np.ndarray:
    """The spin axis when none is given: the body's symmetry axis when exactly two principal
    moments about the fixed point agree to 1e-9 relative, pointing from the fixed point towards
    the centre of mass — or, when the axis is perpendicular to that line or the centre of mass
    is the fixed point (a free body), with its largest-magnitude component positive; otherwise
    the body z axis.

    inertia: (3, 3) about the fixed point, body axes. com_from_fixed_point: (3,) centre of mass
    minus the fixed point, body frame (zeros for a free body)."""
    axis = distinct_principal_axis(inertia)
    if axis is None:
        return Z_AXIS.copy()
    offset = np.asarray(com_from_fixed_point, dtype=float).reshape(3)
    length = float(np.linalg.norm(offset))
    along = float(axis @ offset)
    if length > 0.0 and abs(along) > EQUAL_MOMENTS_RTOL * length:
        return axis if along > 0.0 else -axis
    return axis  # principal_axes, at these moments' tolerance, made its largest component positive


def quaternion_from_z_to(axis: ArrayLike) -> np.ndarray:
    """Unit quaternion [w, x, y, z] of the shortest turn carrying the body z axis onto the unit
    vector ``axis`` (a turn of 180° about x for ``-z``). For ``axis`` = z it is exactly
    [1, 0, 0, 0], so a quantity measured through it equals the body-z one bit for bit."""
    a = unit_vector(axis)
    sine = float(np.hypot(a[0], a[1]))  # |z × a|
    if sine == 0.0:
        return np.array([1.0, 0.0, 0.0, 0.0]) if a[2] > 0.0 else np.array([0.0, 1.0, 0.0, 0.0])
    half = 0.5 * float(np.arctan2(sine, a[2]))
    # about the unit axis z × a / |z × a| = (-a_y, a_x, 0) / sine
    return np.array([np.cos(half), -np.sin(half) * a[1] / sine, np.sin(half) * a[0] / sine, 0.0])
