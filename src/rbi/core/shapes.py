"""Primitive solids: volume, centre of mass and inertia about their own centre of mass.

Every function here works in one consistent set of units chosen by the caller (lengths L,
masses M): inertias come back in M·L². Positions and inertia matrices are expressed in the
body frame. Inertia is ``I = ∫ (|r|² E − r rᵀ) dm`` with ``r`` measured from the part's own
centre of mass, so that shifting to the body's centre of mass later involves only small
differences (see :mod:`rbi.core.inertia`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np


class MassElement(NamedTuple):
    """One part's mass properties.

    mass: M. com: centre of mass, body frame, L. inertia_com: 3×3 inertia about ``com``,
    body-frame axes, M·L².
    """

    mass: float
    com: np.ndarray
    inertia_com: np.ndarray


def axis_between(start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, float]:
    """Unit vector from ``start`` to ``end`` and the distance between them (L)."""
    d = np.asarray(end, dtype=float) - np.asarray(start, dtype=float)
    length = float(np.linalg.norm(d))
    return d / length, length


def axisymmetric_inertia(axial: float, transverse: float, axis: np.ndarray) -> np.ndarray:
    """Inertia matrix of a body symmetric about the unit vector ``axis``.

    ``axial`` is the moment about the axis, ``transverse`` about any perpendicular line through
    the same point. Written as ``axial·uuᵀ + transverse·(E − uuᵀ)`` rather than
    ``transverse·E + (axial − transverse)·uuᵀ``: for an axis along a coordinate direction the
    small moment is then exact instead of the difference of two large ones (a thin rod).
    """
    u = np.asarray(axis, dtype=float)
    uu = np.outer(u, u)
    return axial * uu + transverse * (np.eye(3) - uu)


# --- solid right circular cone -------------------------------------------------------------

def cone_volume(radius: float, height: float) -> float:
    """Volume of a solid right circular cone (L³)."""
    return math.pi * radius * radius * height / 3.0


def cone(mass: float, radius: float, apex: np.ndarray, base: np.ndarray) -> MassElement:
    """Solid right circular cone from its apex (tip) to the centre of its base disc.

    The centre of mass lies a quarter of the height above the base. About it the axial
    moment is 3/10 m r² and the transverse one 3/80 m (4 r² + h²).
    """
    apex = np.asarray(apex, dtype=float)
    u, height = axis_between(apex, base)
    com = apex + 0.75 * height * u
    axial = 0.3 * mass * radius * radius
    transverse = 3.0 * mass * (4.0 * radius * radius + height * height) / 80.0
    return MassElement(mass, com, axisymmetric_inertia(axial, transverse, u))


# --- solid circular cylinder ---------------------------------------------------------------

def cylinder_volume(radius: float, length: float) -> float:
    """Volume of a solid circular cylinder (L³)."""
    return math.pi * radius * radius * length


def cylinder(mass: float, radius: float, start: np.ndarray, end: np.ndarray) -> MassElement:
    """Solid circular cylinder between the centres of its end faces ``start`` and ``end``.

    About its centre: axial moment m r²/2, transverse m (3 r² + L²)/12.
    """
    start = np.asarray(start, dtype=float)
    end = np.asarray(end, dtype=float)
    u, length = axis_between(start, end)
    com = 0.5 * (start + end)
    axial = 0.5 * mass * radius * radius
    transverse = mass * (3.0 * radius * radius + length * length) / 12.0
    return MassElement(mass, com, axisymmetric_inertia(axial, transverse, u))


# --- point mass ----------------------------------------------------------------------------

def point(mass: float, position: np.ndarray) -> MassElement:
    """A point mass: no inertia about its own position."""
    return MassElement(mass, np.asarray(position, dtype=float), np.zeros((3, 3)))
