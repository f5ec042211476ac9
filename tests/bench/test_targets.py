"""rbi.bench.report.targets: each target's ratio, limit and verdict from the sections'
measurements (synthetic numbers: no timing here)."""

from __future__ import annotations

from rbi.bench import sweep
from rbi.bench.report import Report, report_sections, targets


def target_rows(rows: list[dict]) -> list[list[str]]:
    """The cells of the report's Targets table of ``rows``."""
    return report_sections({"targets": rows})[0].rows


def csv_rows(result: dict) -> list[dict]:
    """The rows of ``rbi bench --format csv`` of ``result``."""
    return Report(result).csv_rows()


def _kernel(chapter=3.0, default=0.001, minimal=0.0009, best=0.0004):
    return {
        "case": {"spec": "bodies/top_bolted.yaml", "duration": 4.0},
        "chapter": {"seconds": chapter, "orientation_error_deg": 1e-3},
        "default": {"seconds": default, "orientation_error_deg": 1e-7, "steps": 2000},
        "minimal_loop": {"seconds": minimal, "same_steps": True, "same_samples": True},
        "best_matching": {"rtol": 1e-9, "seconds": best, "orientation_error_deg": 5e-4},
        "ratio_default": chapter / default,
        "ratio_best_matching": chapter / best,
        "ratio_to_minimal_loop": default / minimal,
        "targets": {"ratio_default": 3000.0, "ratio_best_matching": 6000.0, "ratio_to_minimal_loop": 1.3},
    }


def test_kernel_targets_and_verdicts():
    rows = targets({"kernel": _kernel()})
    assert [r["met"] for r in rows] == [True, True, True]
    assert rows[0]["measured"] == 3000.0 and rows[0]["comparison"] == "≥"
    assert rows[2]["measured"] == 0.001 / 0.0009 and rows[2]["comparison"] == "≤"
    slow = targets({"kernel": _kernel(default=0.002, best=0.0006)})
    assert [r["met"] for r in slow] == [False, False, False]
    assert all(len(row) == 7 for row in target_rows(slow))


def test_missing_measurement_is_not_a_pass():
    rows = targets({"largespec": {"target": 0.5, "specs": [{"n_parts": 10, "shape": "point", "error": "x"}]}})
    assert rows[0]["met"] is None and rows[0]["measured"] is None


def test_largespec_uses_the_measured_ratio():
    rows = targets(
        {
            "largespec": {
                "target": 0.5,
                "specs": [
                    {"n_parts": 100000, "shape": "point", "ratio": 0.4},
                    {"n_parts": 10000, "shape": "cylinder", "ratio": 0.7},
                ],
            }
        }
    )
    assert [r["met"] for r in rows] == [True, False]
    assert "100,000 × point" in rows[0]["target"]


def test_start_up_targets_per_file_in_ms_and_whole_process_as_a_ratio():
    lat = {
        "baseline": 'python -c "import numpy"',
        "commands": [
            {"command": 'python -c "import numpy"', "median_s": 0.1, "repeats": 3},
            {
                "command": "rbi inertia bodies/top.yaml",
                "median_s": 0.24,
                "ratio_to_numpy_import": 2.4,
                "target": 2.5,
                "repeats": 3,
            },
        ],
        "per_file": {
            "files": 120,
            "one_file_median_s": 0.24,
            "many_files_median_s": 0.714,
            "per_file_ms": 4.0,
            "target_ms": 5.0,
        },
    }
    per_file, inertia = targets({"latency": lat})
    assert per_file["met"] is True and per_file["measured"] == 4.0 and per_file["comparison"] == "≤"
    assert inertia["met"] is True and inertia["measured"] == 2.4
    shown = target_rows([per_file, inertia])
    assert shown[0][2:4] == ["4", "≤ 5"] and shown[1][2:4] == ["2.4×", "≤ 2.5×"]
    lat["per_file"] = {"error": "exit 2: x", "target_ms": 5.0}
    assert targets({"latency": lat})[0]["met"] is None


def test_import_breakdown_rows_are_sorted_with_shares_and_a_total():
    from rbi.bench.report import report_sections

    imports = {"command": "rbi inertia x.yaml", "modules": 400, "repeats": 5, "total_ms": 200.0}
    imports["groups_ms"] = {"numpy": 80.0, "pydantic": 100.0, "rich (tables)": 20.0}
    lat = {"baseline": 'python -c "import numpy"', "commands": [], "imports": imports}
    section = report_sections({"latency": lat})[-1]
    assert section.title == "Where `rbi inertia`'s start-up goes"
    assert section.rows == [
        ["pydantic", "100", "50%"],
        ["numpy", "80", "40%"],
        ["rich (tables)", "20", "10%"],
        ["all imports", "200", "100%"],
    ]


def test_sample_runs_spread_over_the_grid():
    g = {"spin": (150.0, 260.0, 100), "tilt": (0.01, 1.0, 100), "duration": 4.0}
    picks = sweep.sample_runs(g, 10)
    assert len(picks) == 10
    assert picks[0] == (150.0, 0.01) and picks[-1] == (260.0, 1.0)
    assert len(set(picks)) == 10


def test_headline_quotes_the_kernel_measurement_the_targets_table_shows():
    from rbi.bench.report import headline

    kernel = _kernel(chapter=4.5, default=0.00188, best=0.000957)
    kernel["chapter"]["omega_error"], kernel["default"]["omega_error"] = 6e-4, 4e-8
    other_timing = {
        "ratio_default": 3197.0,
        "default_seconds": 0.00127,
        "chapter_seconds": 4.05,
        "chapter_orientation_error_deg": 1e-3,
        "default_orientation_error_deg": 1e-7,
        "default_no_worse": True,
    }
    case = {"name": "bolted top", "spec": "bodies/top_bolted.yaml", "duration": 4.0, "speedup": other_timing}
    line = headline({"kernel": kernel, "workprecision": {"cases": [case]}})[0]
    shown = target_rows(targets({"kernel": kernel}))[0][2]
    assert shown == "2,394×" and f"are {shown} faster" in line and "0.00188 s against 4.5 s" in line
    assert "(rtol 1e-09) is 4,702× faster" in line
    assert "3,197" not in headline({"kernel": kernel, "workprecision": {"cases": [case]}})[0]


def test_robot_audit_target_is_shown_in_seconds_not_as_a_ratio():
    """The robot-audit row is an absolute time: '3.21 s' against '≤ 5 s' (it printed '3.21×')."""
    measured = {
        "target_s": 5.0,
        "links": 10**5,
        "megabytes": 48.5,
        "seconds": 3.21,
        "links_per_second": 31152.6,
    }
    (row,) = targets({"robotaudit": measured})
    assert row["met"] is True and row["unit"] == "s"
    shown = target_rows([row])[0]
    assert shown[2:5] == ["3.21 s", "≤ 5 s", "yes"] and "×" not in "".join(shown)
    slow = target_rows(
        targets({"robotaudit": dict(measured, seconds=12.5, cpu_seconds=3.9, load_average=6.1)})
    )[0]
    assert slow[2:5] == ["12.5 s", "≤ 5 s", "NO"] and slow[6].endswith("; CPU 3.9 s at load 6.1")


def test_csv_without_work_precision_is_the_targets():
    """`rbi bench --only uncertainty --format csv` printed nothing: its CSV rows are its targets."""
    rows = targets({"robotaudit": {"target_s": 5.0, "links": 10**5, "error": "ValueError: x"}})
    assert csv_rows({"robotaudit": {}, "targets": rows}) == rows and rows[0]["area"] == "robot audit"
    run = {"method": "default", "rtol": 1e-8, "chapter_setup": False, "seconds": 0.001}
    case = {"name": "top", "runs": [run], "default": run | {"default_settings": True}}
    assert [r["case"] for r in csv_rows({"workprecision": {"cases": [case]}, "targets": rows})] == [
        "top",
        "top",
    ]
    # neither (`--only cad`): the section's records, every row with every column; failed, its error
    files = [{"file": "STEP", "seconds": 1.5, "integration_error": 1e-13}, {"file": "STL", "seconds": 0.1}]
    assert csv_rows({"machine": {"cores": 2}, "cad": {"holes": 200, "files": files}, "targets": []}) == [
        {"section": "cad", "table": "files", "file": "STEP", "seconds": 1.5, "integration_error": 1e-13},
        {"section": "cad", "table": "files", "file": "STL", "seconds": 0.1, "integration_error": None},
    ]
    assert csv_rows({"cad": {"error": "no STEP reader"}, "targets": []}) == [
        {"section": "cad", "error": "no STEP reader"}
    ]


def test_csv_carries_the_rows_of_every_selected_section():
    """`rbi bench --only throughput,latency --format csv` printed latency's targets alone: the
    throughput records are there too, in the order the sections ran, each row every column."""
    lat = {"baseline": "numpy", "commands": [{"command": "numpy", "median_s": 0.1}], "per_file": {}}
    lat["commands"].append({"command": "rbi --help", "median_s": 0.1, "repeats": 3, "target": 1.3})
    lat["commands"][1]["ratio_to_numpy_import"] = 1.0
    clouds = [{"points": 1000, "total_s": 0.001}]
    result = {"throughput": {"point_clouds": clouds, "csv_format": "%.10g"}, "latency": lat}
    result["targets"] = targets(result)
    rows = csv_rows(result)
    assert [(r["section"], r["area"]) for r in rows] == [("throughput", None), (None, "start-up")]
    assert rows[0]["points"] == 1000 and rows[1]["measured"] == 1.0 and rows[1]["points"] is None
    assert rows[1]["target"] == result["targets"][0]["target"] and set(rows[0]) == set(rows[1])


def test_terminal_tables_show_cells_as_written():
    """`rbi bench`'s tables read no cell as rich markup: a command or its error holding [brackets]
    is printed as written (`rbi [bold]x` printed as `rbi x`, in bold)."""
    import io

    from rich.console import Console

    from rbi.cli.bench_command import _tables

    machine = {
        "date": "d",
        "cpu": "c",
        "cores": 2,
        "platform": "p",
        "python": "3",
        "numpy": "2",
        "scipy": "1",
    }
    failed = {"command": "rbi [bold]x", "error": "exit 2: rbi: error: [Errno 2] [red]no file"}
    lat = {"baseline": "numpy", "commands": [failed]}
    text = io.StringIO()
    Console(file=text, width=200, color_system=None).print(
        _tables({"machine": machine, "quick": True, "latency": lat})
    )
    assert "rbi [bold]x" in text.getvalue() and "[Errno 2] [red]no file" in text.getvalue()
