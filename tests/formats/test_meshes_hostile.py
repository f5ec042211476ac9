"""Meshes from a careless user or an attacker: files that say one thing and mean another,
numbers that overflow, pieces that overlap or turn inside out, headers that promise more than
the file holds, and random vertex/face data. Whatever comes in, rbi gives the right numbers or
exit 2 with one line saying what is wrong — never a wrong answer with exit 0, a traceback, or
unbounded time and memory."""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbi.core.mesh import MeshError
from tests.conftest import one_line_exit_2, run_rbi_inprocess
from tests.mesh_builders import box_mesh, mesh_mass_properties, write_binary_stl, write_obj

TETRA = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
TETRA_FACES = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"


def spec_for(tmp_path, file_name, extra=""):
    spec = tmp_path / "body.yaml"
    spec.write_text(f"parts:\n  - {{name: piece, shape: mesh, file: '{file_name}', mass: 6{extra}}}\n")
    return spec


def inertia(tmp_path, file_name, extra=""):
    return run_rbi_inprocess("inertia", spec_for(tmp_path, file_name, extra), "--format", "json")


def obj_text(vertices, faces, one_based=True):
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in np.asarray(vertices, float).tolist()]
    lines += ["f " + " ".join(str(i + one_based) for i in f) for f in np.asarray(faces).tolist()]
    return "\n".join(lines) + "\n"


# --- OBJ numbering ----------------------------------------------------------------------------


def test_obj_index_zero_is_refused_not_read_as_the_last_vertex(tmp_path):
    (tmp_path / "zero.obj").write_text(TETRA + "f 0 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    one_line_exit_2(
        inertia(tmp_path, "zero.obj"), "parts[0] (piece)", "line 5", "vertex 0", "OBJ numbers vertices from 1"
    )


def test_negative_obj_indices_count_back_from_the_last_vertex_read(tmp_path):
    # the same tetrahedron with every face written relative to the vertices read so far
    (tmp_path / "relative.obj").write_text(TETRA + "f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n")
    out = json.loads(inertia(tmp_path, "relative.obj").stdout)
    np.testing.assert_allclose(out["center_of_mass"], [0.25, 0.25, 0.25], rtol=1e-15)


def test_negative_obj_indices_ignore_vertices_that_come_later(tmp_path):
    # faces of the tetrahedron on 1-4 written with negative numbers before four decoy vertices
    # (trimesh counted back from the end of the file, taking the decoys)
    decoys = "v 5 5 5\nv 6 5 5\nv 5 6 5\nv 5 5 6\n"
    (tmp_path / "later.obj").write_text(TETRA + "f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n" + decoys)
    out = json.loads(inertia(tmp_path, "later.obj").stdout)
    np.testing.assert_allclose(out["center_of_mass"], [0.25, 0.25, 0.25], rtol=1e-15)


def test_negative_obj_index_before_the_first_vertex_is_refused(tmp_path):
    (tmp_path / "back.obj").write_text("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n")
    one_line_exit_2(inertia(tmp_path, "back.obj"), "line 3", "counts back 3 vertices", "only 2 were read")


def test_obj_index_beyond_the_last_vertex_names_the_line_and_count(tmp_path):
    (tmp_path / "far.obj").write_text(TETRA + "f 1 3 2\nf 1 2 9\n")
    one_line_exit_2(inertia(tmp_path, "far.obj"), "face on line 6 names vertex 9", "the file has 4 vertices")


@pytest.mark.parametrize(
    "line, words",
    [
        ("v 1 2\n", "line 5: a vertex needs three coordinates"),
        ("v 1 two 3\n", "line 5: a vertex coordinate is not a number"),
        ("f \n", "line 5: a face names no vertex"),
        ("f 1 2 x\n", "line 5: a face's vertex number is not a whole number"),
    ],
)
def test_malformed_obj_lines_name_the_line_never_the_content(tmp_path, line, words):
    (tmp_path / "bad.obj").write_text(TETRA + line + TETRA_FACES)
    proc = inertia(tmp_path, "bad.obj")
    one_line_exit_2(proc, words)
    assert "two" not in proc.stderr.split("line 5")[1]


def test_obj_polygons_and_slashed_corners_are_read_as_the_format_says(tmp_path):
    vertices, _ = box_mesh((2, 2, 2))
    # a cube as six quads, corners with texture and normal numbers
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    text = "\n".join(f"v {x} {y} {z}" for x, y, z in vertices.tolist()) + "\nvt 0 0\nvn 0 0 1\n"
    text += "\n".join("f " + " ".join(f"{i + 1}/1/1" for i in q) for q in quads) + "\n"
    (tmp_path / "quads.obj").write_text(text)
    out = json.loads(inertia(tmp_path, "quads.obj").stdout)
    np.testing.assert_allclose(out["inertia"], 6 / 6 * 4 * np.eye(3), rtol=1e-14)


# --- pieces -----------------------------------------------------------------------------------


def test_two_cubes_on_one_edge_in_one_obj_are_twice_the_cube(tmp_path):
    a, fa = box_mesh(center=(0.5, 0.5, 0.5))
    b, fb = box_mesh(center=(1.5, 1.5, 0.5))
    (tmp_path / "pair.obj").write_text(obj_text(np.vstack([a, b]), np.vstack([fa, fb + 8])))
    proc = inertia(tmp_path, "pair.obj")
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["mass"] == 6
    np.testing.assert_allclose(out["center_of_mass"], [1, 1, 0.5], rtol=1e-15)
    # each cube: mass 3, (3/6) about its own centre, plus 3 · distance² to the common centre
    expected = 3 / 6 * 2 * np.eye(3) + 3 * np.array([[0.5, -0.5, 0], [-0.5, 0.5, 0], [0, 0, 1.0]])
    np.testing.assert_allclose(out["inertia"], expected, rtol=1e-14, atol=1e-15)


def test_a_cube_with_every_face_written_twice_is_flagged_as_overlapping():
    vertices, faces = box_mesh()
    props = mesh_mass_properties(vertices, np.vstack([faces, faces]), "exact", density=1.0)
    assert props.volume == pytest.approx(2.0) and "overlap" in props.notes[0]


def test_a_small_inside_out_cube_beside_a_big_one_is_refused_not_subtracted(tmp_path):
    big, big_faces = box_mesh((2, 2, 2))
    small, small_faces = box_mesh(center=(5, 0, 0))
    write_obj(
        tmp_path / "mixed.obj", np.vstack([big, small]), np.vstack([big_faces, small_faces[:, ::-1] + 8])
    )
    one_line_exit_2(inertia(tmp_path, "mixed.obj"), "inside out", "no cavity")


def test_a_cavity_is_still_a_cavity(tmp_path):
    outer, outer_faces = box_mesh((4, 4, 4))
    inner, inner_faces = box_mesh((2, 2, 2))
    write_obj(
        tmp_path / "hollow.obj", np.vstack([outer, inner]), np.vstack([outer_faces, inner_faces[:, ::-1] + 8])
    )
    out = json.loads(inertia(tmp_path, "hollow.obj", extra=", inertia: exact").stdout)
    # density 6/56: outer box 64 minus inner box 8
    rho = 6 / 56
    expected = rho * (64 * 32 / 12 - 8 * 8 / 12)
    np.testing.assert_allclose(np.diag(out["inertia"]), expected, rtol=1e-14)


# --- numbers and headers ----------------------------------------------------------------------


def test_coordinates_whose_fifth_power_overflows_are_refused(tmp_path):
    vertices, faces = box_mesh((1e200, 1e200, 1e200))
    write_obj(tmp_path / "huge.obj", vertices, faces)
    one_line_exit_2(inertia(tmp_path, "huge.obj"), "vertex 0", "beyond ±1e+50", "smaller unit")


def test_a_binary_stl_whose_header_lies_about_its_size(tmp_path):
    write_binary_stl(tmp_path / "cube.stl", *box_mesh())
    data = bytearray((tmp_path / "cube.stl").read_bytes())
    data[:5] = b"BINAR"
    data[80:84] = struct.pack("<I", 4_000_000_000)
    (tmp_path / "liar.stl").write_bytes(bytes(data))
    one_line_exit_2(inertia(tmp_path, "liar.stl"), "promises 4000000000 triangles", f"has {len(data)}")


def test_a_binary_stl_beyond_the_triangle_cap_is_refused_before_it_is_read(tmp_path, monkeypatch):
    from rbi.formats import mesh_file

    write_binary_stl(tmp_path / "cube.stl", *box_mesh())
    monkeypatch.setattr(mesh_file, "MAX_MESH_TRIANGLES", 11)
    one_line_exit_2(inertia(tmp_path, "cube.stl"), "mesh has 12 triangles; rbi reads at most 11", "decimate")


PEAK_PROBE = """
import sys
from pathlib import Path
from rbi.formats.mesh_file import read_mesh_solid
try:
    read_mesh_solid(Path(sys.argv[1]))
    print("read")
except ValueError as exc:
    print(exc)
# VmHWM: this process's own peak (ru_maxrss would include the parent's size at the fork)
print(next(line.split()[1] for line in open("/proc/self/status") if line.startswith("VmHWM:")))
"""


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="peak memory read from /proc")
def test_a_252_mib_binary_stl_is_refused_from_its_header_in_little_memory(tmp_path):
    # the file of issue 18 (5,274,750 triangles under the 256 MiB size cap peaked at 4.6 GB):
    # a sparse file with that header, refused before any triangle is read
    import subprocess
    import sys

    count = 5_274_750
    path = tmp_path / "big.stl"
    with open(path, "wb") as out:
        out.write(b"binary".ljust(80, b" ") + struct.pack("<I", count))
        out.truncate(84 + 50 * count)
    proc = subprocess.run(
        [sys.executable, "-c", PEAK_PROBE, str(path)], capture_output=True, text=True, timeout=120
    )
    message, peak_kib = proc.stdout.strip().splitlines()
    assert message.startswith("mesh has 5274750 triangles; rbi reads at most 2000000")
    assert int(peak_kib) < 200 * 1024, peak_kib  # kilobytes on Linux: under 200 MB


@pytest.mark.parametrize(
    "name, text",
    [
        ("many.obj", TETRA + TETRA_FACES),
        ("many.stl", None),
    ],
)
def test_text_meshes_beyond_the_triangle_cap_are_refused(tmp_path, monkeypatch, name, text):
    from rbi.formats import mesh_file
    from tests.mesh_builders import write_ascii_stl

    if text is None:
        write_ascii_stl(tmp_path / name, *box_mesh())
    else:
        (tmp_path / name).write_text(text)
    monkeypatch.setattr(mesh_file, "MAX_MESH_TRIANGLES", 3)
    one_line_exit_2(inertia(tmp_path, name), "triangles; rbi reads at most 3")


def test_a_ply_header_promising_a_trillion_vertices_is_refused_before_allocating(tmp_path):
    header = (
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
        "property float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\n"
        "end_header\n"
    )
    (tmp_path / "liar.ply").write_bytes(header.encode() + bytes(64))
    one_line_exit_2(inertia(tmp_path, "liar.ply"), "header promises 1000000000000 vertices")


def test_a_ply_beyond_its_byte_cap_is_refused_before_trimesh_parses_it(tmp_path, monkeypatch):
    from rbi.formats import mesh_file
    from tests.mesh_builders import write_ply

    write_ply(tmp_path / "cube.ply", *box_mesh())
    monkeypatch.setattr(mesh_file, "MAX_PLY_BYTES", 100)
    one_line_exit_2(inertia(tmp_path, "cube.ply"), "PLY file too large", "convert it to binary STL")


def test_an_ascii_stl_facet_with_four_vertices_is_refused(tmp_path):
    facet = (
        "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
        "endloop\nendfacet\n"
    )
    (tmp_path / "quad.stl").write_text("solid q\n" + facet + "endsolid q\n")
    one_line_exit_2(inertia(tmp_path, "quad.stl"), "a facet does not have three vertices")


def test_vertices_crowding_within_the_weld_tolerance_are_refused_quickly():
    rng = np.random.default_rng(1)
    vertices, faces = box_mesh()
    crowd = rng.uniform(0, 1e-12, size=(200, 3))  # 200 distinct points within 1e-12 of a corner
    vertices = np.vstack([vertices, crowd - 0.5])
    faces = np.vstack([faces, np.arange(8, 8 + 198).reshape(-1, 3)])
    from rbi.core.mesh import weld_vertices

    with pytest.raises(MeshError, match="distinct vertices lie within"):
        weld_vertices(vertices, faces)


# --- modes through the spec -------------------------------------------------------------------


def test_exact_refusal_names_the_other_modes(tmp_path):
    vertices, faces = box_mesh()
    write_obj(tmp_path / "open.obj", vertices, faces[1:])
    one_line_exit_2(
        inertia(tmp_path, "open.obj"),
        "not closed: 3 boundary edges",
        "inertia: convex",
        "inertia: shell",
        "repair: true",
    )


def test_repair_in_a_spec_gives_the_cube(tmp_path):
    vertices, faces = box_mesh((2, 2, 2))
    write_obj(tmp_path / "open.obj", vertices, faces[1:])
    out = json.loads(inertia(tmp_path, "open.obj", extra=", repair: true").stdout)
    np.testing.assert_allclose(out["inertia"], 6 / 12 * 8 * np.eye(3), rtol=1e-14, atol=1e-15)


def test_rbi_parts_reports_the_area_repair_added_and_overlapping_pieces(tmp_path):
    vertices, faces = box_mesh((2, 2, 2))
    write_obj(tmp_path / "open.obj", vertices, faces[1:])
    write_obj(tmp_path / "twice.obj", vertices, np.vstack([faces, faces]))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: mended, shape: mesh, file: open.obj, mass: 1, repair: true, scale: 0.5}\n"
        "  - {name: doubled, shape: mesh, file: twice.obj, mass: 1}\n"
    )
    proc = run_rbi_inprocess("parts", spec)
    assert proc.returncode == 0, proc.stderr
    # one triangle of a face of side 2 · 0.5: half of 1 m², 1/12 of the surface
    assert (
        "parts[0] (mended): file: open.obj: repair added 1 triangle closing holes, 0.5 m² (8.33% of the surface)"
        in proc.stderr
    )
    assert "parts[1] (doubled): file: twice.obj: pieces of the mesh overlap" in proc.stderr


def test_shell_and_convex_in_a_spec(tmp_path):
    vertices, faces = box_mesh((2, 2, 2))
    write_obj(tmp_path / "cube.obj", vertices, faces[1:])  # open: fine for both
    shell = json.loads(inertia(tmp_path, "cube.obj", extra=", inertia: shell").stdout)
    # the open cube's surface: five full faces and half of one, centre of mass moved off centre
    assert shell["mass"] == 6
    hull = json.loads(inertia(tmp_path, "cube.obj", extra=", inertia: convex").stdout)
    np.testing.assert_allclose(hull["inertia"], 6 / 12 * 8 * np.eye(3), rtol=1e-14, atol=1e-15)


def test_shell_with_a_density_is_refused(tmp_path):
    write_obj(tmp_path / "cube.obj", *box_mesh())
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: piece, shape: mesh, file: cube.obj, density: steel, inertia: shell}\n"
    )
    one_line_exit_2(run_rbi_inprocess("inertia", spec), "density", "give mass instead")


@pytest.mark.parametrize(
    "extra, words",
    [
        (", inertia: legacy", "inertia"),
        (", repair: maybe", "repair"),
    ],
)
def test_bad_mode_fields_are_refused(tmp_path, extra, words):
    write_obj(tmp_path / "cube.obj", *box_mesh())
    one_line_exit_2(inertia(tmp_path, "cube.obj", extra=extra), "parts[0] (piece)", words)


def test_convex_of_a_flat_mesh_is_refused(tmp_path):
    (tmp_path / "flat.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n")
    one_line_exit_2(inertia(tmp_path, "flat.obj", extra=", inertia: convex"), "convex hull is flat")


# --- random vertex and face data --------------------------------------------------------------

coordinate = st.one_of(
    st.floats(-10, 10),
    st.sampled_from([0.0, -0.0, 1e-300, 1e49, 1e60, 1e308, float("nan"), float("inf"), -float("inf")]),
)


@st.composite
def mesh_arrays(draw):
    n = draw(st.integers(1, 10))
    vertices = np.array(draw(st.lists(st.tuples(coordinate, coordinate, coordinate), min_size=n, max_size=n)))
    faces = draw(st.lists(st.tuples(*[st.integers(-2, n + 1)] * 3), min_size=0, max_size=14))
    if draw(st.booleans()):  # sometimes a real closed mesh, damaged a little
        vertices, faces = box_mesh()
        faces = faces.tolist()
        faces += draw(st.lists(st.sampled_from(faces), max_size=3))  # duplicated faces
        if draw(st.booleans()):
            faces.pop(draw(st.integers(0, len(faces) - 1)))
        vertices = vertices * draw(st.sampled_from([1.0, 1e-200, 1e40, 1e60]))
    return np.asarray(vertices, float).reshape(-1, 3), np.asarray(faces, dtype=np.int64).reshape(-1, 3)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mesh_arrays(), st.sampled_from(["exact", "convex", "shell"]))
def test_any_arrays_give_physical_numbers_or_a_mesh_error(arrays, mode):
    vertices, faces = arrays
    try:
        props = mesh_mass_properties(vertices, faces, mode, mass=2.0)
    except MeshError as exc:
        assert str(exc) and "\n" not in str(exc)
        return
    assert props.properties.mass == 2.0
    assert np.all(np.isfinite(props.properties.center_of_mass)) and np.all(
        np.isfinite(props.properties.inertia_about_com)
    )
    moments = np.linalg.eigvalsh(props.properties.inertia_about_com)
    assert moments.min() >= -1e-12 * moments.max()
    # triangle inequality of principal moments, with rounding room
    assert moments[0] + moments[1] >= moments[2] * (1 - 1e-9)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(mesh_arrays(), st.booleans())
def test_any_obj_through_the_cli_is_exit_0_or_one_line_exit_2(tmp_path, arrays, zero_based):
    vertices, faces = arrays
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices.tolist()]
    lines += ["f " + " ".join(str(i + (0 if zero_based else 1)) for i in f) for f in faces.tolist()]
    (tmp_path / "random.obj").write_text("\n".join(lines) + "\n")
    proc = inertia(tmp_path, "random.obj")
    if proc.returncode == 0:
        out = json.loads(proc.stdout)
        assert np.all(np.isfinite(out["inertia"]))
    else:
        one_line_exit_2(proc, "parts[0] (piece)")
