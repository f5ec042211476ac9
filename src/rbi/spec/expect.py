"""The spec's optional ``expect:`` block, read by ``rbi check`` (see docs/check.md).

Every expectation is ``{value: ..., tol: ...}`` in the file's own units; ``tol`` is an
absolute number or a percentage of the expected value's magnitude.
"""

from __future__ import annotations

from pydantic import model_validator

from rbi.spec.fields import AboutPoint, InertiaMatrix, Number, StrictModel as _Strict, Tolerance, Vector3


class ScalarExpectation(_Strict):
    value: Number
    tol: Tolerance


class VectorExpectation(_Strict):
    value: Vector3
    tol: Tolerance


class MomentsExpectation(_Strict):
    """Principal moments (compared in ascending order) about ``about``."""

    value: Vector3
    tol: Tolerance
    about: AboutPoint = "com"


class InertiaExpectation(_Strict):
    """The inertia matrix about ``about``, body axes."""

    value: InertiaMatrix
    tol: Tolerance
    about: AboutPoint = "com"


class Expect(_Strict):
    """What ``rbi check`` compares: at least one of the quantities below."""

    mass: ScalarExpectation | None = None
    center_of_mass: VectorExpectation | None = None
    moments: MomentsExpectation | None = None
    inertia: InertiaExpectation | None = None

    @model_validator(mode="after")
    def _not_empty(self):
        if all(getattr(self, name) is None for name in type(self).model_fields):
            raise ValueError(f"give at least one of: {', '.join(type(self).model_fields)}")
        return self
