"""`rbi simulate` as a user runs it: output formats, files, errors and verdicts."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from tests.conftest import BODIES, one_line_exit_2, run_rbi, run_rbi_inprocess

BOLTED = BODIES / "top_bolted.yaml"
TOP = BODIES / "top.yaml"
COLUMNS = ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz"]
# DOP853 at rtol 1e-13 (shared/cases/expected.json)
BOLTED_FINAL_Q = [-0.8115423374746441, -0.0004863881802677963, 0.4154746034509781, 0.4108280075651523]
BOLTED_FINAL_OMEGA = [17.837792494482816, 4.26069065811585, 199.41803075686732]


def simulate_json(*args):
    proc = run_rbi("simulate", *args, "--format", "json", check=True)
    return json.loads(proc.stdout)


def test_json_summary_of_the_bolted_top():
    out = simulate_json(BOLTED, "--spin", "200")
    final = out["final"]
    assert final["t"] == 4.0 and out["method"] == "default" and out["steps"] > 0
    q = np.array(final["q"])
    assert abs(abs(q @ BOLTED_FINAL_Q) - 1.0) < 1e-12  # within ~1e-4 deg; the API test checks 1e-5 deg
    assert np.max(np.abs(np.array(final["omega"]) - BOLTED_FINAL_OMEGA)) < 1e-5
    assert 0.0 == out["tilt_min_deg"] < out["tilt_max_deg"] < 90.0
    assert out["max_relative_drift"] < 1e-9
    assert out["error_estimate"]["orientation_deg"] < 1e-5
    assert out["stability"]["kind"] == "asymmetric top"
    for key in (
        "rhs_evals",
        "wall_seconds",
        "mean_precession_rate_deg_s",
        "conserved",
        "quaternion_norm_error",
    ):
        assert key in out


def test_csv_file_has_the_contract_columns_and_one_row_per_sample(tmp_path):
    path = tmp_path / "traj.csv"
    run_rbi(
        "simulate",
        TOP,
        "--spin",
        "200",
        "--tilt",
        "5",
        "--duration",
        "1",
        "--samples",
        "11",
        "--out",
        path,
        check=True,
    )
    rows = list(csv.reader(path.open()))
    assert rows[0][:8] == COLUMNS
    assert rows[0][8:] == ["tilt_deg", "precession_deg", "energy"]
    assert len(rows) == 12
    values = np.array(rows[1:], dtype=float)
    np.testing.assert_allclose(values[:, 0], np.linspace(0, 1, 11), rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(values[:, 1:5], axis=1), 1.0, atol=1e-15)
    assert values[0, 8] == pytest.approx(5.0, abs=1e-12)
    assert not list(tmp_path.glob(".rbi-*"))  # no temporary file left behind


def test_format_csv_prints_the_trajectory():
    proc = run_rbi(
        "simulate",
        TOP,
        "--spin",
        "100",
        "--tilt",
        "3",
        "--duration",
        "0.5",
        "--samples",
        "6",
        "--format",
        "csv",
        check=True,
    )
    rows = list(csv.reader(io.StringIO(proc.stdout)))
    assert rows[0][:8] == COLUMNS and len(rows) == 7


def test_table_states_the_chapter_top_is_below_its_sleeping_threshold():
    proc = run_rbi("simulate", TOP, "--spin", "200", "--tilt", "0.01", check=True)
    assert "207.9" in proc.stdout and "unstable" in proc.stdout
    out = simulate_json(TOP, "--spin", "200", "--tilt", "0.01")
    assert out["stability"]["above_threshold"] is False
    assert out["closed_form"]["kind"] == "Lagrange top"
    assert out["tilt_max_deg"] == pytest.approx(out["closed_form"]["nutation_tilt_max_deg"], abs=1e-3)


def test_free_body_near_its_intermediate_axis_is_called_unstable():
    out = simulate_json(BODIES / "tbar.yaml", "--omega", "0.01,0.01,3", "--duration", "20")
    assert out["stability"]["intermediate_axis"] is True and "Dzhanibekov" in out["stability"]["verdict"]
    assert set(out["conserved"]) == {"energy", "h_world"}
    assert out["max_relative_drift"] < 1e-9


def test_exact_method_and_the_scipy_baseline():
    exact = simulate_json(TOP, "--spin", "150", "--tilt", "20", "--method", "exact", "--duration", "1")
    default = simulate_json(TOP, "--spin", "150", "--tilt", "20", "--duration", "1")
    q_a, q_b = np.array(exact["final"]["q"]), np.array(default["final"]["q"])
    assert abs(abs(q_a @ q_b) - 1.0) < 1e-13
    assert exact["steps"] == 0 and exact["error_estimate"] is None  # a closed form has no integration error
    chapter = simulate_json(
        TOP, "--spin", "150", "--tilt", "20", "--method", "rk45", "--duration", "0.2", "--no-error-estimate"
    )
    assert chapter["rtol"] == 1e-8 and chapter["error_estimate"] is None


def test_duration_zero_and_one_sample(tmp_path):
    still = simulate_json(TOP, "--spin", "100", "--duration", "0")
    assert (
        still["final"]["t"] == 0.0 and still["final"]["omega"] == [0.0, 0.0, 100.0] and still["samples"] == 1
    )
    one = simulate_json(TOP, "--spin", "100", "--tilt", "5", "--duration", "1", "--samples", "1")
    assert one["final"]["t"] == 1.0 and one["samples"] == 1


@pytest.mark.parametrize(
    "args,words",
    [
        (["--duration", "-1"], ["--duration"]),
        (["--samples", "0"], ["--samples"]),
        (["--samples", "-5"], ["--samples"]),
        (["--spin", "10", "--omega", "1,2,3"], ["--spin", "--omega"]),
        (["--omega", "1,2"], ["--omega"]),
        (["--method", "euler"], ["--method"]),
        (["--rtol", "0"], ["--rtol"]),
        (["--method", "exact", "--spin", "200"], ["exact", "Lagrange"]),
    ],
)
def test_bad_options_exit_2_with_one_line(args, words, tmp_path):
    out = tmp_path / "never.csv"
    proc = run_rbi("simulate", BOLTED, *args, "--out", out)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    for word in words:
        assert word in proc.stderr
    assert not out.exists()


def test_singular_inertia_about_the_pivot_exits_2(write_spec, tmp_path):
    spec = write_spec("""
name: needle
pivot: [0, 0, 0]
parts:
  - {name: low, shape: point, mass: 1.0, position: [0, 0, 1]}
  - {name: high, shape: point, mass: 1.0, position: [0, 0, 2]}
""")
    out = tmp_path / "never.csv"
    proc = run_rbi("simulate", spec, "--spin", "10", "--out", out)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert "pivot" in proc.stderr and "singular" in proc.stderr and str(spec) in proc.stderr
    assert not out.exists()


def test_plot_writes_a_png(tmp_path):
    path = tmp_path / "top.png"
    run_rbi("simulate", TOP, "--spin", "200", "--tilt", "10", "--plot", path, check=True)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_without_matplotlib_says_how_to_install_it(tmp_path, monkeypatch):
    blocker = tmp_path / "blocker"
    (blocker / "matplotlib").mkdir(parents=True)
    (blocker / "matplotlib" / "__init__.py").write_text("raise ImportError('blocked for the test')\n")
    monkeypatch.setenv("PYTHONPATH", str(blocker))
    proc = run_rbi("simulate", TOP, "--spin", "200", "--plot", tmp_path / "x.png")
    assert proc.returncode == 2 and "pip install '.[plot]'" in proc.stderr and "rbi[plot]" not in proc.stderr
    assert not (tmp_path / "x.png").exists()


def test_out_to_stdout_with_format_json_is_refused_not_printed_as_csv():
    """`--out -` streams the trajectory CSV to standard output, where `--format json` promises
    exactly one JSON object: the two cannot share it. Before: the CSV was printed and exit 0,
    so a script reading JSON got CSV. Now exit 2, one line naming both options. `--format csv`
    (or the default table) with `--out -` still streams the trajectory: 3 rows of the
    contract's columns, t = 0, 0.025, 0.05."""
    args = ["simulate", str(BODIES / "top.yaml"), "--spin", "1", "--duration", "0.05", "--samples", "3"]
    proc = run_rbi_inprocess(*args, "--out", "-", "--format", "json")
    one_line_exit_2(proc, "--out", "--format json")
    assert proc.stdout == ""
    for form in ("csv", "table"):
        done = run_rbi_inprocess(*args, "--out", "-", "--format", form)
        rows = list(csv.reader(io.StringIO(done.stdout)))
        assert done.returncode == 0 and rows[0][:8] == ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz"]
        assert [float(r[0]) for r in rows[1:]] == [0.0, 0.025, 0.05]


def test_the_table_says_the_quaternions_order(monkeypatch):
    # the row was written 'final q [w, x, y, z]' and printed 'final q': rich read the brackets
    # as a style and dropped them, so the table never said the scalar comes first
    monkeypatch.setenv("COLUMNS", "80")
    proc = run_rbi_inprocess("simulate", BODIES / "top.yaml", "--spin", "200", "--duration", "0.1")
    row = next(line for line in proc.stdout.splitlines() if line.startswith(" final q"))
    assert row.startswith(" final q [w, x, y, z] "), row
    # upright, spinning 200 rad/s about z for 0.1 s: turned 20 rad, q = [cos 10, 0, 0, sin 10]
    shown = [float(v) for v in row.split("]", 1)[1].strip().strip("[]").split(",")]
    assert shown == pytest.approx([math.cos(10), 0, 0, math.sin(10)], abs=1e-6)


def test_the_duration_and_the_samples_are_two_rows(monkeypatch):
    # the row 'duration, samples [s]  0.5, 11' put a unit of seconds on a count of samples
    monkeypatch.setenv("COLUMNS", "80")
    proc = run_rbi_inprocess("simulate", TOP, "--spin", "200", "--duration", "0.5", "--samples", "11")
    rows = {line.split()[0]: line.split()[1:] for line in proc.stdout.splitlines() if line.strip()}
    assert rows["duration"] == ["s", "0.5"] and rows["samples"] == ["11"], proc.stdout
