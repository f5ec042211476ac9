"""`rbi parts`: each part's numbers against hand-worked closed forms."""

from __future__ import annotations

import json
import math

import pytest

from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi


def parts_json(path):
    proc = rbi("parts", path, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout), proc.stderr


def test_the_bolted_top_part_by_part():
    out, warnings = parts_json(BODIES / "top_bolted.yaml")
    assert warnings == ""
    cone, stem, bolt = out["parts"]
    assert [p["name"] for p in out["parts"]] == ["cone", "stem", "bolt"]
    assert [p["shape"] for p in out["parts"]] == ["cone", "cylinder", "point"]
    # cone: m 0.4, r 0.04, h 0.06, CoM 3h/4 from the apex; I about its CoM 3/20 m r² + 3/80 m h², axial 3/10 m r²
    assert cone["center_of_mass"] == pytest.approx([0, 0, 0.045], abs=1e-15)
    transverse = 3 / 20 * 0.4 * 0.04**2 + 3 / 80 * 0.4 * 0.06**2
    assert cone["inertia_about_com"][0][0] == pytest.approx(transverse, rel=1e-13)
    assert cone["inertia_about_com"][2][2] == pytest.approx(3 / 10 * 0.4 * 0.04**2, rel=1e-13)
    assert cone["implied_density"] == pytest.approx(0.4 / (math.pi * 0.04**2 * 0.06 / 3), rel=1e-13)
    # stem: m 0.1, r 0.008, l 0.04 from z 0.06 to 0.10: I = m(3r² + l²)/12, axial m r²/2
    assert stem["inertia_about_com"][1][1] == pytest.approx(0.1 * (3 * 0.008**2 + 0.04**2) / 12, rel=1e-13)
    assert bolt["implied_density"] is None and bolt["inertia_about_com"] == [[0.0] * 3] * 3
    assert sum(p["mass"] for p in out["parts"]) == pytest.approx(out["mass"], rel=1e-15)
    assert sum(p["inertia_share"] for p in out["parts"]) == pytest.approx(1.0, rel=1e-12)
    # the bolt's share: m |d|² twice over (trace of a point mass's inertia is 2 m |d|²) over the body's trace
    com = out["center_of_mass"]
    d2 = (0.04 - com[0]) ** 2 + com[1] ** 2 + (0.06 - com[2]) ** 2
    body = json.loads(rbi("inertia", BODIES / "top_bolted.yaml", "--format", "json").stdout)
    trace = sum(body["inertia"][i][i] for i in range(3))
    assert bolt["inertia_share"] == pytest.approx(2 * 0.02 * d2 / trace, rel=1e-12)


def test_holes_count_negative_and_the_masses_still_add_up():
    out, _ = parts_json(BODIES / "wheel_with_holes.yaml")
    holes = [p for p in out["parts"] if p["hole"]]
    assert holes and all(p["mass"] < 0 for p in holes)
    assert sum(p["mass"] for p in out["parts"]) == pytest.approx(out["mass"], rel=1e-12)


def test_a_spec_written_in_millimetres_without_saying_so_is_flagged(write_spec):
    spec = write_spec(
        "parts:\n  - {name: cone, shape: cone, mass: 0.4, radius: 40, apex: [0, 0, 0], base: [0, 0, 60]}\n"
    )
    out, warnings = parts_json(spec)
    assert out["parts"][0]["implied_density_si"] == pytest.approx(0.4 / (math.pi * 40**2 * 60 / 3), rel=1e-12)
    assert warnings == "" and len(out["warnings"]) == 1  # JSON carries the warning (table output prints it)
    assert "(cone)" in out["warnings"][0] and "length: mm" in out["warnings"][0]


def test_table_and_csv(write_spec):
    table = rbi("parts", BODIES / "top_bolted.yaml")
    assert table.returncode == 0 and "kg/m³" in table.stdout and "bolt" in table.stdout
    rows = rbi("parts", BODIES / "top_bolted.yaml", "--format", "csv").stdout.splitlines()
    assert len(rows) == 4 and rows[0].startswith("name,shape,")


def test_the_table_never_cuts_a_name_or_number_short_in_80_columns(monkeypatch):
    """Piped or in a narrow terminal, long part names and long numbers wrap instead of ending
    in '…' (a cut number would be a wrong number)."""
    monkeypatch.setenv("COLUMNS", "80")
    for body in ("wheel_pattern.yaml", "cubesat.yaml", "robot_link.yaml", "bracket.yaml"):
        proc = rbi("parts", BODIES / body)
        assert proc.returncode == 0, proc.stderr
        assert "…" not in proc.stdout, body


def test_the_centre_of_mass_table_prints_rounding_noise_as_zero_and_keeps_real_offsets(tmp_path, monkeypatch):
    # a coordinate of 1e-17 m on a 0.1 m sphere is far below 1e-12 of the body's size: noise;
    # 1 mm is a real offset. JSON keeps every digit. The spec is named relative to its folder:
    # the titles carry the path, and pytest's long tmp_path made them wrap at 80 columns
    # ('...spheres.yaml: parts' / '— centre of mass'), which the split below does not expect.
    monkeypatch.chdir(tmp_path)
    spec = "spheres.yaml"
    (tmp_path / spec).write_text(
        "parts:\n"
        "  - {name: noisy, shape: sphere, mass: 1, radius: 0.1, center: [1.0e-17, 0, 0]}\n"
        "  - {name: offset, shape: sphere, mass: 1, radius: 0.1, center: [0, 0.001, 0]}\n"
    )
    proc = rbi("parts", spec)
    assert proc.returncode == 0, proc.stderr
    table = proc.stdout.split("parts — centre of mass")[1].split("parts — principal")[0]
    rows = {line.split()[0]: line.split()[1:4] for line in table.splitlines() if line.split()}
    assert rows["noisy"] == ["0", "0", "0"]
    assert rows["offset"] == ["0", "0.001", "0"]
    assert rows["total"] == ["0", "0.0005", "0"]
    out, _ = parts_json(spec)
    assert out["parts"][0]["center_of_mass"][0] == 1e-17


def test_the_table_of_thousands_of_parts_lists_the_first_and_counts_the_rest(write_spec):
    """Found: `rbi parts` of 10,000 parts took 25 s in table form (1.7 s as JSON) laying out
    30,000 rich rows nobody reads. The table lists the first 200 parts of each section, says
    how many more there are and where to find them, and keeps the body's total: 1000 points of
    1 g weigh 1 kg. JSON and CSV still list every part."""
    lines = ["parts:"] + [
        f"  - {{name: p{i}, shape: point, mass: 0.001, position: [{i % 10}, {i // 10 % 10}, {i // 100}]}}"
        for i in range(1000)
    ]
    path = write_spec("\n".join(lines) + "\n")
    table = rbi("parts", path)
    assert table.returncode == 0, table.stderr
    rows = table.stdout.splitlines()
    assert sum(line.split()[:1] == ["p199"] for line in rows) == 3  # the 200th part, in each section
    assert not any(line.split()[:1] == ["p200"] for line in rows)
    assert sum("800 more parts" in line for line in rows) == 3
    total = next(line for line in rows if line.split()[:1] == ["total"])
    assert float(total.split()[1]) == pytest.approx(1.0, rel=1e-12)
    assert len(json.loads(rbi("parts", path, "--format", "json").stdout)["parts"]) == 1000
    assert len(rbi("parts", path, "--format", "csv").stdout.splitlines()) == 1001


def test_a_holes_volume_has_one_sign_in_every_output_form():
    # bodies/wheel_with_holes.yaml: six 11 mm-radius, 16.07 mm-long drillings in aluminium (2700 kg/m³ =
    # 0.0027 g/mm³). `rbi parts` printed hole-1's volume as -6107.26 mm³ in the table and as
    # +6107.256... in --format json and csv: one column, two signs. Now every form gives it
    # negative, as its mass, and the parts' volumes add up to the body's.
    path = BODIES / "wheel_with_holes.yaml"
    out, _ = parts_json(path)
    hole = next(p for p in out["parts"] if p["name"] == "hole-1")
    drilled = hole["mass"] / 0.0027  # mm³: its mass over the density, negative for a hole
    assert hole["volume"] == pytest.approx(drilled, rel=1e-12) and hole["volume"] < 0
    assert hole["implied_density"] == pytest.approx(0.0027, rel=1e-12)
    assert sum(p["volume"] for p in out["parts"]) == pytest.approx(out["volume"], rel=1e-14)
    csv_rows = rbi("parts", path, "--format", "csv").stdout.splitlines()
    header, hole_row = csv_rows[0].split(","), next(r for r in csv_rows if r.startswith("hole-1,")).split(",")
    assert float(hole_row[header.index("volume")]) == pytest.approx(drilled, rel=1e-12)
    table_row = next(
        line for line in rbi("parts", path).stdout.splitlines() if line.split()[:1] == ["hole-1"]
    )
    assert float(table_row.split()[5]) == pytest.approx(
        drilled, rel=1e-5
    )  # part, shape, (hole), mass, share, volume


def test_the_mean_density_of_the_table_is_in_json_too():
    # the table's total row gave the top's mean density, 4605 kg/m³ (0.5 kg in 1.0857e-4 m³),
    # and --format json had no such number
    out, _ = parts_json(BODIES / "top.yaml")
    cone = math.pi * 0.04**2 * 0.06 / 3
    stem = math.pi * 0.008**2 * 0.04
    assert out["mean_density"] == pytest.approx(0.5 / (cone + stem), rel=1e-12)
    total = next(
        line for line in rbi("parts", BODIES / "top.yaml").stdout.splitlines() if line.startswith(" total")
    )
    assert float(total.split()[-1]) == pytest.approx(out["mean_density"], rel=1e-3)
    assert parts_json(BODIES / "top_bolted.yaml")[0]["mean_density"] is None  # the bolt has no volume
