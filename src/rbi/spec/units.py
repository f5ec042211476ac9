"""Unit tables and the labels rbi prints.

rbi computes in the spec file's own units (no conversion, so no rounding is added); these
tables convert only where a quantity comes from outside the file (gravity) or goes out in
fixed units (SI exports, ``--units SI``).
"""

from __future__ import annotations

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
        "energy": f"{mass}·{length}²/s²",
        "density": f"{mass}/{length}³",
        "velocity": f"{length}/s",
        "omega": "rad/s",
    }
