"""The spec's optional ``expect:`` block, read by ``rbi check`` (see docs/check.md).

Every expectation is ``{value: ..., tol: ...}`` in the file's own units; ``tol`` is an
absolute number or a percentage of the expected value's magnitude.
"""

from __future__ import annotations

from typing import Any

from pydantic import Field, model_validator

from rbi.spec.fields import AboutPoint, BuiltWhenUsed, InertiaMatrix, Number, Tolerance, Vector3


def _tolerance(of_what: str) -> Any:
    """The ``tol`` field: the deviation allowed (``of_what``: of each component, ...)."""
    return Field(description=f"Allowed deviation{of_what}.")


def _about(what: str) -> Any:
    """The ``about`` field of moments and the inertia: the point ``what`` about (default com)."""
    return Field("com", description=f"Point the {what} about: com, origin, pivot or [x, y, z].")


class ScalarExpectation(BuiltWhenUsed):
    value: Number = Field(description="Expected value, in the file's units.")
    tol: Tolerance = _tolerance(": an absolute number in file units, or a percentage such as 1%")


class VectorExpectation(BuiltWhenUsed):
    value: Vector3 = Field(description="Expected point [x, y, z], body frame, file units.")
    tol: Tolerance = _tolerance(" of each component: an absolute number in file units, or a percentage")


class MomentsExpectation(BuiltWhenUsed):
    """Principal moments (compared in ascending order) about ``about``."""

    value: Vector3 = Field(description="Expected principal moments, ascending, mass·length².")
    tol: Tolerance = _tolerance(" of each moment: an absolute number, or a percentage")
    about: AboutPoint = _about("moments are")


class InertiaExpectation(BuiltWhenUsed):
    """The inertia matrix about ``about``, body axes."""

    value: InertiaMatrix = Field(description="Expected inertia matrix, body axes, mass·length².")
    tol: Tolerance = _tolerance(" of each entry: an absolute number, or a percentage")
    about: AboutPoint = _about("inertia is")


class Expect(BuiltWhenUsed):
    """What ``rbi check`` compares: at least one of the quantities below."""

    mass: ScalarExpectation | None = Field(None, description="Expected total mass.")
    center_of_mass: VectorExpectation | None = Field(None, description="Expected centre of mass.")
    moments: MomentsExpectation | None = Field(None, description="Expected principal moments.")
    inertia: InertiaExpectation | None = Field(None, description="Expected inertia matrix.")

    @model_validator(mode="after")
    def _not_empty(self):
        if all(getattr(self, name) is None for name in type(self).model_fields):
            raise ValueError(f"give at least one of: {', '.join(type(self).model_fields)}")
        return self
