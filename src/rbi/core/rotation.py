"""Rotations: matrices and unit quaternions.

Quaternions are ``[w, x, y, z]`` (scalar first) and map body coordinates to world
coordinates: ``v_world = quaternion_to_matrix(q) @ v_body``.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

Z_AXIS = np.array([0.0, 0.0, 1.0])
"""The z axis: the world's up (gravity pulls along −z), and the body's spin axis by default."""

ROUNDING_ZERO = 1e-15
"""Rotation-matrix entries below this are rounding left by sin and cos of exact quarter turns."""


LARGEST_ANGLE_DEG = 1e9
"""Largest angle accepted as a turn, degrees (2.8 million turns): beyond it neighbouring doubles
are more than 1e-7 degree apart, and by 1e17 degrees not even the turn is known (``--tilt
1e300`` is some angle, not the one meant)."""


def angle_is_kept(degrees: float) -> bool:
    """Whether a turn of ``degrees`` is finite and small enough that rounding keeps it."""
    return math.isfinite(degrees) and abs(degrees) <= LARGEST_ANGLE_DEG


def turn_lost_to_rounding(shown: str, unit: str = "degrees") -> str:
    """The words for a turn that :func:`angle_is_kept` refuses: ``shown`` is the value as the
    caller wrote it, in ``unit`` (``"degrees"`` or ``"radians"``)."""
    limit = LARGEST_ANGLE_DEG if unit == "degrees" else math.radians(LARGEST_ANGLE_DEG)
    return f"{shown} {unit} is too large to be a turn: rounding loses it (at most {limit:.4g} {unit})"


def without_rounding_noise(R: np.ndarray) -> np.ndarray:
    """``R`` (one matrix or a stack) with entries below :data:`ROUNDING_ZERO` set to exactly
    zero, so that a part turned by 90° keeps exact zero products of inertia. Changes ``R``
    in place and returns it."""
    R.real[np.abs(R.real) < ROUNDING_ZERO] = 0.0
    return R


def numbers(values: ArrayLike) -> np.ndarray:
    """``values`` as an array of floats, or of complex numbers when they are complex: the closed
    forms that take it then carry a complex step (``x + ih``, whose imaginary part comes out as
    h times the derivative, exact to rounding: :mod:`rbi.spec.uncertain`)."""
    array = np.asarray(values)
    return array if array.dtype.kind == "c" else array.astype(float, copy=False)


def scalar(value: Any) -> Any:
    """``value`` as a float, or as a complex number when it is one (a complex step, as
    :func:`numbers`)."""
    return complex(value) if np.iscomplexobj(value) else float(value)


def radians(degrees: ArrayLike) -> np.ndarray:
    """``np.radians`` of ``degrees``, also of complex numbers (a complex step)."""
    values = numbers(degrees)
    return values * (math.pi / 180.0) if values.dtype.kind == "c" else np.radians(values)


def vector_length(v: ArrayLike) -> float | np.ndarray:
    """Euclidean length of ``v`` (or of each row of a stack) computed without squaring the
    components directly: they are divided by the largest |component| first, so a vector of
    components near 1e200 or 1e-200 has its length (not inf or 0). Inf only when the length
    itself exceeds the largest double."""
    v = numbers(v)
    largest = np.max(np.abs(v), axis=-1)
    safe = np.where(largest > 0, largest, 1.0)
    with np.errstate(over="ignore"):
        return largest * np.sqrt(np.sum((v / safe[..., None]) ** 2, axis=-1))


def unit_vector(v: ArrayLike) -> np.ndarray:
    """``v / |v|`` (or each row of a stack) for any finite non-zero vector, however large or
    small its components (from 5e-324 up to 1.8e308): scaled by the largest |component| before
    the norm, so nothing overflows to inf or underflows to 0. ValueError for a zero or
    non-finite vector."""
    v = numbers(v)
    if not np.all(np.isfinite(v)):
        raise ValueError(f"a direction must be finite (got {v.tolist()})")
    largest = np.max(np.abs(v), axis=-1, keepdims=True)
    if np.any(largest == 0):
        raise ValueError("a direction must not be the zero vector")
    scaled = v / largest
    return scaled / np.sqrt(np.sum(scaled * scaled, axis=-1, keepdims=True))


def axis_angle_matrix(axis: np.ndarray, angle_rad: float) -> np.ndarray:
    """Rotation matrix turning vectors by ``angle_rad`` about ``axis`` (right-hand rule).

    ``axis`` need not be normalised but must be finite and non-zero (any size).
    """
    u = unit_vector(axis)
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    K = skew(u)
    return c * np.eye(3) + s * K + (1.0 - c) * np.outer(u, u)


def elementary_rotation(axis: str, angle_rad: float) -> np.ndarray:
    """Rotation by ``angle_rad`` about the coordinate axis ``'x'``, ``'y'`` or ``'z'``.

    Built entry by entry so that the untouched axis stays exactly 0/1.
    """
    i = "xyz".index(axis)
    j, k = (i + 1) % 3, (i + 2) % 3
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    R = np.zeros((3, 3), dtype=np.result_type(c, float))
    R[i, i] = 1.0
    R[j, j] = c
    R[k, k] = c
    R[k, j] = s
    R[j, k] = -s
    return R


def compose_world_rotations(rotations: list[tuple[str, float]]) -> np.ndarray:
    """Matrix of successive turns about fixed world axes, applied in the order given.

    ``[(a1, t1), (a2, t2)]`` gives ``R = R2 @ R1``: the body is first turned by ``t1``
    about world axis ``a1``, then by ``t2`` about world axis ``a2``. Angles in radians.
    """
    matrices = [elementary_rotation(axis, angle) for axis, angle in reversed(rotations)]  # last turn first
    return functools.reduce(np.matmul, matrices) if matrices else np.eye(3)


def euler_matrix(angles_rad: ArrayLike, sequence: str) -> np.ndarray:
    """Rotation matrix of three successive turns ``angles_rad`` about the axes named by
    ``sequence`` (three letters of x, y, z).

    Lower case (``"xyz"``): about the fixed (extrinsic) axes, first about the first letter, so
    ``R = R3 R2 R1``. Upper case (``"XYZ"``): about the moving (intrinsic) axes, ``R = R1 R2 R3``.
    This is the convention of scipy's ``Rotation.from_euler``. ``sequence`` is taken as given (a
    spec's is checked when it is read: :class:`rbi.spec.models.Rotation`).
    """
    turns = list(zip(sequence.lower(), numbers(angles_rad).reshape(3)))
    return compose_world_rotations(turns if sequence.islower() else turns[::-1])


def skew(v: np.ndarray) -> np.ndarray:
    """Cross-product matrix ``[v]x`` such that ``skew(v) @ u == np.cross(v, u)``."""
    x, y, z = v
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def quaternion_to_matrix(q: ArrayLike) -> np.ndarray:
    """Rotation matrix (body -> world) of the quaternion ``q = [w, x, y, z]``, (3, 3); of each
    quaternion of a stack (..., 4), (..., 3, 3).

    ``q`` is normalised first (:func:`unit_vector`, so any finite non-zero size), so a slightly
    drifted quaternion still gives a rotation.
    """
    w, x, y, z = unit_vector(q).T  # numbers for one quaternion, arrays (axes reversed) for a stack
    rows = (
        (1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
        (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
        (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)),
    )
    return np.array(rows).T.swapaxes(-1, -2)


def rotate(q: ArrayLike, v: ArrayLike) -> np.ndarray:
    """``R(q) v``: body-frame ``v`` (3,) or (..., 3) in world axes, for ``q`` (4,) or (..., 4)."""
    return np.einsum("...ij,...j->...i", quaternion_to_matrix(q), np.asarray(v, dtype=float))


def rotate_into_body(q: ArrayLike, v: ArrayLike) -> np.ndarray:
    """``R(q)ᵀ v``: world-frame ``v`` (3,) or (..., 3) in body axes, for ``q`` (4,) or (..., 4)."""
    return np.einsum("...ji,...j->...i", quaternion_to_matrix(q), np.asarray(v, dtype=float))


def z_axis_in_world(q: ArrayLike) -> np.ndarray:
    """``R(q) e_z``, the third column of :func:`quaternion_to_matrix`, for each unit quaternion
    of a stack (..., 4) (not normalised here: a trajectory's already are), without building the
    matrices: a sweep asks it of every sample."""
    w, x, y, z = np.moveaxis(np.asarray(q, dtype=float), -1, 0)
    return np.stack((2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)), axis=-1)


def up_in_body(q: ArrayLike) -> np.ndarray:
    """``R(q)ᵀ e_z``, the world's up axis in body axes (the matrix's third row), as
    :func:`z_axis_in_world` (of the inverse turn, the same arithmetic to the bit)."""
    return z_axis_in_world(quaternion_conjugate(q))


def quaternion_conjugate(q: ArrayLike) -> np.ndarray:
    """``[w, -x, -y, -z]``, (4,) or (..., 4): the inverse turn of a unit quaternion."""
    return np.asarray(q, dtype=float) * np.array([1.0, -1.0, -1.0, -1.0])


def quaternion_from_axis_angle(axis: np.ndarray, angle_rad: ArrayLike) -> np.ndarray:
    """Unit quaternions ``[w, x, y, z]`` of turns by ``angle_rad`` (a number, or an array: one
    quaternion per angle, (..., 4)) about ``axis`` (any non-zero length)."""
    half = 0.5 * np.asarray(angle_rad, dtype=float)[..., None]
    return np.concatenate((np.cos(half), np.sin(half) * unit_vector(axis)), axis=-1)


def quaternion_multiply(p: ArrayLike, r: ArrayLike) -> np.ndarray:
    """Hamilton product ``p * r`` of ``[w, x, y, z]`` quaternions, (4,) or stacks (..., 4),
    broadcasting."""
    pw, px, py, pz = np.moveaxis(np.asarray(p, dtype=float), -1, 0)
    rw, rx, ry, rz = np.moveaxis(np.asarray(r, dtype=float), -1, 0)
    w = pw * rw - px * rx - py * ry - pz * rz
    x = pw * rx + px * rw + py * rz - pz * ry
    y = pw * ry - px * rz + py * rw + pz * rx
    z = pw * rz + px * ry - py * rx + pz * rw
    return np.stack((w, x, y, z), axis=-1)


def matrix_to_quaternion(R: np.ndarray) -> np.ndarray:
    """Unit quaternion ``[w, x, y, z]`` (with ``w >= 0``) of a rotation matrix.

    Uses the largest of the four squared components to stay accurate near 180 degrees.
    """
    R = np.asarray(R, dtype=float)
    trace = np.trace(R)
    candidates = np.array([trace, R[0, 0], R[1, 1], R[2, 2]])
    k = int(np.argmax(candidates))
    if k == 0:
        s = 2.0 * np.sqrt(1.0 + trace)
        q = np.array([0.25 * s, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s])
    else:
        i = k - 1
        j, m = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * np.sqrt(1.0 + R[i, i] - R[j, j] - R[m, m])
        q = np.empty(4)
        q[0] = (R[m, j] - R[j, m]) / s
        q[1 + i] = 0.25 * s
        q[1 + j] = (R[j, i] + R[i, j]) / s
        q[1 + m] = (R[m, i] + R[i, m]) / s
    q = unit_vector(q)
    return q if q[0] >= 0 else -q
