"""`rbi schema` (JSON Schema of the spec, usable by editors) and `rbi validate FILE...`."""

from __future__ import annotations

import json
import sys

import jsonschema
import pytest

from rbi.spec.load import read_yaml
from tests.conftest import BODIES, run_rbi, run_rbi_inprocess


@pytest.fixture(scope="module")
def validator():
    schema = json.loads(run_rbi_inprocess("schema", "-f", "json").stdout)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def test_every_bundled_body_satisfies_the_schema(validator):
    paths = sorted(BODIES.glob("*.yaml"))
    assert len(paths) >= 8
    for path in paths:
        errors = [e.message for e in validator.iter_errors(read_yaml(path))]  # as rbi reads YAML
        assert not errors, (path.name, errors)


@pytest.mark.parametrize(
    "spec",
    [
        {"parts": [{"shape": "box", "mass": 1, "center": [0, 0, 0], "size": [1, 1, 1], "colour": "red"}]},
        {"parts": [{"shape": "cylindre", "mass": 1, "radius": 1, "start": [0, 0, 0], "end": [0, 0, 1]}]},
        {"parts": [{"shape": "sphere", "density": "unobtainium", "center": [0, 0, 0], "radius": 1}]},
        {"parts": [{"shape": "point", "mass": 1, "position": [0, 0]}]},
        {"units": {"length": "furlong"}, "parts": [{"shape": "point", "mass": 1, "position": [0, 0, 0]}]},
        {
            "parts": [{"shape": "point", "mass": 1, "position": [0, 0, 0]}],
            "expect": {"mass": {"value": 1, "tol": "1 percent"}},
        },
    ],
)
def test_schema_catches_typos_an_editor_should_flag(validator, spec):
    assert list(validator.iter_errors(spec))


def test_table_format_is_indented_json_and_csv_is_refused():
    assert json.loads(run_rbi_inprocess("schema").stdout)["title"] == "rbi body spec"
    assert run_rbi_inprocess("schema", "-f", "csv").returncode == 2


BAD = """
parts:
  - {name: a, shape: cone, mass: -1, radius: 0.1, apex: [0, 0, 0], base: [0, 0, 1]}
  - {name: b, shape: cylinder, mass: 1, radius: 0.1, start: [0, 0, 0], end: [0, 0, 1], colour: red}
"""


def test_validate_reports_every_problem_of_every_file(write_spec):
    good = BODIES / "top.yaml"
    bad = write_spec(BAD, "bad.yaml")
    broken = write_spec("parts: [\n", "broken.yaml")
    proc = run_rbi_inprocess("validate", good, bad, broken)
    assert proc.returncode == 2
    lines = proc.stdout.splitlines()
    assert len(lines) == 3
    assert lines[0].startswith(f"{bad}: parts[") and any(
        "parts[0] (a): mass: must be greater than 0" in l for l in lines
    )
    assert any(f"{bad}: parts[1] (b): colour: unknown field" in l for l in lines)
    assert lines[2].startswith(f"{broken}: YAML syntax error")
    assert "1 of 3" not in proc.stderr and "2 of 3 file(s) invalid, 3 problem(s)" in proc.stderr


def test_validate_sees_physical_problems_too(write_spec):
    hole = write_spec(
        "parts:\n  - {name: s, shape: sphere, mass: 1, radius: 1, center: [0, 0, 0]}\n"
        "  - {name: h, shape: sphere, mass: 2, radius: 1, center: [0, 0, 0], subtract: true}\n"
    )
    proc = run_rbi_inprocess("validate", hole, "-f", "json")
    out = json.loads(proc.stdout)
    assert proc.returncode == 2 and out["ok"] is False
    assert "parts[1] (h): subtract: no mass left" in out["files"][0]["problems"][0]


def test_validate_all_good_exits_0():
    proc = run_rbi("validate", *sorted(BODIES.glob("*.yaml")))
    assert proc.returncode == 0 and proc.stdout == ""


def test_validate_names_standard_input_as_every_command_does():
    """`rbi validate - --format json` gave {"file": "-"} (and CSV a row for '-') where its own
    problems and every other command name standard input <stdin>."""
    import subprocess

    text = (BODIES / "top.yaml").read_text()
    for form in ("json", "csv"):
        done = subprocess.run(
            [sys.executable, "-m", "rbi", "validate", "-", "--format", form],
            input=text,
            capture_output=True,
            text=True,
            timeout=120,
        )
        assert done.returncode == 0, done.stderr
        if form == "json":
            assert json.loads(done.stdout)["files"] == [{"file": "<stdin>", "problems": [], "ok": True}]
        else:
            assert done.stdout.splitlines()[1].startswith("<stdin>,"), done.stdout


def test_the_schema_takes_numbers_written_with_their_uncertainty(validator):
    spec = {
        "uncertainty": "tolerance",
        "parts": [
            {
                "name": "ball",
                "shape": "sphere",
                "mass": "2 ± 0.02",
                "radius": "0.1 +- 1%",
                "center": ["0 ± 0.001", 0, 0],
            },
            {
                "shape": "box",
                "mass": 1,
                "size": [0.1, "0.2 ± 0.001", 0.3],
                "center": [0, 0, 0],
                "rotation": {"axis": [0, 0, 1], "angle_deg": "30 ± 0.5"},
            },
        ],
    }
    assert not [e.message for e in validator.iter_errors(spec)]
    assert list(validator.iter_errors({"uncertainty": "loose", "parts": spec["parts"]}))
    assert list(
        validator.iter_errors(
            {"parts": [{"shape": "sphere", "mass": "two", "radius": 1, "center": [0, 0, 0]}]}
        )
    )
