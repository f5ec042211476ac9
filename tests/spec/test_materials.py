"""Material names for `density`: the table, its conversion to the file's units, and errors."""

from __future__ import annotations

import math
import re

import pytest

from rbi.spec.errors import InputError
from rbi.spec.load import load_body
from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name, density_in_units


@pytest.mark.parametrize(
    "name, length, mass, expected, rel",
    [
        ("steel", "mm", "g", 0.00785, 1e-12),  # 7.85 g/cm³
        ("steel", "cm", "g", 7.85, 1e-12),
        ("aluminium 6061", "in", "lb", 0.0975, 1e-3),  # handbook: 0.0975 lb/in³
        ("water", "ft", "lb", 62.3, 1e-3),  # 62.3 lb/ft³ at 20 °C
        ("copper", "m", "kg", 8960.0, 0.0),
    ],
)
def test_conversion_to_file_units_matches_handbook_figures(name, length, mass, expected, rel):
    assert density_in_units(name, length, mass) == pytest.approx(expected, rel=rel)


@pytest.mark.parametrize(
    "spelling", ["Steel", "STAINLESS_STEEL", "aluminum-6061", "Aluminium", "Ti-6Al-4V", "ti64", " pla "]
)
def test_names_ignore_case_and_separators(spelling):
    assert canonical_name(spelling) in MATERIAL_DENSITIES_SI


def test_named_density_gives_the_same_body_as_the_number(write_spec):
    named = load_body(
        write_spec(
            """
units: {length: mm, mass: g}
parts:
  - {shape: box, density: brass, center: [0, 0, 0], size: [10, 20, 30]}
""",
            "named.yaml",
        )
    )
    assert named.props.mass == pytest.approx(8500 * 1e-6 * 6000, rel=1e-13)  # 8.5 g/cm³ × 6 cm³


def test_every_table_density_is_plausible_for_a_solid_or_liquid():
    # Between cork-light wood and lead: catches a value typed in g/cm³ or with a lost digit.
    for name, rho in MATERIAL_DENSITIES_SI.items():
        assert 500 <= rho <= 12000, name
    assert math.isclose(MATERIAL_DENSITIES_SI["water"], 998.2)


def test_unknown_material_suggests_the_closest_name(write_spec):
    path = write_spec(
        "parts:\n  - {name: arm, shape: sphere, density: stainles steel, center: [0, 0, 0], radius: 1}\n"
    )
    with pytest.raises(InputError) as info:
        load_body(path)
    message = str(info.value)
    assert (
        "parts[0] (arm): density: unknown material 'stainles steel' (did you mean 'stainless steel'?)"
        in message
    )
    assert "steel, stainless steel" in message


def test_material_is_another_way_to_write_a_material_density(write_spec):
    """``material: NAME`` on a solid part (as the contract lists it beside mass and density):
    a 10 mm steel cube in a mm/g file weighs 7.85 g, as ``density: steel`` does (a handbook
    figure, not rbi's); with mass or density too, on a point, or misspelt, one line naming it."""
    cube = "{name: b, shape: box, size: [10, 10, 10], center: [0, 0, 0], %s}"
    for field in ("material: steel", "material: Stainless_Steel", "density: steel"):
        path = write_spec("units: {length: mm, mass: g}\nparts:\n  - " + cube % field + "\n")
        expected = 8.0 if "Stainless" in field else 7.85
        assert load_body(path).props.mass == pytest.approx(expected, rel=1e-12), field
    for field, words in (
        ("material: steel, density: 2", "parts[0] (b): material, density: give one of them"),
        ("material: steel, mass: 2", "parts[0] (b): material, mass: give one of them"),
        ("material: stel", "parts[0] (b): material: unknown material 'stel' (did you mean 'steel'?)"),
        ("material: 7", "parts[0] (b): material: unknown material '7'"),
    ):
        path = write_spec("parts:\n  - " + cube % field + "\n")
        with pytest.raises(InputError, match=re.escape(words)):
            load_body(path)
    point = write_spec("parts:\n  - {name: p, shape: point, position: [0, 0, 0], material: steel}\n")
    with pytest.raises(InputError, match=re.escape("parts[0] (p): material: unknown field")):
        load_body(point)
