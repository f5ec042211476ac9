"""`rbi bench --quick`: runs as CI would, prints one JSON object, writes the docs page and the
plot, and its numbers are internally consistent (no timing thresholds: the machine is shared)."""

from __future__ import annotations

import json
import math

import pytest

from tests.conftest import run_rbi


@pytest.fixture(scope="module")
def quick_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bench")
    doc, png = folder / "performance.md", folder / "workprecision.png"
    proc = run_rbi("bench", "--quick", "--format", "json", "--write-docs", doc, "--plot", png)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout), doc, png


def test_quick_bench_prints_one_json_object_with_every_section(quick_run):
    result, _, _ = quick_run
    assert result["quick"] is True
    assert {"workprecision", "throughput", "latency", "machine", "headline", "command"} <= set(result)
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
    assert "![Final orientation error against in-process time](workprecision.png)" in text
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("args, message", [
    (["--only", "speed"], "--only: expected a comma-separated list"),
    (["--only", "latency", "--plot", "x.png"], "--plot: needs the workprecision section"),
    (["--plot", "/no/such/folder/x.png"], "--plot: /no/such/folder/x.png: folder"),
])
def test_bad_options_exit_2_with_one_line(args, message):
    proc = run_rbi("bench", *args)
    assert proc.returncode == 2
    assert message in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1
