"""The one mass-properties value type: :class:`MassProperties` (mass, centre of mass, inertia
about the centre of mass, and the name of the frame its vectors are expressed in), and the
operations every layer needs: the sum of several (:meth:`MassProperties.sum`, :func:`combine`),
the inertia about another point (parallel axis, :meth:`MassProperties.inertia_about`), the same
body seen from a turned and moved frame (:meth:`MassProperties.transformed`), and the principal
moments and axes (:meth:`MassProperties.principal`).

Units are the caller's (lengths L, masses M, inertias M·L²); rbi's robot files are SI. The
inertia is ``I = ∫ (|r|² E − r rᵀ) dm`` (products carry a minus sign), about the centre of mass,
in the axes of ``frame``.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from rbi.core.inertia import (
    centre_of_mass,
    parallel_axis,
    principal_axes,
    principal_axes_of_stack,
    symmetrize,
)
from rbi.core.rotation import numbers, scalar
from rbi.errors import ArgumentError, literal


def _frozen(values: ArrayLike, shape: tuple[int, ...], name: str) -> np.ndarray:
    """``values`` as a read-only array of ``shape`` (floats, or complex numbers when they are
    complex); ArgumentError naming the field ``name`` when they are no numbers of that size."""
    try:
        array = np.array(values, dtype=complex if np.iscomplexobj(values) else float).reshape(shape)
    except (TypeError, ValueError, OverflowError):  # None, text, another size, 10**400
        raise _refused(name, values, [shape]) from None
    array.flags.writeable = False
    return array


def _given(values: ArrayLike, name: str, *shapes: tuple[int, ...]) -> np.ndarray:
    """``values`` given as the argument ``name`` of a method: numbers (floats, or complex
    numbers: a complex step) of one of ``shapes``; ArgumentError naming it else (None, text or
    another shape, which gave NaN or numpy's own message)."""
    try:
        array = np.asarray(values)
    except ValueError:  # a ragged list
        array = np.asarray(None)
    if array.dtype.kind not in "iufc" or array.shape not in shapes:
        raise _refused(name, values, list(shapes))
    return numbers(array)


def _refused(name: str, values: Any, shapes: list[tuple[int, ...]]) -> ArgumentError:
    """The refusal of ``values`` given as ``name``, which must be numbers of one of ``shapes``
    (-1: any length)."""
    arrays = " or ".join(str(shape).replace("-1", "n") for shape in shapes if shape)
    wanted = ["a number"] * (() in shapes) + [f"numbers of shape {arrays}"] * bool(arrays)
    return ArgumentError(name, f"expected {' or '.join(wanted)}, got {literal(values)}")


@dataclass(frozen=True, eq=False)
class MassProperties:
    """A rigid body's mass properties, or a stack of n bodies' (as scipy's ``Rotation`` holds one
    rotation or many), immutable.

    ``mass`` (M): a float, or (n,) for a stack; ``center_of_mass`` (3,) or (n, 3) in ``frame``
    (L); ``inertia_about_com`` (3, 3) or (n, 3, 3) about each centre of mass in ``frame``'s axes
    (M·L²); ``frame`` a short name of the frame, one for the stack (``"body"``, ``"link"``,
    ``"world"``, ``"root link NAME"``, ``"mesh"``). The arrays are read-only copies. A stack has
    ``len()``, ``[i]`` (one body), slices and index arrays (a stack) and iteration; every
    operation works on the whole stack at once.
    """

    mass: Any
    center_of_mass: np.ndarray
    inertia_about_com: np.ndarray
    frame: str = "body"

    def __post_init__(self) -> None:
        mass = self.mass
        if type(mass) is float or np.ndim(mass) == 0:
            n: tuple[int, ...] = ()
            try:
                object.__setattr__(self, "mass", scalar(mass))
            except (TypeError, ValueError, OverflowError):  # None, text, 10**400
                raise _refused("mass", mass, [()]) from None
        elif np.ndim(mass) == 1:
            object.__setattr__(self, "mass", _frozen(mass, (-1,), "mass"))
            n = (len(self.mass),)
        else:
            raise ValueError(f"mass must be a number or a 1-D array, got shape {np.shape(mass)}")
        object.__setattr__(self, "center_of_mass", _frozen(self.center_of_mass, (*n, 3), "center_of_mass"))
        object.__setattr__(
            self, "inertia_about_com", _frozen(self.inertia_about_com, (*n, 3, 3), "inertia_about_com")
        )

    def __repr__(self) -> str:
        com, inertia = self.center_of_mass, self.inertia_about_com
        if self.single:  # one body reads as plain lists of its numbers
            com, inertia = com.tolist(), inertia.tolist()
        return (
            f"MassProperties(mass={self.mass!r}, center_of_mass={com!r}, "
            f"inertia_about_com={inertia!r}, frame={self.frame!r})"
        )

    @property
    def single(self) -> bool:
        """One body (mass a float, or a complex number: a complex step), not a stack."""
        return type(self.mass) in (float, complex)

    def __bool__(self) -> bool:
        return True

    def __len__(self) -> int:
        if self.single:
            raise TypeError("a single MassProperties has no len()")
        return len(self.mass)

    def __getitem__(self, index: Any) -> MassProperties:
        """One body (an integer index) or a stack (a slice, an index or boolean array)."""
        if self.single:
            raise TypeError("a single MassProperties is not subscriptable")
        return MassProperties(
            self.mass[index], self.center_of_mass[index], self.inertia_about_com[index], self.frame
        )

    def _argument(self, values: ArrayLike, name: str, shape: tuple[int, ...]) -> np.ndarray:
        """`_given` ``values`` of ``shape``, or for a stack also one of that shape a body."""
        return _given(values, name, shape, *([] if np.ndim(self.mass) == 0 else [(len(self.mass), *shape)]))

    def __iter__(self) -> Iterator[MassProperties]:
        return (self[i] for i in range(len(self)))

    @classmethod
    def concatenate(cls, parts: Iterable[MassProperties], frame: str | None = None) -> MassProperties:
        """One stack of all the bodies of ``parts`` (single bodies and stacks, in order; all in
        one frame). ``frame``: the result's frame name (default: the first part's)."""
        parts = list(parts)
        if not parts:
            raise ValueError("no mass properties to concatenate")
        stranger = next((p for p in parts if not isinstance(p, MassProperties)), None)
        if stranger is not None:  # not its AttributeError "'str' object has no attribute 'frame'"
            raise TypeError(f"parts: expected MassProperties, got {type(stranger).__name__} {stranger!r:.60}")
        frame = parts[0].frame if frame is None else frame
        if all(type(p.mass) is float for p in parts):  # many single bodies: one copy of each
            return cls(
                np.array([p.mass for p in parts]),
                np.array([p.center_of_mass for p in parts]),
                np.array([p.inertia_about_com for p in parts]),
                frame,
            )
        return cls(
            np.concatenate([np.reshape(p.mass, -1) for p in parts]),
            np.concatenate([p.center_of_mass.reshape(-1, 3) for p in parts]),
            np.concatenate([p.inertia_about_com.reshape(-1, 3, 3) for p in parts]),
            frame,
        )

    @staticmethod
    def zero(frame: str = "body") -> MassProperties:
        """No mass: zero mass, centre of mass at the origin, zero inertia."""
        return MassProperties(0.0, np.zeros(3), np.zeros((3, 3)), frame)

    @staticmethod
    def point(mass: ArrayLike, position: ArrayLike, frame: str = "body") -> MassProperties:
        """A point mass at ``position`` (or a stack: masses (n,), positions (n, 3)): no
        inertia about itself."""
        shape = _given(mass, "mass", np.shape(mass)).shape  # numbers first: the positions' shape follows
        position = _given(position, "position", shape + (3,))
        return MassProperties(mass, position, np.zeros(shape + (3, 3)), frame)

    def sum(self: MassProperties | Iterable[MassProperties], frame: str | None = None) -> MassProperties:
        """The one body made of a stack's bodies (``stack.sum()``), or of several mass properties
        (``MassProperties.sum(parts)``, singles or stacks, all in one frame); a negative mass
        removes material. ValueError when the total mass is not positive. ``frame``: the
        result's frame name (default: the first part's)."""
        if not isinstance(self, MassProperties):
            parts = list(self)
            if not parts:
                raise ValueError("total mass must be positive, got 0 (no parts)")
            return MassProperties.concatenate(parts).sum(frame)
        frame = self.frame if frame is None else frame
        return combine(self.mass, self.center_of_mass, self.inertia_about_com, frame=frame)

    def inertia_about(self, point: ArrayLike) -> np.ndarray:
        """Inertia (M·L²) about ``point`` (L, this frame; for a stack (3,) or one a body
        (n, 3)) in this frame's axes (parallel axis): (3, 3), or (n, 3, 3) for a stack."""
        offset = self._argument(point, "point", (3,)) - self.center_of_mass
        return symmetrize(parallel_axis(self.inertia_about_com, self.mass, offset))

    def transformed(
        self,
        rotation: ArrayLike | None = None,
        translation: ArrayLike | None = None,
        frame: str | None = None,
    ) -> MassProperties:
        """The same body (each of a stack) in another frame, where ``x_new = rotation @ x +
        translation`` (``rotation`` (3, 3), or one a body (n, 3, 3); None: the same axes;
        ``translation`` (3,) or (n, 3), None: the same origin): the centre of mass moves, the
        inertia is re-expressed ``R I Rᵀ``."""
        com, inertia = self.center_of_mass, self.inertia_about_com
        if rotation is not None:
            R = self._argument(rotation, "rotation", (3, 3))
            com = R @ com if self.single else (R @ com[..., None])[..., 0]
            inertia = symmetrize(R @ inertia @ np.swapaxes(R, -1, -2))
        if translation is not None:
            com = com + self._argument(translation, "translation", (3,))
        return MassProperties(self.mass, com, inertia, self.frame if frame is None else frame)

    def scaled(self, factor: ArrayLike) -> MassProperties:
        """The same shape at ``factor`` times the mass (a density applied to a unit density's
        properties, a measured mass; for a stack one factor or one a body): the centre of mass
        stays, mass and inertia scale."""
        f = self._argument(factor, "factor", ())
        return MassProperties(
            self.mass * f, self.center_of_mass, self.inertia_about_com * f[..., None, None], self.frame
        )

    def with_mass(self, mass: ArrayLike) -> MassProperties:
        """The same shape at exactly ``mass`` (M; for a stack one a body): the centre of mass
        stays, the inertia scales by ``mass / self.mass``."""
        ratio = self._argument(mass, "mass", ()) / self.mass
        return MassProperties(
            mass, self.center_of_mass, self.inertia_about_com * ratio[..., None, None], self.frame
        )

    def principal(self) -> tuple[np.ndarray, np.ndarray]:
        """Principal moments about the centre of mass (M·L², ascending) and axes (rows, unit,
        right-handed, in this frame's axes), as :func:`rbi.core.inertia.principal_axes` chooses
        them: (3,) and (3, 3), or (n, 3) and (n, 3, 3) for a stack."""
        if self.single:
            return principal_axes(self.inertia_about_com)
        return principal_axes_of_stack(self.inertia_about_com)

    @property
    def moments(self) -> np.ndarray:
        """Principal moments about the centre of mass (M·L², ascending)."""
        return self.principal()[0]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: ``mass`` (a number, or a list for a stack), ``center_of_mass`` and
        ``inertia_about_com`` (nested lists)."""
        return {
            "mass": self.mass if self.single else self.mass.tolist(),
            "center_of_mass": self.center_of_mass.tolist(),
            "inertia_about_com": self.inertia_about_com.tolist(),
        }


def combine(
    masses: np.ndarray, coms: np.ndarray, inertias_com: np.ndarray | None = None, frame: str = "body"
) -> MassProperties:
    """Mass properties of a body made of parts given as arrays.

    masses: (N,) M (a negative mass removes material). coms: (N, 3) each part's centre of
    mass, L. inertias_com: (N, 3, 3) each part about its own centre of mass, M·L², or None when
    every part is a point mass. Each part is shifted straight to the body's centre of mass, so
    only the small offsets between nearby points enter. ValueError when the total mass is not
    positive.
    """
    m = numbers(masses).reshape(-1)
    c = numbers(coms).reshape(-1, 3)
    total = scalar(m.sum())
    if not total.real > 0.0:
        raise ValueError(f"total mass must be positive, got {total!r}")
    com = centre_of_mass(m, c)
    d = c - com
    second_moment = (d * m[:, None]).T @ d  # Σ m d dᵀ
    inertia = np.trace(second_moment) * np.eye(3) - second_moment
    if inertias_com is not None:
        inertia = inertia + numbers(inertias_com).reshape(-1, 3, 3).sum(axis=0)
    return MassProperties(total, com, symmetrize(inertia), frame)


def inertia_shares(parts: MassProperties | Sequence[MassProperties], body: MassProperties) -> np.ndarray:
    """Each part's (a stack, or single bodies) share of the trace of the body's inertia about
    the body's centre of mass (fractions that add up to 1; a hole's share is negative).

    The trace is the sum of the three moments, ``2 ∫ |r|² dm``, so the share says which part
    carries the body's rotational inertia whatever the axes.
    """
    total = float(np.trace(body.inertia_about_com))
    if total == 0.0 or len(parts) == 0:
        return np.zeros(len(parts))
    stack = parts if isinstance(parts, MassProperties) else MassProperties.concatenate(parts)
    return np.trace(stack.inertia_about(body.center_of_mass), axis1=-2, axis2=-1) / total
