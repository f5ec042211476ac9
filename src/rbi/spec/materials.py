"""Built-in material densities, so that a part may say ``density: steel``.

Values are nominal room-temperature densities in kg/m³; docs/spec.md gives the source of
each and how much real stock varies. They are converted to the spec file's own units.
"""

from __future__ import annotations

import difflib

from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

MATERIAL_DENSITIES_SI: dict[str, float] = {
    "steel": 7850.0,
    "stainless steel": 8000.0,
    "cast iron": 7200.0,
    "aluminium 6061": 2700.0,
    "brass": 8500.0,
    "copper": 8960.0,
    "titanium": 4510.0,
    "ti-6al-4v": 4430.0,
    "lead": 11340.0,
    "abs": 1040.0,
    "pla": 1240.0,
    "nylon": 1140.0,
    "oak": 750.0,
    "water": 998.2,
}
"""Density of each built-in material, kg/m³ (names in canonical form)."""

ALIASES: dict[str, str] = {
    "aluminum 6061": "aluminium 6061",
    "aluminium": "aluminium 6061",
    "aluminum": "aluminium 6061",
    "al 6061": "aluminium 6061",
    "6061": "aluminium 6061",
    "stainless": "stainless steel",
    "stainless steel 304": "stainless steel",
    "ss304": "stainless steel",
    "mild steel": "steel",
    "carbon steel": "steel",
    "ti6al4v": "ti-6al-4v",
    "ti64": "ti-6al-4v",
    "nylon 6": "nylon",
    "pa6": "nylon",
}
"""Other spellings accepted for a built-in material."""


def _normal(name: str) -> str:
    return " ".join(name.strip().lower().replace("_", " ").replace("-", " ").split())


_LOOKUP: dict[str, str] = {_normal(n): n for n in MATERIAL_DENSITIES_SI} | {
    _normal(a): n for a, n in ALIASES.items()
}


def canonical_name(name: str) -> str | None:
    """The table's name for ``name`` (case, spaces, ``_`` and ``-`` ignored), or None."""
    return _LOOKUP.get(_normal(name))


def unknown_material_message(name: str, numbers_too: bool = True) -> str:
    """The one-line complaint for a name that is not in the table, with a suggestion; a spec's
    ``density`` also takes a number (``numbers_too``), ``rbi audit --material`` only a name."""
    names = list(MATERIAL_DENSITIES_SI) + list(ALIASES)
    hint = difflib.get_close_matches(name.strip().lower(), names, n=1, cutoff=0.6)
    suggestion = f" (did you mean '{hint[0]}'?)" if hint else ""
    choices = (
        "give a number (mass per length³ in the file's units) or one of" if numbers_too else "give one of"
    )
    return f"unknown material {name!r}{suggestion}; {choices}: {', '.join(MATERIAL_DENSITIES_SI)}"


def density_in_units(name: str, length_unit: str, mass_unit: str) -> float:
    """Density of the named material in ``mass_unit``/``length_unit``³.

    Raises KeyError for an unknown name (the spec models refuse those before this runs).
    """
    canonical = canonical_name(name)
    if canonical is None:
        raise KeyError(name)
    kg_per_m3 = MATERIAL_DENSITIES_SI[canonical]
    return kg_per_m3 / MASS_UNITS_IN_KG[mass_unit] * LENGTH_UNITS_IN_M[length_unit] ** 3
