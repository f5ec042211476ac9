"""What a simulation needs to know about the body, in plain floats and arrays.

Public names (other modules and ``rbi bench`` code against these):

- :class:`Scene`: the body's :class:`rbi.core.mass.MassProperties`, gravity and pivot; from
  them the inertia about the fixed point (the pivot of a top, the centre of mass of a free
  body) in body axes, ``com_from_pivot``, ``pivoted``.
- :func:`scene_from_properties`: a :class:`Scene` from :class:`rbi.core.mass.MassProperties`.
- :func:`initial_state`: the contract's initial orientation and angular velocity.

The scene's ``spin_axis`` (unit, body frame) is the axis the run speaks of: ``--spin`` turns
about it, and the tilt and precession a run reports are those of this axis
(:mod:`rbi.core.spin_axis` gives the default).

Units are the spec file's own (length L, mass M, time s); angles in radians unless a name
ends in ``_deg``. Gravity acts along world −z.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.core.mass import MassProperties
from rbi.core.rotation import unit_vector
from rbi.core.spin_axis import default_spin_axis, quaternion_from_z_to

SINGULAR_RTOL = 1e-12
"""Smallest principal moment below this fraction of the largest: the inertia is singular."""


@dataclass(frozen=True)
class Scene:
    """A heavy top on a fixed frictionless pivot, or a torque-free body.

    properties: the body's mass properties (body frame, units L and M). gravity: magnitude in
    L/s² (0 for a free body), acting along world −z. pivot: the pivot in body coordinates (None
    for a free body). spin_axis: (3,) unit vector, body frame: the axis the spin is given about
    and whose tilt and precession are reported (body z unless set). From them: ``mass`` (M),
    ``com`` (the centre of mass, body coordinates), ``pivoted``, ``inertia`` ((3, 3) about the
    pivot, or about the centre of mass of a free body, body axes, M·L²) and ``com_from_pivot``
    ((3,) centre of mass relative to the pivot, body frame, L; zeros for a free body).
    """

    properties: MassProperties
    gravity: float
    pivot: np.ndarray | None = None
    spin_axis: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))

    @property
    def mass(self) -> float:
        return self.properties.mass

    @property
    def com(self) -> np.ndarray:
        return self.properties.center_of_mass

    @property
    def pivoted(self) -> bool:
        return self.pivot is not None

    @cached_property
    def inertia(self) -> np.ndarray:
        if self.pivot is None:
            return np.array(self.properties.inertia_about_com, dtype=float)
        return self.properties.inertia_about(self.pivot)

    @cached_property
    def com_from_pivot(self) -> np.ndarray:
        if self.pivot is None:
            return np.zeros(3)
        return np.asarray(self.properties.center_of_mass, dtype=float) - self.pivot

    @cached_property
    def spin_frame(self) -> np.ndarray:
        """Quaternion [w, x, y, z] turning body z onto :attr:`spin_axis`: ``q ⊗ spin_frame``
        carries the spin axis where ``q`` carries body z (exactly the identity for body z)."""

        return quaternion_from_z_to(self.spin_axis)

    @cached_property
    def inertia_inv(self) -> np.ndarray:
        return np.linalg.inv(self.inertia)

    @property
    def gravity_moment(self) -> np.ndarray:
        """``c = m g r_{c/o}`` (body frame, M·L²/s²): the gravity torque about the pivot is
        ``e_z × c`` with ``e_z`` the world's up axis seen in the body."""
        return self.mass * self.gravity * np.asarray(self.com_from_pivot, dtype=float)

    @cached_property
    def _principal(self) -> tuple[np.ndarray, np.ndarray]:
        return principal_axes(self.inertia)

    @property
    def principal_moments(self) -> np.ndarray:
        """Principal moments of ``inertia`` (ascending), M·L²."""
        return self._principal[0]

    @property
    def principal_axes(self) -> np.ndarray:
        """Unit principal axes (rows, body frame) matching :attr:`principal_moments`."""
        return self._principal[1]

    @cached_property
    def natural_rate(self) -> float:
        """A rate (rad/s) the motion cannot be much slower than: the pendulum frequency
        ``sqrt(m g l / I_max)`` of a pivoted body (0 for a free body)."""
        if not self.pivoted:
            return 0.0
        moment = self.mass * self.gravity * float(np.linalg.norm(self.com_from_pivot))
        return float(np.sqrt(moment / self.principal_moments[-1]))


def scene_from_properties(
    props: MassProperties, pivot: np.ndarray | None, gravity: float, spin_axis=None
) -> Scene:
    """The scene of a body with mass properties ``props``.

    pivot: the fixed point in body coordinates (L), or None for a free body (gravity is then
    ignored: a free body's centre of mass falls, but its rotation is torque-free). gravity:
    magnitude in L/s². spin_axis: a body-frame direction (any length), or None for
    :func:`rbi.core.spin_axis.default_spin_axis` (the symmetry axis, else body z). Raises
    ValueError when the inertia about the pivot (or the centre of mass) overflows or is singular,
    i.e. all the mass lies on a line through that point, or when ``spin_axis`` is zero or not
    finite.
    """

    pivot = None if pivot is None else np.asarray(pivot, dtype=float)
    scene = Scene(props, 0.0 if pivot is None else float(gravity), pivot)
    where = "centre of mass" if pivot is None else "pivot"
    if not np.all(np.isfinite(scene.inertia)):
        raise ValueError(
            f"the inertia about the {where} is too large for double precision (it overflows): is the "
            f"{where} that far from the body, and the length unit right?"
        )
    moments = np.linalg.eigvalsh(scene.inertia)
    if not (moments[0] > SINGULAR_RTOL * moments[-1] and np.all(np.isfinite(moments))):
        raise ValueError(
            f"the inertia about the {where} is singular (principal moments {moments[0]:.3g} and "
            f"{moments[-1]:.3g}): all the mass lies on a line through the {where}, so a spin about "
            f"that line has no inertia and the motion is undefined"
        )
    if spin_axis is None:
        axis = default_spin_axis(scene.inertia, scene.com_from_pivot)
    else:
        try:
            axis = unit_vector(spin_axis)
        except ValueError as exc:
            raise ValueError(f"spin axis: {exc}") from None
    return replace(scene, spin_axis=axis)


def initial_state(tilt_deg: float, omega_body, tilt_axis: str = "y") -> tuple[np.ndarray, np.ndarray]:
    """The initial state rbi simulates from: identity orientation turned by ``tilt_deg``
    degrees about the world ``tilt_axis`` (``"x"`` or ``"y"``); ``omega_body`` (rad/s, body
    frame).

    Returns ``(q0, omega0)``: q0 = [w, x, y, z] body -> world, omega0 (3,).
    """
    half = 0.5 * np.radians(float(tilt_deg))
    if tilt_axis not in ("x", "y"):
        raise ValueError(f"tilt_axis must be 'x' or 'y' (got {tilt_axis!r})")
    q0 = np.array([np.cos(half), 0.0, 0.0, 0.0])
    q0["xy".index(tilt_axis) + 1] = np.sin(half)
    return q0, np.array(omega_body, dtype=float).reshape(3)
