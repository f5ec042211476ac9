"""``pattern:`` on a part: equal copies turned evenly about an axis line, or in a row.

The copies of one written part are combined into a single mass element (their total mass,
common centre of mass, and inertia about it), so a patterned part stays one part in ``rbi
parts`` and in hole checks; a pattern on a hole removes every copy.
"""

from __future__ import annotations

import math

import numpy as np

from rbi.core.mass import MassProperties, combine
from rbi.core.rotation import axis_angle_matrix, numbers, without_rounding_noise


def copy_rotations(count: int, axis) -> np.ndarray:
    """(count, 3, 3) matrices turning by 360°·k/count about ``axis``, k = 0 … count − 1 (the
    first is the identity)."""
    rotations = np.array(
        [axis_angle_matrix(np.asarray(axis, dtype=float), 2.0 * math.pi * k / count) for k in range(count)]
    )
    without_rounding_noise(rotations)
    rotations[0] = np.eye(3)
    return rotations


def copy_motions(pattern) -> list[tuple[np.ndarray, np.ndarray]]:
    """(R, t) of each copy, x -> R x + t (the first is the part as written)."""
    if pattern is None or pattern.count <= 1:
        return [(np.eye(3), np.zeros(3))]
    if pattern.step is not None:
        return [(np.eye(3), k * np.asarray(pattern.step, dtype=float)) for k in range(pattern.count)]

    through = np.zeros(3) if pattern.through is None else np.asarray(pattern.through, dtype=float)
    return [(R, through - R @ through) for R in copy_rotations(pattern.count, pattern.axis)]


def patterned(element: MassProperties, pattern) -> MassProperties:
    """The ``pattern.count`` copies of ``element`` (a part's own mass element, positive mass)
    as one element. ``pattern`` has ``count`` and either ``axis`` (with ``through``, default
    the origin) or ``step``."""
    count = int(pattern.count)
    com = numbers(element.center_of_mass)
    inertia = numbers(element.inertia_about_com)
    if pattern.step is not None:
        offsets = np.arange(count)[:, None] * np.asarray(pattern.step, dtype=float)
        coms = com + offsets
        inertias = np.broadcast_to(inertia, (count, 3, 3))
    else:
        through = np.zeros(3) if pattern.through is None else np.asarray(pattern.through, dtype=float)
        rotations = copy_rotations(count, pattern.axis)
        coms = through + np.einsum("kij,j->ki", rotations, com - through)
        inertias = np.einsum("kij,jl,kml->kim", rotations, inertia, rotations)
    return combine(np.full(count, element.mass), coms, inertias)
