"""`rbi simulate` against hostile options and unsafe output paths: refused before any work,
nothing written on failure, no run that eats the machine."""

from __future__ import annotations

import csv
import io
import json
import math
import os
import stat

import pytest

from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

TOP = BODIES / "top.yaml"
BOLTED = BODIES / "top_bolted.yaml"
TBAR = BODIES / "tbar.yaml"


def test_out_naming_the_input_spec_is_refused_and_the_spec_kept(tmp_path):
    spec = tmp_path / "top.yaml"
    spec.write_text(TOP.read_text())
    one_line_exit_2(rbi("simulate", spec, "--spin", "200", "--out", spec), "--out", "input")
    one_line_exit_2(rbi("simulate", spec, "--spin", "200", "--plot", spec), "--plot")
    assert spec.read_text() == TOP.read_text()


def test_out_and_plot_naming_one_file_are_refused(tmp_path):
    path = tmp_path / "x.csv"
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--out", path, "--plot", path), "--plot")
    assert not path.exists()


def test_devices_and_fifos_are_never_replaced(tmp_path):
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--out", "/dev/null"), "device")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--out", fifo), "FIFO")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_the_extension_decides_the_format(tmp_path):
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--out", tmp_path / "x.json"), ".json")
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--plot", tmp_path / "x.jpg"), ".jpg")
    svg = tmp_path / "x.svg"
    proc = rbi("simulate", TOP, "--spin", "200", "--tilt", "5", "--duration", "0.5", "--plot", svg)
    assert proc.returncode == 0, proc.stderr
    assert b"<svg" in svg.read_bytes()[:2000]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.svg"]


def test_dash_streams_the_trajectory_to_standard_output(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    proc = rbi("simulate", TOP, "--spin", "200", "--duration", "1", "--samples", "11", "--out", "-")
    assert proc.returncode == 0, proc.stderr
    rows = list(csv.reader(io.StringIO(proc.stdout)))
    assert rows[0][:8] == ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz"] and len(rows) == 12
    assert list(tmp_path.iterdir()) == []


def test_an_overflowing_trajectory_writes_nothing_and_prints_no_inf(tmp_path):
    out = tmp_path / "x.csv"
    proc = rbi("simulate", TBAR, "--omega", "1e160,0,0", "--duration", "0", "--out", out)
    one_line_exit_2(proc, "not finite")
    assert not out.exists()
    proc = rbi("simulate", TBAR, "--omega", "1e160,0,0", "--duration", "0", "--format", "csv")
    one_line_exit_2(proc)
    assert "inf" not in proc.stdout


@pytest.mark.parametrize(
    "args",
    [
        ["--spin", "1e9"],
        ["--spin", "200", "--duration", "1e9"],
        ["--spin", "200", "--method", "rk45", "--duration", "1e5"],
    ],
)
def test_a_run_far_over_the_step_budget_is_refused_before_it_starts(args, tmp_path):
    out = tmp_path / "x.csv"
    one_line_exit_2(rbi("simulate", TOP, *args, "--out", out), "budget", "--max-steps")
    assert not out.exists()


def test_the_budget_also_stops_a_run_that_was_let_through():
    one_line_exit_2(rbi("simulate", BOLTED, "--spin", "200", "--max-steps", "100"), "budget")
    proc = rbi("simulate", BOLTED, "--spin", "200", "--max-steps", "100", "--yes", "--no-error-estimate")
    one_line_exit_2(proc, "100", "step budget")


@pytest.mark.parametrize("value", ["2e7", "1e23", "5000000", "0"])
def test_absurd_sample_counts_are_refused(value):
    one_line_exit_2(rbi("simulate", TOP, "--spin", "200", "--samples", value), "--samples")


def test_an_upright_top_claims_no_precession(tmp_path):
    out = tmp_path / "x.csv"
    proc = rbi(
        "simulate",
        TOP,
        "--spin",
        "200",
        "--duration",
        "0.5",
        "--samples",
        "6",
        "--out",
        out,
        "--format",
        "json",
    )
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["mean_precession_rate_deg_s"] is None
    rows = list(csv.DictReader(out.open()))
    assert all(r["precession_deg"] == "" for r in rows) and all(float(r["tilt_deg"]) == 0.0 for r in rows)
    table = rbi("simulate", TOP, "--spin", "200", "--duration", "0.5")
    assert "undefined" in table.stdout


def test_the_error_estimate_is_strictly_tighter_or_says_it_cannot_be():
    tight = json.loads(
        rbi(
            "simulate", BOLTED, "--spin", "200", "--duration", "0.5", "--rtol", "1e-14", "--format", "json"
        ).stdout
    )
    assert "1e-15" in tight["error_estimate"]["reference"]
    floor = json.loads(
        rbi(
            "simulate", BOLTED, "--spin", "200", "--duration", "0.5", "--rtol", "1e-15", "--format", "json"
        ).stdout
    )
    assert floor["error_estimate"]["orientation_deg"] is None
    assert "not available" in floor["error_estimate"]["reference"]
    default = json.loads(
        rbi("simulate", BOLTED, "--spin", "200", "--duration", "0.5", "--format", "json").stdout
    )
    assert "1e-15" in default["error_estimate"]["reference"]  # 1000x tighter than 1e-12


def test_tilt_about_x_is_the_mirror_of_tilt_about_y():
    """An axisymmetric top tilted 10° about world x or about world y nutates the same way: the
    two tilt histories are one motion turned by 90° about the vertical."""

    def tilts(axis):
        proc = rbi(
            "simulate",
            TOP,
            "--spin",
            "150",
            "--tilt",
            "10",
            "--tilt-axis",
            axis,
            "--duration",
            "0.5",
            "--samples",
            "26",
            "--format",
            "csv",
        )
        assert proc.returncode == 0, proc.stderr
        return [float(r["tilt_deg"]) for r in csv.DictReader(io.StringIO(proc.stdout))]

    x, y = tilts("x"), tilts("y")
    assert x[0] == pytest.approx(10.0, abs=1e-12)
    assert x == pytest.approx(y, abs=1e-8)


def test_without_gravity_a_top_spinning_about_its_axis_keeps_its_tilt():
    proc = rbi("simulate", TOP, "--spin", "50", "--tilt", "20", "--gravity", "0", "--format", "json")
    out = json.loads(proc.stdout)
    assert out["gravity"] == 0.0
    assert out["tilt_max_deg"] - out["tilt_min_deg"] < 1e-8


def test_gravity_is_given_in_si_and_converted_to_the_spec_units(write_spec):
    spec = write_spec(
        "units: {length: mm, mass: g}\npivot: [0, 0, 0]\n"
        "parts:\n  - {shape: cone, mass: 400, radius: 40, apex: [0, 0, 0], base: [0, 0, 60]}\n"
    )
    out = json.loads(
        rbi(
            "simulate",
            spec,
            "--spin",
            "200",
            "--tilt",
            "5",
            "--gravity",
            "1.62",
            "--duration",
            "0.1",
            "--format",
            "json",
        ).stdout
    )
    assert math.isclose(out["gravity"], 1620.0, rel_tol=1e-15)
    one_line_exit_2(rbi("simulate", spec, "--spin", "200", "--gravity", "-1"), "--gravity")
    one_line_exit_2(rbi("simulate", spec, "--spin", "200", "--tilt-axis", "z"), "--tilt-axis")


def test_no_code_from_the_current_folder_runs_and_no_writable_home_is_needed(tmp_path):
    """The installed `rbi` in a folder holding modules named like rbi's build tools and
    dependencies, with HOME and the cache folder unwritable: it simulates, prints no
    'compiling' line, and none of those modules runs."""
    import subprocess
    import sys
    from pathlib import Path

    marker = tmp_path / "ran"
    for name in ("numba", "Cython", "rbi_kernels", "sitecustomize", "usercustomize"):
        (tmp_path / f"{name}.py").write_text(f"open({str(marker)!r}, 'a').write({name!r})\n")
    home = tmp_path / "home"
    home.mkdir(mode=0o500)
    env = dict(os.environ, HOME=str(home), XDG_CACHE_HOME=str(home / "cache"), PYTHONPATH="")
    rbi_script = Path(sys.executable).with_name("rbi")
    proc = subprocess.run(
        [str(rbi_script), "simulate", str(TOP), "--spin", "200", "--duration", "0.2", "--format", "json"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    assert "compiling" not in proc.stderr and json.loads(proc.stdout)["final"]["t"] == 0.2
    assert not marker.exists()
