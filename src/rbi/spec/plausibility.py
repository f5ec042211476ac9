"""Unit slips: a spec without ``units:`` is read in metres and kilograms; when its solids then
imply a density no material has, or sizes no part has, the spec was most likely written in
other units. :func:`unit_warnings` says so in one line, naming the part and the ``units:``
block that makes the body plausible. A spec that states its units is never warned about.

How the units are guessed: every length unit (m, cm, mm, in, ft) with every mass unit (kg, g,
lb) is tried. A unit pair is plausible when every checked solid then has a density between
:data:`PLAUSIBLE_DENSITY_KG_M3` (a part given its mass: mass ÷ volume; a part given a density
number: that number) and a size (cube root of its volume) up to :data:`LARGEST_PART_M` (a part
given a density). Among the plausible pairs the one whose densities lie nearest to a built-in
material wins (a steel ball drawn in mm with its mass in kg comes out at exactly steel's 7850
kg/m³), then the more common pair (:data:`COMMON_UNITS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name
from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

PLAUSIBLE_DENSITY_KG_M3 = (100.0, 25_000.0)
"""Densities of the solids bodies are made of: from balsa (about 150 kg/m³) to osmium (22,590).
Foams and aerogels are lighter and get a warning they can ignore; a spec in cm and g read as m
and kg is 1000× too light (a few kg/m³) and must not pass."""

LARGEST_PART_M = 5.0
"""The largest plausible size of one part given a density, metres (cube root of its volume:
a 125 m³ solid); a spec drawn in millimetres and read as metres is far beyond it."""

COMMON_UNITS = [
    ("m", "kg"),
    ("mm", "kg"),
    ("mm", "g"),
    ("cm", "g"),
    ("in", "lb"),
    ("cm", "kg"),
    ("m", "g"),
    ("in", "kg"),
    ("ft", "lb"),
    ("mm", "lb"),
    ("in", "g"),
    ("cm", "lb"),
    ("ft", "kg"),
    ("m", "lb"),
    ("ft", "g"),
]
"""Every length and mass unit pair, the ones CAD programs and people use most first."""

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
        low, high = PLAUSIBLE_DENSITY_KG_M3
        density = self.density_si(length, mass)
        if density is not None and not low <= density <= high:
            return False
        return self.mass is not None or self.size_m(length) <= LARGEST_PART_M

    def problem(self) -> str:
        """What is wrong with the part read in metres and kilograms."""
        density = self.density_si("m", "kg")
        low, high = PLAUSIBLE_DENSITY_KG_M3
        if density is not None and not low <= density <= high:
            what = "implied density" if self.mass is not None else "density"
            return f"{what} {density:.3g} kg/m³ is outside {low:,.0f}–{high:,.0f} kg/m³ (balsa to osmium)"
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
    """How far the parts' densities lie from the nearest built-in material (sum of |log ratio|)."""
    total = 0.0
    for solid in solids:
        density = solid.density_si(length, mass)
        if density is not None and density > 0:
            total += min(abs(math.log(density / known)) for known in MATERIAL_DENSITIES_SI.values())
    return total


def likely_units(solids: list[_Solid]) -> list[tuple[str, str]]:
    """The unit pairs that make every solid plausible and lie equally near real materials,
    the most common first (several when only sizes tell, e.g. parts given a material: mm, cm
    and in may all fit); empty when no pair makes the body plausible."""
    plausible = [pair for pair in COMMON_UNITS if all(s.plausible(*pair) for s in solids)]
    distance = {pair: round(_distance_to_materials(solids, *pair), 6) for pair in plausible}
    nearest = min(distance.values(), default=None)
    return [pair for pair in plausible if distance[pair] == nearest]


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
