"""`rbi bench --quick`: runs as CI would, prints one JSON object, writes the docs page and the
plot, and its numbers are internally consistent (no timing thresholds: the machine is shared).
The run is made once, by the module's quick_proc (under pytest-xdist's --dist loadfile one worker
runs this whole file)."""

from __future__ import annotations

import json
import math

import pytest

from tests.conftest import run_rbi, run_rbi_inprocess


def test_the_written_page_is_named_escaped(quick_proc):
    proc, doc, _ = quick_proc
    assert "\x1b" not in proc.stderr
    assert f"rbi: wrote {doc.parent}/perf\\x1b[31m.md" in proc.stderr


def test_quick_bench_prints_one_json_object_with_every_section(quick_run):
    result, _, _ = quick_run
    assert result["quick"] is True
    assert {
        "kernel",
        "workprecision",
        "throughput",
        "largespec",
        "latency",
        "sweep",
        "uncertainty",
        "machine",
        "headline",
        "command",
        "targets",
    } <= set(result)
    assert result["command"].startswith("rbi bench --quick")
    for key in ("date", "cpu", "cores", "python", "numpy", "scipy"):
        assert result["machine"][key]


def test_work_precision_rows_are_consistent(quick_run):
    result, _, _ = quick_run
    cases = result["workprecision"]["cases"]
    assert [c["name"] for c in cases] == ["bolted top", "free asymmetric body"]
    for case in cases:
        runs = case["runs"]
        assert sum(r["chapter_setup"] for r in runs) == 1
        for r in runs + [case["default"]]:
            assert r["steps"] > 0 and r["rhs_evals"] >= r["steps"]
            assert r["seconds"] > 0
            for key in ("orientation_error_deg", "omega_error", "drift"):
                assert math.isfinite(r[key]) and r[key] >= 0
        # A tighter tolerance of the same method gives a smaller error.
        rbi = sorted((r for r in runs if r["method"] == "default"), key=lambda r: r["rtol"])
        assert rbi[0]["orientation_error_deg"] < rbi[-1]["orientation_error_deg"]
        s = case["speedup"]
        assert s["ratio_default"] == pytest.approx(s["chapter_seconds"] / s["default_seconds"])
        # rbi's defaults are at least as accurate as the chapter's set-up (issue 3's promise).
        assert s["default_no_worse"] is True
    top = cases[0]
    assert top["reference"]["check"]["orientation_difference_deg"] < 1e-6


def test_throughput_rows_compute_the_right_thing(quick_run):
    result, _, _ = quick_run
    clouds = result["throughput"]["point_clouds"]
    assert [r["points"] for r in clouds] == [1000, 10_000, 100_000]
    for r in clouds:
        assert r["relative_difference_to_direct_sum"] < 1e-12
    assert result["throughput"]["solid_parts"][0]["parts"] == 1000


def test_latency_compares_with_the_numpy_import(quick_run):
    result, _, _ = quick_run
    rows = result["latency"]["commands"]
    assert rows[0]["command"] == 'python -c "import numpy"'
    assert rows[0]["ratio_to_numpy_import"] == 1.0
    inertia = next(r for r in rows if r["command"].startswith("rbi inertia"))
    assert "error" not in inertia and inertia["ratio_to_numpy_import"] > 0


def test_docs_page_and_plot_are_written(quick_run):
    result, doc, png = quick_run
    text = doc.read_text()
    assert text.startswith("# Performance")
    assert "rbi bench --quick" in text and result["machine"]["cpu"] in text
    assert "| method | rtol |" in text
    assert "## Targets" in text and "## The kernel against its baselines" in text
    assert "## Sweep throughput and memory" in text
    assert "![Final orientation error against in-process time](workprecision.png)" in text
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    "args, message",
    [
        (["--only", "speed"], "--only: expected a comma-separated list"),
        (["--only", "latency", "--plot", "x.png"], "--plot: needs the workprecision section"),
        (["--plot", "/no/such/folder/x.png"], "--plot: /no/such/folder/x.png: folder"),
    ],
)
def test_bad_options_exit_2_with_one_line(args, message):
    proc = run_rbi_inprocess("bench", *args)
    assert proc.returncode == 2
    assert message in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1


def test_kernel_section_compares_with_the_chapter_and_the_minimal_loop(quick_run):
    result, _, _ = quick_run
    k = result["kernel"]
    assert k["ratio_default"] == pytest.approx(k["chapter"]["seconds"] / k["default"]["seconds"])
    assert k["ratio_to_minimal_loop"] == pytest.approx(k["default"]["seconds"] / k["minimal_loop"]["seconds"])
    # the baseline loop really is the same computation
    assert k["minimal_loop"]["same_steps"] is True and k["minimal_loop"]["same_samples"] is True
    assert k["minimal_loop"]["steps"] == k["default"]["steps"] > 0
    best = k["best_matching"]
    assert best is not None and best["no_worse"]
    assert best["orientation_error_deg"] <= k["chapter"]["orientation_error_deg"]
    assert k["ratio_best_matching"] == pytest.approx(k["chapter"]["seconds"] / best["seconds"])
    # tighter tolerances take more steps
    steps = [t["steps"] for t in k["trials"]]
    assert steps == sorted(steps)


def test_latency_has_first_run_and_every_timed_target(quick_run):
    result, _, _ = quick_run
    lat = result["latency"]
    labels = {r["command"]: r for r in lat["commands"]}
    for label in (
        "rbi --help",
        "rbi inertia bodies/top.yaml",
        "rbi inertia bodies/top.yaml --format json",
        "rbi simulate bodies/top.yaml --spin 200 --tilt 10",
    ):
        row = labels[label]
        assert "error" not in row, row
        assert row["ratio_to_numpy_import"] == pytest.approx(row["median_s"] / lat["commands"][0]["median_s"])
        assert row["cpu_ratio_to_numpy_import"] == pytest.approx(
            row["cpu_median_s"] / lat["commands"][0]["cpu_median_s"]
        )
        assert row["target"] in (1.3, 2.5, 3.0)
    # many files in one process: the cost of each file after the first, and the start-up ratio, reported
    per_file = lat["per_file"]
    many = next(r for r in lat["commands"] if r["command"].startswith("rbi inertia (the bundled bodies"))
    assert per_file["files"] == 600 and "600 files" in many["command"]
    assert per_file["per_file_ms"] == pytest.approx(
        1000 * (many["median_s"] - labels["rbi inertia bodies/top.yaml --format json"]["median_s"]) / 599
    )
    assert per_file["target_ms"] == 5.0
    # where the start-up goes: every module's own import time, summed by package
    imports = lat["imports"]
    # typer parses every command line (there is no second parser any more), so it is measured too
    assert imports["groups_ms"]["numpy"] > 0 and imports["groups_ms"]["typer and click"] > 0
    assert sum(imports["groups_ms"].values()) == pytest.approx(imports["total_ms"])
    assert lat["bytecode_compiled"] is True  # no timed run compiles rbi's sources
    first = lat["first_run"]
    assert first["ratio"] == pytest.approx(first["first_median_s"] / first["later_median_s"])
    assert first["files_left_in_home"] == []  # nothing compiled or cached in HOME
    assert first["compiling_line"] is False


def test_sweep_section_ratios_are_against_their_baselines(quick_run):
    result, _, _ = quick_run
    sw = result["sweep"]
    runs = sw["grid"]["spin"][2] * sw["grid"]["tilt_deg"][2]
    assert sw["sweep"]["runs"] == sw["sweep"]["rows_written"] == runs
    assert sw["ratio_to_cores_x_single"] == pytest.approx(
        sw["sweep"]["runs_per_second"] / (sw["cores"] * sw["single_run"]["runs_per_second"])
    )
    assert sw["ratio_to_process_loop"] == pytest.approx(
        sw["sweep"]["runs_per_second"] / sw["process_loop"]["runs_per_second"]
    )
    mem = sw["memory"]
    assert "error" not in mem, mem
    assert mem["rows_written"] == mem["runs"]
    assert 0 < mem["peak_rss_mb"] < 10_000 and mem["samples"]


def test_targets_list_each_ratio_with_its_limit(quick_run):
    result, _, _ = quick_run
    targets = result["targets"]
    assert {t["area"] for t in targets} == {
        "kernel",
        "start-up",
        "large specs",
        "sweep",
        "robot audit",
        "uncertainty",
    }
    assert len(targets) >= 12
    for t in targets:
        assert t["baseline"]
        if t["measured"] is not None:
            expected = t["measured"] >= t["limit"] if t["comparison"] == "≥" else t["measured"] <= t["limit"]
            assert t["met"] is expected


def test_csv_of_a_section_without_targets_is_its_records():
    """`rbi bench --only throughput --format csv` printed nothing (no work-precision runs, no
    targets): it prints one row per record of the section's tables, the numbers the JSON's."""
    import csv

    from rbi.bench.report import Report

    proc = run_rbi("bench", "--only", "throughput", "--quick", "--format", "csv", check=True)
    lines = list(csv.DictReader(proc.stdout.splitlines()))
    result = json.loads(
        run_rbi_inprocess("bench", "--only", "throughput", "--quick", "--format", "json").stdout
    )
    tp = result["throughput"]
    header = ["section", "table", *tp["point_clouds"][0], *tp["solid_parts"][0]]
    assert proc.stdout.splitlines()[0] == ",".join(header)
    records = [("point_clouds", r) for r in tp["point_clouds"]] + [
        ("solid_parts", r) for r in tp["solid_parts"]
    ]
    assert [(r["section"], r["table"]) for r in lines] == [("throughput", t) for t, _ in records]
    for row, (_, record) in zip(lines, records):
        # the sizes are the same in every run; the times differ from run to run but are times
        assert all(row[k] == "" for k in header[2:] if k not in record)
        assert row.get("points", "") == str(record.get("points", "")) and row["parts"] == str(
            record.get("parts", "")
        )
        assert all(float(row[k]) >= 0 for k in record)
    # the JSON's own numbers, written as CSV, read back exactly
    again = list(csv.DictReader(Report(result).to_csv().splitlines()))
    for row, (_, record) in zip(again, records, strict=True):
        assert {k: float(row[k]) for k in record} == record


def test_step_is_exact_and_the_stl_is_not(quick_run):
    """The cad section (cad.run(quick=True)): the 200-hole plate read as STEP is exact to 1e-9 of
    its closed form (tests/bench/test_cad.py), its STL tessellation is not; both rows reach the
    report's table."""
    pytest.importorskip("OCP")
    from rbi.bench import report

    result = quick_run[0]["cad"]
    step, stl = result["files"]
    assert step["file"] == "STEP" and stl["file"] == "STL"
    assert max(step["volume_error"], step["com_error"], step["inertia_error"]) < 1e-9
    assert step["integration_error"] < 1e-9
    assert stl["triangles"] > 10_000 and stl["inertia_error"] > 1e-6 and stl["volume_error"] > 1e-6
    (section,) = report.report_sections({"cad": result})
    assert section.title == "CAD solids: STEP against STL" and len(section.columns) == 8
    assert [row[0] for row in section.rows] == ["STEP", "STL"]
    assert section.rows[1][1] == f"{stl['triangles']:,}" and section.rows[0][1] == "—"
