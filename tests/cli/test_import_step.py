"""`rbi import FILE.step`: a spec rbi reads back (one `shape: step` part per solid, named after
it, names escaped for YAML), its JSON and CSV listings, and its refusals; `rbi show` and
`rbi animate` draw STEP parts."""

from __future__ import annotations

import csv
import io
import json
import math
import os

import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess
from tests.step_builders import box, moved, sphere, write_step

AWKWARD = "arm: left #1 'quoted' - [x]"  # YAML syntax: a key, a comment, quotes, a list


@pytest.fixture
def kit(tmp_path):
    """An assembly in mm: a 10 × 20 × 30 box named AWKWARD and a Ø10 ball 100 mm along x."""
    write_step(
        tmp_path / "kit.step",
        [(AWKWARD, box(10, 20, 30).shape), ("ball", moved(sphere(5.0).shape, (100, 0, 0)))],
        "mm",
        assembly="kit",
    )
    return tmp_path / "kit.step"


def test_the_printed_spec_reads_back_with_the_same_masses(tmp_path, kit, monkeypatch):
    monkeypatch.chdir(tmp_path)
    proc = run_rbi_inprocess("import", "kit.step", "--material", "steel")
    assert proc.returncode == 0, proc.stderr
    (tmp_path / "kit.yaml").write_text(proc.stdout)
    parts = run_rbi_inprocess("parts", "kit.yaml", "--format", "json")
    assert parts.returncode == 0, parts.stderr
    rows = json.loads(parts.stdout)["parts"]
    assert [r["name"] for r in rows] == [AWKWARD, "ball"]
    v_box, v_ball = 10 * 20 * 30 * 1e-9, 4 / 3 * math.pi * 125e-9  # m³
    assert rows[0]["mass"] == pytest.approx(7850 * v_box, rel=1e-12)
    assert rows[1]["mass"] == pytest.approx(7850 * v_ball, rel=1e-12)
    assert rows[1]["center_of_mass"] == pytest.approx([0.1, 0, 0], abs=1e-12)


def test_density_and_the_placeholder(tmp_path, kit, monkeypatch):
    monkeypatch.chdir(tmp_path)
    given = run_rbi_inprocess("import", "kit.step", "--density", "2700")
    assert given.returncode == 0 and "density: 2700.0" in given.stdout and "placeholder" not in given.stdout
    default = run_rbi_inprocess("import", "kit.step")
    assert default.returncode == 0 and "density: 1000.0" in default.stdout and "placeholder" in default.stdout


def test_out_writes_the_file_path_relative_to_the_spec(tmp_path, kit, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "specs").mkdir()
    proc = run_rbi_inprocess("import", "kit.step", "--density", "1000", "--out", "specs/kit.yaml")
    assert proc.returncode == 0, proc.stderr
    assert "file: '../kit.step'" in (tmp_path / "specs" / "kit.yaml").read_text()
    # reading it back needs --allow-outside-paths, and the import says so; beside the file, no note
    assert "--allow-outside-paths" in proc.stderr and "../kit.step" in proc.stderr
    refused = run_rbi_inprocess("inertia", "specs/kit.yaml", "--format", "json")
    assert refused.returncode == 2 and "--allow-outside-paths" in refused.stderr
    beside = run_rbi_inprocess("import", "kit.step", "--density", "1000", "--out", "kit.yaml")
    assert beside.returncode == 0 and "note" not in beside.stderr, beside.stderr
    back = run_rbi_inprocess("inertia", "specs/kit.yaml", "--format", "json", "--allow-outside-paths")
    assert back.returncode == 0, back.stderr
    assert json.loads(back.stdout)["mass"] == pytest.approx(
        1000 * (6e-6 + 4 / 3 * math.pi * 125e-9), rel=1e-12
    )


def test_json_and_csv_list_the_solids(tmp_path, kit):
    out = run_rbi_inprocess("import", str(kit), "--density", "1000", "--format", "json")
    assert out.returncode == 0, out.stderr
    listing = json.loads(out.stdout)
    assert listing["file_unit"] == "mm" and listing["density"] == 1000
    box_row, ball_row = listing["solids"]
    assert box_row["name"] == AWKWARD and box_row["volume"] == pytest.approx(6e-6, rel=1e-12)
    # a 10 × 20 × 30 mm box of 6 g: Ixx = m (b² + c²)/12
    assert box_row["inertia_about_com"][0][0] == pytest.approx(6e-3 * (0.02**2 + 0.03**2) / 12, rel=1e-12)
    assert ball_row["integration_error"] < 1e-9
    table = run_rbi_inprocess("import", str(kit), "--density", "1000", "--format", "csv")
    assert table.returncode == 0, table.stderr
    rows = list(csv.DictReader(io.StringIO(table.stdout)))
    assert [r["name"] for r in rows][1] == "ball"
    assert float(rows[1]["mass"]) == pytest.approx(1000 * 4 / 3 * math.pi * 125e-9, rel=1e-12)


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--material", "stel"], ["--material", "did you mean 'steel'"]),
        (["--density", "-1"], ["--density", "positive"]),
        (["--density", "1", "--material", "steel"], ["--density and --material: give one of them"]),
        (["--link", "x"], ["--link", "solids, not links"]),
    ],
)
def test_bad_options_are_one_line(kit, args, words):
    one_line_exit_2(run_rbi_inprocess("import", str(kit), *args), *words)


@pytest.mark.parametrize(
    ("settings", "head"),
    [
        ({"density": 1.0, "material": "steel"}, "density and material: give one of them"),
        ({"density": -1.0}, "density: must be a positive number"),
        ({"density": "x"}, "density: must be a positive number"),
        ({"material": "stel"}, "material: unknown material 'stel'"),
    ],
)
def test_the_api_names_its_parameters_with_a_value_error(kit, settings, head):
    """rbi.spec.from_step.import_step: a bad density or material is a ValueError naming the parameter."""
    from rbi.spec.from_step import import_step

    with pytest.raises(ValueError) as caught:
        import_step(kit, **settings)
    assert str(caught.value).startswith(head) and "--" not in str(caught.value)


def test_bad_files_are_one_line(tmp_path):
    (tmp_path / "x.step").write_text("not step\n")
    one_line_exit_2(run_rbi_inprocess("import", str(tmp_path / "x.step")), "x.step", "not a STEP file")
    one_line_exit_2(run_rbi_inprocess("import", str(tmp_path / "none.stp")), "none.stp", "no such file")
    os.mkfifo(tmp_path / "pipe.step")  # a FIFO is there, but is no file to read: said so, without blocking
    one_line_exit_2(
        run_rbi_inprocess("import", str(tmp_path / "pipe.step")), "pipe.step", "not a regular file"
    )


def test_show_and_animate_draw_step_parts(tmp_path, kit):
    spec = tmp_path / "kit.yaml"
    spec.write_text("units: {length: mm}\nparts:\n  - {name: kit, shape: step, file: kit.step, mass: 1}\n")
    page = run_rbi_inprocess("show", spec, "--out", tmp_path / "kit.html")
    assert page.returncode == 0, page.stderr
    html = (tmp_path / "kit.html").read_text()
    assert '"kind": "mesh"' in html or '"kind":"mesh"' in html
    animation = run_rbi_inprocess("animate", spec, "--out", tmp_path / "kit-motion.html", "--spin", "5")
    assert animation.returncode == 0, animation.stderr


def test_the_json_listing_is_the_imports_to_dict_with_the_file(kit, monkeypatch):
    """`rbi import FILE.step --format json` = `import_step(FILE).to_dict()` with "file"
    first; the CSV rows are its csv_rows(): the box of 10 × 20 × 30 mm at 1000 kg/m³ weighs
    6 g, the Ø10 mm ball π/6 g."""
    from rbi.spec.from_step import import_step

    monkeypatch.chdir(kit.parent)
    proc = run_rbi_inprocess("import", "kit.step", "--format", "json")
    imported = import_step("kit.step")
    assert json.loads(proc.stdout) == json.loads(
        json.dumps({"file": "kit.step", **imported.to_dict()}, default=list)
    )
    masses = sorted(row["mass"] for row in imported.csv_rows())
    assert masses == pytest.approx(sorted([6e-3, math.pi / 6 * 1e-3]), rel=1e-9)


def test_the_import_is_a_result_whose_table_lists_the_solids(kit):
    """The STEP import presents itself as every rbi.Result does: its table, one row a solid,
    from the same rows as its JSON and CSV."""
    import rbi

    imported = rbi.import_robot(kit, density=1000)
    assert isinstance(imported, rbi.Result)
    (table,) = imported.rows()
    assert [cells[0] for cells in table.cells] == [AWKWARD, "ball"]
    assert [cells[2] for cells in table.cells] == ["0.006", "0.000523599"]
    assert len(imported.to_pandas()) == 2 and "ball" in str(imported)
