"""The report of ``rbi bench``: the targets each measured against its baseline, the headline,
the rows of every table, Markdown for docs/performance.md and CSV rows for spreadsheets (the
CLI draws the same rows as terminal tables). The measurements themselves come from the other
modules of :mod:`rbi.bench`."""

from __future__ import annotations

from rbi.text import number

METHOD_NAMES = {
    "default": "rbi",
    "rk45": "scipy RK45",
    "dop853": "scipy DOP853",
}
METHOD_NOTE = (
    "rbi: the default method (compiled DOP853, unit-quaternion projection); scipy: solve_ivp's "
    "solver with a Python right-hand side, atol = rtol/100; ★: the chapter's set-up (RK45, rtol 1e-8, "
    'atol 1e-10); "rbi defaults": `rbi simulate` with no options.'
)


def _sci(value: float | None, digits: int = 2) -> str:
    return "—" if value is None else number(value, digits)


def _times(value: float | None) -> str:
    """A ratio such as ``1,830×``."""
    if value is None:
        return "—"
    return f"{value:,.0f}×" if value >= 100 else f"{value:.3g}×"


# --- targets (kernel, start-up, large specs, sweep) ------------------------------------------------------------


def _target(
    area: str,
    what: str,
    measured: float | None,
    limit: float,
    at_least: bool,
    baseline: str,
    detail: str = "",
    unit: str | None = None,
) -> dict:
    """One target row; ``unit`` names the unit of ``measured`` and ``limit`` when they are a
    quantity shown with it (``"s"``), None for a ratio or a unit the target's words end in."""
    met = None if measured is None else (measured >= limit if at_least else measured <= limit)
    return {
        "area": area,
        "target": what,
        "measured": measured,
        "limit": limit,
        "unit": unit,
        "comparison": "≥" if at_least else "≤",
        "baseline": baseline,
        "met": met,
        "detail": detail,
    }


def targets(result: dict) -> list[dict]:
    """Every speed target (kernel, start-up, large specs, sweep) that this run measured: the ratio, its limit and the
    baseline it was measured against (in the same run)."""
    out = []
    for section, section_targets in SECTION_TARGETS.items():
        if result.get(section):
            out += section_targets(result[section])
    return out


def _kernel_targets(k: dict) -> list[dict]:
    """The compiled kernel against the chapter's set-up and against a minimal loop."""
    out = []
    if k:
        chapter = (
            f"the chapter's set-up (scipy RK45, rtol 1e-8, Python RHS): {number(k['chapter']['seconds'], 3)} s, "
            f"error {_sci(k['chapter']['orientation_error_deg'])}°"
        )
        out.append(
            _target(
                "kernel",
                f"in-process simulate at defaults ({k['case']['spec']}, {k['case']['duration']:g} s) "
                "÷ the chapter's set-up, speed-up",
                k["ratio_default"],
                k["targets"]["ratio_default"],
                True,
                chapter,
                f"rbi {number(k['default']['seconds'], 3)} s, error "
                f"{_sci(k['default']['orientation_error_deg'])}°",
            )
        )
        best = k.get("best_matching")
        out.append(
            _target(
                "kernel",
                "the same at equal-or-better error, speed-up",
                k.get("ratio_best_matching"),
                k["targets"]["ratio_best_matching"],
                True,
                chapter,
                "no rbi tolerance reached the chapter's error"
                if not best
                else f"rbi at rtol {best['rtol']:g}: {number(best['seconds'], 3)} s, error "
                f"{_sci(best['orientation_error_deg'])}°",
            )
        )
        m = k["minimal_loop"]
        same = (
            "same steps and samples"
            if m["same_steps"] and m["same_samples"]
            else "DIFFERENT steps or samples"
        )
        out.append(
            _target(
                "kernel",
                "in-process simulate at defaults ÷ a minimal loop with the same DOP853 steps, time",
                k["ratio_to_minimal_loop"],
                k["targets"]["ratio_to_minimal_loop"],
                False,
                f"rbi.sim._dop853.integrate_minimal: {number(m['seconds'], 3)} s ({same})",
                f"simulate {number(k['default']['seconds'], 3)} s, {k['default']['steps']:,} steps",
            )
        )
    return out


def _latency_targets(lat: dict) -> list[dict]:
    """Start-up: the first run in a fresh HOME, each additional file, each command as a whole process."""
    out = []
    if lat:
        first = lat.get("first_run") or {}
        if "ratio" in first:
            out.append(
                _target(
                    "start-up",
                    f"first `{first['command']}` in a fresh HOME ÷ a later one, time",
                    first["ratio"],
                    first["target"],
                    False,
                    f"the run after it: {number(first['later_median_s'], 3)} s",
                    f"first {number(first['first_median_s'], 3)} s; median of {first['repeats']} fresh "
                    f"HOMEs; files left in HOME: {len(first['files_left_in_home'])}",
                )
            )
        elif "error" in first:
            out.append(
                _target(
                    "start-up",
                    "first rbi simulate in a fresh HOME ÷ a later one",
                    None,
                    1.3,
                    False,
                    "",
                    first["error"],
                )
            )
        per_file = lat.get("per_file") or {}
        if per_file:
            out.append(
                _target(
                    "start-up",
                    "each additional file in one `rbi inertia` process (the bundled bodies), ms",
                    per_file.get("per_file_ms"),
                    per_file["target_ms"],
                    False,
                    f"one file: {number(per_file['one_file_median_s'], 3)} s" if "files" in per_file else "",
                    per_file.get("error")
                    or f"{per_file['files']} files: {number(per_file['many_files_median_s'], 3)} s",
                )
            )
        for row in lat["commands"]:
            if "target" in row:
                out.append(
                    _target(
                        "start-up",
                        f"`{row['command']}` as a whole process, {_clock(row)} time",
                        _ratio(row),
                        row["target"],
                        False,
                        f"{lat['baseline']}: {number(_seconds(lat['commands'][0]), 3)} s"
                        if "median_s" in lat["commands"][0]
                        else lat["baseline"],
                        row.get("error") or f"{number(_seconds(row), 3)} s median of {row['repeats']}",
                    )
                )
    return out


def _largespec_targets(ls: dict) -> list[dict]:
    """Loading large specs against a bare yaml.load."""
    out = []
    if ls:
        for row in ls.get("specs", []) or [{"error": ls.get("error")}]:
            ratio = row.get("ratio")
            label = (
                f"{row.get('n_parts', 0):,} × {row.get('shape', '?')}" if "n_parts" in row else "large specs"
            )
            base = row.get("bare_s")
            detail = row.get("error") or ""
            if "rbi_load_s" in row:
                detail = (
                    f"rbi {number(row['rbi_load_s'], 3)} s (read {number(row['rbi_read_s'], 3)}, validate "
                    f"{number(row['rbi_validate_s'], 3)}, translate {number(row['rbi_translate_s'], 3)}); "
                    f"{number(row['yaml_megabytes'], 3)} MB"
                )
            out.append(
                _target(
                    "large specs",
                    f"whole load of a YAML spec of {label} ÷ a bare yaml.load (CSafeLoader), time",
                    ratio,
                    ls["target"],
                    False,
                    "bare yaml.load(f, Loader=yaml.CSafeLoader) in a plain Python"
                    + (f": {number(base, 3)} s" if isinstance(base, float) else ""),
                    detail,
                )
            )
    return out


def _sweep_targets(sw: dict) -> list[dict]:
    """Sweep throughput against single runs and process loops, and its peak memory."""
    out = []
    if sw:
        single, loop, sweep = sw["single_run"], sw["process_loop"], sw["sweep"]
        out.append(
            _target(
                "sweep",
                f"`rbi sweep` throughput over {sweep['runs']:,} runs ÷ (cores × single-run rate)",
                sw["ratio_to_cores_x_single"],
                sw["targets"]["ratio_to_cores_x_single"],
                True,
                f"{sw['cores']} cores × {number(single['runs_per_second'], 3)} runs/s (simulate, one run "
                f"after another, {single['runs']} grid points)",
                f"sweep {number(sweep['runs_per_second'], 3)} runs/s ({number(sweep['seconds'], 3)} s; "
                f"CPU time ÷ wall time {number(sweep.get('cores_used', float('nan')), 3)})",
            )
        )
        out.append(
            _target(
                "sweep",
                "`rbi sweep` throughput ÷ a loop of `rbi simulate` processes",
                sw["ratio_to_process_loop"],
                sw["targets"]["ratio_to_process_loop"],
                True,
                f"{loop['runs']} processes: {number(loop['runs_per_second'], 3)} runs/s",
                f"sweep {number(sweep['runs_per_second'], 3)} runs/s",
            )
        )
        mem = sw["memory"]
        out.append(
            _target(
                "sweep",
                f"peak resident memory of a streaming sweep of {mem.get('runs', 0):,} runs, MB",
                mem.get("peak_rss_mb"),
                sw["targets"]["peak_rss_mb"],
                False,
                "500 MB (absolute)",
                mem.get("error")
                or f"RSS {number(mem['rss_first_quarter_mb'], 3)} MB in the first quarter, "
                f"{number(mem['rss_last_quarter_mb'], 3)} MB in the last ({mem['rows_written']:,} rows)",
            )
        )
    return out


def _robotaudit_targets(ra: dict) -> list[dict]:
    """The audit of a large generated URDF against its absolute time target."""
    if not ra:
        return []
    quick = ra.get("links", 0) < 10**5
    detail = ra.get("error") or (
        f"{number(ra['megabytes'], 3)} MB, {number(ra['links_per_second'], 3)} links/s"
        + ("; a quick run: the target is for 100,000 links" if quick else "")
    )
    return [
        _target(
            "robot audit",
            f"`rbi audit` of a URDF of {ra.get('links', 0):,} links (inertial, box collision, revolute joints), wall time",
            ra.get("seconds"),
            ra["target_s"],
            False,
            "5 s (absolute)",
            detail,
            unit="s",
        )
    ]


SECTION_TARGETS = {
    "kernel": _kernel_targets,
    "latency": _latency_targets,
    "largespec": _largespec_targets,
    "sweep": _sweep_targets,
    "robotaudit": _robotaudit_targets,
}
"""Each section of a bench result that has speed targets, and the function that lists them."""


TARGET_COLUMNS = ["area", "target", "measured", "limit", "met", "baseline (same run)", "detail"]


def target_rows(rows: list[dict]) -> list[list[str]]:
    def value(x):
        return "—" if x is None else (_times(x) if not isinstance(x, float) or x >= 0 else number(x, 3))

    out = []
    for r in rows:
        measured, unit = r["measured"], r.get("unit")
        absolute = unit is not None or r["target"].endswith(("MB", "ms"))  # a quantity, not a ratio
        suffix = f" {unit}" if unit else ""
        shown = "—" if measured is None else (number(measured, 3) + suffix if absolute else _times(measured))
        limit = number(r["limit"], 3) + suffix if absolute else _times(r["limit"])
        met = {True: "yes", False: "NO", None: "—"}[r["met"]]
        out.append(
            [
                str(r["area"]),
                r["target"],
                shown,
                f"{r['comparison']} {limit}",
                met,
                r["baseline"],
                r["detail"],
            ]
        )
    return out


# --- headline --------------------------------------------------------------------------------


def headline(result: dict) -> list[str]:
    """The few sentences a reader needs: speed-ups at equal or better error, throughput, latency."""
    lines = []
    for case in result.get("workprecision", {}).get("cases", []):
        s = _kernel_speedup(result.get("kernel"), case) or case.get("speedup")
        if not s:
            continue
        verdict = "better" if s["default_no_worse"] else "WORSE"
        line = (
            f"{case['name']} ({case['spec']}, {case['duration']:g} s): rbi's defaults are "
            f"{_times(s['ratio_default'])} faster in-process than the chapter's set-up "
            f"({number(s['default_seconds'], 3)} s against {number(s['chapter_seconds'], 3)} s), with a {verdict} "
            f"final orientation error ({_sci(s['default_orientation_error_deg'])}° against "
            f"{_sci(s['chapter_orientation_error_deg'])}°)"
        )
        if "ratio_best_matching" in s:
            line += (
                f"; at equal or better error the fastest rbi run (rtol {s['best_matching_rtol']:g}) is "
                f"{_times(s['ratio_best_matching'])} faster"
            )
        lines.append(line + ".")
    tp = result.get("throughput")
    if tp and tp["point_clouds"]:
        big = tp["point_clouds"][-1]
        lines.append(
            f"{big['points']:,} point masses: mass, centre of mass, inertia and principal axes in "
            f"{number(big['total_s'], 3)} s from arrays ({number(big['ns_per_point'], 3)} ns per point; time grows as "
            f"size^{number(tp['scaling_exponent'], 3)}), {number(big['load_csv_s'], 3)} s including reading the spec "
            f"and a {number(big['csv_megabytes'], 3)} MB CSV cloud, {number(big['load_npy_s'], 3)} s from .npy."
        )
    if tp and tp["solid_parts"]:
        big = tp["solid_parts"][-1]
        lines.append(
            f"A YAML spec of {big['parts']:,} parts ({number(big['yaml_megabytes'], 3)} MB) takes "
            f"{number(big['load_total_s'], 3)} s to load ({number(big['us_per_part'], 3)} µs per part; "
            f"{_share(big, 'read_yaml_s')} of it parsing YAML); written as JSON (also valid YAML) it loads in "
            f"{number(big['load_total_json_s'], 3)} s. For many point masses, a point cloud file is faster still."
        )
    lat = result.get("latency")
    if lat:
        for row in lat["commands"][1:]:
            if (
                "target" in row
                and "ratio_to_numpy_import" in row
                and row["command"].startswith(("rbi inertia", "rbi simulate"))
            ):
                lines.append(
                    f"`{row['command']}` as a whole process: {_times(_ratio(row))} the {_clock(row)} time of "
                    f"`{lat['baseline']}` ({number(_seconds(row), 3)} s median)."
                )
        per_file = lat.get("per_file") or {}
        if "per_file_ms" in per_file:
            lines.append(
                f"Each further file in the same `rbi inertia` process: {number(per_file['per_file_ms'], 3)} ms "
                f"({per_file['files']} files in {number(per_file['many_files_median_s'], 3)} s), against "
                f"{number(per_file['one_file_median_s'], 3)} s for a process of its own."
            )
    return lines


def _kernel_speedup(k: dict | None, case: dict) -> dict | None:
    """The kernel section's measurement of ``case``'s body, in the form of the work-precision
    speed-up, so that the headline quotes the numbers the Targets table and the kernel table
    show (the work-precision sweep times the same runs again, with other repeats)."""
    if not k or k["case"]["spec"] != case["spec"] or k["case"]["duration"] != case["duration"]:
        return None
    chapter, default, best = k["chapter"], k["default"], k.get("best_matching")
    out = {
        "chapter_seconds": chapter["seconds"],
        "default_seconds": default["seconds"],
        "chapter_orientation_error_deg": chapter["orientation_error_deg"],
        "default_orientation_error_deg": default["orientation_error_deg"],
        "default_no_worse": (
            default["orientation_error_deg"] <= chapter["orientation_error_deg"]
            and default["omega_error"] <= chapter["omega_error"]
        ),
        "ratio_default": k["ratio_default"],
    }
    if best:
        out.update(best_matching_rtol=best["rtol"], ratio_best_matching=k["ratio_best_matching"])
    return out


def _share(row: dict, key: str) -> str:
    return f"{100 * row[key] / row['load_total_s']:.0f}%"


def sections(result: dict) -> list[dict]:
    """The report as a list of blocks for a terminal, in the order of docs/performance.md: each
    ``{"title", "columns": [(header, justify, no_wrap)], "rows"}`` (header a string or a
    ``(quantity, unit)`` pair) or ``{"text", "dim"}``."""

    def block(title, columns, rows, justify=lambda header: "right", no_wrap=lambda header: False):
        return {"title": title, "columns": [(h, justify(h), no_wrap(h)) for h in columns], "rows": rows}

    out = [{"text": machine_line(result), "dim": True}]
    if result.get("targets"):
        out.append(
            block(
                "Targets, each against its baseline measured in this run",
                TARGET_COLUMNS,
                target_rows(result["targets"]),
                lambda h: "right" if h in ("measured", "limit") else "left",
                lambda h: h in ("measured", "limit", "met"),
            )
        )
    for case in result.get("workprecision", {}).get("cases", []):
        justify = dict(WORK_COLUMNS)
        out.append(
            block(
                f"Work-precision: {case['name']} ({case['spec']}, ω₀ = {vector_text(case['omega0'])} rad/s, "
                f"{case['duration']:g} s) — reference: {reference_text(case)}",
                list(justify),
                work_rows(case),
                justify.get,
                lambda h: h == "method",
            )
        )
    if result.get("workprecision"):
        out.append({"text": METHOD_NOTE, "dim": True})
    tp = result.get("throughput")
    if tp:
        out.append(
            block(
                f"Mass properties of point clouds (time grows as size^{number(tp['scaling_exponent'], 3)})",
                CLOUD_COLUMNS,
                cloud_rows(tp),
            )
        )
        out.append(block("Specs of many solid parts, written in YAML", PARTS_COLUMNS, parts_rows(tp)))
    lat = result.get("latency")
    if lat:
        out.append(
            block(
                f"Whole-process latency (median of repeated runs) against {lat['baseline']}",
                LATENCY_COLUMNS,
                latency_rows(lat),
                lambda h: "left" if h == "command" else "right",
            )
        )
    cad = result.get("cad")
    if cad:
        out.append(block(cad_title(cad), CAD_COLUMNS, cad_rows(cad)))
    lines = headline(result)
    if lines:
        out.append({"text": "\n".join("• " + line for line in lines), "dim": False})
    return out


CAD_COLUMNS = ["file", "triangles", "MB", "load [s]", "volume err", "CoM err", "inertia err", "estimate"]
"""Errors are relative to the closed form; the estimate is the integration's own (STEP only)."""


def cad_title(cad: dict) -> str:
    if cad.get("error"):
        return f"CAD solids: {cad['error']}"
    a, b, c = cad["plate_mm"]
    return (
        f"CAD solids: a {a:g} × {b:g} × {c:g} mm plate with {cad['holes']} holes of radius "
        f"{cad['hole_radius_mm']:g} mm, read as STEP (exact geometry) and as STL, whole load cold; "
        "errors relative, against the closed form"
    )


def cad_rows(cad: dict) -> list[list[str]]:
    """One row per file: the STEP (exact B-rep) and its STL tessellation."""
    return [
        [
            row["file"],
            "—" if row.get("triangles") is None else f"{row['triangles']:,}",
            number(row["bytes"] / 1e6, 3),
            number(row["seconds"], 3),
            _sci(row["volume_error"]),
            _sci(row["com_error"]),
            _sci(row["inertia_error"]),
            _sci(row.get("integration_error")),
        ]
        for row in cad.get("files", [])
    ]


def vector_text(v) -> str:
    return "(" + ", ".join(number(x, 6) for x in v) + ")"


def machine_line(result: dict) -> str:
    m = result["machine"]
    load = m.get("load_average_1min")
    return (
        f"{m['date']} · {m['cpu']} · {m['cores']} cores · load average {load} at start · Python {m['python']}, "
        f"numpy {m['numpy']}, scipy {m['scipy']}, kernel: {m.get('kernel')} · {'quick' if result['quick'] else 'full'} run"
    )


def reference_text(case: dict) -> str:
    ref = case["reference"]
    if ref["method"] == "exact":
        return "closed form (Euler–Poinsot)"
    check = ref.get("check", {})
    return (
        f"rbi at rtol {ref['rtol']:g}; scipy DOP853 at rtol {check.get('rtol', 0):g} differs from it by "
        f"{_sci(check.get('orientation_difference_deg'))}°"
    )


WORK_COLUMNS = [
    ("method", "left"),
    ("rtol", "right"),
    (("orient. error", "deg"), "right"),
    (("ω error", "rad/s"), "right"),
    ("rel. drift", "right"),
    ("steps", "right"),
    ("RHS evals", "right"),
    (("time", "s"), "right"),
    ("chapter ÷ this", "right"),
]


def work_rows(case: dict) -> list[list[str]]:
    chapter = next((r for r in case["runs"] if r["chapter_setup"]), None)
    rows = []
    for r in case["runs"] + [case["default"]]:
        name = METHOD_NAMES[r["method"]]
        if r.get("chapter_setup"):
            name += " ★"
        if r.get("default_settings"):
            name = "rbi defaults"
        ratio = chapter["seconds"] / r["seconds"] if chapter and r["seconds"] > 0 else None
        rows.append(
            [
                name,
                f"{r['rtol']:g}",
                _sci(r["orientation_error_deg"]),
                _sci(r["omega_error"]),
                _sci(r["drift"]),
                f"{r['steps']:,}",
                f"{r['rhs_evals']:,}",
                number(r["seconds"], 2),
                _times(ratio),
            ]
        )
    return rows


CLOUD_COLUMNS = [
    "points",
    "mass [ms]",
    "CoM [ms]",
    "+inertia [ms]",
    "principal [ms]",
    "total [ms]",
    "ns/point",
    "CSV spec [ms]",
    ".npy spec [ms]",
    "CSV [MB]",
]


def cloud_rows(tp: dict) -> list[list[str]]:
    def ms(seconds):
        return number(1e3 * seconds, 3)

    return [
        [
            f"{r['points']:,}",
            ms(r["mass_s"]),
            ms(r["com_s"]),
            ms(r["combine_s"]),
            ms(r["principal_s"]),
            ms(r["total_s"]),
            number(r["ns_per_point"], 3),
            ms(r["load_csv_s"]),
            ms(r["load_npy_s"]),
            number(r["csv_megabytes"], 3),
        ]
        for r in tp["point_clouds"]
    ]


PARTS_COLUMNS = [
    "parts",
    "YAML [MB]",
    "parse YAML [s]",
    "validate [s]",
    "translate [s]",
    "load total [s]",
    "µs/part",
    "same as JSON [s]",
    "core [s]",
]


def parts_rows(tp: dict) -> list[list[str]]:
    return [
        [
            f"{r['parts']:,}",
            number(r["yaml_megabytes"], 3),
            number(r["read_yaml_s"], 3),
            number(r["validate_s"], 3),
            number(r["translate_s"], 3),
            number(r["load_total_s"], 3),
            number(r["us_per_part"], 3),
            number(r["load_total_json_s"], 3),
            _sci(r["core_s"]),
        ]
        for r in tp["solid_parts"]
    ]


LATENCY_COLUMNS = [
    "command",
    "CPU median [s]",
    "× numpy import (CPU)",
    "wall median [s]",
    "wall best [s]",
    "× numpy import (wall)",
    "wall spread",
]


def latency_rows(lat: dict) -> list[list[str]]:
    rows = []
    for r in lat["commands"]:
        if "error" in r:
            rows.append([r["command"], "failed", "", "", "", "", r["error"]])
        else:
            rows.append(
                [
                    r["command"],
                    number(r["cpu_median_s"], 3) if "cpu_median_s" in r else "",
                    _times(r.get("cpu_ratio_to_numpy_import")),
                    number(r["median_s"], 3),
                    number(r["best_s"], 3),
                    _times(r.get("ratio_to_numpy_import")),
                    f"{100 * r['spread']:.0f}%",
                ]
            )
    return rows


def _clock(row: dict) -> str:
    """Which time a latency row's target is judged on: CPU when it was measured, else wall."""
    return "CPU" if "cpu_ratio_to_numpy_import" in row else "wall"


def _ratio(row: dict) -> float | None:
    return row.get("cpu_ratio_to_numpy_import", row.get("ratio_to_numpy_import"))


def _seconds(row: dict) -> float | None:
    return row.get("cpu_median_s", row.get("median_s"))


# --- Markdown --------------------------------------------------------------------------------


def _md_table(headers: list[str], rows: list[list[str]]) -> str:
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
    out += ["| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |" for row in rows]
    return "\n".join(out)


def markdown(result: dict, command: str, plot_link: str | None) -> str:
    """docs/performance.md: how it was made, on what, the headline, then every table."""
    out = _preamble(result, command)
    out += _kernel_markdown(result.get("kernel"))
    out += _sweep_markdown(result.get("sweep"))
    out += _workprecision_markdown(result.get("workprecision"), plot_link)
    out += _throughput_markdown(result.get("throughput"))
    out += _latency_markdown(result.get("latency"))
    out += _cad_markdown(result.get("cad"))
    return "\n".join(out) + "\n"


def _preamble(result: dict, command: str) -> list[str]:
    """How the page was made, on what machine, the headline and the targets."""
    m = result["machine"]
    noisy = (m.get("load_average_1min") or 0) > 0.5
    out = [
        "# Performance",
        "",
        "Generated by `rbi bench`; do not edit by hand. To regenerate, on a machine that is otherwise idle:",
        "",
        "```",
        command,
        "```",
        "",
        f"- Date: {m['date']}",
        f"- Machine: {m['cpu']}, {m['cores']} cores, {m['platform']}",
        f"- Software: Python {m['python']}, numpy {m['numpy']}, scipy {m['scipy']}, kernel: {m.get('kernel')}",
        f"- Load average (1 min) when the run started: {m.get('load_average_1min')}",
        f"- Run: {'quick (`--quick`, shortened cases)' if result['quick'] else 'full'}",
        "",
        (
            "> **Noise.** These numbers were measured on a shared machine while other work was running "
            "(see the load average), so single timings may be off by tens of percent. Ratios measured in "
            'the same run (rbi against the chapter\'s set-up, commands against `python -c "import numpy"`) '
            "are more trustworthy than the seconds. Re-run the command above on a quiet machine for "
            "publishable numbers."
        )
        if noisy
        else (
            "> Timings are wall-clock; ratios measured in the same run are more trustworthy than the "
            "seconds themselves."
        ),
        "",
        "## Headline",
        "",
    ]
    out += [f"- {line}" for line in headline(result)]
    if result.get("targets"):
        out += [
            "",
            "## Targets",
            "",
            "Each speed target (kernel, start-up, large specs, sweep) with the baseline it was measured "
            "against in this same run.",
            "",
            _md_table(TARGET_COLUMNS, target_rows(result["targets"])),
        ]
    return out


def _cad_markdown(cad: dict | None) -> list[str]:
    """CAD solids: the STEP plate against its STL, time and error side by side."""
    if not cad:
        return []
    return [
        "",
        "## CAD solids: STEP against STL",
        "",
        cad_title(cad) + ".",
        "",
        _md_table(CAD_COLUMNS, cad_rows(cad)),
    ]


def _workprecision_markdown(wp: dict | None, plot_link: str | None) -> list[str]:
    """Work against precision: each case's error and time per method."""
    out: list[str] = []
    if wp:
        out += [
            "",
            "## Work against precision",
            "",
            "Final orientation error (angle between the computed and the reference orientation at the "
            "last sample) and angular-velocity error against in-process time (one whole call of "
            "`rbi.sim.api.simulate`, with the compiled kernel already loaded; the median of repeated runs "
            'for the fast method). "rel. drift" is the largest relative '
            "change of any conserved quantity along the run (energy, vertical and spin angular momentum for "
            "the top; energy and the angular-momentum vector for the free body). The chapter's set-up is "
            "scipy `solve_ivp` RK45 at rtol 1e-8, atol 1e-10 with a Python right-hand side "
            "(`--method rk45`); the last column is its time divided by each row's. " + METHOD_NOTE,
        ]
        for case in wp["cases"]:
            out += [
                "",
                f"### {case['name']}: `{case['spec']}`, ω₀ = {vector_text(case['omega0'])} rad/s, "
                f"tilt {case['tilt_deg']:g}°, {case['duration']:g} s, {case['samples']} samples",
                "",
                f"Reference: {reference_text(case)}. Loading the compiled kernel cost "
                f"{number(case['kernel_load_seconds'], 3)} s once in this process (not in any time below).",
                "",
            ]
            headers = [h if isinstance(h, str) else f"{h[0]} [{h[1]}]" for h, _ in WORK_COLUMNS]
            out.append(_md_table(headers, work_rows(case)))
        if plot_link:
            out += ["", f"![Final orientation error against in-process time]({plot_link})"]
    return out


def _throughput_markdown(tp: dict | None) -> list[str]:
    """Mass-property throughput: point clouds and specs of many solid parts."""
    out: list[str] = []
    if tp:
        out += [
            "",
            "## Mass-property throughput",
            "",
            'Random point masses (seeded). "mass+CoM+inertia" is `rbi.core.mass.combine` on arrays in memory; '
            '"total" adds the principal axes. "from … spec" is the whole load of a spec file naming the cloud '
            f"(`point_cloud: {{file: cloud.csv}}`: YAML, validation, reading the cloud, the reduction) plus the "
            f"principal axes, as `rbi principal` does after start-up; the CSV holds `{tp['csv_format']}` numbers. "
            f"Time grows as size^{number(tp['scaling_exponent'], 3)} from 10⁴ points up (1 = linear).",
            "",
            _md_table(CLOUD_COLUMNS, cloud_rows(tp)),
            "",
            "### Specs of many solid parts",
            "",
            "Cones, cylinders (by density) and point masses in turn, one YAML flow mapping per line. Parsing uses "
            "libyaml's C parser; validation is pydantic; translation builds one mass element per part in Python. "
            '"same as JSON" is the whole load of the same spec written as one JSON object (JSON is valid YAML; '
            "rbi reads it with Python's json module when the file starts with `{`). "
            '"core" is the vectorised reduction (mass, CoM, inertia, principal axes) of the translated parts.',
            "",
            _md_table(PARTS_COLUMNS, parts_rows(tp)),
        ]
    return out


def _latency_markdown(lat: dict | None) -> list[str]:
    """Whole-process latency of each command, and where the start-up goes."""
    out: list[str] = []
    if lat:
        out += [
            "",
            "## Whole-process latency",
            "",
            f"Each command ran once untimed (warm OS file caches), then repeatedly, in turn; the "
            f"medians of CPU time (user + system, which other work on the machine disturbs less; "
            f"the targets are on it) and of wall time are compared with `{lat['baseline']}` "
            f"measured in the same rounds"
            + (
                ", rbi's bytecode having been compiled first, as `pip install` does."
                if lat.get("bytecode_compiled")
                else "."
            ),
            "",
            _md_table(LATENCY_COLUMNS, latency_rows(lat)),
        ]
        out += _imports_markdown(lat.get("imports"))
    return out


IMPORT_COLUMNS = ["imported", "time [ms]", "share"]


def import_rows(imports: dict) -> list[list[str]]:
    total = imports["total_ms"]
    groups = sorted(imports["groups_ms"].items(), key=lambda item: -item[1])
    return [[name, number(ms, 3), f"{100 * ms / total:.0f}%"] for name, ms in groups] + [
        ["all imports", number(total, 3), "100%"]
    ]


def _imports_markdown(imports: dict | None) -> list[str]:
    if not imports or "error" in imports:
        return []
    return [
        "",
        "### Where `rbi inertia`'s start-up goes",
        "",
        f"`{imports['command']}`: the time each of the {imports['modules']} imported modules takes itself "
        f'(Python\'s "self" column, so a package counts once whoever imports it first), smallest of '
        f"{imports['repeats']} runs, summed by package. `-X importtime` adds its own overhead, so these add up "
        "to more than the import part of a plain run; the shares are what to compare. The rest of a run is "
        "the interpreter's own start-up and the work itself (reading and validating the spec, about a "
        "millisecond for a small one, then printing).",
        "",
        _md_table(IMPORT_COLUMNS, import_rows(imports)),
    ]


def _kernel_markdown(k: dict | None) -> list[str]:
    if not k:
        return []
    rows = [
        [
            f"{t['rtol']:g}",
            _sci(t["orientation_error_deg"]),
            _sci(t["omega_error"]),
            f"{t['steps']:,}",
            "yes" if t["no_worse"] else "no",
            "—" if t["seconds"] is None else number(t["seconds"], 3),
            "—" if t["seconds"] is None else _times(k["chapter"]["seconds"] / t["seconds"]),
        ]
        for t in k["trials"]
    ]
    return [
        "",
        "## The kernel against its baselines",
        "",
        f"`{k['case']['spec']}`, ω₀ = {vector_text(k['case']['omega0'])} rad/s, {k['case']['duration']:g} s, "
        f"{k['case']['samples']} samples, in this process with the compiled kernel loaded. The chapter's set-up "
        f"took {number(k['chapter']['seconds'], 3)} s ({k['chapter']['steps']:,} steps, final orientation error "
        f"{_sci(k['chapter']['orientation_error_deg'])}°); `simulate` at its defaults (rtol "
        f"{k['default']['rtol']:g}) {number(k['default']['seconds'], 3)} s; the minimal loop "
        f"(`rbi.sim._dop853.integrate_minimal`: the same DOP853 steps without chunking, step budget, counters "
        f"or the result object, called on prepared arrays) {number(k['minimal_loop']['seconds'], 3)} s with "
        f"{k['minimal_loop']['steps']:,} steps (same steps: {k['minimal_loop']['same_steps']}, same samples bit "
        f"for bit: {k['minimal_loop']['same_samples']}). Errors are against rbi at rtol 1e-14. The fastest "
        "tolerance at the chapter's error or better:",
        "",
        _md_table(
            [
                "rtol",
                "orient. error [deg]",
                "ω error [rad/s]",
                "steps",
                "no worse than chapter",
                "time [s]",
                "chapter ÷ this",
            ],
            rows,
        ),
    ]


def _sweep_markdown(sw: dict | None) -> list[str]:
    if not sw:
        return []
    g, mem = sw["grid"], sw["memory"]
    out = [
        "",
        "## Sweep throughput and memory",
        "",
        f"Grid: spin {g['spin'][0]:g}–{g['spin'][1]:g} rad/s × {g['spin'][2]}, tilt {g['tilt_deg'][0]:g}–"
        f"{g['tilt_deg'][1]:g}° × {g['tilt_deg'][2]}, {g['duration']:g} s a run, default rtol, on "
        f"{sw['cores']} cores: `{sw['sweep']['command']}` ran in this process in "
        f"{number(sw['sweep']['seconds'], 3)} s ({number(sw['sweep']['runs_per_second'], 3)} runs/s, "
        f"{_times(sw['ratio_to_single'])} the single-run rate). The single-run rate is `simulate` called "
        f"for {sw['single_run']['runs']} grid points one after another in this process; the process loop is "
        f"`rbi simulate FILE --spin S --tilt T --duration {g['duration']:g}` for "
        f"{sw['process_loop']['runs']} grid points.",
    ]
    if "error" in mem:
        return out + ["", f"Memory: the child sweep failed: {mem['error']}"]
    out += [
        "",
        f"Memory: `{mem['command']}` as a child process: peak resident memory "
        f"{number(mem['peak_rss_mb'], 3)} MB over {mem['rows_written']:,} rows streamed in "
        f"{number(mem['seconds'], 3)} s; resident memory sampled while it ran (flat means bounded):",
        "",
        _md_table(
            ["time [s]", "RSS [MB]", "CSV written [MB]"],
            [
                [number(s["seconds"], 3), number(s["rss_mb"], 3), number(s["csv_bytes"] / 2**20, 3)]
                for s in mem["samples"]
            ],
        ),
    ]
    return out


# --- CSV -------------------------------------------------------------------------------------


def csv_rows(result: dict) -> list[dict]:
    """One row per work-precision run (the table scripts most often want)."""
    rows = []
    for case in result.get("workprecision", {}).get("cases", []):
        for r in case["runs"] + [case["default"]]:
            rows.append(
                {
                    "case": case["name"],
                    "method": r["method"],
                    "rtol": r["rtol"],
                    "chapter_setup": r.get("chapter_setup", False),
                    "default_settings": r.get("default_settings", False),
                    "orientation_error_deg": r["orientation_error_deg"],
                    "omega_error": r["omega_error"],
                    "drift": r["drift"],
                    "steps": r["steps"],
                    "rhs_evals": r["rhs_evals"],
                    "seconds": r["seconds"],
                }
            )
    return rows
