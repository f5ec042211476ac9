"""The bundled sub-assembly and prism bodies through every command and output form: the CubeSat
built from a bus and four panels equals bodies/cubesat.yaml, the gusset bracket's mass and centre
of mass by hand, `rbi parts --expand` (CLI and API), pictures, export, sweeps and files read."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES, run_rbi_inprocess

NEW = ["cubesat_assembly.yaml", "cubesat_bus.yaml", "cubesat_panel.yaml", "bracket_prism.yaml"]
COMMANDS = [["inertia"], ["principal"], ["parts"], ["parts", "--expand"], ["momentum", "--omega", "1,2,3"]]


@pytest.mark.parametrize("name", NEW)
@pytest.mark.parametrize("command", COMMANDS, ids=" ".join)
def test_every_output_form(name, command):
    table = run_rbi_inprocess(*command, BODIES / name)
    assert table.returncode == 0, table.stderr
    assert max(map(len, table.stdout.splitlines())) <= 80
    out = json.loads(run_rbi_inprocess(*command, BODIES / name, "--format", "json").stdout)
    rows = list(
        csv.DictReader(io.StringIO(run_rbi_inprocess(*command, BODIES / name, "--format", "csv").stdout))
    )
    assert rows and out
    if command[0] == "parts":
        assert [r["name"] for r in rows] == [p["name"] for p in out["parts"]]
        assert sum(p["mass"] for p in out["parts"]) == pytest.approx(out["mass"], rel=1e-13)


def json_of(*args) -> dict:
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


@pytest.mark.parametrize(
    "command", [["inertia"], ["principal"], ["momentum", "--omega", "1,2,3"]], ids=" ".join
)
def test_the_cubesat_from_sub_assemblies_is_the_cubesat(command):
    built, written = (json_of(*command, BODIES / n) for n in ("cubesat_assembly.yaml", "cubesat.yaml"))
    for key, value in written.items():
        if isinstance(value, float) or (isinstance(value, list) and value and not isinstance(value[0], str)):
            scale = np.abs(np.asarray(value, dtype=float)).max() or 1.0
            np.testing.assert_allclose(built[key], value, rtol=1e-13, atol=1e-13 * scale, err_msg=key)


def test_parts_expand_lists_the_four_panels_and_the_bus():
    parts = json_of("parts", BODIES / "cubesat_assembly.yaml", "--expand")["parts"]
    names = [p["name"] for p in parts]
    assert names[:2] == ["bus/bus", "bus/bus-cavity"] and len(names) == 9 + 4
    assert names[-4:] == [
        "wing-left[0]/panel",
        "wing-left[1]/panel",
        "wing-right[0]/panel",
        "wing-right[1]/panel",
    ]
    panels = [p for p in parts if p["name"].endswith("/panel")]
    assert [p["volume"] for p in panels] == pytest.approx([0.2 * 22 * 15] * 4, rel=1e-14)  # cm³, from mm³
    assert [p["mass"] for p in panels] == pytest.approx([1.9 * 0.2 * 22 * 15] * 4, rel=1e-14)
    one = json_of("parts", BODIES / "cubesat_assembly.yaml")["parts"]
    assert [p["name"] for p in one] == ["bus", "wing-left", "wing-right"]
    assert [p["shape"] for p in one] == ["assembly"] * 3
    api = rbi.load(BODIES / "cubesat_assembly.yaml").parts(expand=True)
    assert [p.name for p in api] == names
    written = rbi.load(BODIES / "cubesat.yaml").parts()
    for mine, theirs in zip(api[:9], written[:4] + written[6:]):  # the bus's parts, as written out
        np.testing.assert_allclose(mine.inertia_about_com, theirs.inertia_about_com, rtol=1e-13, atol=1e-9)


def test_the_bracket_by_hand():
    # the outline (convex) less two 8 mm squares and a right triangle, 6 mm of 2.7e-3 g/mm³
    pieces = [(3360.0, None), (-64.0, [10, 10]), (-64.0, [10, 46]), (-360.0, [40, 16])]
    fan = [[0, 0], [80, 0], [80, 12], [20, 60], [0, 60]]
    triangles = [(fan[0], fan[k], fan[k + 1]) for k in range(1, 4)]
    areas = [
        0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) for a, b, c in triangles
    ]
    assert sum(areas) == pytest.approx(3360.0, rel=1e-15)
    first = sum(area * np.mean(t, axis=0) for area, t in zip(areas, triangles))
    first = first + sum(area * np.asarray(c) for area, c in pieces[1:])
    area = sum(a for a, _ in pieces)
    out = json_of("inertia", BODIES / "bracket_prism.yaml")
    assert out["mass"] == pytest.approx(area * 6 * 2.7e-3, rel=1e-14)
    np.testing.assert_allclose(out["center_of_mass"], [*(first / area), 3.0], rtol=1e-13)


def test_pictures_export_and_sweeps(tmp_path):
    for name in ("cubesat_assembly.yaml", "bracket_prism.yaml"):
        for out in ("p.png", "p.html"):
            proc = run_rbi_inprocess("show", BODIES / name, "--out", tmp_path / out)
            assert proc.returncode == 0 and (tmp_path / out).stat().st_size > 1000, proc.stderr
        xml = run_rbi_inprocess("export", BODIES / name, "--to", "urdf").stdout
        assert f'<mass value="{rbi.load(BODIES / name).in_units("m", "kg").mass!r}"' in xml
    # a spec with a measured panel mass and a prism to sweep
    (tmp_path / "panel.yaml").write_bytes((BODIES / "cubesat_panel.yaml").read_bytes())
    spec = tmp_path / "sat.yaml"
    spec.write_text(
        "units: {length: cm, mass: g}\npivot: [0, 0, -20]\nparts:\n"
        "  - {name: panel, shape: assembly, file: panel.yaml, mass: 125, pattern: {count: 4, axis: [0, 0, 1]}}\n"
        "  - {name: beam, shape: prism, density: 2.7, outline: [[-1, -1], [1, -1], [1, 1], [-1, 1]],"
        " start: [0, 0, -20], end: [0, 0, 0]}\n"
    )
    out = json_of(
        "sweep", spec, "--spin", "50", "--duration", "0.05",
        "--vary", "parts.panel.mass=100:200:2", "--vary", "parts.beam.outline[2][0]=1:2:2",
    )  # fmt: skip
    assert out["count"] == 4 and all(r["status"] == "ok" for r in out["runs"])
    assert [r["parts.beam.outline[2][0]"] for r in out["runs"]] == [1.0, 2.0, 1.0, 2.0]
    animation = tmp_path / "a.html"
    assert (
        run_rbi_inprocess(
            "animate", spec, "--spin", "50", "--duration", "0.05", "--out", animation
        ).returncode
        == 0
    )
    # what no output of a run may replace: the spec and the sub-assembly's file
    assert rbi.load(spec).files_read == [str(spec), str(tmp_path / "panel.yaml")]


def test_plus_minus_on_prism_and_sub_assembly_numbers(tmp_path):
    (tmp_path / "panel.yaml").write_bytes((BODIES / "cubesat_panel.yaml").read_bytes())
    spec = tmp_path / "sat.yaml"
    spec.write_text(
        "units: {length: cm, mass: g}\nparts:\n"
        "  - {name: wing, shape: assembly, file: panel.yaml, mass: '125 ± 2', pattern: {count: 2, step: [0, 30, 0]}}\n"
        "  - {name: beam, shape: prism, density: 2.7, outline: [[0, 0], [4, 0], ['4 ± 0.01', 1], [0, 1]],"
        " start: [0, 0, 0], end: [0, 0, 20]}\n"
    )
    out = json_of("uncertainty", spec, "--of", "mass")["quantities"][0]
    sensitivity = {c["input"]: c["sensitivity"] for c in out["contributions"]}
    assert sensitivity["parts.wing.mass"] == pytest.approx(2.0, rel=1e-9)  # two copies
    # moving the vertex (4, 1) along x changes the area by 1/2 × (1 − 0) per unit: ρ L / 2
    assert sensitivity["parts.beam.outline[2][0]"] == pytest.approx(2.7 * 20 / 2, rel=1e-9)
    assert out["u"] == pytest.approx(np.hypot(2 * 2.0, 27 * 0.01), rel=1e-9)


def test_the_picture_legend_counts_copies_of_a_sub_assembly_not_its_parts():
    from rbi.spec.geometry import part_geometry
    from rbi.viz.still import part_legend

    items = part_geometry(rbi.load(BODIES / "cubesat_assembly.yaml")._loaded)
    assert len(items) == 9 + 2 + 2  # every part of the bus, each panel of each wing
    legend = [(e["name"], e["shape"], e["copies"]) for e in part_legend(items)]
    assert legend == [("bus", "assembly", 1), ("wing-left", "assembly", 2), ("wing-right", "assembly", 2)]
