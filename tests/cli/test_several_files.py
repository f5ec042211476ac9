"""Several FILEs in one run, and FILE `-` (standard input): `inertia`, `principal`, `parts` and
`check` (contract, "Several files, standard input").

Numbers are checked against closed forms: the spinning top is a cone (m 0.4) and a stem
(m 0.1); the bolted top adds a 0.02 kg bolt."""

from __future__ import annotations

import csv
import io
import json
import math
import sys

import numpy as np
import pytest

from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi

TOP, BOLTED = BODIES / "top.yaml", BODIES / "top_bolted.yaml"
TOP_MASS, BOLTED_MASS = 0.4 + 0.1, 0.4 + 0.1 + 0.02


@pytest.fixture
def bad_spec(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("parts:\n  - {shape: point, mass: -1, position: [0, 0, 0]}\n")
    return path


@pytest.fixture
def failing_check(tmp_path):
    """The robot link with a mass budget it misses (1.9 kg expected, 1.7487 kg built)."""
    text = (BODIES / "robot_link.yaml").read_text()
    assert "mass: {value: 1.7487, tol: 0.1%}" in text
    path = tmp_path / "over_budget.yaml"
    path.write_text(text.replace("mass: {value: 1.7487, tol: 0.1%}", "mass: {value: 1.9, tol: 0.1%}"))
    return path


def json_lines(text):
    return [json.loads(line) for line in text.splitlines()]


@pytest.mark.parametrize("command", ["inertia", "principal", "parts"])
def test_json_lines_one_object_per_good_file_and_one_error_line_for_the_bad_one(command, bad_spec):
    proc = rbi(command, TOP, bad_spec, BOLTED, "--format", "json")
    assert proc.returncode == 2
    lines = json_lines(proc.stdout)
    assert [line["file"] for line in lines] == [str(TOP), str(BOLTED)]
    assert [line["mass"] for line in lines] == pytest.approx([TOP_MASS, BOLTED_MASS], rel=1e-14)
    errors = proc.stderr.strip().splitlines()
    assert len(errors) == 1 and str(bad_spec) in errors[0] and "mass" in errors[0]
    # each object carries the keys of the one-file form, with the same values
    alone = json.loads(rbi(command, BOLTED, "--format", "json").stdout)
    assert {k: v for k, v in lines[1].items() if k != "file"} == alone


def test_csv_one_header_and_one_row_per_file_file_first(bad_spec):
    proc = rbi("inertia", TOP, bad_spec, BOLTED, "--about", "origin", "--format", "csv")
    assert proc.returncode == 2 and str(bad_spec) in proc.stderr
    rows = list(csv.DictReader(io.StringIO(proc.stdout)))
    assert proc.stdout.splitlines()[0].startswith("file,name,")
    assert [r["file"] for r in rows] == [str(TOP), str(BOLTED)]
    assert [float(r["mass"]) for r in rows] == pytest.approx([TOP_MASS, BOLTED_MASS], rel=1e-14)
    # the top about its tip: cone 3/5 m h² + 3/20 m r² ... about z only the axial terms
    Izz = 0.3 * 0.4 * 0.04**2 + 0.5 * 0.1 * 0.008**2
    assert float(rows[0]["inertia_zz"]) == pytest.approx(Izz, rel=1e-12)


def test_table_one_section_per_file_in_order(bad_spec):
    proc = rbi("principal", TOP, bad_spec, BOLTED)
    assert proc.returncode == 2
    out = proc.stdout
    assert (
        out.index(f"==> {TOP} <==")
        < out.index("spinning-top")
        < out.index(f"==> {BOLTED} <==")
        < out.index("bolted-top")
    )
    assert f"==> {bad_spec} <==" not in out
    assert len(proc.stderr.strip().splitlines()) == 1


def test_all_good_files_exit_0_and_one_file_keeps_its_one_object_form():
    proc = rbi("inertia", TOP, BOLTED, TOP, "--format", "json")
    assert proc.returncode == 0 and proc.stderr == ""
    assert len(json_lines(proc.stdout)) == 3
    alone = rbi("inertia", TOP, "--format", "json").stdout
    assert "file" not in json.loads(alone) and alone.count("\n") == 1


def test_check_exit_status_is_the_worst_of_the_files(failing_check, bad_spec):
    link = BODIES / "robot_link.yaml"
    assert rbi("check", link, BODIES / "wheel_pattern.yaml").returncode == 0
    failed = rbi("check", link, failing_check, "--format", "csv")
    assert failed.returncode == 1 and failed.stderr == ""
    rows = list(csv.DictReader(io.StringIO(failed.stdout)))
    assert [(r["file"], r["ok"], r["failed"]) for r in rows] == [
        (str(link), "True", "0"),
        (str(failing_check), "False", "1"),
    ]
    worst = rbi("check", failing_check, bad_spec, link, "--format", "json")
    assert worst.returncode == 2
    assert [(line["file"], line["ok"]) for line in json_lines(worst.stdout)] == [
        (str(failing_check), False),
        (str(link), True),
    ]
    # a spec without expect: is bad input for check, the others still checked
    missing = rbi("check", TOP, link, "--format", "json")
    assert missing.returncode == 2 and "expect" in missing.stderr and len(json_lines(missing.stdout)) == 1


def test_parts_csv_among_several_files_is_one_summary_row_per_file():
    proc = rbi("parts", TOP, BOLTED, "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(proc.stdout)))
    assert proc.returncode == 0 and len(rows) == 2
    assert [int(r["parts"]) for r in rows] == [2, 3]
    cone = math.pi * 0.04**2 * 0.06 / 3
    stem = math.pi * 0.008**2 * 0.04
    assert [float(r["volume"]) for r in rows] == pytest.approx([cone + stem] * 2, rel=1e-12)


# --- standard input -------------------------------------------------------------------------


def with_stdin(monkeypatch, text: str) -> None:
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(text.encode("utf-8")), encoding="utf-8"))


def test_a_yaml_spec_from_standard_input(monkeypatch):
    with_stdin(monkeypatch, TOP.read_text())
    proc = rbi("inertia", "-", "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["mass"] == pytest.approx(TOP_MASS, rel=1e-15)


def test_a_json_spec_from_standard_input_among_files(monkeypatch):
    with_stdin(
        monkeypatch,
        json.dumps(
            {
                "name": "two-points",
                "parts": [
                    {"shape": "point", "mass": 1.0, "position": [-1, 0, 0]},
                    {"shape": "point", "mass": 1.0, "position": [1, 0, 0]},
                ],
            }
        ),
    )
    proc = rbi("principal", TOP, "-", "--format", "json")
    assert proc.returncode == 0, proc.stderr
    top, points = json_lines(proc.stdout)
    assert points["file"] == "<stdin>" and points["name"] == "two-points"
    assert points["moments"] == pytest.approx([0.0, 2.0, 2.0], abs=1e-15)  # 2 m d² about y and z


def test_messages_name_standard_input_stdin(monkeypatch):
    with_stdin(monkeypatch, "parts:\n  - {shape: sphere, radius: 0, mass: 1, center: [0, 0, 0]}\n")
    proc = rbi("parts", "-")
    assert proc.returncode == 2
    assert proc.stderr.startswith("rbi: <stdin>: parts[0]") and "radius" in proc.stderr


@pytest.mark.parametrize(
    "spec, vary, words",
    [
        ("parts:\n  - {shape: assembly, file: missing.yaml}\n", [], "parts[0]: file: missing.yaml"),
        (None, ["--vary", "parts.nope.mass=1:2:2"], "--vary parts.nope.mass"),
    ],
)
def test_sweep_messages_name_standard_input_stdin(monkeypatch, spec, vary, words):
    """rbi sweep - names standard input as the other commands do, also where the nominal body or a
    --vary path is refused (they said '-')."""
    with_stdin(monkeypatch, spec or TOP.read_text())
    proc = rbi("sweep", "-", "--spin", "1", "--duration", "0.1", *vary)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.startswith(f"rbi: <stdin>: {words}") and len(proc.stderr.splitlines()) == 1


@pytest.mark.parametrize(
    "command",
    [
        ["check"],
        ["export", "--to", "urdf"],
        ["momentum", "--omega", "0,0,1"],
        ["dynamics", "--alpha", "0,0,1"],
        ["simulate", "--spin", "100", "--duration", "0.01"],
    ],
)
def test_every_command_that_takes_a_spec_reads_standard_input(monkeypatch, command):
    with_stdin(monkeypatch, (BODIES / "robot_link.yaml").read_text())
    proc = rbi(command[0], "-", *command[1:], "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)


def test_mesh_paths_in_a_spec_from_standard_input_are_relative_to_the_current_folder(monkeypatch, tmp_path):
    spec = (BODIES / "bracket.yaml").read_text()
    monkeypatch.chdir(BODIES)
    with_stdin(monkeypatch, spec)
    here = rbi("inertia", "-", "--format", "json")
    assert here.returncode == 0, here.stderr
    assert json.loads(here.stdout)["mass"] == pytest.approx(0.0619037, rel=1e-4)  # the bracket's own budget
    monkeypatch.chdir(tmp_path)
    with_stdin(monkeypatch, spec)
    elsewhere = rbi("inertia", "-")
    assert elsewhere.returncode == 2 and "<stdin>" in elsewhere.stderr and "no such file" in elsewhere.stderr
    with_stdin(monkeypatch, spec.replace("file: bracket.stl", f"file: {BODIES / 'bracket.stl'}"))
    outside = rbi("inertia", "-")
    assert outside.returncode == 2 and "leaves the spec's folder" in outside.stderr


# --- rbi parts: totals, volumes, principal moments (issue 19) --------------------------------


def test_parts_totals_are_the_body_built_by_hand():
    """The bolted top: cone (m 0.4, r 0.04, h 0.06), stem (m 0.1, r 0.008, l 0.04), bolt
    (0.02 kg point at (0.04, 0, 0.06))."""
    out = json.loads(rbi("parts", BOLTED, "--format", "json").stdout)
    cone_v, stem_v = math.pi * 0.04**2 * 0.06 / 3, math.pi * 0.008**2 * 0.04
    assert [p["volume"] for p in out["parts"][:2]] == pytest.approx([cone_v, stem_v], rel=1e-13)
    assert out["parts"][2]["volume"] is None
    assert out["volume"] == pytest.approx(cone_v + stem_v, rel=1e-13)  # the point bolt has no volume
    assert out["mass"] == pytest.approx(BOLTED_MASS, rel=1e-15)
    # principal moments of each part about its own centre of mass, ascending
    cone_t = 3 / 20 * 0.4 * 0.04**2 + 3 / 80 * 0.4 * 0.06**2
    stem_t = 0.1 * (3 * 0.008**2 + 0.04**2) / 12
    expected = [
        sorted([cone_t, cone_t, 0.3 * 0.4 * 0.04**2]),
        sorted([stem_t, stem_t, 0.5 * 0.1 * 0.008**2]),
        [0, 0, 0],
    ]
    for part, moments in zip(out["parts"], expected):
        assert part["principal_moments"] == pytest.approx(moments, rel=1e-12, abs=1e-18)
    # the body's principal moments: parallel axis for each part about the body's centre of mass
    masses = [0.4, 0.1, 0.02]
    centres = np.array([[0, 0, 0.045], [0, 0, 0.08], [0.04, 0, 0.06]])
    own = [
        np.diag([cone_t, cone_t, 0.3 * 0.4 * 0.04**2]),
        np.diag([stem_t, stem_t, 0.5 * 0.1 * 0.008**2]),
        np.zeros((3, 3)),
    ]
    com = sum(m * c for m, c in zip(masses, centres)) / sum(masses)
    total = sum(
        I + m * ((c - com) @ (c - com) * np.eye(3) - np.outer(c - com, c - com))
        for m, c, I in zip(masses, centres, own)
    )
    assert out["principal_moments"] == pytest.approx(np.linalg.eigvalsh(total), rel=1e-12)


def test_parts_table_ends_with_a_total_row(monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    proc = rbi("parts", BOLTED)
    assert proc.returncode == 0, proc.stderr
    totals = [line.split() for line in proc.stdout.splitlines() if line.strip().startswith("total")]
    assert len(totals) == 3  # mass and volume; centre of mass; principal moments
    mass_row, com_row, moments_row = totals
    assert mass_row[1:3] == ["0.52", "100"] and mass_row[4] == "—"  # no mean density: the bolt has no volume
    assert float(mass_row[3]) == pytest.approx(
        math.pi * 0.04**2 * 0.06 / 3 + math.pi * 0.008**2 * 0.04, rel=1e-5
    )
    assert [float(x) for x in com_row[1:4]] == pytest.approx([0.02 * 0.04 / 0.52, 0, 0.0272 / 0.52], rel=1e-5)
    json_moments = json.loads(rbi("parts", BOLTED, "--format", "json").stdout)["principal_moments"]
    assert [float(x) * 1e-4 for x in moments_row[1:4]] == pytest.approx(json_moments, rel=1e-4)  # shown ×10⁻⁴
    assert "[m³]" in proc.stdout and "×10⁻⁴" in proc.stdout and "…" not in proc.stdout
    assert max(len(line) for line in proc.stdout.splitlines()) <= 80


def test_holes_are_taken_from_the_total_volume():
    out = json.loads(rbi("parts", BODIES / "wheel_with_holes.yaml", "--format", "json").stdout)
    assert all((p["volume"] < 0) == p["hole"] for p in out["parts"])  # a hole's volume is negative
    assert out["volume"] == pytest.approx(sum(p["volume"] for p in out["parts"]), rel=1e-14)
    assert out["mass"] == pytest.approx(out["volume"] * 0.0027, rel=1e-12)  # aluminium throughout, g/mm³
