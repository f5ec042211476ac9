"""`rbi sweep` from the command line: the contract's rows, equality with single `rbi simulate`
runs, Monte Carlo with a seed, vary paths, failed-run rows, Dask, resume after a kill, the
stability map against the sleeping-top closed form, mass-property spreads."""

from __future__ import annotations

import csv
import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

TOP = BODIES / "top.yaml"
BOLTED = BODIES / "top_bolted.yaml"
CONTRACT_COLUMNS = {"spin", "tilt_deg", "max_tilt_deg", "final_tilt_deg", "energy_drift", "status"}


def rows_of(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def json_rows(*args):
    proc = rbi("sweep", *args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_contract_grid_writes_one_row_per_run(tmp_path):
    out = tmp_path / "sweep.csv"
    proc = rbi("sweep", TOP, "--spin", "150:250:2", "--tilt", "1:1:1", "--duration", "0.5", "--out", out)
    assert proc.returncode == 0, proc.stderr
    rows = rows_of(out)
    assert len(rows) == 2 and CONTRACT_COLUMNS <= set(rows[0])
    assert [float(r["spin"]) for r in rows] == [150.0, 250.0] and all(r["status"] == "ok" for r in rows)
    assert not (tmp_path / ".sweep.csv.rbi-sweep.json").exists()  # finished: no resume state left behind


def test_every_row_equals_rbi_simulate_of_that_run_alone():
    result = json_rows(BOLTED, "--spin", "180:220:2", "--tilt", "0:5:2", "--duration", "1")
    assert result["count"] == 4
    for row in result["runs"]:
        single = rbi(
            "simulate",
            BOLTED,
            "--spin",
            repr(row["spin"]),
            "--tilt",
            repr(row["tilt_deg"]),
            "--duration",
            "1",
            "--format",
            "json",
            "--no-error-estimate",
        )
        alone = json.loads(single.stdout)
        assert row["max_tilt_deg"] == pytest.approx(alone["tilt_max_deg"], rel=1e-12, abs=1e-12)
        assert row["final_tilt_deg"] == pytest.approx(alone["final"]["tilt_deg"], rel=1e-12, abs=1e-12)
        assert row["energy_drift"] == pytest.approx(
            alone["conserved"]["energy"]["drift"], rel=1e-9, abs=1e-15
        )
        assert row["steps"] == alone["steps"]


def test_monte_carlo_is_reproducible_with_a_seed_and_changes_with_it():
    args = (
        BOLTED,
        "--spin",
        "200",
        "--vary",
        "parts.bolt.mass=normal(0.02,0.004)",
        "--runs",
        "6",
        "--duration",
        "0.3",
    )
    first = json_rows(*args, "--seed", "3")
    again = json_rows(*args, "--seed", "3")
    other = json_rows(*args, "--seed", "4")
    assert first["runs"] == again["runs"] and len(first["runs"]) == 6
    masses = [r["parts.bolt.mass"] for r in first["runs"]]
    assert len(set(masses)) == 6 and masses != [r["parts.bolt.mass"] for r in other["runs"]]


def test_a_varied_bolt_changes_the_wobble_as_a_heavier_bolt_should():
    result = json_rows(BOLTED, "--spin", "200", "--vary", "parts.bolt.mass=0.001:0.041:3", "--duration", "1")
    tilts = [r["max_tilt_deg"] for r in result["runs"]]
    assert 0 < tilts[0] < tilts[1] < tilts[2]


def test_a_bad_vary_path_is_exit_2_naming_it():
    proc = rbi("sweep", BOLTED, "--vary", "parts.nut.mass=0:1:3")
    assert proc.returncode == 2 and "parts.nut.mass" in proc.stderr and "bolt" in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize(
    "args, words",
    [
        (["--spin", "1:2"], ["--spin"]),
        (["--tilt", "x"], ["--tilt"]),
        (["--runs", "0"], ["--runs"]),
        (["--runs", "5"], ["--runs", "normal"]),
        (["--resume"], ["--resume", "--out"]),
        (["--mass-properties", "--spin", "1:2:2"], ["--mass-properties"]),
        (["--mass-properties"], ["--vary"]),
        (["--vary", "parts.bolt.mass"], ["PATH=RANGE"]),
        (["--vary", "parts.bolt.mass=1:2:2", "--vary", "parts.bolt.mass=1:2:2"], ["twice"]),
        (["--spin", "0:1:200000"], ["--out"]),
        (["--out", "x.json"], ["--out"]),
        (["--samples", "0"], ["--samples"]),
        (["--rtol", "1"], ["--rtol"]),
    ],
)
def test_bad_options_are_one_line_exit_2(tmp_path, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    one_line_exit_2(rbi("sweep", BOLTED, *args), *words)


def test_out_naming_the_spec_is_refused(tmp_path):
    spec = tmp_path / "top.csv"
    spec.write_text(TOP.read_text())
    proc = rbi("sweep", spec, "--out", spec)
    assert proc.returncode == 2 and spec.read_text() == TOP.read_text()


def test_a_failed_run_is_a_row_with_its_reason_and_the_others_run(tmp_path):
    spec = tmp_path / "top.yaml"
    spec.write_text(BOLTED.read_text())
    result = json_rows(
        spec, "--spin", "200", "--vary", "parts.stem.radius=-0.008:0.008:3", "--duration", "0.2"
    )
    status = [r["status"] for r in result["runs"]]
    assert (
        "radius" in status[0] and "greater than 0" in status[0] and result["runs"][0]["max_tilt_deg"] is None
    )
    assert status[2] == "ok" and result["failed"] >= 1


def test_a_run_past_its_step_budget_fails_alone():
    result = json_rows(TOP, "--spin", "50:400:2", "--tilt", "1", "--duration", "1", "--max-steps", "500")
    assert [r["status"].startswith("failed: step budget") for r in result["runs"]] == [False, True]


def test_dask_local_cluster_gives_the_same_rows_in_the_same_order(tmp_path):
    pytest.importorskip("distributed")
    pytest.importorskip("cryptography")  # the local cluster's private TLS certificates
    args = [
        "sweep",
        str(BOLTED),
        "--spin",
        "150:250:5",
        "--tilt",
        "0:2:2",
        "--duration",
        "0.3",
        "--format",
        "csv",
    ]
    local = subprocess.run([sys.executable, "-m", "rbi", *args], capture_output=True, text=True, timeout=120)
    remote = subprocess.run(
        [sys.executable, "-m", "rbi", *args, "--dask", "local", "--workers", "2"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert local.returncode == 0 and remote.returncode == 0, remote.stderr
    assert remote.stdout == local.stdout and len(remote.stdout.splitlines()) == 11


def test_parquet_rows_equal_csv_rows(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    args = [BOLTED, "--spin", "190:210:3", "--duration", "0.2"]
    assert rbi("sweep", *args, "--out", tmp_path / "a.parquet").returncode == 0
    assert rbi("sweep", *args, "--out", tmp_path / "a.csv").returncode == 0
    table = pq.read_table(tmp_path / "a.parquet").to_pylist()
    for p, c in zip(table, rows_of(tmp_path / "a.csv")):
        assert p["max_tilt_deg"] == float(c["max_tilt_deg"]) and p["run"] == int(c["run"])


def interrupt_after(monkeypatch, chunks: int, chunk_size: int):
    """Make the next sweep stop with Ctrl-C after ``chunks`` chunks of ``chunk_size`` runs;
    returns what puts the runs back."""
    from rbi.sweeps import runs

    real, calls = runs.run_chunk, []

    def interrupted(job, a, b, threads=0):
        calls.append(a)
        if len(calls) > chunks:
            raise KeyboardInterrupt
        return real(job, a, b, threads)

    monkeypatch.setattr(runs, "run_chunk", interrupted)
    monkeypatch.setattr("rbi.sweeps.runs.SweepJob.chunk_size", lambda self, threads: chunk_size)
    return lambda: monkeypatch.setattr(runs, "run_chunk", real)


def test_interrupted_sweep_keeps_finished_runs_and_resume_completes_it(tmp_path, monkeypatch):
    args = [BOLTED, "--spin", "150:250:40", "--duration", "0.2", "--workers", "1"]
    reference = tmp_path / "all.csv"
    assert rbi("sweep", *args, "--out", reference).returncode == 0
    out = tmp_path / "part.csv"
    restore = interrupt_after(monkeypatch, 2, 8)
    proc = rbi("sweep", *args, "--out", out)
    assert proc.returncode == 130 and "--resume" in proc.stderr
    kept = rows_of(out)
    assert 0 < len(kept) < 40 and [int(r["run"]) for r in kept] == list(range(len(kept)))
    with open(out, "a") as handle:  # what a kill in the middle of a write leaves: part of the next row
        handle.write(f"{len(kept)},150.0,0.0,1.2")
    restore()
    proc = rbi("sweep", *args, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_text() == reference.read_text()


def test_the_rows_file_writes_negative_zero_as_format_csv_does(tmp_path):
    """One CSV cell rule: -0.0 is 0.0 in the rows file as on stdout (the file had -0.0)."""
    args = [TOP, "--spin", "-0", "--tilt", "-0", "--duration", "0.2"]
    out = tmp_path / "x.csv"
    assert rbi("sweep", *args, "--out", out).returncode == 0
    printed = rbi("sweep", *args, "--format", "csv")
    assert printed.returncode == 0, printed.stderr
    assert out.read_text() == printed.stdout
    assert rows_of(out)[0]["spin"] == rows_of(out)[0]["tilt_deg"] == "0.0"


def test_a_rows_file_holding_negative_zero_cells_resumes(tmp_path, monkeypatch):
    """A rows file written before -0.0 was written 0.0 ('-0.0' cells) is resumed: its cells are
    read back as numbers, -0.0 == 0.0, and kept as they are."""
    args = [TOP, "--spin", "-0", "--tilt", "0:1:12", "--duration", "0.2", "--workers", "1"]
    reference = tmp_path / "all.csv"
    assert rbi("sweep", *args, "--out", reference).returncode == 0
    out = tmp_path / "part.csv"
    restore = interrupt_after(monkeypatch, 1, 4)
    assert rbi("sweep", *args, "--out", out).returncode == 130
    header, *kept = out.read_text().splitlines(keepends=True)
    assert len(kept) == 4 and all(line.split(",")[1] == "0.0" for line in kept)
    old = [line.replace(",0.0,", ",-0.0,", 1) for line in kept]  # the spin cell as it was written
    out.write_text(header + "".join(old))
    restore()
    proc = rbi("sweep", *args, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_text() == reference.read_text().replace(
        "".join(reference.read_text().splitlines(keepends=True)[1:5]), "".join(old)
    )


def test_resume_with_other_settings_is_refused(tmp_path, monkeypatch):
    out = tmp_path / "s.csv"
    from rbi.sweeps import store

    store.settings_path(out).write_text(json.dumps({"spin": "elsewhere"}))
    out.write_text("run\n")
    proc = rbi("sweep", BOLTED, "--spin", "150:250:4", "--out", out, "--resume")
    assert proc.returncode == 2 and "other settings" in proc.stderr


def test_stability_map_shows_the_transition_at_the_closed_form_sleeping_threshold(tmp_path):
    """Sleeping top: upright is stable for spins above ω_c = √(4 m g l I₁)/I₃ (moments about the
    pivot). Computed here from the mass properties, not by rbi's own threshold code."""
    about_pivot = json.loads(rbi("inertia", TOP, "--about", "pivot", "--format", "json").stdout)
    I = np.array(about_pivot["inertia"])
    height = about_pivot["center_of_mass"][2]  # the pivot is the origin of the textbook top
    omega_c = float(math.sqrt(4 * about_pivot["mass"] * 9.81 * height * I[0][0]) / I[2][2])
    assert 200 < omega_c < 215  # the textbook top: about 208 rad/s
    spins = f"{0.97 * omega_c!r}:{1.03 * omega_c!r}:2"
    plot = tmp_path / "map.png"
    result = json_rows(TOP, "--spin", spins, "--tilt", "0.01:0.02:2", "--duration", "4", "--plot", plot)
    by_spin = {}
    for row in result["runs"]:
        by_spin.setdefault(row["spin"] > omega_c, []).append(row["max_tilt_deg"])
    assert min(by_spin[False]) > 10 and max(by_spin[True]) < 0.1
    assert plot.stat().st_size > 10_000 and plot.read_bytes()[:4] == b"\x89PNG"


def test_mass_properties_spread_of_a_moved_point_mass_is_exact(tmp_path):
    """Moving the 0.02 kg bolt along x by d moves the centre of mass by 0.02 d / M exactly."""
    result = json_rows(BOLTED, "--mass-properties", "--vary", "parts.bolt.position[0]=0.03:0.05:5")
    rows = result["runs"]
    total = rows[0]["mass"]
    assert all(r["mass"] == pytest.approx(0.52, rel=1e-12) for r in rows) and total == pytest.approx(0.52)
    for r in rows:
        assert r["com_x"] == pytest.approx(0.02 * r["parts.bolt.position[0]"] / total, rel=1e-12)
    spread = result["spread"]["com_x"]
    assert spread["p0"] == pytest.approx(0.02 * 0.03 / total) and spread["p100"] == pytest.approx(
        0.02 * 0.05 / total
    )
    # the nominal position (0.04, the middle run) leaves the principal axes where they were
    assert max(rows[2][f"axis_{k}_tilt_deg"] for k in (1, 2, 3)) < 1e-6
    assert rows[0]["axis_1_tilt_deg"] > 1e-3 and all(r["status"] == "ok" for r in rows)


def test_the_table_never_cuts_a_number_short_in_80_columns(monkeypatch):
    """Piped or in a narrow terminal (80 columns), every cell is shown whole (wrapped if it
    must be): a drift shown as '7.9e-…' would hide its exponent."""
    monkeypatch.setenv("COLUMNS", "80")
    proc = rbi(
        "sweep",
        BOLTED,
        "--spin",
        "150:250:2",
        "--tilt",
        "1",
        "--vary",
        "parts.bolt.position[0]=0.03:0.04:2",
        "--duration",
        "0.5",
    )
    assert proc.returncode == 0, proc.stderr
    assert "…" not in proc.stdout
    assert max(len(line) for line in proc.stdout.splitlines()) <= 80


def test_a_refused_resume_names_the_out_option(tmp_path):
    """The rows file's messages name it as the command line does (--out), not as rbi.sweep's
    parameter."""
    out = tmp_path / "map.csv"
    proc = rbi(
        "sweep", BODIES / "top_bolted.yaml", "--spin", "100", "--duration", "0.1", "--out", out, "--resume"
    )
    assert proc.returncode == 2
    assert proc.stderr.startswith(f"rbi: --out: {out}: cannot resume: no unfinished sweep there")


def test_a_monte_carlo_sweep_draws_its_map_over_the_drawn_value(tmp_path):
    """Found: `--runs N --vary PATH=normal(..) --plot` was refused ('the map needs at least one
    axis with more than one value') though each run draws its own value. The map is now the
    largest tilt against the drawn values. Physics of the rows: a heavier bolt off the axis of a
    top spun at 150 rad/s from upright tilts it more (the unbalance grows with the mass)."""
    plot = tmp_path / "mc.png"
    result = json_rows(
        BOLTED,
        "--runs",
        "6",
        "--seed",
        "3",
        "--vary",
        "parts.bolt.mass=uniform(0.005,0.04)",
        "--spin",
        "150",
        "--duration",
        "0.2",
        "--plot",
        plot,
    )
    rows = sorted(result["runs"], key=lambda r: r["parts.bolt.mass"])
    masses = [r["parts.bolt.mass"] for r in rows]
    assert len(set(masses)) == 6 and 0.005 <= masses[0] and masses[-1] <= 0.04
    assert rows[0]["max_tilt_deg"] < rows[-1]["max_tilt_deg"]
    assert plot.stat().st_size > 10_000 and plot.read_bytes()[:4] == b"\x89PNG"


def test_a_varied_field_has_its_unit_in_the_tables(monkeypatch):
    # `rbi sweep bodies/top_bolted.yaml --mass-properties --vary 'parts.bolt.mass=normal(..)'`
    # printed the row 'parts.bolt.mass   (no unit)   0.015 ...' while every other row had one;
    # a grid's column for a varied field had no unit under it either
    monkeypatch.setenv("COLUMNS", "120")
    spread = rbi(
        "sweep",
        BOLTED,
        "--mass-properties",
        "--vary",
        "parts.bolt.mass=normal(0.02,0.002)",
        "--vary",
        "parts.bolt.position[0]=uniform(0.039,0.041)",
        "--runs",
        "5",
    ).stdout
    units = {line.split()[0]: line.split()[1] for line in spread.splitlines() if line.startswith(" parts.")}
    assert units == {"parts.bolt.mass": "kg", "parts.bolt.position[0]": "m"}, spread
    wheel = BODIES / "wheel_with_holes.yaml"  # in mm and g
    grid = rbi(
        "sweep", wheel, "--spin", "10", "--vary", "parts.rim.outer_radius=99:101:2", "--duration", "0.1"
    )
    header = grid.stdout.splitlines()[1:3]
    assert "parts.rim.outer_radius" in header[0] and " mm " in header[1], grid.stdout


def test_the_maps_axes_are_labelled_as_every_other_picture(tmp_path):
    # `rbi sweep top.yaml --spin A:B:N --tilt A:B:N --plot map.png` labelled its axes 'spin, rad/s'
    # and 'initial tilt, deg'; the tilt axis holds each run's nudge (--tilt), which is the
    # initial tilt only for a body drawn upright (a gyroscope on its side starts at 90°)
    pytest.importorskip("matplotlib")
    out = tmp_path / "map.svg"
    proc = rbi("sweep", TOP, "--spin", "180:240:3", "--tilt", "0.01:1:2", "--duration", "1", "--plot", out)
    assert proc.returncode == 0, proc.stderr
    texts = re.findall(r"<!-- (.*?) -->", out.read_text(encoding="utf-8"))
    assert "spin [rad/s]" in texts and "nudge at t = 0 [deg]" in texts, texts
