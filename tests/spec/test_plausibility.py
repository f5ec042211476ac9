"""Unit slips: a spec without `units:` whose numbers were written in other units is warned
about with the units it was written in; a spec that states its units never is. Each spec
below is a real object (steel, aluminium) drawn in known units, so the right answer is known."""

from __future__ import annotations

import math

import pytest

import rbi
from tests.conftest import BODIES

STEEL_BALL_KG = 7850 * 4 / 3 * math.pi * 0.01**3  # radius 10 mm: 0.0329 kg
ALUMINIUM_CYLINDER_G = 2.7 * math.pi * 2**2 * 5  # radius 2 cm, length 5 cm, 2.7 g/cm³
STEEL_BLOCK_LB = 24 * 7850 / 27679.9047  # 2 × 3 × 4 in, steel in lb/in³


def ball(radius, **mass_or_density):
    return {"name": "ball", "shape": "sphere", "radius": radius, "center": [0, 0, 0], **mass_or_density}


CASES = {
    # name: (part written in those units, the units it was written in, the hint expected)
    "mm and kg": (
        ball(10, mass=STEEL_BALL_KG),
        {"length": "mm", "mass": "kg"},
        "lengths look like millimetres: add units: {length: mm}",
    ),
    "mm and g": (
        ball(10, mass=1000 * STEEL_BALL_KG),
        {"length": "mm", "mass": "g"},
        "lengths look like millimetres and masses like grams: add units: {length: mm, mass: g}",
    ),
    "cm and g": (
        {
            "name": "rod",
            "shape": "cylinder",
            "radius": 2,
            "start": [0, 0, 0],
            "end": [0, 0, 5],
            "mass": ALUMINIUM_CYLINDER_G,
        },
        {"length": "cm", "mass": "g"},
        "lengths look like centimetres and masses like grams: add units: {length: cm, mass: g}",
    ),
    "cm, density in g/cm³": (
        {"name": "block", "shape": "box", "center": [0, 0, 0], "size": [10, 20, 30], "density": 7.85},
        {"length": "cm", "mass": "g"},
        "add units: {length: cm, mass: g}",
    ),
    "in and lb": (
        {"name": "block", "shape": "box", "center": [0, 0, 0], "size": [2, 3, 4], "mass": STEEL_BLOCK_LB},
        {"length": "in", "mass": "lb"},
        "lengths look like inches and masses like pounds: add units: {length: in, mass: lb}",
    ),
    "in, density in lb/in³": (
        ball(2, density=7850 / 27679.9047),
        {"length": "in", "mass": "lb"},
        "add units: {length: in, mass: lb}",
    ),
    "g": (
        {"name": "cube", "shape": "box", "center": [0, 0, 0], "size": [0.1, 0.1, 0.1], "mass": 7850.0},
        {"length": "m", "mass": "g"},
        "masses look like grams: add units: {mass: g}",
    ),
    "mm, density: steel": (  # only size tells: a part over 0.2 m read as metres is over 200 m
        ball(300, density="steel"),
        {"length": "mm", "mass": "kg"},
        "lengths look like millimetres: add units: {length: mm}",
    ),
    "mm, a steel ball of radius 10": (  # rbi 4: 32,882,003 kg of steel in metres, not warned
        ball(10, density="steel"),
        {"length": "mm", "mass": "kg"},
        "lengths look like millimetres: add units: {length: mm}",
    ),
    "mm, material: copper": (
        {"name": "bar", "shape": "box", "center": [0, 0, 0], "size": [100, 20, 10], "material": "copper"},
        {"length": "mm", "mass": "kg"},
        "lengths look like millimetres: add units: {length: mm}",
    ),
}


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
def test_a_spec_without_units_is_warned_with_the_units_it_was_written_in(case):
    part, _, expected = CASES[case]
    body = rbi.load({"parts": [part]})
    assert len(body.warnings) == 1, body.warnings
    line = body.warnings[0]
    assert line.startswith(f"<dict>: parts[0] ({part['name']}): ") and expected in line, line


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
def test_the_same_spec_with_its_units_is_never_warned(case):
    part, units, _ = CASES[case]
    body = rbi.load({"units": units, "parts": [part]})
    assert body.warnings == []
    # and stating units is enough, even units that do not fit: rbi never second-guesses them
    assert rbi.load({"units": {"length": "m", "mass": "kg"}, "parts": [part]}).warnings == []


def test_the_steel_ball_in_mm_and_kg_comes_out_as_exactly_steel():
    """The issue's case: 0.0329 kg at radius 10 was told "mm and lb?"; mm and kg give 7850."""
    body = rbi.load({"parts": [ball(10, mass=STEEL_BALL_KG)]})
    assert "mm" in body.warnings[0] and "lb" not in body.warnings[0]
    density = body.mass / (4 / 3 * math.pi * 10**3) * (1 / 0.001**3)
    assert density == pytest.approx(7850, rel=1e-12)


def test_several_wrong_parts_give_one_line_naming_the_first():
    parts = [
        ball(10, mass=STEEL_BALL_KG),
        {**ball(5, mass=STEEL_BALL_KG / 8), "name": "small", "center": [30, 0, 0]},
    ]
    warnings = rbi.load({"parts": parts}).warnings
    assert len(warnings) == 1 and "parts[0] (ball) (and 1 more part)" in warnings[0]


def test_plausible_bodies_and_parts_without_volume_are_not_warned():
    for path in sorted(BODIES.glob("*.yaml")):
        assert rbi.load(path).warnings == [], path.name
    point = {"name": "p", "shape": "point", "mass": 1e6, "position": [0, 0, 0]}
    assert rbi.load({"parts": [point]}).warnings == []


LEAD_BRICK_CM_G = {  # 20 × 10 × 5 cm of lead (11.34 g/cm³): 11,340 g; read as SI, an 11.3 kg/m³ "foam"
    "name": "brick",
    "shape": "box",
    "center": [0, 0, 0],
    "size": [20, 10, 5],
    "mass": 20 * 10 * 5 * 11.34,
}


def test_a_foam_light_part_that_is_exactly_lead_in_cm_and_g_is_warned():
    warnings = rbi.load({"parts": [LEAD_BRICK_CM_G]}).warnings
    assert len(warnings) == 1, warnings
    assert "11.3 kg/m³ is a light foam's, but 11,340 kg/m³ (lead's) in centimetres and grams" in warnings[0]
    assert warnings[0].endswith("add units: {length: cm, mass: g}")
    assert rbi.load({"units": {"length": "cm", "mass": "g"}, "parts": [LEAD_BRICK_CM_G]}).warnings == []


@pytest.mark.parametrize("kg_m3", [11.0, 11.2, 11.5, 15.0, 19.0, 22.0])
def test_a_real_foam_not_exactly_a_metal_in_cm_and_g_is_not_warned(kg_m3):
    """11.34 kg/m³ to 0.1 % is lead in cm and g; 11.2 or 11.5 is a foam like any other."""
    foam = {"name": "foam", "shape": "box", "center": [0, 0, 0], "size": [2, 1, 0.5], "mass": kg_m3}
    assert rbi.load({"parts": [foam]}).warnings == []


def test_the_steel_ball_of_radius_10_says_what_it_weighs_in_metres():
    (line,) = rbi.load({"parts": [ball(10, density="steel")]}).warnings
    tonnes = 7850 * 4 / 3 * math.pi * 10**3 / 1000  # 32,882 t: no piece of metal is made that heavy
    assert f"16.1 m across ({tonnes * 1000:,.0f} kg of steel), heavier than any piece of metal made" in line


def test_a_density_number_in_kg_m3_with_lengths_in_mm_is_told_both():
    """radius 10 and density 7850: no units: block alone fits (in mm, 7850 kg/mm³ is no
    material); lengths in mm with the density in kg/mm³ do, and the line says so."""
    (line,) = rbi.load({"parts": [ball(10, density=7850)]}).warnings
    assert line.endswith(
        "lengths look like millimetres and the density like kg/m³: add units: {length: mm} and give"
        " the density in kg/mm³ (7.85e-06)"
    ), line
    fixed = rbi.load({"units": {"length": "mm"}, "parts": [ball(10, density=7.85e-06)]})
    assert fixed.warnings == [] and fixed.mass == pytest.approx(STEEL_BALL_KG, rel=1e-12)


def rod(radius, length, density):
    return {
        "name": "rod",
        "shape": "cylinder",
        "radius": radius,
        "start": [0, 0, 0],
        "end": [0, 0, length],
        "density": density,
    }


LARGE_SI_SOLIDS = {
    # real solids given their density, in metres: big, and not warned
    "Taipei 101's damper ball (660 t of steel, 5.5 m)": ball(2.75, density="steel"),
    "a 600 t steel ingot": rod(1.5, 600e3 / (7850 * math.pi * 1.5**2), "steel"),
    "a wind-turbine foundation (20 m, 2,260 t of concrete)": rod(10, 3, 2400),
    "a 1,000 m³ tank of water": {
        "name": "tank",
        "shape": "box",
        "center": [0, 0, 0],
        "size": [10] * 3,
        "density": "water",
    },
    "an asteroid 200 m across": ball(100, density=2000),
    "an oak trunk 30 m long": rod(1.0, 30, "oak"),
}


@pytest.mark.parametrize("name", LARGE_SI_SOLIDS)
def test_large_real_solids_given_their_density_are_not_warned(name):
    assert rbi.load({"parts": [LARGE_SI_SOLIDS[name]]}).warnings == []


def test_no_corpus_object_drawn_with_its_density_in_si_is_warned():
    """Every corpus object with each part given its density (mass ÷ volume) instead of its mass,
    and again by material name where the density is a built-in material's (to 0.1 %)."""
    from rbi.spec.materials import MATERIAL_DENSITIES_SI
    from tests.spec.plausibility_corpus import OBJECTS, spec

    warned = []
    for entry in OBJECTS:
        parts = spec(entry)["parts"]
        numbers = []
        for part in parts:
            solid = {key: value for key, value in part.items() if key != "mass"}
            volume = rbi.load({"parts": [{**solid, "density": 1.0}]}).mass
            numbers.append({**solid, "density": part["mass"] / volume})
        names = [
            next(
                (name for name, d in MATERIAL_DENSITIES_SI.items() if abs(d / p["density"] - 1) < 1e-3), None
            )
            for p in numbers
        ]
        variants = [numbers] + ([[{**p, "density": n} for p, n in zip(numbers, names)]] if all(names) else [])
        warned += [(entry[0], w) for variant in variants for w in rbi.load({"parts": variant}).warnings]
    assert warned == []
