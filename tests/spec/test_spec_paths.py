"""Files a spec names are read from the spec's folder only: an absolute path, a ``..`` that
climbs out or a symlink pointing out is refused unless ``--allow-outside-paths`` is given
(before or after the command), and no error ever prints what such a file holds."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess

SECRET = "SECRET-MARKER-5b1e"
LEAVES = "leaves the spec's folder"


@pytest.fixture
def layout(tmp_path):
    """``tmp_path/spec/`` (where specs go) and ``tmp_path/outside/`` holding a good cloud
    (masses 1 and 3 on the z axis) and files whose content is a secret."""
    spec_dir, outside = tmp_path / "spec", tmp_path / "outside"
    spec_dir.mkdir()
    outside.mkdir()
    (outside / "good.csv").write_text("mass,x,y,z\n1,0,0,1\n3,0,0,-1\n")
    (outside / "secret.csv").write_text(f"{SECRET},b,c\n1,2,3\n")
    (outside / "secret_cell.csv").write_text(f"mass,x,y,z\n1,0,{SECRET},0\n")
    (outside / "secret.npy").write_bytes(b"\x93NUMPY\x01\x00" + f"{SECRET}{SECRET}".encode())
    return spec_dir, outside


def write(spec_dir, file: str, name: str = "body.yaml"):
    spec = spec_dir / name
    spec.write_text(f"point_cloud: {{file: '{file}'}}\n")
    return spec


def test_an_absolute_path_is_refused(layout):
    spec_dir, outside = layout
    proc = run_rbi_inprocess("inertia", write(spec_dir, str(outside / "good.csv")))
    one_line_exit_2(proc, "point_cloud: file:", LEAVES, "--allow-outside-paths")


def test_dot_dot_out_of_the_folder_is_refused(layout):
    spec_dir, _ = layout
    one_line_exit_2(run_rbi_inprocess("inertia", write(spec_dir, "../outside/good.csv")), LEAVES)


def test_a_symlink_pointing_out_is_refused(layout):
    spec_dir, outside = layout
    (spec_dir / "link.csv").symlink_to(outside / "good.csv")
    one_line_exit_2(run_rbi_inprocess("inertia", write(spec_dir, "link.csv")), LEAVES)


def test_paths_that_stay_inside_are_read(layout):
    spec_dir, outside = layout
    (spec_dir / "data").mkdir()
    (spec_dir / "data" / "pts.csv").write_text((outside / "good.csv").read_text())
    (spec_dir / "inside_link.csv").symlink_to(spec_dir / "data" / "pts.csv")
    for file in ("data/pts.csv", "data/../data/pts.csv", "inside_link.csv"):
        proc = run_rbi_inprocess("inertia", write(spec_dir, file), "--format", "json")
        assert proc.returncode == 0, proc.stderr
        assert '"mass": 4.0' in proc.stdout


@pytest.mark.parametrize("before", [True, False], ids=["flag-before-command", "flag-after-command"])
def test_allow_outside_paths_before_or_after_the_command(layout, before):
    spec_dir, outside = layout
    spec = write(spec_dir, str(outside / "good.csv"))
    args = (
        ["--allow-outside-paths", "inertia", spec] if before else ["inertia", spec, "--allow-outside-paths"]
    )
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    import json

    result = json.loads(proc.stdout)
    # Masses 1 at z=+1 and 3 at z=-1: M = 4, centre of mass at z = -0.5, I_xx = Σ m d² = 3.
    assert result["mass"] == 4.0
    np.testing.assert_allclose(result["center_of_mass"], [0, 0, -0.5], atol=1e-15)
    # ``..`` is allowed by the flag too
    proc = run_rbi_inprocess(
        "inertia", write(spec_dir, "../outside/good.csv", "b.yaml"), "--allow-outside-paths"
    )
    assert proc.returncode == 0, proc.stderr


@pytest.mark.parametrize("file", ["secret.csv", "secret_cell.csv", "secret.npy"])
@pytest.mark.parametrize("allowed", [False, True], ids=["refused", "allowed"])
def test_an_error_never_prints_the_files_content(layout, file, allowed):
    spec_dir, outside = layout
    spec = write(spec_dir, str(outside / file))
    proc = run_rbi_inprocess("inertia", spec, *(["--allow-outside-paths"] if allowed else []))
    one_line_exit_2(proc, "point_cloud: file:")
    assert SECRET.lower() not in (proc.stderr + proc.stdout).lower()


def test_proc_self_environ_is_refused_and_never_printed(tmp_path):
    spec = tmp_path / "env.yaml"
    spec.write_text("point_cloud: {file: /proc/self/environ}\n")
    env = dict(os.environ, RBI_TEST_SECRET=SECRET)
    for extra in ([], ["--allow-outside-paths"]):
        proc = subprocess.run(
            [sys.executable, "-m", "rbi", "inertia", str(spec), *extra],
            capture_output=True,
            text=True,
            timeout=60,
            env=env,
        )
        one_line_exit_2(proc, "/proc/self/environ")
        assert SECRET.lower() not in proc.stderr.lower()  # (the header is lower-cased before it is read)


def test_an_unreadable_cloud_is_exit_2(tmp_path):
    # /proc/self/mem is a regular file whose first page cannot be read (EIO), even by root.
    spec = tmp_path / "mem.yaml"
    spec.write_text("point_cloud: {file: /proc/self/mem}\n")
    one_line_exit_2(run_rbi_inprocess("inertia", spec, "--allow-outside-paths"), "cannot read")


def test_sys_paths_are_refused_or_missing(tmp_path):
    spec = tmp_path / "sys.yaml"
    spec.write_text("point_cloud: {file: /sys/x.csv}\n")
    one_line_exit_2(run_rbi_inprocess("inertia", spec), LEAVES)
    one_line_exit_2(run_rbi_inprocess("inertia", spec, "--allow-outside-paths"), "/sys/x.csv", "no such file")


def test_a_fifo_beside_the_spec_is_refused_without_blocking(tmp_path):
    os.mkfifo(tmp_path / "pts.csv")
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", "inertia", str(write(tmp_path, "pts.csv"))],
        capture_output=True,
        text=True,
        timeout=60,
    )
    one_line_exit_2(proc, "not a regular file")


@pytest.mark.parametrize(
    "file, words",
    [
        ('"a\\0b.csv"', ["NUL"]),
        ('"' + "a" * 300 + '.csv"', ["no such file"]),
        ('"."', ["not a regular file"]),
    ],
    ids=["nul-character", "300-character-name", "the-folder-itself"],
)
def test_odd_paths_are_one_line_errors(tmp_path, file, words):
    spec = tmp_path / "odd.yaml"
    spec.write_text(f"point_cloud: {{file: {file}}}\n")
    for extra in ([], ["--allow-outside-paths"]):
        one_line_exit_2(run_rbi_inprocess("inertia", spec, *extra), "point_cloud: file:", *words)
