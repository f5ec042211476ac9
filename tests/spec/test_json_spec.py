"""A spec written as one JSON object (valid YAML too) takes the json module's fast path and
means exactly what the same YAML means; a bad JSON spec is reported by the YAML parser."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rbi.spec.errors import InputError
from rbi.spec.load import load_body, read_yaml

YAML = """
name: top
pivot: [0, 0, 0]
parts:
  - {name: cone, shape: cone, mass: 0.4, radius: 0.04, apex: [0, 0, 0], base: [0, 0, 0.06]}
  - {name: bolt, shape: point, mass: 2.0e-2, position: [0.04, 0, 0.06]}
"""


def test_json_and_yaml_give_the_same_body(write_spec):
    from_yaml = load_body(write_spec(YAML, "top.yaml"))
    as_json = json.dumps(read_yaml(write_spec(YAML, "top.yaml")), indent=1)
    from_json = load_body(write_spec(as_json, "top.json"))
    assert from_json.name == "top" and from_json.part_names == ["cone", "bolt"]
    assert from_json.props.mass == from_yaml.props.mass
    np.testing.assert_array_equal(from_json.props.center_of_mass, from_yaml.props.center_of_mass)
    np.testing.assert_array_equal(from_json.props.inertia_about_com, from_yaml.props.inertia_about_com)
    np.testing.assert_array_equal(from_json.pivot, [0.0, 0.0, 0.0])


@pytest.mark.parametrize(
    "text, message",
    [
        (
            '{"parts": [{"shape": "point", "mass": 1, "mass": 2, "position": [0, 0, 0]}]}',
            "line 1, column 42: duplicate key 'mass'",
        ),
        ('{"parts": [{"shape": "point", "mass": 1 "position": [0, 0, 0]}]}', "YAML syntax error: line 1"),
        (
            '{"parts": [{"shape": "point", "mass": NaN, "position": [0, 0, 0]}]}',
            "parts[0]: mass: must be a finite number",
        ),
    ],
)
def test_bad_json_specs_are_one_line_errors(write_spec, text, message):
    with pytest.raises(InputError, match=message.replace("[", r"\[").replace("]", r"\]")):
        load_body(write_spec(text, "bad.json"))
