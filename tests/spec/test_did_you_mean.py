"""A misspelt field is named and the intended one suggested, at every depth of the spec."""

import pytest

from rbi.spec.errors import InputError
from rbi.spec.load import read_yaml, spec_from_raw

POINT = "parts: [{shape: point, mass: 1, position: [0, 0, 0]}]\n"


@pytest.mark.parametrize(
    "text, where, suggestion",
    [
        ("unit: {length: mm}\n" + POINT, "unit:", "units"),
        ("units: {lenght: mm}\n" + POINT, "units.lenght:", "length"),
        (
            "parts: [{shape: cone, mass: 1, radius: 1, apex: [0, 0, 0], bsae: [0, 0, 1]}]\n",
            "parts[0]: bsae:",
            "base",
        ),
        (
            "parts: [{shape: box, mass: 1, center: [0, 0, 0], size: [1, 1, 1], rotation: {axis: [0, 0, 1], angle_dg: 3}}]\n",
            "rotation.angle_dg:",
            "angle_deg",
        ),
        (POINT + "expect: {masss: {value: 1, tol: 1%}}\n", "expect.masss:", "mass"),
        (POINT + "expect: {mass: {valeu: 1, tol: 1%}}\n", "expect.mass.valeu:", "value"),
    ],
)
def test_unknown_field_is_named_with_a_suggestion(write_spec, text, where, suggestion):
    path = write_spec(text)
    with pytest.raises(InputError) as info:
        spec_from_raw(str(path), read_yaml(path))
    message = str(info.value)
    assert where in message and "unknown field" in message
    assert f"did you mean '{suggestion}'" in message
