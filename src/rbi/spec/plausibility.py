"""Unit slips: a spec without ``units:`` is read in metres and kilograms; when a part then
has a density no body has, the spec was most likely written in other units. :func:`unit_warnings`
says so in one line, naming the part and the ``units:`` block that makes the body plausible. A
spec that states its units is never warned about.

When it warns: a part given its mass (mass ÷ volume) or a density number has a density outside
:data:`POSSIBLE_DENSITY_KG_M3`, a part given a density is larger than :data:`LARGEST_PART_M`, or
a part given a metal's density (a solid of it) is heavier than :data:`LARGEST_METAL_PIECE_KG`.
The range is wide on purpose: a foam block (25 kg/m³), a satellite bus or a ship hull drawn as one
solid of its outside size (50–500 kg/m³) and osmium (22,590) are all plausible SI bodies. It also
warns a body possible in SI that another pair makes more than ten times likelier
(:data:`SI_PREFERENCE_DECADES`): in practice a 9–23 kg/m³ "foam" that is exactly lead, gold,
tungsten or osmium in cm and g.

Which units it names: every length unit with every mass unit is tried; among the pairs under
which every part is possible (:meth:`_Solid.plausible`; no part over :data:`LARGEST_PART_M`),
the likeliest wins (:func:`likely_units`). How likely a part is comes from a model of the sizes
and densities real bodies have together (:meth:`_Solid.improbability`): a share of parts,
falling with size (:func:`material_share`), is exactly one handbook material
(:data:`REFERENCE_DENSITIES_KG_M3`, to 0.1 %: a mass computed from a density by CAD or by
hand); the rest spread log-normally about a typical density that
falls with size by the square-cube law, from steel's for parts under 2.6 mm (solid) to 140 kg/m³
for bodies over 1.2 m (structures round air: :data:`TYPICAL_DENSITY_KG_M3`,
:data:`STRUCTURE_SIZES_M`); sizes follow a logistic distribution about :data:`BODY_SIZE_M`; rarer
unit pairs pay their rarity (:data:`COMMON_UNITS`). The model's numbers are not chosen by hand
but are the maximum-likelihood fit to real objects (:data:`CALIBRATION`); the pair priors are
equal for the common pairs, as nothing says which of them a slipping author uses more.

What it cannot tell apart (docs/spec.md gives the rates measured on a corpus of real objects,
tests/spec/test_plausibility_corpus.py): one unit pair differs from another by a factor on every
density and one on every size, and real bodies spread over more than those factors (15 to
22,590 kg/m³; in/lb is 28× denser and 2.5× larger than cm/g, 36× lighter and 25× larger than
mm/g). So a part a centimetre across that is not exactly a handbook material (a coin, a bar
drawn as a box) in mm and g reads as a hollow body in inches and pounds; a light body (foam, a
chair or a violin drawn by its outline) in cm and g reads as a solid in inches and pounds; a
body metres across (a car, a satellite) in inches and pounds reads as a part a few centimetres
across in mm and g; parts denser than 9 g/cm³ written in cm and g read as 9–23 kg/m³ in SI,
light foams, and are warned about only when they are exactly a handbook metal; and mm with g
gives the same densities as cm with kg (mm and g is named).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rbi.spec.errors import part_label
from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name
from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG
from rbi.spec.volumes import part_volume

POSSIBLE_DENSITY_KG_M3 = (9.0, 23_000.0)
"""Densities a part of a real body can have, kg/m³: from polystyrene foam and a vehicle or a
satellite drawn as one solid of its outside size (15–100) to osmium (22,590). A spec in mm and
g read as m and kg is a million times too light and cannot pass; one in cm and g is a thousand
times too light and passes only for parts denser than 9 g/cm³ (lead, gold, tungsten)."""

TYPICAL_DENSITY_KG_M3 = 159.0
"""The typical density of bodies a metre across when they are not one handbook material,
kg/m³: hollow and assembled bodies drawn as one solid of their outside size (a fridge 100, a
washing machine 230, a car 120, a person 1,000), woods and foams spread around it (smaller and
larger bodies: :data:`STRUCTURE_SIZES_M`). Like every number of the model below, the
maximum-likelihood fit to the calibration corpus (:data:`CALIBRATION`)."""

DENSITY_SPREAD_DECADES = 0.558
"""How widely densities spread about the typical density for their size (standard deviation
of log10 density, a normal distribution): 68 % within a factor 3.6 either way, 95 % within 13."""

TYPICAL_SIZE_M = 1.0
"""The size (cube root of the volume, m) whose typical density is :data:`TYPICAL_DENSITY_KG_M3`."""

STRUCTURE_SIZES_M = (0.0026, 1.22)
STRUCTURE_THINNING = 0.657
"""Small parts are solid (metals, plastics, glass: a coin, a bolt, a bearing), larger bodies
more and more structures round air (shells, frames, assemblies), the walls' share of the outside
volume falling as the body grows (square-cube law): between the two sizes (cube root of the
volume, m) the typical density falls by 10^-STRUCTURE_THINNING per tenfold size, from steel's
(7,900 kg/m³) at 2.6 mm through 3,300 at 1 cm and 720 at 10 cm to :data:`TYPICAL_DENSITY_KG_M3` at
a metre and 140 at 1.22 m. Smaller parts stay at steel's (a part is no denser than its
material, and few materials are denser than steel); larger bodies (vehicles, hulls,
buildings) stay at 140. The lower size is where the fitted fall reaches steel's density, the
upper one is fitted."""

BODY_SIZE_M = 0.13
BODY_SIZE_SPREAD_DECADES = 0.5
"""How large the bodies people compute are (cube root of the volume, m): log10 size follows a
logistic distribution about BODY_SIZE_M with scale BODY_SIZE_SPREAD_DECADES (standard deviation
0.9 decade; 95 % lie between 2 mm and 9 m, screws to trucks, with wires, ships and rockets in
its tails, which fall off more slowly than a normal distribution's: the logistic fits the
corpus's sizes better). A unit pair that makes a body 25 times smaller or larger than another
pays for it."""

CALIBRATION = "the first 128 objects of tests/spec/plausibility_corpus.py (134 parts)"
"""What the model's numbers were fitted to by maximum likelihood (the last test of
tests/spec/test_plausibility_corpus.py refits them): the typical density, its fall with size,
the size where the fall stops, the spread and how the share of handbook materials falls with
size (:data:`MATERIAL_HALF_SIZE_M`), all at once as the mixture :meth:`_Solid.improbability`
uses; the size distribution on its own.
The objects added after them (the third hold-out) measure the rule without having shaped it."""

REFERENCE_DENSITIES_KG_M3 = MATERIAL_DENSITIES_SI | {
    "osmium": 22_590.0,
    "platinum": 21_450.0,
    "gold": 19_300.0,
    "tungsten": 19_250.0,
    "tungsten alloy": 19_300.0,
    "tantalum": 16_690.0,
    "tungsten carbide": 15_630.0,
    "silver": 10_490.0,
    "molybdenum": 10_280.0,
    "nickel": 8_908.0,
    "bronze": 8_800.0,
    "iron": 7_874.0,
    "tin": 7_310.0,
    "zinc": 7_140.0,
    "alumina": 3_950.0,
    "marble": 2_710.0,
    "glass": 2_500.0,
    "concrete": 2_400.0,
    "ptfe": 2_200.0,
    "fr4": 1_850.0,
    "magnesium": 1_740.0,
    "cfrp": 1_600.0,
    "pvc": 1_380.0,
    "polycarbonate": 1_200.0,
    "pmma": 1_180.0,
    "seawater": 1_025.0,
    "water (1 t/m³)": 1_000.0,
    "hdpe": 950.0,
    "ice": 917.0,
    "polypropylene": 905.0,
}
"""Handbook densities of materials whose density is well defined (metals, minerals, plastics,
water and ice; not woods or foams, which vary by a factor of two), kg/m³. A part drawn with
its mass computed from one of them (as CAD programs do) comes out at it in the right units,
and almost never in the wrong ones."""

MATERIAL_MATCH_DECADES = 0.0005
"""How near (in log10 density: 0.1 %) a part must come to a handbook density to count as that
material."""

MATERIAL_HALF_SIZE_M = 0.0124
MATERIAL_SHARE_SLOPE = 1.81
"""How often a part is one handbook material at its handbook density (the rest spread as
:data:`DENSITY_SPREAD_DECADES` says) falls with its size (cube root of the volume, m): logistic
in log10 size, half the parts at MATERIAL_HALF_SIZE_M (a coin, a nut: solid metal or plastic),
the log odds falling by MATERIAL_SHARE_SLOPE per tenfold size (88 % at 1 mm, 16 % at 10 cm,
3 % at 1 m, 0.5 % at 10 m: large bodies are assemblies, not one material). Fitted with the
density model (:data:`CALIBRATION`): 30 of its 134 parts are exactly a handbook material, 15 of
the 27 between 3 mm and 3 cm, 1 of the 13 over 3 m."""

SI_PREFERENCE_DECADES = 1.0
"""A spec without ``units:`` is taken to be in metres and kilograms ten times as often as in
any other pair: a body possible in SI is warned about only when another pair makes it more
than ten times likelier (log10 odds), as when a 11.3 kg/m³ "foam" is exactly lead in cm and g."""

_REFERENCE_DECADES = sorted({math.log10(d) for d in REFERENCE_DENSITIES_KG_M3.values()})

LARGEST_PART_M = 200.0
"""The largest plausible size of one part given a density, metres (cube root of its volume: a
ship's hull); a spec drawn in millimetres and read as metres is far beyond it for parts over
0.2 m."""

METAL_DENSITY_KG_M3 = 4_000.0
LARGEST_METAL_PIECE_KG = 1.0e6
"""A part given a density of at least METAL_DENSITY_KG_M3 (titanium and every denser metal; no
common non-metal but alumina comes near) is a solid piece of metal, and no single piece of
metal heavier than LARGEST_METAL_PIECE_KG (1,000 t) is made: the heaviest steel ingots and
forgings weigh up to about 700 t, Taipei 101's steel damper ball 660 t. Water, concrete, stone
and wood come in larger solids (tanks, foundations, monoliths) and are judged by size only. In
millimetres read as metres, a steel part is over it from 5 mm across (a ball of radius 10 mm
is a 33,000 t ball of radius 10 m); a steel part 5 m across in metres is under it."""

COMMON_UNITS = {
    ("m", "kg"): 0.0,
    ("mm", "kg"): 0.0,
    ("mm", "g"): 0.0,
    ("cm", "g"): 0.0,
    ("in", "lb"): 0.0,
    ("cm", "kg"): 1.0,
    ("m", "g"): 1.0,
    ("ft", "lb"): 1.0,
    ("in", "kg"): 2.0,
    ("mm", "lb"): 2.0,
    ("in", "g"): 2.0,
    ("cm", "lb"): 2.0,
    ("ft", "kg"): 2.0,
    ("m", "lb"): 2.0,
    ("ft", "g"): 2.0,
}
"""Every length and mass unit pair, the ones CAD programs and people use most first, each with
how much rarer it is than the five common ones (log10 of the odds: a pair mixing metric and
imperial units is taken to be a hundred times rarer)."""

MAX_CHECKED_PARTS = 200
"""Solids looked at (the first ones in the file): a unit slip shows in every part, and a spec of
10⁵ parts should not pay for the check."""

LENGTH_WORDS = {"m": "metres", "cm": "centimetres", "mm": "millimetres", "in": "inches", "ft": "feet"}
MASS_WORDS = {"kg": "kilograms", "g": "grams", "lb": "pounds"}


def material_share(size_decades: float) -> float:
    """The share of parts of size 10**size_decades m (cube root of the volume) that are exactly
    one handbook material (:data:`MATERIAL_HALF_SIZE_M`)."""
    odds = MATERIAL_SHARE_SLOPE * (size_decades - math.log10(MATERIAL_HALF_SIZE_M))
    return 1 / (1 + math.exp(min(odds, 700.0)))


@dataclass(frozen=True)
class _Solid:
    """One solid as the file gives it: volume (one copy, file length³) and its mass (file
    mass unit), density number (file units) or material name."""

    label: str
    volume: float
    mass: float | None = None
    density: float | None = None
    material: str | None = None
    material_si: float | None = None

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
        """Whether the part can be a real one in those units: a density within
        :data:`POSSIBLE_DENSITY_KG_M3`, and no larger than :data:`LARGEST_PART_M` (sizes are
        not judged in metres for a part given its mass: rbi does not second-guess a large SI
        body, only refuses to suggest units that make one)."""
        low, high = POSSIBLE_DENSITY_KG_M3
        density = self.density_si(length, mass)
        if density is not None and not low <= density <= high:
            return False
        return (self.mass is not None and length == "m") or (
            self.size_m(length) <= LARGEST_PART_M and self.metal_kg(length, mass) <= LARGEST_METAL_PIECE_KG
        )

    def metal_kg(self, length: str, mass: str) -> float:
        """The part's kilograms if it is given a metal's density (:data:`METAL_DENSITY_KG_M3`),
        else 0."""
        solid = self.material_si or (self.density_si(length, mass) if self.mass is None else None) or 0.0
        return solid * self.size_m(length) ** 3 if solid >= METAL_DENSITY_KG_M3 else 0.0

    def improbability(self, length: str, mass: str) -> float:
        """How unlikely the part's density and size are together if the file is in ``length``
        and ``mass``: minus log10 of their joint probability density per decade of each. The
        density's, given the size, from a mixture of the handbook materials
        (:data:`REFERENCE_DENSITIES_KG_M3`, each a spike :data:`MATERIAL_MATCH_DECADES` wide
        holding :func:`material_share` between them) and a log-normal spread about the typical
        density of bodies that size (:data:`STRUCTURE_SIZES_M`); the size's, logistic in log10 size
        about :data:`BODY_SIZE_M`. 0 for a part given a material name."""
        density = self.density_si(length, mass)
        if not density:
            return 0.0
        decades, size_decades = math.log10(density), math.log10(self.size_m(length))
        smallest, largest = (math.log10(size) for size in STRUCTURE_SIZES_M)
        thinning = STRUCTURE_THINNING * (
            min(max(size_decades, smallest), largest) - math.log10(TYPICAL_SIZE_M)
        )
        z = (decades - math.log10(TYPICAL_DENSITY_KG_M3) + thinning) / DENSITY_SPREAD_DECADES
        spread = math.exp(-z * z / 2) / (DENSITY_SPREAD_DECADES * math.sqrt(2 * math.pi))
        matches = sum(abs(decades - known) < MATERIAL_MATCH_DECADES for known in _REFERENCE_DECADES)
        spike = matches / (2 * MATERIAL_MATCH_DECADES * len(_REFERENCE_DECADES))
        size_tail = math.exp(-abs(size_decades - math.log10(BODY_SIZE_M)) / BODY_SIZE_SPREAD_DECADES)
        size_prior = size_tail / (BODY_SIZE_SPREAD_DECADES * (1 + size_tail) ** 2)  # logistic density
        share = material_share(size_decades)
        probability = (share * spike + (1 - share) * spread) * size_prior
        return -math.log10(probability) if probability > 0 else math.inf  # 0: underflow (absurd sizes)

    def rare_in_si(self, length: str, mass: str) -> str:
        """What is odd about a part possible in metres and kilograms that ``length`` and
        ``mass`` explain far better: its density is one of :data:`REFERENCE_DENSITIES_KG_M3`
        there."""
        si, there = self.density_si("m", "kg") or 0.0, self.density_si(length, mass) or 0.0
        names = [
            name
            for name, known in REFERENCE_DENSITIES_KG_M3.items()
            if there and abs(math.log10(there / known)) < MATERIAL_MATCH_DECADES
        ]
        what = "implied density" if self.mass is not None else "density"
        material = f" ({names[0]}'s)" if names else ""
        return (
            f"{what} {si:.3g} kg/m³ is a light foam's, but {there:,.5g} kg/m³{material}"
            f" in {LENGTH_WORDS[length]} and {MASS_WORDS[mass]}"
        )

    def problem(self) -> str:
        """What is wrong with the part read in metres and kilograms."""
        density = self.density_si("m", "kg")
        low, high = POSSIBLE_DENSITY_KG_M3
        if density is not None and not low <= density <= high:
            what = "implied density" if self.mass is not None else "density"
            return f"{what} {density:.3g} kg/m³ is outside {low:,.0f}–{high:,.0f} kg/m³ (foam to osmium)"
        material = f" of {self.material}" if self.material else ""
        kilograms = self.volume * (self.material_si or self.density or 0.0)
        if self.size_m("m") <= LARGEST_PART_M:
            return (
                f"{self.size_m('m'):.3g} m across ({kilograms:,.0f} kg{material}), heavier than any"
                f" piece of metal made ({LARGEST_METAL_PIECE_KG / 1000:,.0f} t)"
            )
        return f"{self.size_m('m'):.3g} m across ({kilograms:.3g} kg{material}), larger than any part"

    def kg_per_m3_advice(self) -> str | None:
        """For a part given a density number that is plausible in kg/m³ while its size in metres
        is not (lengths in millimetres, the density in kg/m³): the units: block and the density
        that fit it together, or None."""
        low, high = POSSIBLE_DENSITY_KG_M3
        if self.density is None or not low <= self.density <= high:
            return None
        fitting = likely_units([_Solid(self.label, self.volume, material_si=self.density)])
        if not fitting or fitting[0][0] == "m":
            return None
        length = fitting[0][0]
        return (
            f"lengths look like {LENGTH_WORDS[length]} and the density like kg/m³: add units:"
            f" {{length: {length}}} and give the density in kg/{length}³"
            f" ({self.density * LENGTH_UNITS_IN_M[length] ** 3:.4g})"
        )


def _solids(spec) -> list[_Solid]:

    out = []
    for index, part in enumerate(spec.parts):
        volume = part_volume(part)
        if not volume or not math.isfinite(volume):
            continue
        volume /= 1 if part.pattern is None else part.pattern.count
        density = getattr(part, "density", None)
        label = part_label(index, part)
        if isinstance(density, str):
            name = canonical_name(density) or density
            out.append(_Solid(label, volume, material=name, material_si=MATERIAL_DENSITIES_SI.get(name)))
        else:
            out.append(_Solid(label, volume, mass=getattr(part, "mass", None), density=density))
        if len(out) >= MAX_CHECKED_PARTS:
            break
    return out


def likely_units(solids: list[_Solid]) -> list[tuple[str, str]]:
    """The unit pairs that make every solid possible and are most likely, the most likely
    first: the parts' mean :meth:`_Solid.improbability` plus the pair's rarity
    (:data:`COMMON_UNITS`), to 0.01 decade. Several when only sizes tell (parts given a
    material: mm, cm and in may all fit); empty when no pair makes the body possible."""
    plausible = [pair for pair in COMMON_UNITS if all(s.plausible(*pair) for s in solids)]
    cost = {
        pair: round(sum(s.improbability(*pair) for s in solids) / max(len(solids), 1) + COMMON_UNITS[pair], 2)
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


def _better_explained(solids: list[_Solid]) -> tuple[_Solid, tuple[str, str]] | None:
    """For a body possible in metres and kilograms: the part and unit pair that explain it
    more than :data:`SI_PREFERENCE_DECADES` better (a foam-light part that is exactly a
    handbook metal in cm and g), or None."""
    fitting = likely_units(solids)
    if not fitting or fitting[0] == ("m", "kg"):
        return None
    pair = fitting[0]

    def gain(solid: _Solid) -> float:
        return solid.improbability("m", "kg") - solid.improbability(*pair)

    total = sum(gain(s) for s in solids) / len(solids) - COMMON_UNITS[pair]
    return (max(solids, key=gain), pair) if total > SI_PREFERENCE_DECADES else None


def unit_warnings(spec, path: str) -> list[str]:
    """One line (or none) about a spec without ``units:`` whose solids are implausible in
    metres and kilograms, or far likelier in other units (:func:`_better_explained`):
    ``FILE: parts[i] (name): what is wrong: the units that fit``."""
    if "units" in spec.model_fields_set:
        return []
    solids = _solids(spec)
    wrong = [s for s in solids if not s.plausible("m", "kg")]
    if not wrong:
        better = _better_explained(solids)
        if better is None:
            return []
        solid, (length, mass) = better
        return [f"{path}: {solid.label}: {solid.rare_in_si(length, mass)}: {hint(length, mass)}"]
    more = f" (and {len(wrong) - 1} more part{'s' if len(wrong) > 2 else ''})" if len(wrong) > 1 else ""
    fitting = likely_units(solids)
    mixed = wrong[0].kg_per_m3_advice()
    if mixed:
        advice = mixed
    elif fitting:
        length, mass = fitting[0]
        advice = hint(length, mass, [u for u, m in fitting[1:] if m == mass])
    else:
        advice = "no units rbi knows make it a plausible body: check the numbers"
    return [f"{path}: {wrong[0].label}{more}: {wrong[0].problem()}: {advice}"]
