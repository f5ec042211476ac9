"""Unit tables and the labels rbi prints.

rbi computes in the spec file's own units (no conversion, so no rounding is added); these
tables convert only where a quantity comes from outside the file (gravity) or goes out in
fixed units (SI exports, ``--units SI``).
"""

from __future__ import annotations

import dataclasses

import numpy as np

LENGTH_UNITS_IN_M: dict[str, float] = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
MASS_UNITS_IN_KG: dict[str, float] = {"kg": 1.0, "g": 0.001, "lb": 0.45359237}

STANDARD_GRAVITY_SI = 9.81
"""Gravity's default magnitude in m/s² (the contract's value)."""


def gravity_in(length_unit: str, g_si: float = STANDARD_GRAVITY_SI) -> float:
    """Gravity's magnitude in the file's length unit per s²."""
    return g_si / LENGTH_UNITS_IN_M[length_unit]


def unit_labels(length: str, mass: str) -> dict[str, str]:
    """Printable units of each quantity rbi reports, for a file in ``length``/``mass``."""
    return {
        "length": length,
        "mass": mass,
        "inertia": f"{mass}·{length}²",
        "angular_momentum": f"{mass}·{length}²/s",
        "energy": "J" if (length, mass) == ("m", "kg") else f"{mass}·{length}²/s²",
        "density": f"{mass}/{length}³",
        "velocity": f"{length}/s",
        "omega": "rad/s",
    }


# --- converting results to other units (`--units`, exports) --------------------------------


def convert_body(body, length_unit: str, mass_unit: str):
    """The same :class:`~rbi.spec.translate.LoadedBody` with every number in other units: masses,
    centres of mass, inertias (mass·length²) and the pivot. The body's own units are
    returned unchanged (no rounding added)."""

    if (body.length_unit, body.mass_unit) == (length_unit, mass_unit):
        return body
    L = LENGTH_UNITS_IN_M[body.length_unit] / LENGTH_UNITS_IN_M[length_unit]
    M = MASS_UNITS_IN_KG[body.mass_unit] / MASS_UNITS_IN_KG[mass_unit]

    def element(e):
        return type(e)(
            e.mass * M, np.asarray(e.center_of_mass) * L, np.asarray(e.inertia_about_com) * (M * L * L)
        )

    return dataclasses.replace(
        body,
        length_unit=length_unit,
        mass_unit=mass_unit,
        props=element(body.props),
        pivot=None if body.pivot is None else body.pivot * L,
        elements=element(body.elements),
    )
