"""Unit slips: a spec without ``units:`` is read in metres and kilograms; when a part then
has a density no body has, the spec was most likely written in other units. :func:`unit_warnings`
says so in one line, naming the part and the ``units:`` block that makes the body plausible. A
spec that states its units is never warned about.

When it warns: a part given its mass (mass ÷ volume) or a density number has a density outside
:data:`POSSIBLE_DENSITY_KG_M3`, or a part given a density is larger than :data:`LARGEST_PART_M`.
The range is wide on purpose: a foam block (25 kg/m³), a satellite bus or a ship hull drawn as one
solid of its outside size (50–500 kg/m³) and osmium (22,590) are all plausible SI bodies.

Which units it names: every length unit with every mass unit is tried; among the pairs under
which every part is possible, the one whose densities lie nearest the densities solids usually
have (:data:`USUAL_DENSITY_KG_M3`, wood to lead; distance measured in decades outside that band)
wins, then the more common pair (:data:`COMMON_UNITS`).

What it cannot tell apart (docs/spec.md says it too): one unit pair differs from another by a
factor on every density, so a body in inches and pounds reads as an ordinary solid in mm and g
(36× denser) or in cm and g (28× lighter), and mostly gets one of those hints; a body lighter
than 100 kg/m³ in cm and g gets the inches-and-pounds hint; parts denser than 9 g/cm³ written
in cm and g read as 9–23 kg/m³ in SI, light foams, and are not warned about; and mm with g gives
the same densities as cm with kg (mm and g is named).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name
from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

POSSIBLE_DENSITY_KG_M3 = (9.0, 23_000.0)
"""Densities a part of a real body can have, kg/m³: from polystyrene foam and a vehicle or a
satellite drawn as one solid of its outside size (15–100) to osmium (22,590). A spec in mm and
g read as m and kg is a million times too light and cannot pass; one in cm and g is a thousand
times too light and passes only for parts denser than 9 g/cm³ (lead, gold, tungsten)."""

USUAL_DENSITY_KG_M3 = (100.0, 12_000.0)
"""Densities most bodies have, kg/m³ (balsa to lead): when several unit pairs make a body
possible, the one that puts its parts nearest this band is named."""

LARGEST_PART_M = 200.0
"""The largest plausible size of one part given a density, metres (cube root of its volume: a
ship's hull); a spec drawn in millimetres and read as metres is far beyond it for parts over
0.2 m."""

COMMON_UNITS = {
    ("m", "kg"): 0.0,
    ("mm", "kg"): 0.0,
    ("mm", "g"): 0.0,
    ("cm", "g"): 0.0,
    ("in", "lb"): 0.0,
    ("cm", "kg"): 0.5,
    ("m", "g"): 0.5,
    ("ft", "lb"): 0.5,
    ("in", "kg"): 1.0,
    ("mm", "lb"): 1.0,
    ("in", "g"): 1.0,
    ("cm", "lb"): 1.0,
    ("ft", "kg"): 1.0,
    ("m", "lb"): 1.0,
    ("ft", "g"): 1.0,
}
"""Every length and mass unit pair, the ones CAD programs and people use most first, each with
how much less likely it is than the five common ones (in decades of density distance: a pair
mixing metric and imperial units must fit the usual band a decade better to be named)."""

MAX_CHECKED_PARTS = 200
"""Solids looked at (the first ones in the file): a unit slip shows in every part, and a spec of
10⁵ parts should not pay for the check."""

LENGTH_WORDS = {"m": "metres", "cm": "centimetres", "mm": "millimetres", "in": "inches", "ft": "feet"}
MASS_WORDS = {"kg": "kilograms", "g": "grams", "lb": "pounds"}


@dataclass(frozen=True)
class _Solid:
    """One solid as the file gives it: volume (one copy, file length³) and its mass (file
    mass unit), density number (file units) or material name."""

    label: str
    volume: float
    mass: float | None = None
    density: float | None = None
    material: str | None = None

    def density_si(self, length: str, mass: str) -> float | None:
        """The density the part has if the file is in ``length`` and ``mass``, kg/m³ (None for
        a material, whose density does not depend on the file's units)."""
        to_si = MASS_UNITS_IN_KG[mass] / LENGTH_UNITS_IN_M[length] ** 3
        if self.mass is not None:
            return self.mass / self.volume * to_si
        return None if self.density is None else self.density * to_si

    def size_m(self, length: str) -> float:
        return self.volume ** (1 / 3) * LENGTH_UNITS_IN_M[length]

    def plausible(self, length: str, mass: str) -> bool:
        low, high = POSSIBLE_DENSITY_KG_M3
        density = self.density_si(length, mass)
        if density is not None and not low <= density <= high:
            return False
        return self.mass is not None or self.size_m(length) <= LARGEST_PART_M

    def unusualness(self, length: str, mass: str) -> float:
        """How far the part's density lies outside :data:`USUAL_DENSITY_KG_M3`, in decades."""
        density = self.density_si(length, mass)
        if not density:
            return 0.0
        low, high = USUAL_DENSITY_KG_M3
        return max(0.0, math.log10(low / density), math.log10(density / high))

    def problem(self) -> str:
        """What is wrong with the part read in metres and kilograms."""
        density = self.density_si("m", "kg")
        low, high = POSSIBLE_DENSITY_KG_M3
        if density is not None and not low <= density <= high:
            what = "implied density" if self.mass is not None else "density"
            return f"{what} {density:.3g} kg/m³ is outside {low:,.0f}–{high:,.0f} kg/m³ (foam to osmium)"
        material = f" of {self.material}" if self.material else ""
        kilograms = self.volume * (
            MATERIAL_DENSITIES_SI[self.material] if self.material else self.density or 0.0
        )
        return f"{self.size_m('m'):.3g} m across ({kilograms:.3g} kg{material}), larger than any part"


def _solids(spec) -> list[_Solid]:
    from rbi.spec.errors import part_label
    from rbi.spec.volumes import part_volume

    out = []
    for index, part in enumerate(spec.parts):
        volume = part_volume(part)
        if not volume or not math.isfinite(volume):
            continue
        volume /= 1 if part.pattern is None else part.pattern.count
        density = getattr(part, "density", None)
        label = part_label(index, part)
        if isinstance(density, str):
            out.append(_Solid(label, volume, material=canonical_name(density)))
        else:
            out.append(_Solid(label, volume, mass=getattr(part, "mass", None), density=density))
        if len(out) >= MAX_CHECKED_PARTS:
            break
    return out


def _distance_to_materials(solids: list[_Solid], length: str, mass: str) -> float:
    """How far the parts' densities lie from the nearest built-in material (mean |log10 ratio|)."""
    total = 0.0
    for solid in solids:
        density = solid.density_si(length, mass)
        if density:
            total += min(abs(math.log10(density / known)) for known in MATERIAL_DENSITIES_SI.values())
    return total / max(len(solids), 1)


def likely_units(solids: list[_Solid]) -> list[tuple[str, str]]:
    """The unit pairs that make every solid possible and are equally likely, the most likely
    first: their parts' mean distance from the usual densities (decades) plus the pair's rarity
    (:data:`COMMON_UNITS`), to 0.01; then, among pairs as likely, those whose densities lie
    nearest a built-in material (to 0.01 decade: a steel block in inches and pounds comes out
    at steel's 7850 kg/m³). Several when only sizes tell (parts given a material: mm, cm and
    in may all fit); empty when no pair makes the body possible."""
    plausible = [pair for pair in COMMON_UNITS if all(s.plausible(*pair) for s in solids)]
    cost = {
        pair: (
            round(sum(s.unusualness(*pair) for s in solids) / max(len(solids), 1) + COMMON_UNITS[pair], 2),
            round(_distance_to_materials(solids, *pair), 2),
        )
        for pair in plausible
    }
    nearest = min(cost.values(), default=None)
    return [pair for pair in plausible if cost[pair] == nearest]


def hint(length: str, mass: str, other_lengths: list[str] = ()) -> str:
    """``lengths look like millimetres: add units: {length: mm}`` and the like;
    ``other_lengths`` that would fit as well are named in brackets."""
    looks, block = [], []
    if length != "m":
        others = [LENGTH_WORDS[u] for u in other_lengths if u not in (length, "m")]
        looks.append(
            f"lengths look like {LENGTH_WORDS[length]}" + (f" (or {', '.join(others)})" if others else "")
        )
        block.append(f"length: {length}")
    if mass != "kg":
        looks.append(f"masses {'' if looks else 'look '}like {MASS_WORDS[mass]}")
        block.append(f"mass: {mass}")
    return f"{' and '.join(looks)}: add units: {{{', '.join(block)}}}"


def unit_warnings(spec, path: str) -> list[str]:
    """One line (or none) about a spec without ``units:`` whose solids are implausible in
    metres and kilograms: ``FILE: parts[i] (name): what is wrong: the units that fit``."""
    if "units" in spec.model_fields_set:
        return []
    solids = _solids(spec)
    wrong = [s for s in solids if not s.plausible("m", "kg")]
    if not wrong:
        return []
    more = f" (and {len(wrong) - 1} more part{'s' if len(wrong) > 2 else ''})" if len(wrong) > 1 else ""
    fitting = likely_units(solids)
    if fitting:
        length, mass = fitting[0]
        advice = hint(length, mass, [u for u, m in fitting[1:] if m == mass])
    else:
        advice = "no units rbi knows make it a plausible body: check the numbers"
    return [f"{path}: {wrong[0].label}{more}: {wrong[0].problem()}: {advice}"]
