"""`shape: mesh` in a spec: every file format read to the same exact box, placement (scale,
rotation, position), density and holes, SolidWorks figures for two CAD parts, and every
refusal — each one line, exit 2, naming the part and never the file's content."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import one_line_exit_2, run_rbi, run_rbi_inprocess
from tests.mesh_builders import WRITERS, box_mesh, sphere_mesh, write_binary_stl, write_obj

CAD = Path(__file__).resolve().parents[1] / "data" / "cad"


def inertia_json(spec: Path, *extra: str) -> dict:
    proc = run_rbi_inprocess("inertia", spec, "--format", "json", *extra)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def box_moments(mass, a, b, c):
    return mass / 12.0 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])


@pytest.mark.parametrize("file_name", sorted(WRITERS))
def test_every_format_gives_the_exact_box(tmp_path, file_name):
    size, center = (0.2, 0.3, 0.5), (1.0, -2.0, 0.5)
    WRITERS[file_name](tmp_path / file_name, *box_mesh(size, center))
    spec = tmp_path / "body.yaml"
    spec.write_text(f"parts:\n  - {{name: block, shape: mesh, file: {file_name}, mass: 3.0}}\n")
    out = inertia_json(spec)
    # binary STL and MSH store float32: the corners are the float32 values nearest the box's
    rtol = 1e-7 if file_name in ("binary.stl", "mesh.msh") else 1e-14
    assert out["mass"] == 3.0
    np.testing.assert_allclose(out["center_of_mass"], center, rtol=rtol, atol=rtol)
    np.testing.assert_allclose(out["inertia"], np.diag(box_moments(3.0, *size)), rtol=rtol * 10, atol=1e-15)


def test_density_gives_the_enclosed_volume_times_density(tmp_path):
    write_obj(tmp_path / "box.obj", *box_mesh((0.1, 0.2, 0.4)))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: b, shape: mesh, file: box.obj, density: 7850}\n"
        "  - {name: s, shape: mesh, file: box.obj, density: steel, position: [1, 0, 0]}\n"
    )
    proc = run_rbi_inprocess("parts", spec, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    rows = json.loads(proc.stdout)["parts"]
    assert rows[0]["mass"] == pytest.approx(7850 * 0.008, rel=1e-14)
    assert rows[0]["implied_density"] == pytest.approx(7850, rel=1e-14)
    assert rows[0]["volume"] == pytest.approx(0.008, rel=1e-14)
    assert rows[1]["implied_density_si"] == pytest.approx(rows[1]["mass"] / 0.008, rel=1e-14)


def test_scale_rotation_and_position_place_the_mesh(tmp_path):
    # a 20 × 40 × 100 mm box written in mm, with its own origin at one corner
    write_obj(tmp_path / "box_mm.obj", *box_mesh((20, 40, 100), (10, 20, 50)))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: b, shape: mesh, file: box_mm.obj, mass: 2.0, scale: 0.001,\n"
        "     position: [1, 2, 3], rotation: {axis: [0, 0, 1], angle_deg: 90}}\n"
    )
    out = inertia_json(spec)
    # turned +90° about z: the corner-origin box's centre (0.01, 0.02, 0.05) goes to (−0.02, 0.01, 0.05)
    np.testing.assert_allclose(out["center_of_mass"], [1 - 0.02, 2 + 0.01, 3 + 0.05], rtol=1e-14)
    own = box_moments(2.0, 0.02, 0.04, 0.1)  # along the box's x, y, z
    np.testing.assert_allclose(out["inertia"], np.diag([own[1], own[0], own[2]]), rtol=1e-12, atol=1e-18)


def test_a_mesh_hole_removes_its_volume(tmp_path):
    write_obj(tmp_path / "cube.obj", *box_mesh((0.1, 0.1, 0.1)))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: slab, shape: box, density: 1000, center: [0, 0, 0], size: [1, 1, 0.1]}\n"
        "  - {name: pocket, shape: mesh, file: cube.obj, density: 1000, subtract: true, position: [0.3, 0, 0]}\n"
    )
    out = inertia_json(spec)
    assert out["mass"] == pytest.approx(100 - 1, rel=1e-14)
    assert out["center_of_mass"][0] == pytest.approx(-0.3 * 1 / 99, rel=1e-12)


def test_sphere_mesh_in_a_spec_approaches_the_sphere(tmp_path):
    write_binary_stl(tmp_path / "ball.stl", *sphere_mesh(0.05, 64, 128))
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {name: ball, shape: mesh, file: ball.stl, mass: 1.0}\n")
    out = inertia_json(spec)
    np.testing.assert_allclose(np.diag(out["inertia"]), 0.4 * 0.05**2, rtol=2e-3)


# Figures SolidWorks reports for two parts (density, mass in lb, centre of mass in in, inertia
# about the centre of mass in lb·in², tensor sign), as published with trimesh's tests
# (tests/data/mass_properties.json in github.com/mikedh/trimesh). The STL files are
# tessellations of the CAD solids, so they differ from the exact solids by the chord error.
SOLIDWORKS = {
    "angle_block.STL": dict(
        density=0.036127,
        mass=0.041358,
        center_mass=[0, 0.436105, -0.599006],
        inertia=[[0.008312, 0, 0], [0, 0.012823, -0.000807], [0, -0.000807, 0.009005]],
    ),
    "idler_riser.STL": dict(
        density=0.09754366,
        mass=0.14522859,
        center_mass=[1.25, 1.21830489, 0.20084261],
        inertia=[[0.12108243, 0, 0], [0, 0.09131981, -0.00013893], [0, -0.00013893, 0.2057651]],
    ),
}


@pytest.mark.parametrize("file_name", sorted(SOLIDWORKS))
def test_cad_parts_match_solidworks(tmp_path, file_name):
    truth = SOLIDWORKS[file_name]
    (tmp_path / file_name).write_bytes((CAD / file_name).read_bytes())
    spec = tmp_path / "part.yaml"
    spec.write_text(
        f"units: {{length: in, mass: lb}}\nparts:\n"
        f"  - {{name: part, shape: mesh, file: {file_name}, density: {truth['density']!r}}}\n"
    )
    out = inertia_json(spec)
    assert out["mass"] == pytest.approx(truth["mass"], rel=1e-3)  # measured: 6e-4 and 7e-4
    np.testing.assert_allclose(
        out["center_of_mass"], truth["center_mass"], rtol=0, atol=2e-3
    )  # measured ≤ 1.1e-3 in
    inertia = np.array(out["inertia"])
    expected = np.array(truth["inertia"])
    np.testing.assert_allclose(np.diag(inertia), np.diag(expected), rtol=2.5e-3)  # measured ≤ 1.9e-3
    off = ~np.eye(3, dtype=bool)  # products: same sign and size (measured ≤ 2e-6 lb·in² apart)
    np.testing.assert_allclose(inertia[off], expected[off], rtol=0, atol=2e-5 * np.max(np.diag(expected)))


def test_bundled_bracket_through_every_mass_command(bodies):
    for command in ("inertia", "principal", "parts", "validate"):
        proc = run_rbi_inprocess(
            command, bodies / "bracket.yaml", *(["--format", "json"] if command != "validate" else [])
        )
        assert proc.returncode == 0, (command, proc.stderr)


def test_bracket_mesh_matches_its_boxes(bodies, tmp_path):
    """The bundled bracket STL is an L of two plates: the same body written as two boxes."""
    plates = (
        "parts:\n"
        "  - {shape: box, density: aluminium 6061, center: [0.03, 0.02, 0.0025], size: [0.06, 0.04, 0.005]}\n"
        "  - {shape: box, density: aluminium 6061, center: [0.0025, 0.02, 0.03], size: [0.005, 0.04, 0.05]}\n"
    )
    fittings = [
        line
        for line in (bodies / "bracket.yaml").read_text().splitlines()
        if line.startswith("  - {name: bolt")
    ]
    (tmp_path / "boxes.yaml").write_text(plates + "\n".join(fittings) + "\n")
    mesh = inertia_json(bodies / "bracket.yaml")
    boxes = inertia_json(tmp_path / "boxes.yaml")
    assert len(fittings) == 2
    # the STL holds float32 millimetres: exact for these whole-millimetre corners
    assert mesh["mass"] == pytest.approx(boxes["mass"], rel=1e-14)
    np.testing.assert_allclose(mesh["center_of_mass"], boxes["center_of_mass"], rtol=1e-13)
    np.testing.assert_allclose(
        mesh["inertia"], boxes["inertia"], rtol=0, atol=1e-13 * np.max(boxes["inertia"])
    )


def test_installed_rbi_reads_a_mesh(tmp_path):
    write_binary_stl(tmp_path / "cube.stl", *box_mesh((2, 2, 2)))
    spec = tmp_path / "body.yaml"
    spec.write_text("parts:\n  - {shape: mesh, file: cube.stl, mass: 6}\n")
    proc = run_rbi("inertia", spec, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    np.testing.assert_allclose(json.loads(proc.stdout)["inertia"], 4 * np.eye(3), rtol=1e-14)


# --- refusals -----------------------------------------------------------------------------------


def mesh_spec(tmp_path, file_name, extra=""):
    spec = tmp_path / "body.yaml"
    spec.write_text(f"parts:\n  - {{name: shell, shape: mesh, file: '{file_name}', mass: 1{extra}}}\n")
    return spec


def test_open_mesh_names_the_part_and_counts_boundary_edges(tmp_path):
    vertices, faces = box_mesh()
    write_binary_stl(tmp_path / "open.stl", vertices, faces[1:])
    proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, "open.stl"))
    one_line_exit_2(proc, "body.yaml", "parts[0] (shell)", "file: open.stl", "not closed: 3 boundary edges")


def test_flipped_faces_are_refused(tmp_path):
    vertices, faces = box_mesh()
    faces = faces.copy()
    faces[[3, 8]] = faces[[3, 8], ::-1]
    write_obj(tmp_path / "flipped.obj", vertices, faces)
    proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, "flipped.obj"))
    one_line_exit_2(proc, "parts[0] (shell)", "not consistently wound: 6 edges")


def test_inside_out_mesh_is_refused(tmp_path):
    vertices, faces = box_mesh((1, 2, 3))
    write_obj(tmp_path / "inverted.obj", vertices, faces[:, ::-1])
    proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, "inverted.obj"))
    one_line_exit_2(proc, "parts[0] (shell)", "inside out", "negative (-6)")


@pytest.mark.parametrize(
    "content, words",
    [
        (b"", "file is empty"),
        (b"   \n\n", "file is empty"),
        (b"solid nothing\nendsolid nothing\n", "holds no triangles"),
        (bytes(range(256)) * 8, "cannot be read as STL"),
    ],
)
def test_empty_and_unreadable_stl(tmp_path, content, words):
    (tmp_path / "bad.stl").write_bytes(content)
    one_line_exit_2(run_rbi_inprocess("inertia", mesh_spec(tmp_path, "bad.stl")), "parts[0] (shell)", words)


def test_a_ply_that_is_not_a_ply_is_refused(tmp_path):
    (tmp_path / "bad.ply").write_text("this is not a ply file\n")
    one_line_exit_2(run_rbi_inprocess("inertia", mesh_spec(tmp_path, "bad.ply")), "cannot be read as PLY")


def test_nan_vertex_and_bad_index(tmp_path):
    (tmp_path / "nan.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 1\nf 1 2 3\nf 1 2 4\n")
    one_line_exit_2(
        run_rbi_inprocess("inertia", mesh_spec(tmp_path, "nan.obj")), "vertex 3: coordinates must be finite"
    )
    (tmp_path / "index.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, "index.obj"))
    one_line_exit_2(proc, "parts[0] (shell)")


def test_messages_never_repeat_the_files_content(tmp_path):
    secret = "TOPSECRET-7f3a"
    (tmp_path / "leak.obj").write_text(f"# {secret}\nv 0 0 0\nv {secret} 0 0\nf 1 2 3\nmtllib {secret}.mtl\n")
    (tmp_path / "leak.stl").write_text(f"solid {secret}\nfacet normal {secret}\nendsolid\n")
    for name in ("leak.obj", "leak.stl"):
        proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, name))
        assert proc.returncode == 2 and secret not in proc.stderr + proc.stdout, proc.stderr


def test_an_obj_never_makes_rbi_open_its_material_file(tmp_path, monkeypatch):
    import builtins

    vertices, faces = box_mesh()
    write_obj(tmp_path / "box.obj", vertices, faces)
    (tmp_path / "box.obj").write_text("mtllib box.mtl\n" + (tmp_path / "box.obj").read_text())
    (tmp_path / "box.mtl").write_text("newmtl steel\nKd 0.5 0.5 0.5\n")
    opened = []
    real_open, real_os_open = builtins.open, os.open

    def recording_open(file, *args, **kwargs):
        opened.append(str(file))
        return real_open(file, *args, **kwargs)

    def recording_os_open(file, *args, **kwargs):  # rbi reads input files through os.open
        opened.append(str(file))
        return real_os_open(file, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", recording_open)
    monkeypatch.setattr(os, "open", recording_os_open)
    proc = run_rbi_inprocess("inertia", mesh_spec(tmp_path, "box.obj"), "--format", "json")
    monkeypatch.undo()
    assert proc.returncode == 0, proc.stderr
    assert any(name.endswith("box.obj") for name in opened)
    assert not any(name.endswith(".mtl") for name in opened), opened


def test_unknown_extension_and_missing_file(tmp_path):
    (tmp_path / "part.step").write_text("ISO-10303-21;\n")
    one_line_exit_2(
        run_rbi_inprocess("inertia", mesh_spec(tmp_path, "part.step")), "unknown mesh format '.step'"
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", mesh_spec(tmp_path, "nowhere.stl")), "file: nowhere.stl: no such file"
    )


def test_too_large_a_file_is_refused_before_reading(tmp_path, monkeypatch):
    from rbi.formats import mesh_file

    write_binary_stl(tmp_path / "cube.stl", *box_mesh())
    monkeypatch.setattr(mesh_file, "MAX_MESH_BYTES", 100)
    one_line_exit_2(
        run_rbi_inprocess("inertia", mesh_spec(tmp_path, "cube.stl")), "file too large for a mesh"
    )


def test_path_outside_the_spec_folder_needs_the_flag(tmp_path):
    outside = tmp_path / "shared"
    outside.mkdir()
    write_obj(outside / "cube.obj", *box_mesh((2, 2, 2)))
    specs = tmp_path / "specs"
    specs.mkdir()
    for file_name in ("../shared/cube.obj", str(outside / "cube.obj")):
        spec = mesh_spec(specs, file_name)
        one_line_exit_2(run_rbi_inprocess("inertia", spec), "parts[0] (shell)", "leaves the spec's folder")
        proc = run_rbi_inprocess("inertia", spec, "--format", "json", "--allow-outside-paths")
        assert proc.returncode == 0, proc.stderr
        np.testing.assert_allclose(json.loads(proc.stdout)["inertia"], 2 / 3 * np.eye(3), rtol=1e-14)


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symlinks here")
def test_a_symlink_out_of_the_folder_is_refused(tmp_path):
    outside = tmp_path / "elsewhere.obj"
    write_obj(outside, *box_mesh())
    specs = tmp_path / "specs"
    specs.mkdir()
    (specs / "link.obj").symlink_to(outside)
    one_line_exit_2(run_rbi_inprocess("inertia", mesh_spec(specs, "link.obj")), "leaves the spec's folder")


@pytest.mark.parametrize(
    "extra, words",
    [
        (", scale: 0", "scale: must be greater than 0"),
        (", scale: -1", "scale: must be greater than 0"),
        (", position: [0, 0]", "position"),
        (", density: 5", "give exactly one of `mass` or `density`"),
        (", file_name: x", "unknown field"),
    ],
)
def test_field_errors_name_the_field(tmp_path, extra, words):
    write_obj(tmp_path / "cube.obj", *box_mesh())
    one_line_exit_2(
        run_rbi_inprocess("inertia", mesh_spec(tmp_path, "cube.obj", extra)), "parts[0] (shell)", words
    )


def test_validate_reports_a_bad_mesh(tmp_path):
    vertices, faces = box_mesh()
    write_obj(tmp_path / "open.obj", vertices, faces[2:])
    proc = run_rbi_inprocess("validate", mesh_spec(tmp_path, "open.obj"))
    assert proc.returncode == 2 and "not closed: 4 boundary edges" in proc.stdout + proc.stderr


def test_mesh_in_the_json_schema():
    proc = run_rbi_inprocess("schema")
    assert proc.returncode == 0
    text = proc.stdout
    for word in ('"mesh"', '"torus"', '"hemisphere"', '"capsule"', '"pattern"', "major_radius", "scale"):
        assert word in text, word


def test_capsule_torus_hemisphere_through_the_cli(tmp_path):
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n"
        "  - {name: ring, shape: torus, mass: 2, center: [0, 0, 0], axis: [0, 0, 3], major_radius: 1, minor_radius: 0.2}\n"
    )
    out = inertia_json(spec)
    np.testing.assert_allclose(
        np.diag(out["inertia"]), [2 * (0.5 + 0.625 * 0.04)] * 2 + [2 * (1 + 0.75 * 0.04)], rtol=1e-14
    )
    spec.write_text(
        "parts:\n  - {name: dome, shape: hemisphere, density: 1000, center: [0, 0, 0], axis: [0, 0, -1], radius: 0.1}\n"
    )
    out = inertia_json(spec)
    assert out["mass"] == pytest.approx(1000 * 2 / 3 * math.pi * 0.001, rel=1e-14)
    assert out["center_of_mass"][2] == pytest.approx(-0.0375, rel=1e-14)
    spec.write_text(
        "parts:\n  - {name: pill, shape: capsule, mass: 1, start: [0, 0, 0], end: [0, 0, 0], radius: 0.1}\n"
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec), "parts[0] (pill)", "start, end: must be different points"
    )
    spec.write_text(
        "parts:\n  - {name: ring, shape: torus, mass: 1, center: [0, 0, 0], axis: [0, 0, 1], major_radius: 0.1, minor_radius: 0.2}\n"
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec), "parts[0] (ring)", "minor_radius: must not exceed major_radius"
    )
    spec.write_text(
        "parts:\n  - {name: dome, shape: hemisphere, mass: 1, center: [0, 0, 0], axis: [0, 0, 0], radius: 0.2}\n"
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec), "parts[0] (dome)", "axis: must not be the zero vector"
    )
