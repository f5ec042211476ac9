"""A spec builds only the part models it uses (start-up time), and reports every problem
exactly as pydantic's discriminated union of all shapes does."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from pydantic import TypeAdapter, ValidationError

from rbi.spec.models import BodySpec, Part
from tests.conftest import BODIES

BAD_PARTS = [
    5,
    None,
    "cone",
    [],
    {},
    {"shape": "cyl"},
    {"shape": 5},
    {"shape": None, "mass": 1},
    {"shape": "cone", "radius": -1, "apex": [0, 0, 0], "base": [0, 0, 1], "mass": 1},
    {"shape": "cone", "radius": 1, "apex": [0, 0, 0], "base": [0, 0, 0], "mass": 1},
    {"shape": "cylinder", "radius": 1, "start": [0, 0], "end": [0, 0, 1], "density": "unobtainium"},
    {"shape": "point", "mass": 1, "position": [0, 0, 0], "density": 3},
    {"shape": "box", "size": [1, 1, 1], "center": [0, 0, 0], "mass": 1, "colour": "red"},
    {
        "shape": "box",
        "size": [1, 1, 1],
        "center": [0, 0, 0],
        "mass": 1,
        "rotation": {"axis": [0, 0, 0], "angle_deg": 3},
    },
    {
        "shape": "sphere",
        "radius": 1,
        "center": [0, 0, 0],
        "mass": 1,
        "pattern": {"count": 0, "step": [1, 0, 0]},
    },
    {"shape": "custom", "mass": 1, "centre_of_mass": [0, 0, 0], "inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
]


def _errors(exc: ValidationError) -> list[tuple]:
    return [(e["type"], e["loc"], e["msg"], repr(e["input"])) for e in exc.errors(include_url=False)]


@pytest.mark.parametrize("part", BAD_PARTS, ids=lambda p: json.dumps(p)[:60])
def test_each_problem_is_reported_as_the_union_of_every_shape_reports_it(part):
    with pytest.raises(ValidationError) as union:
        TypeAdapter(list[Part]).validate_python([part])
    with pytest.raises(ValidationError) as lazy:
        BodySpec.model_validate({"parts": [part]})
    expected = [(kind, ("parts", *loc), msg, given) for kind, loc, msg, given in _errors(union.value)]
    assert _errors(lazy.value) == expected


def test_a_spec_builds_only_the_models_of_its_shapes():
    code = (
        "import json, sys\nfrom rbi.spec.load import load_body\nfrom rbi.spec import models, expect\n"
        "load_body(sys.argv[1])\n"
        "print(json.dumps({name: model.__pydantic_complete__ for name, model in models.SHAPE_MODELS.items()}"
        " | {'expect': expect.Expect.__pydantic_complete__, 'body': models.BodySpec.__pydantic_complete__}))"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code, str(BODIES / "top.yaml")], capture_output=True, text=True, timeout=120
    )
    built = json.loads(proc.stdout)
    assert {name for name, done in built.items() if done} == {"cone", "cylinder", "body"}
