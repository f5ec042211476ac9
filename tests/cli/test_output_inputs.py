"""rbi never overwrites its input: not the spec, and not a file the spec reads (a point cloud, a
mesh). An output naming one, by its own name, a symbolic link or a hard link, is exit 2 with one
line naming the option and the path, checked right after the spec is loaded, before the run."""

from __future__ import annotations

import os

import pytest

from tests.conftest import run_rbi_inprocess as rbi
from tests.mesh_builders import box_mesh, write_binary_stl

CLOUD = "mass,x,y,z\n1,0,0,0.1\n1,0.1,0,0.1\n1,0,0.1,0.1\n1,-0.1,0,0.1\n1,0,-0.1,0.1\n"
RUN = ("--spin", "5", "--duration", "0.1")


def write_cloud_spec(folder):
    """``(spec, cloud)``: a top whose mass is the five points of the cloud file beside it."""
    (folder / "cloud.csv").write_text(CLOUD)
    spec = folder / "pc.yaml"
    spec.write_text("units: {length: m, mass: kg}\npivot: [0, 0, 0]\npoint_cloud: {file: cloud.csv}\n")
    return spec, folder / "cloud.csv"


@pytest.fixture
def cloud_spec(tmp_path):
    return write_cloud_spec(tmp_path)


@pytest.fixture
def mesh_spec(tmp_path):
    mesh = write_binary_stl(tmp_path / "block.stl", *box_mesh((0.1, 0.2, 0.3)))
    spec = tmp_path / "block.yaml"
    spec.write_text("parts:\n  - {name: block, shape: mesh, file: block.stl, mass: 1}\n")
    return spec, mesh


def named(read, out, how: str):
    """``out``, made to name the file ``read``: its own path (``same``), a symbolic link or a
    hard link to it."""
    if how == "same":
        return read
    (os.symlink if how == "symlink" else os.link)(read, out)
    return out


def assert_refused(proc, option: str, out, read, before: bytes) -> None:
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert proc.stdout == ""
    lines = proc.stderr.splitlines()
    assert len(lines) == 1, proc.stderr
    assert lines[0].startswith(f"rbi: {option}: {out}: is an input of this run"), lines[0]
    assert str(read) in lines[0] and "never overwrites its input" in lines[0]
    assert read.read_bytes() == before


@pytest.mark.parametrize("how", ["same", "symlink", "hardlink"])
def test_simulate_out_never_replaces_the_point_cloud(cloud_spec, tmp_path, how):
    spec, cloud = cloud_spec
    out = named(cloud, tmp_path / "run.csv", how)
    proc = rbi("simulate", spec, *RUN, "--out", out)
    assert_refused(proc, "--out", out, cloud, CLOUD.encode())
    assert rbi("inertia", spec).returncode == 0  # the spec still reads its cloud


def test_the_refusal_comes_before_the_run(cloud_spec):
    """A run far past the step budget would be refused for that; the output is refused first."""
    spec, cloud = cloud_spec
    proc = rbi("simulate", spec, "--spin", "5", "--duration", "1e9", "--out", cloud)
    assert_refused(proc, "--out", cloud, cloud, CLOUD.encode())


def test_simulate_plot_never_replaces_the_point_cloud(cloud_spec, tmp_path):
    pytest.importorskip("matplotlib")
    spec, cloud = cloud_spec
    out = named(cloud, tmp_path / "run.png", "symlink")
    proc = rbi("simulate", spec, *RUN, "--plot", out)
    assert_refused(proc, "--plot", out, cloud, CLOUD.encode())


@pytest.mark.parametrize(("option", "name"), [("--out", "run.csv"), ("--plot", "run.png")])
def test_simulate_never_replaces_the_mesh(mesh_spec, tmp_path, option, name):
    if option == "--plot":
        pytest.importorskip("matplotlib")
    spec, mesh = mesh_spec
    before = mesh.read_bytes()
    out = named(mesh, tmp_path / name, "symlink")
    proc = rbi("simulate", spec, *RUN, option, out)
    assert_refused(proc, option, out, mesh, before)


def test_show_and_animate_never_replace_the_point_cloud(cloud_spec, tmp_path):
    spec, cloud = cloud_spec
    page = named(cloud, tmp_path / "body.html", "symlink")
    assert_refused(rbi("show", spec, "--out", page), "--out", page, cloud, CLOUD.encode())
    assert_refused(rbi("animate", spec, *RUN, "--out", page), "--out", page, cloud, CLOUD.encode())


def test_other_outputs_beside_the_inputs_are_written(cloud_spec, tmp_path):
    spec, cloud = cloud_spec
    proc = rbi("simulate", spec, *RUN, "--out", tmp_path / "run.csv")
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "run.csv").read_text().startswith("t,qw,qx,qy,qz,wx,wy,wz")
    streamed = rbi("simulate", spec, *RUN, "--out", "-")
    assert streamed.returncode == 0 and streamed.stdout.startswith("t,qw")
    assert rbi("show", spec, "--out", tmp_path / "body.html").returncode == 0
    assert cloud.read_text() == CLOUD


@pytest.fixture
def no_runs(monkeypatch):
    """A sweep that starts a run fails the test: the refusal must come before any."""

    def run(*args, **kwargs):
        raise AssertionError("a run started")

    monkeypatch.setattr("rbi.sweeps.execute.run_local", run)
    monkeypatch.setattr("rbi.sweeps.execute.run_dask", run)


@pytest.mark.parametrize("how", ["same", "symlink", "hardlink"])
def test_sweep_out_never_replaces_the_point_cloud(cloud_spec, tmp_path, no_runs, how):
    spec, cloud = cloud_spec
    out = named(cloud, tmp_path / "rows.csv", how)
    proc = rbi("sweep", spec, *RUN, "--out", out)
    assert_refused(proc, "--out", out, cloud, CLOUD.encode())
    assert not list(tmp_path.glob(".*rbi-lock"))  # nothing opened there


@pytest.mark.parametrize("how", ["same", "symlink"])
def test_sweep_plot_never_replaces_the_point_cloud(tmp_path, no_runs, how):
    """By its own name (a cloud whose name ends .png: the map's extension) or a link to it."""
    pytest.importorskip("matplotlib")
    cloud = tmp_path / "cloud.png"
    cloud.write_text(CLOUD)
    spec = tmp_path / "pc.yaml"
    spec.write_text("units: {length: m, mass: kg}\npivot: [0, 0, 0]\npoint_cloud: {file: cloud.png}\n")
    out = named(cloud, tmp_path / "map.png", how)
    proc = rbi("sweep", spec, "--spin", "1:5:3", "--duration", "0.1", "--plot", out)
    assert_refused(proc, "--plot", out, cloud, CLOUD.encode())


def test_sweep_never_replaces_the_mesh(mesh_spec, tmp_path, no_runs):
    spec, mesh = mesh_spec
    before = mesh.read_bytes()
    out = named(mesh, tmp_path / "rows.csv", "symlink")
    assert_refused(rbi("sweep", spec, *RUN, "--out", out), "--out", out, mesh, before)


def test_sweep_outputs_beside_the_inputs_are_written(cloud_spec, tmp_path):
    pytest.importorskip("matplotlib")
    spec, cloud = cloud_spec
    outputs = ("--out", tmp_path / "rows.csv", "--plot", tmp_path / "map.png")
    proc = rbi("sweep", spec, "--spin", "1:5:3", "--duration", "0.1", *outputs)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "rows.csv").read_text().count("\n") == 4
    assert (tmp_path / "map.png").read_bytes().startswith(b"\x89PNG")
    assert cloud.read_text() == CLOUD
