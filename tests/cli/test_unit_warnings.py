"""Every command that computes mass properties or simulates says the same one line about a
spec whose units look wrong: on stderr for table (and CSV) output, as `"warnings"` in JSON
(an empty list when there is nothing to say)."""

from __future__ import annotations

import json

import pytest

from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi

BALL_IN_MM = "parts:\n  - {name: ball, shape: sphere, radius: 10, mass: 0.0329, center: [0, 0, 0]}\n"
HINT = (
    "parts[0] (ball): implied density 7.85e-06 kg/m³ is outside 9–23,000 kg/m³ (foam to osmium): "
    "lengths look like millimetres: add units: {length: mm}"
)
STEEL_BALL_IN_MM = "parts:\n  - {name: ball, shape: sphere, radius: 10, density: steel, center: [0, 0, 0]}\n"
STEEL_HINT = (  # 4/3 pi 10^3 m^3 of steel at 7850 kg/m^3
    "parts[0] (ball): 16.1 m across (32,882,003 kg of steel), heavier than any piece of metal made "
    "(1,000 t): lengths look like millimetres: add units: {length: mm}"
)
BALLS = {"ball_mass": (BALL_IN_MM, HINT), "ball_steel": (STEEL_BALL_IN_MM, STEEL_HINT)}

COMMANDS = {
    "inertia": [],
    "principal": [],
    "parts": [],
    "momentum": ["--omega", "0,0,1"],
    "dynamics": ["--alpha", "0,0,1"],
    "export": ["--to", "urdf"],
    "simulate": ["--spin", "1", "--duration", "0.1"],
    "sweep": ["--spin", "1:2:2", "--duration", "0.1"],
}


@pytest.fixture(params=BALLS)
def ball(tmp_path, request):
    """A ball of radius 10 mm written without units: given its mass (0.0329 kg), and given
    steel's density (read in metres, 32,882,003 kg: rbi 4 did not warn it)."""
    path = tmp_path / f"{request.param}.yaml"
    path.write_text(BALLS[request.param][0])
    return path


def hint(ball):
    return BALLS[ball.stem][1]


@pytest.mark.parametrize("command", COMMANDS)
def test_json_carries_the_warning_and_table_output_prints_it_once(command, ball):
    args = COMMANDS[command]
    as_json = rbi(command, ball, *args, "--format", "json")
    assert as_json.returncode == 0, as_json.stderr
    assert json.loads(as_json.stdout)["warnings"] == [f"{ball}: {hint(ball)}"]
    assert "rbi: warning:" not in as_json.stderr
    table = rbi(command, ball, *args)
    assert table.returncode == 0, table.stderr
    assert table.stderr.splitlines().count(f"rbi: warning: {ball}: {hint(ball)}") == 1
    assert table.stderr.count("rbi: warning:") == 1


@pytest.mark.parametrize("command", COMMANDS)
def test_a_plausible_body_has_an_empty_list(command):
    proc = rbi(command, BODIES / "top.yaml", *COMMANDS[command], "--format", "json")
    assert json.loads(proc.stdout)["warnings"] == [] and proc.stderr == ""


def test_check_and_several_files(ball, tmp_path):
    budget = tmp_path / "budget.yaml"
    budget.write_text(BALLS[ball.stem][0] + "expect:\n  mass: {value: 0.0329, tol: 1%}\n")
    assert json.loads(rbi("check", budget, "--format", "json").stdout)["warnings"] == [
        f"{budget}: {hint(ball)}"
    ]
    lines = rbi("inertia", ball, BODIES / "top.yaml", "--format", "json").stdout.splitlines()
    assert [json.loads(line)["warnings"] for line in lines] == [[f"{ball}: {hint(ball)}"], []]
    several = rbi("inertia", ball, BODIES / "top.yaml")
    assert several.stderr.count("rbi: warning:") == 1
    csv = rbi("inertia", ball, "--format", "csv")
    assert "warnings" not in csv.stdout and csv.stderr.count("rbi: warning:") == 1


@pytest.mark.parametrize("command, args", [("show", []), ("animate", ["--spin", "1", "--duration", "0.1"])])
def test_pictures_print_the_warning_once(command, args, ball, tmp_path):
    proc = rbi(command, ball, *args, "--out", tmp_path / f"{command}.html")
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.splitlines().count(f"rbi: warning: {ball}: {hint(ball)}") == 1
