"""The JSON Schema reads well in an editor: every field described in plain text, each
material name listed once yet any case accepted, as rbi itself accepts it."""

from __future__ import annotations

import json
import re

import pytest

from rbi.api import spec_schema
from rbi.spec.materials import ALIASES, MATERIAL_DENSITIES_SI
from tests.conftest import run_rbi_inprocess

jsonschema = pytest.importorskip("jsonschema")


def _properties(node, path=""):
    """(path, schema) of every property anywhere in the schema."""
    if isinstance(node, dict):
        for name, value in node.get("properties", {}).items():
            yield f"{path}.{name}", value
        for key, value in node.items():
            yield from _properties(value, f"{path}/{key}")
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _properties(value, f"{path}[{i}]")


def _descriptions(node):
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "description":
                yield value
            else:
                yield from _descriptions(value)
    elif isinstance(node, list):
        for value in node:
            yield from _descriptions(value)


def test_every_property_has_a_description():
    missing = [path for path, value in _properties(spec_schema()) if not value.get("description")]
    assert missing == []


def test_descriptions_are_plain_text():
    for text in _descriptions(spec_schema()):
        assert "``" not in text and not re.search(r":(mod|func|class|data):`", text), text
        assert "\n" not in text


def test_each_material_name_is_listed_once():
    text = json.dumps(spec_schema())
    enums = [e for e in re.findall(r'"enum": (\[[^\]]*\])', text) if "steel" in e]
    assert enums
    for enum in map(json.loads, enums):
        assert sorted(enum) == sorted(set(MATERIAL_DENSITIES_SI) | set(ALIASES))
    assert '"STEEL"' not in text and '"Steel"' not in text  # no case variants listed


@pytest.mark.parametrize(
    "density, valid",
    [
        ("steel", True),
        ("Stainless_Steel", True),
        ("TI-6AL-4V", True),
        ("aluminium-6061", True),
        ("unobtainium", False),
        ("steel!", False),
    ],
)
def test_schema_and_rbi_agree_on_material_spellings(write_spec, density, valid):
    spec = {"parts": [{"shape": "sphere", "density": density, "center": [0, 0, 0], "radius": 0.01}]}
    errors = list(jsonschema.Draft202012Validator(spec_schema()).iter_errors(spec))
    assert (errors == []) == valid
    proc = run_rbi_inprocess("validate", write_spec(json.dumps(spec)))
    assert (proc.returncode == 0) == valid, proc.stderr
