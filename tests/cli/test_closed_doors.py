"""Issue 26's doors: each bad input is one line, exit 2, no traceback, naming the option or
the file."""

from __future__ import annotations

import pytest

from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

TOP = BODIES / "top.yaml"
ARM = BODIES / "two_link_arm.urdf"


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_about_a_point_so_far_the_inertia_overflows_names_the_file(fmt):
    one_line_exit_2(rbi("inertia", TOP, "--about", "1e200,0,0", "-f", fmt), str(TOP), "--about", "overflows")


def test_several_files_name_the_one_that_overflowed():
    proc = rbi("inertia", TOP, BODIES / "cubesat.yaml", "--about", "1e200,0,0", "-f", "json")
    assert proc.returncode == 2 and f"rbi: {TOP}: --about: the point is too far from the body" in proc.stderr


@pytest.mark.parametrize(
    "args, words",
    [
        (["simulate", TOP, "--spin", "100", "--tilt", "1e300", "--duration", "0.01"], ["--tilt", "1e+300"]),
        (["simulate", TOP, "--spin", "100", "--tilt", "-2e9", "--duration", "0.01"], ["--tilt"]),
        (["inertia", TOP, "--rotate", "y:1e300"], ["--rotate", "1e300", "too large to be a turn"]),
    ],
)
def test_a_turn_lost_to_rounding_is_refused(args, words):
    one_line_exit_2(rbi(*args), *words)


def test_a_turn_of_many_whole_turns_is_still_a_turn():
    plain, turned = rbi("inertia", TOP, "-f", "json"), rbi("inertia", TOP, "--rotate", "y:3600", "-f", "json")
    assert plain.returncode == turned.returncode == 0, turned.stderr


def test_a_joint_given_twice_is_refused():
    proc = rbi("audit", ARM, "--joints", "shoulder=0.1", "--joints", "shoulder=0.2")
    one_line_exit_2(proc, "--joints", "'shoulder'", "twice")


def test_the_material_option_asks_for_a_name_not_a_number():
    proc = rbi("audit", ARM, "--material", "stel")
    one_line_exit_2(proc, "--material", "did you mean 'steel'", "give one of: steel", "--density")
    assert "give a number" not in proc.stderr


def test_a_spec_density_still_takes_a_number_or_a_name(write_spec):
    text = "parts:\n  - {shape: sphere, radius: 1, density: stel, center: [0, 0, 0]}\n"
    one_line_exit_2(rbi("inertia", write_spec(text)), "density", "give a number")


@pytest.mark.parametrize("command", ["inertia", "principal"])
def test_a_centre_of_mass_of_rounding_noise_prints_0(command):
    """wheel_with_holes' centre of mass is 1.75e-17, 3.14e-17 mm from its axis by rounding
    (the body is 170 mm across): the table prints [0, 0, 0]; JSON keeps every digit."""
    table = rbi(command, BODIES / "wheel_with_holes.yaml")
    assert table.returncode == 0 and "centre of mass   mm     [0, 0, 0]" in table.stdout, table.stdout
    assert "e-17" not in table.stdout


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_a_lone_surrogate_in_a_json_spec_is_refused_naming_the_field(tmp_path, fmt):
    path = tmp_path / "s.json"
    path.write_text(
        '{"name": "a", "parts": [{"name": "p\\udc00", "shape": "point", "mass": 1, "position": [0, 0, 0]}]}'
    )
    proc = rbi("inertia", path, "-f", fmt)
    one_line_exit_2(proc, str(path), "parts[0].name", "lone surrogate \\udc00")
    assert proc.stdout == ""


def test_a_surrogate_pair_is_one_character(tmp_path):
    path = tmp_path / "s.json"
    path.write_text(
        '{"name": "a\\ud83d\\ude00", "parts": [{"shape": "point", "mass": 1, "position": [0, 0, 0]}]}'
    )
    proc = rbi("inertia", path, "-f", "json")
    assert proc.returncode == 0 and '"name": "a\\ud83d\\ude00"' in proc.stdout.replace("😀", "\\ud83d\\ude00")


@pytest.mark.parametrize(
    "address, words",
    [
        ("tcp://garbage", ["is not a scheduler address", "tcp://HOST:PORT"]),
        ("tcp://", ["is not a scheduler address"]),
        ("tcp://host:99999", ["is not a scheduler address"]),
        ("udp://host:8786", ["is not a scheduler address"]),
        ("tls://127.0.0.1:1", ["TLS scheduler needs this client's certificate", "client.cert"]),
    ],
)
def test_a_dask_address_that_cannot_work_is_refused_before_connecting(address, words, monkeypatch):
    """Each took 22-28 s (Dask's connect and close timeouts) and printed a traceback."""
    for key in ("DASK_DISTRIBUTED__COMM__TLS__CLIENT__CERT", "DASK_DISTRIBUTED__COMM__TLS__CA_FILE"):
        monkeypatch.delenv(key, raising=False)
    proc = rbi("sweep", TOP, "--spin", "100:200:2", "--duration", "0.01", "--dask", address)
    one_line_exit_2(proc, "--dask", *words)


def test_a_robot_file_holding_one_huge_token_is_refused(tmp_path):
    """A 60 MiB name took over a minute in expat (time grows with the square of a token's
    length); a block of 1 MiB without a delimiter is refused before parsing."""
    path = tmp_path / "r.urdf"
    path.write_bytes(b'<robot name="r"><link name="' + b"a" * (4 * 2**20) + b'"/></robot>')
    one_line_exit_2(rbi("audit", path), str(path), "1 MiB without a space, tag or quote")
    ordinary = tmp_path / "ok.urdf"
    ordinary.write_bytes(b'<robot name="r"><link name="' + b"a" * (2**19) + b'"/></robot>')
    assert rbi("audit", ordinary, "-f", "json").returncode == 0


@pytest.mark.parametrize("command", ["spec", "audit"])
def test_an_obj_face_naming_vertex_2_to_the_64_is_blamed_on_the_mesh(tmp_path, command):
    obj = tmp_path / "big.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 18446744073709551616\n")
    if command == "spec":
        path = tmp_path / "m.yaml"
        path.write_text("parts:\n  - {name: m, shape: mesh, file: big.obj, density: 1000}\n")
        proc = rbi("inertia", path)
    else:
        path = tmp_path / "m.urdf"
        path.write_text(
            '<robot name="r"><link name="l"><visual><geometry><mesh filename="big.obj"/></geometry>'
            "</visual></link></robot>"
        )
        proc = rbi("audit", path)
    one_line_exit_2(proc, "big.obj", "line 6", "names vertex 18446744073709551616")


@pytest.mark.parametrize("columns", ["60", "80", "84", "120"])
def test_the_sweep_table_never_breaks_a_path_in_its_header(columns, monkeypatch):
    """At 80 columns the header read 'parts.stem' over '.radius'; a table that cannot show a
    header's words whole is printed stacked, one value a line."""
    monkeypatch.setenv("COLUMNS", columns)
    args = ["--vary", "parts.stem.radius=0.007:0.009:2", "--spin", "100", "--duration", "0.05"]
    proc = rbi("sweep", BODIES / "top_bolted.yaml", *args)
    assert proc.returncode == 0, proc.stderr
    assert "parts.stem.radius" in proc.stdout, proc.stdout
    assert not any(line.strip().startswith(".radius") for line in proc.stdout.splitlines()), proc.stdout


@pytest.mark.parametrize("command", ["inertia", "parts", "principal"])
def test_mesh_notes_are_warnings_in_every_output_form(tmp_path, command):
    """The area repair added and overlapping pieces were said by rbi parts' table only, and
    missing from JSON 'warnings'."""
    import json

    import numpy as np

    from tests.mesh_builders import box_mesh, write_obj

    vertices, faces = box_mesh((2, 2, 2))
    write_obj(tmp_path / "open.obj", vertices, faces[1:])
    write_obj(tmp_path / "twice.obj", vertices, np.vstack([faces, faces]))
    spec = tmp_path / "body.yaml"
    spec.write_text(
        "parts:\n  - {name: mended, shape: mesh, file: open.obj, mass: 1, repair: true, scale: 0.5}\n"
        "  - {name: doubled, shape: mesh, file: twice.obj, mass: 1}\n"
    )
    repaired = f"{spec}: parts[0] (mended): file: open.obj: repair added 1 triangle closing holes, 0.5 m²"
    overlap = f"{spec}: parts[1] (doubled): file: twice.obj: pieces of the mesh overlap"
    data = json.loads(rbi(command, spec, "-f", "json").stdout)
    assert any(w.startswith(repaired) for w in data["warnings"]) and any(
        w.startswith(overlap) for w in data["warnings"]
    ), data["warnings"]
    table = rbi(command, spec)
    assert table.returncode == 0 and table.stderr.count("repair added") == 1, table.stderr
    assert f"rbi: warning: {overlap}" in table.stderr
