"""Is a body with holes (``subtract: true`` parts) still physical? If not, which hole is to
blame?

A hole enters the sum with negative mass and inertia. rbi cannot see whether a hole lies
inside material (it knows only mass properties), but removing material that is not there
shows up as a body with no mass left or an inertia no mass distribution can have. The
rounding tolerance is relative to the gross body (holes counted as material), because the net
numbers are differences of the gross ones.
"""

from __future__ import annotations

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.validity import INERTIA_RTOL, inertia_problem
from rbi.spec.errors import InputError, part_label

MASS_RTOL = 1e-9
"""A net mass below this fraction of the gross mass counts as nothing left."""


def body_problem(elements: MassProperties, mass_unit: str = "") -> str | None:
    """Why the body made of the stack ``elements`` (holes with negative mass) is not physical,
    or None."""
    material = np.abs(elements.mass)  # holes counted as material
    if not material.sum() > 0:
        return None  # no mass at all (sizes that underflow): refused as any massless body is
    sign = np.sign(elements.mass)
    gross = MassProperties(
        material, elements.center_of_mass, sign[:, None, None] * elements.inertia_about_com
    ).sum()
    net_mass = float(sum(elements.mass.tolist()))
    if not net_mass > MASS_RTOL * gross.mass:
        unit = f" {mass_unit}" if mass_unit else ""
        return f"no mass left: the body's mass would be {net_mass:.6g}{unit} (a hole cannot remove more material than there is)"
    props = elements.sum()
    problem = inertia_problem(
        props.inertia_about_com, INERTIA_RTOL, scale=0.5 * float(np.trace(gross.inertia_about_com))
    )
    if problem is not None:
        return f"the body's inertia about its centre of mass would be {problem.message} (the hole removes material that is not there)"
    return None


def check_holes(path: str, spec, elements: MassProperties, holes: list[int]) -> None:
    """Raise :class:`InputError` naming the first hole (in file order) after which the body
    stops being physical; the material parts are counted first."""
    if body_problem(elements, spec.units.mass) is None:
        return

    hole_set = set(holes)
    solid = [i for i in range(len(elements)) if i not in hole_set]
    for k, i in enumerate(holes):
        problem = body_problem(elements[solid + holes[: k + 1]], spec.units.mass)
        if problem is not None:
            raise InputError(f"{path}: {part_label(i, spec.parts[i])}: subtract: {problem}")
    raise InputError(f"{path}: the body with its holes is not physical")  # not reached: the last is the body
