"""`--units` converts results on output; the spec's own units stay the default."""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_rbi_inprocess

# 500 g at (100, 0, 0) mm and 500 g at (-100, 0, 0) mm: CoM at the origin,
# Iyy = Izz = 2 · 0.5 kg · (0.1 m)² = 0.01 kg·m² = 1e7 g·mm².
SPEC = """
units: {length: mm, mass: g}
pivot: [0, 0, -50]
parts:
  - {shape: point, mass: 500, position: [100, 0, 0]}
  - {shape: point, mass: 500, position: [-100, 0, 0]}
"""


def rbi_json(*args):
    proc = run_rbi_inprocess(*args, "-f", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_inertia_in_si(write_spec):
    path = write_spec(SPEC)
    native = rbi_json("inertia", path)
    si = rbi_json("inertia", path, "--units", "SI")
    assert native["units"] == {"length": "mm", "mass": "g"} and native["inertia"][2][2] == pytest.approx(1e7)
    assert si["units"] == {"length": "m", "mass": "kg"}
    assert si["mass"] == pytest.approx(1.0, rel=1e-15)
    assert si["inertia"][1][1] == pytest.approx(0.01, rel=1e-14) and si["inertia"][0][0] == 0


def test_about_point_is_read_in_file_units_and_reported_in_output_units(write_spec):
    # About the pivot 50 mm below: Ixx = Σ m z² = 1 kg · 0.0025 m² = 0.0025 kg·m².
    si = rbi_json("inertia", write_spec(SPEC), "--about", "0,0,-50", "--units", "si")
    assert si["about"] == pytest.approx([0, 0, -0.05], rel=1e-15)
    assert si["inertia"][0][0] == pytest.approx(0.0025, rel=1e-14)


def test_other_units_and_momentum(write_spec):
    out = rbi_json("momentum", write_spec(SPEC), "--omega", "0,0,2", "--units", "cm,kg")
    # h = Izz ω = 1 kg · (10 cm)² · 2 /s = 200 kg·cm²/s; T = ½ Izz ω² = 200 kg·cm²/s².
    assert out["angular_momentum"][2] == pytest.approx(200.0, rel=1e-14)
    assert out["kinetic_energy"] == pytest.approx(200.0, rel=1e-14)


def test_principal_about_pivot_in_si(write_spec):
    out = rbi_json("principal", write_spec(SPEC), "--about", "pivot", "--units", "SI")
    assert out["moments"] == pytest.approx([0.0025, 0.01, 0.0125], rel=1e-14)


def test_bad_units_value_exits_2(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec(SPEC), "--units", "furlongs")
    assert proc.returncode == 2 and "--units: expected SI or LENGTH,MASS" in proc.stderr


# a part whose inertia, 1e305 kg·m², is 1e311 kg·mm²: more than a double holds
HUGE = """
units: {length: m, mass: kg}
parts:
  - {name: huge, shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1e305, iyy: 1e305, izz: 1e305}}
  - {name: small, shape: point, mass: 1, position: [0, 0, 0]}
"""


@pytest.mark.parametrize("command", [["inertia"], ["principal"], ["momentum", "--omega", "0,0,1"]])
def test_units_that_overflow_a_result_are_one_line_naming_file_and_part_in_every_form(write_spec, command):
    """rbi 4 said '--about: expected 3 finite numbers, got [inf, ...]' (an option not given,
    no file) or '--about: the point is too far from the body'."""
    path = write_spec(HUGE)
    lines = set()
    for form in ("table", "json", "csv"):
        proc = run_rbi_inprocess(*command, path, "--units", "mm,kg", "-f", form)
        assert proc.returncode == 2 and proc.stdout == "", (form, proc.stdout)
        assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr
        lines.add(proc.stderr)
    (line,) = lines  # the same line for every form
    assert line.startswith(f"rbi: {path}: parts[0] (huge): ") and "--about" not in line, line
    assert "not finite" in line and "mm" in line, line
