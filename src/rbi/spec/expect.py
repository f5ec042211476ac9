"""The spec's optional ``expect:`` block, read by ``rbi check`` (see docs/check.md).

Every expectation is ``{value: ..., tol: ...}`` in the file's own units; ``tol`` is an
absolute number or a percentage of the expected value's magnitude.
"""

from __future__ import annotations

from pydantic import ConfigDict, Field, model_validator

from rbi.spec.fields import AboutPoint, InertiaMatrix, Number, Tolerance, Vector3
from rbi.spec.fields import StrictModel as _Strict


class _BuiltWhenUsed(_Strict):
    """Built when a spec first has an `expect:` block (start-up time: see docs/performance.md)."""

    model_config = ConfigDict(extra="forbid", frozen=True, defer_build=True)


class ScalarExpectation(_BuiltWhenUsed):
    value: Number = Field(description="Expected value, in the file's units.")
    tol: Tolerance = Field(
        description="Allowed deviation: an absolute number in file units, or a percentage such as 1%."
    )


class VectorExpectation(_BuiltWhenUsed):
    value: Vector3 = Field(description="Expected point [x, y, z], body frame, file units.")
    tol: Tolerance = Field(
        description="Allowed deviation of each component: an absolute number in file units, or a percentage."
    )


class MomentsExpectation(_BuiltWhenUsed):
    """Principal moments (compared in ascending order) about ``about``."""

    value: Vector3 = Field(description="Expected principal moments, ascending, mass·length².")
    tol: Tolerance = Field(
        description="Allowed deviation of each moment: an absolute number, or a percentage."
    )
    about: AboutPoint = Field(
        "com", description="Point the moments are about: com, origin, pivot or [x, y, z]."
    )


class InertiaExpectation(_BuiltWhenUsed):
    """The inertia matrix about ``about``, body axes."""

    value: InertiaMatrix = Field(description="Expected inertia matrix, body axes, mass·length².")
    tol: Tolerance = Field(
        description="Allowed deviation of each entry: an absolute number, or a percentage."
    )
    about: AboutPoint = Field(
        "com", description="Point the inertia is about: com, origin, pivot or [x, y, z]."
    )


class Expect(_BuiltWhenUsed):
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
