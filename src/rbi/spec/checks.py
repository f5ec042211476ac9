"""`rbi check`: each expectation of a spec's ``expect:`` block (:mod:`rbi.spec.expect`) against
the computed value. Numpy only at import (the API imports :class:`Check` at start-up)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.errors import InputError
from rbi.spec.points import NO_PIVOT

PERCENT = re.compile(r"^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*%\s*$")
"""A tolerance written as a percentage (``1%``): its number."""


def tolerance_allowed(tol: float | str, reference: float) -> float:
    """The allowed absolute deviation: ``tol`` itself, or ``tol``% of ``reference`` (the
    magnitude of the expected value)."""
    if isinstance(tol, str):
        return float(PERCENT.match(tol).group(1)) / 100.0 * abs(reference)
    return float(tol)


@dataclass(frozen=True)
class Check:
    """One expectation of the spec's ``expect:`` block against the body (spec units, body axes).

    Attributes:
        quantity: ``"mass"``, ``"center_of_mass"``, ``"moments"`` (principal, ascending) or
            ``"inertia"`` (the matrix).
        unit: the quantity's printed unit (``kg``, ``m``, ``kg·m²`` in SI).
        expected, actual: the values (a number, (3,) or (3, 3)).
        deviation: the largest ``|actual − expected|`` over the components;
            ``component_deviation`` each of them.
        tol: as the spec gives it: a number, or text such as ``"1%"`` (of the largest expected
            magnitude, so a zero component gets the same allowance as the others).
        allowed: the absolute deviation allowed.
        passed: every component within ``allowed``.
        about: for moments and inertia, the point they are about (``"com"``, ``"origin"``,
            ``"pivot"`` or ``"point"``); else None.
    """

    quantity: str
    unit: str
    expected: np.ndarray
    actual: np.ndarray
    deviation: float
    tol: float | str
    allowed: float
    passed: bool
    component_deviation: np.ndarray
    about: str | None = None


def _compare(
    quantity: str, expected: Any, actual: Any, tol: Any, unit: str, about: str | None = None
) -> Check:
    want = np.asarray(expected, dtype=float)
    got = np.asarray(actual, dtype=float)
    allowed = tolerance_allowed(tol, float(np.max(np.abs(want))))
    deviation = np.abs(got - want)
    passed = bool(np.all(deviation <= allowed))
    return Check(quantity, unit, want, got, float(np.max(deviation)), tol, allowed, passed, deviation, about)


def _expected_point(about: Any, body: Any) -> tuple[str, np.ndarray]:
    """``expect``'s ``about`` (validated: a name or a point) as (label, point), by the body's
    :meth:`~rbi.spec.translate.LoadedBody.point`."""
    point = body.point(about)
    if point is None:
        raise InputError(f"{body.path}: expect: about: {NO_PIVOT}")
    return ("point" if isinstance(about, list) else about), point


UNITS = {"mass": "mass", "center_of_mass": "length", "moments": "inertia", "inertia": "inertia"}
"""The quantities `rbi check` compares, in its order, and the unit label of each (a key of
:func:`rbi.spec.units.unit_labels`; the uncertainty budget's quantities are these too)."""


def run_checks(body: Any) -> list[Check]:
    """Every comparison the loaded body's `expect:` block asks for, in a fixed order
    (mass, centre of mass, principal moments, inertia); InputError when it has none."""

    expect = body.spec.expect
    if expect is None:
        raise InputError(
            f"{body.path}: expect: the spec has no `expect:` block, so there is nothing to check "
            f"(see docs/check.md)"
        )
    labels, props, checks = body.labels, body.props, []
    for quantity, unit in UNITS.items():
        e = getattr(expect, quantity)
        if e is None:
            continue
        label, value, actual = None, e.value, getattr(props, quantity, None)
        if quantity in ("moments", "inertia"):
            label, point = _expected_point(e.about, body)
            actual = props.inertia_about(point)
            if quantity == "moments":
                value, actual = sorted(value), principal_axes(actual)[0]
        checks.append(_compare(quantity, value, actual, e.tol, labels[unit], label))
    return checks
