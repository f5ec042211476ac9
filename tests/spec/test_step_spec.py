"""`shape: step` in a spec: the file's own unit honoured (a STEP file in mm in a spec in m and
the other way round), placement, solids by name and index, mass or density, every output form
of inertia and parts, and every refusal — one line, exit 2, naming the part."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess
from tests.step_builders import CLOSED_FORMS, box, moved, sphere, write_step


def run_json(*args):
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


@pytest.mark.parametrize(
    ("file_unit", "spec_unit", "per_mm"), [("mm", "m", 1e-3), ("m", "mm", 1.0), ("mm", "cm", 0.1)]
)
def test_the_files_unit_is_honoured(tmp_path, file_unit, spec_unit, per_mm):
    """The bored plate, written in one unit, read in a spec in another: its sizes come out in
    the spec's unit with no scale, to 1e-9 of the closed form."""
    plate = CLOSED_FORMS["bored plate"]()
    write_step(tmp_path / "plate.step", plate.shape, file_unit)
    spec = tmp_path / "body.yaml"
    spec.write_text(
        f"units: {{length: {spec_unit}, mass: kg}}\nparts:\n  - {{name: plate, shape: step, file: plate.step, mass: 2.5}}\n"
    )
    out = run_json("inertia", spec)
    inertia = plate.inertia * per_mm**2 * 2.5 / plate.volume  # mm⁵ at unit density -> per the mass
    np.testing.assert_allclose(out["center_of_mass"], plate.com * per_mm, rtol=0, atol=1e-9 * 100 * per_mm)
    np.testing.assert_allclose(out["inertia"], inertia, rtol=0, atol=1e-9 * np.abs(inertia).max())
    parts = run_json("parts", spec)["parts"][0]
    assert parts["volume"] == pytest.approx(plate.volume * per_mm**3, rel=1e-9)
    assert 0 <= parts["integration_error"] < 1e-9


def test_density_material_position_and_rotation(tmp_path):
    """A 40 × 30 × 20 mm box in a spec in mm: steel by name, moved and turned 90° about z,
    against the closed form of the turned box."""
    write_step(tmp_path / "box.step", box(40, 30, 20).shape, "m")
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "units: {length: mm, mass: g}\nparts:\n"
        "  - {name: block, shape: step, file: box.step, density: steel, position: [5, 6, 7],\n"
        "     rotation: {axis: [0, 0, 1], angle_deg: 90}}\n"
    )
    out = run_json("inertia", spec)
    mass = 7.85e-3 * 40 * 30 * 20  # g/mm³ × mm³
    assert out["mass"] == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(out["center_of_mass"], [5, 6, 7], atol=1e-9)
    expected = mass / 12 * np.diag([40**2 + 20**2, 30**2 + 20**2, 40**2 + 30**2])  # x and y swapped
    np.testing.assert_allclose(out["inertia"], expected, rtol=1e-9, atol=1e-9 * expected.max())


def assembly(tmp_path):
    ball = sphere(5.0)
    return write_step(
        tmp_path / "asm.step",
        [("base", box(10, 20, 30).shape), ("ball", moved(ball.shape, (100, 0, 0)))],
        "mm",
        assembly="kit",
    )


def test_solids_by_name_by_index_and_all_together(tmp_path):
    assembly(tmp_path)
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "units: {length: mm, mass: g}\nparts:\n"
        "  - {name: every, shape: step, file: asm.step, density: 1}\n"
        "  - {name: base, shape: step, file: asm.step, solid: base, density: 1, position: [0, 0, 1000]}\n"
        "  - {name: ball, shape: step, file: asm.step, solid: 1, density: 1, position: [0, 0, 1000]}\n"
    )
    rows = run_json("parts", spec)["parts"]
    v_box, v_ball = 10 * 20 * 30, 4 / 3 * math.pi * 125
    assert rows[0]["mass"] == pytest.approx(v_box + v_ball, rel=1e-12)
    assert rows[1]["mass"] == pytest.approx(v_box, rel=1e-12)
    assert rows[2]["mass"] == pytest.approx(v_ball, rel=1e-12)
    # the box is centred on the file's origin, the ball 100 mm along x
    np.testing.assert_allclose(
        rows[0]["center_of_mass"], [100 * v_ball / (v_box + v_ball), 0, 0], rtol=1e-12, atol=1e-12
    )
    np.testing.assert_allclose(rows[2]["center_of_mass"], [100, 0, 1000], atol=1e-9)
    assert [r["integration_error"] < 1e-9 for r in rows] == [True] * 3


def test_inertia_and_parts_in_every_output_form(tmp_path):
    """Table, JSON and CSV of inertia and parts on a STEP spec: the same numbers in each."""
    write_step(tmp_path / "ball.step", sphere(10.0).shape, "mm")
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "name: ball\nunits: {length: mm, mass: g}\nparts:\n"
        "  - {name: ball, shape: step, file: ball.step, mass: 100}\n"
        "  - {name: tip, shape: point, mass: 1, position: [0, 0, 50]}\n"
    )
    mass, com_z = 101.0, 50 / 101
    izz = 0.4 * 100 * 100
    out = run_json("inertia", spec)
    assert out["mass"] == pytest.approx(mass)
    assert out["center_of_mass"][2] == pytest.approx(com_z, rel=1e-12)
    assert out["inertia"][2][2] == pytest.approx(izz, rel=1e-12)
    proc = run_rbi_inprocess("inertia", spec, "--format", "csv")
    assert proc.returncode == 0, proc.stderr
    row = next(csv.DictReader(io.StringIO(proc.stdout)))
    assert float(row["mass"]) == pytest.approx(mass)
    assert float(row["inertia_zz"]) == pytest.approx(izz, rel=1e-9)
    table = run_rbi_inprocess("inertia", spec)
    assert table.returncode == 0 and "4000" in table.stdout and "101" in table.stdout
    parts = run_rbi_inprocess("parts", spec, "--format", "csv")
    assert parts.returncode == 0, parts.stderr
    rows = list(csv.DictReader(io.StringIO(parts.stdout)))
    assert rows[0]["shape"] == "step" and float(rows[0]["volume"]) == pytest.approx(
        4 / 3 * math.pi * 1000, rel=1e-12
    )
    assert float(rows[0]["integration_error"]) < 1e-9 and rows[1]["integration_error"] == ""
    parts_table = run_rbi_inprocess("parts", spec)
    assert parts_table.returncode == 0 and "step" in parts_table.stdout and "4188.79" in parts_table.stdout


def test_a_spec_without_step_parts_has_no_integration_error_key(tmp_path):
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {shape: sphere, radius: 1, mass: 1, center: [0, 0, 0]}\n")
    assert "integration_error" not in run_json("parts", spec)["parts"][0]


@pytest.mark.parametrize(
    ("part", "prepare", "words"),
    [
        ("file: nothere.step", None, ["parts[0] (p)", "nothere.step", "no such file"]),
        ("file: ../out.step", None, ["parts[0] (p)", "leaves the spec's folder"]),
        ("file: part.stl", None, ["parts[0] (p)", "must end in .step or .stp"]),
        (
            "file: bad.step",
            lambda d: (d / "bad.step").write_text("solid x\nendsolid\n"),
            ["parts[0] (p)", "bad.step", "not a STEP file"],
        ),
        ("file: asm.step, solid: bal", assembly, ["parts[0] (p)", "no solid named 'bal'", "'base', 'ball'"]),
        ("file: asm.step, solid: 2", assembly, ["parts[0] (p)", "solid: 2 is out of range"]),
        ("file: asm.step, solid: -1", assembly, ["parts[0]", "solid"]),
    ],
    ids=["missing", "outside", "extension", "not step", "unknown name", "index", "negative"],
)
def test_refusals_are_one_line_naming_the_part(tmp_path, part, prepare, words):
    if prepare is not None:
        prepare(tmp_path)
    spec = tmp_path / "body.yaml"
    spec.write_text(f"parts:\n  - {{name: p, shape: step, {part}, density: 1000}}\n")
    one_line_exit_2(run_rbi_inprocess("inertia", spec), *words)


def test_a_huge_file_is_refused_by_its_size(tmp_path):
    from rbi.formats.step import MAX_STEP_BYTES

    with open(tmp_path / "huge.step", "wb") as stream:
        stream.write(b"ISO-10303-21;\n")
        stream.truncate(MAX_STEP_BYTES + 1)
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {name: p, shape: step, file: huge.step, density: 1000}\n")
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[0] (p)", "huge.step", "too large")


def test_without_the_cad_extra_one_line_names_it(tmp_path, monkeypatch):
    import sys

    write_step(tmp_path / "box.step", box().shape, "mm")
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {name: p, shape: step, file: box.step, density: 1000}\n")
    monkeypatch.setitem(sys.modules, "OCP.Message", None)  # as if OCP were not installed
    import rbi.formats.step as step_module

    monkeypatch.setattr(step_module, "_CACHE", type(step_module._CACHE)())
    # OpenCascade is loaded by the child process that reads the file: not installed there either
    monkeypatch.setattr(
        step_module, "_CHILD", "import sys; sys.modules['OCP.Message'] = None; " + step_module._CHILD
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[0] (p)", "pip install '.[cad]'")


def test_without_the_cad_extra_the_extra_is_named_before_anything_else_about_the_part(tmp_path, monkeypatch):
    # without OpenCascade no STEP file can even be written, so a user's spec may name one that
    # is not there yet: the line names the extra to install, not the missing file
    import importlib.util

    real_find_spec = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util, "find_spec", lambda name, *a: None if name == "OCP" else real_find_spec(name, *a)
    )
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {name: p, shape: step, file: not-written-yet.step, density: 1000}\n")
    proc = run_rbi_inprocess("inertia", spec, "--format", "json")
    one_line_exit_2(proc, "parts[0] (p)", "pip install '.[cad]'")
    assert "no such file" not in proc.stderr
