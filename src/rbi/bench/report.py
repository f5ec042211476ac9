"""The report of ``rbi bench``: the targets each measured against its baseline, the headline,
the rows of every table, Markdown for docs/performance.md and CSV rows for spreadsheets (the
CLI draws the same rows as terminal tables). The measurements themselves come from the other
modules of :mod:`rbi.bench`."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import partial
from operator import itemgetter

from rbi.bench.workprecision import speedup
from rbi.reprs import Result
from rbi.text import number, vector_text

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


def _times(value: float | None) -> str:
    """A ratio such as ``1,830×``."""
    if value is None:
        return "—"
    return f"{value:,.0f}×" if value >= 100 else f"{value:.3g}×"


# --- targets (kernel, start-up, large specs, sweep) ------------------------------------------------------------


def _target(what: str, test: tuple, baseline: str, detail: str = "", unit: str | None = None) -> dict:
    """One target row; ``test`` is ``(measured, "≥" or "≤", limit)`` (measured None: not
    measured, neither met nor missed); ``unit`` names the unit of ``measured`` and ``limit`` when
    they are a quantity shown with it (``"s"``), None for a ratio or a unit the target's words end in."""
    measured, comparison, limit = test
    met = None if measured is None else (measured >= limit if comparison == "≥" else measured <= limit)
    return {
        "target": what,
        "measured": measured,
        "limit": limit,
        "unit": unit,
        "comparison": comparison,
        "baseline": baseline,
        "met": met,
        "detail": detail,
    }


def targets(result: dict) -> list[dict]:
    """Every speed target (kernel, start-up, large specs, sweep) that this run measured: the ratio, its limit and the
    baseline it was measured against (in the same run)."""
    out = []
    for section, (area, section_targets) in SECTION_TARGETS.items():
        if result.get(section):
            out += [{"area": area} | row for row in section_targets(result[section])]
    return out


def _kernel_targets(k: dict) -> list[dict]:
    """The compiled kernel against the chapter's set-up and against a minimal loop."""
    chapter = (
        f"the chapter's set-up (scipy RK45, rtol 1e-8, Python RHS): {number(k['chapter']['seconds'], 3)} s, "
        f"error {number(k['chapter']['orientation_error_deg'], 2)}°"
    )
    default, best, m, limit = k["default"], k.get("best_matching"), k["minimal_loop"], k["targets"]
    same = "same steps and samples" if m["same_steps"] and m["same_samples"] else "DIFFERENT steps or samples"
    case = f"({k['case']['spec']}, {k['case']['duration']:g} s)"
    return [
        _target(
            f"in-process simulate at defaults {case} ÷ the chapter's set-up, speed-up",
            (k["ratio_default"], "≥", limit["ratio_default"]),
            chapter,
            f"rbi {number(default['seconds'], 3)} s, error {number(default['orientation_error_deg'], 2)}°",
        ),
        _target(
            "the same at equal-or-better error, speed-up",
            (k.get("ratio_best_matching"), "≥", limit["ratio_best_matching"]),
            chapter,
            f"rbi at rtol {best['rtol']:g}: {number(best['seconds'], 3)} s, error "
            f"{number(best['orientation_error_deg'], 2)}°"
            if best
            else "no rbi tolerance reached the chapter's error",
        ),
        _target(
            "in-process simulate at defaults ÷ a minimal loop with the same DOP853 steps, time",
            (k["ratio_to_minimal_loop"], "≤", limit["ratio_to_minimal_loop"]),
            f"rbi.sim._dop853.integrate_minimal: {number(m['seconds'], 3)} s ({same})",
            f"simulate {number(default['seconds'], 3)} s, {default['steps']:,} steps",
        ),
    ]


def _latency_targets(lat: dict) -> list[dict]:
    """Start-up: the first run in a fresh HOME, each additional file, each command as a whole process."""
    first, per_file = lat.get("first_run") or {}, lat.get("per_file") or {}
    out = []
    if first:
        out.append(
            _target(
                f"first `{first.get('command', 'rbi simulate')}` in a fresh HOME ÷ a later one, time",
                (first.get("ratio"), "≤", first.get("target", 1.3)),
                f"the run after it: {number(first.get('later_median_s'), 3)} s",
                first.get("error")
                or f"first {number(first['first_median_s'], 3)} s; median of {first['repeats']} fresh "
                f"HOMEs; files left in HOME: {len(first['files_left_in_home'])}",
            )
        )
    if per_file:
        out.append(
            _target(
                "each additional file in one `rbi inertia` process (the bundled bodies), ms",
                (per_file.get("per_file_ms"), "≤", per_file["target_ms"]),
                f"one file: {number(per_file.get('one_file_median_s'), 3)} s",
                per_file.get("error")
                or f"{per_file['files']} files: {number(per_file['many_files_median_s'], 3)} s",
            )
        )
    baseline_text = f"{lat['baseline']}: {number(_seconds(lat['commands'][0]), 3)} s"
    return out + [
        _target(
            f"`{row['command']}` as a whole process, {'CPU' if 'cpu_ratio_to_numpy_import' in row else 'wall'} time",
            (row.get("cpu_ratio_to_numpy_import", row.get("ratio_to_numpy_import")), "≤", row["target"]),
            baseline_text,
            row.get("error") or f"{number(_seconds(row), 3)} s median of {row['repeats']}",
        )
        for row in lat["commands"]
        if "target" in row
    ]


def _largespec_targets(ls: dict) -> list[dict]:
    """Loading large specs against a bare yaml.load."""
    out = []
    for row in ls.get("specs", []) or [{"error": ls.get("error")}]:
        label = f"{row.get('n_parts', 0):,} × {row.get('shape', '?')}" if "n_parts" in row else "large specs"
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
                f"whole load of a YAML spec of {label} ÷ a bare yaml.load (CSafeLoader), time",
                (row.get("ratio"), "≤", ls["target"]),
                "bare yaml.load(f, Loader=yaml.CSafeLoader) in a plain Python"
                + (f": {number(base, 3)} s" if isinstance(base, float) else ""),
                detail,
            )
        )
    return out


def _sweep_targets(sw: dict) -> list[dict]:
    """Sweep throughput against single runs and process loops, and its peak memory."""
    single, loop = sw["single_run"], sw["process_loop"]
    sweep, mem, limit = sw["sweep"], sw["memory"], sw["targets"]
    rate = f"sweep {number(sweep['runs_per_second'], 3)} runs/s"
    return [
        _target(
            f"`rbi sweep` throughput over {sweep['runs']:,} runs ÷ (cores × single-run rate)",
            (sw["ratio_to_cores_x_single"], "≥", limit["ratio_to_cores_x_single"]),
            f"{sw['cores']} cores × {number(single['runs_per_second'], 3)} runs/s (simulate, one run "
            f"after another, {single['runs']} grid points)",
            f"{rate} ({number(sweep['seconds'], 3)} s; "
            f"CPU time ÷ wall time {number(sweep.get('cores_used', float('nan')), 3)})",
        ),
        _target(
            "`rbi sweep` throughput ÷ a loop of `rbi simulate` processes",
            (sw["ratio_to_process_loop"], "≥", limit["ratio_to_process_loop"]),
            f"{loop['runs']} processes: {number(loop['runs_per_second'], 3)} runs/s",
            rate,
        ),
        _target(
            f"peak resident memory of a streaming sweep of {mem.get('runs', 0):,} runs, MB",
            (mem.get("peak_rss_mb"), "≤", limit["peak_rss_mb"]),
            "500 MB (absolute)",
            mem.get("error")
            or f"RSS {number(mem['rss_first_quarter_mb'], 3)} MB in the first quarter, "
            f"{number(mem['rss_last_quarter_mb'], 3)} MB in the last ({mem['rows_written']:,} rows)",
        ),
    ]


def _robotaudit_targets(ra: dict) -> list[dict]:
    """The audit of a large generated URDF against its absolute time target."""
    quick = ra.get("links", 0) < 10**5
    detail = ra.get("error") or (
        f"{number(ra['megabytes'], 3)} MB, {number(ra['links_per_second'], 3)} links/s"
        + (
            f"; CPU {number(ra['cpu_seconds'], 3)} s at load {number(ra['load_average'], 2)}"
            if "cpu_seconds" in ra
            else ""
        )
        + ("; a quick run: the target is for 100,000 links" if quick else "")
    )
    what = f"`rbi audit` of a URDF of {ra.get('links', 0):,} links (inertial, box collision, revolute joints)"
    return [
        _target(f"{what}, wall time", (ra.get("seconds"), "≤", ra["target_s"]), "5 s (absolute)", detail, "s")
    ]


def _uncertainty_targets(u: dict) -> list[dict]:
    """Uncertainty propagation against the plain computation, and Monte Carlo against 1 s."""
    limit = u["targets"]
    return [
        _target(
            f"linear uncertainty budget of {u['parts']:,} parts with ± on every number ÷ the plain "
            "computation, CPU time",
            (u["ratio_linear_to_plain"], "≤", limit["ratio_linear_to_plain"]),
            f"rbi.load(the spec without ±).principal(): CPU {number(u['plain_cpu_s'], 3)} s "
            f"(wall {number(u['plain_s'], 3)} s)",
            f"rbi.load(spec).uncertainty(): CPU {number(u['linear_cpu_s'], 3)} s (wall {number(u['linear_s'], 3)} s), "
            f"medians of {u['rounds']} rounds"
            + ("; a quick run: the target is for 1,000 parts" if u["parts"] < 1000 else ""),
        ),
        _target(
            f"{u['draws']:,} Monte Carlo draws of bodies/top_bolted_toleranced.yaml, wall time",
            (u["monte_carlo_s"], "≤", limit["monte_carlo_s"]),
            "1 s (absolute)",
            f"median of {u['monte_carlo_repeats']} (CPU {number(u['monte_carlo_cpu_s'], 3)} s); the first call "
            f"{number(u['monte_carlo_first_s'], 3)} s",
            "s",
        ),
    ]


SECTION_TARGETS = {
    "kernel": ("kernel", _kernel_targets),
    "latency": ("start-up", _latency_targets),
    "largespec": ("large specs", _largespec_targets),
    "sweep": ("sweep", _sweep_targets),
    "robotaudit": ("robot audit", _robotaudit_targets),
    "uncertainty": ("uncertainty", _uncertainty_targets),
}
"""Each section of a bench result that has speed targets: its area and the function that lists them."""


def _shown(target: dict, key: str) -> str:
    """A target's measured value or limit: a ratio as ``1,830×``; a quantity (its ``unit``, or a
    target whose words end in MB or ms) as a number with its unit."""
    value, unit = target[key], target.get("unit")
    if unit is None and not target["target"].endswith(("MB", "ms")):
        return _times(value)
    return "—" if value is None else number(value, 3) + (f" {unit}" if unit else "")


# --- headline --------------------------------------------------------------------------------


def headline(result: dict) -> list[str]:
    """The few sentences a reader needs: for each work-precision case, rbi's speed-up at its
    defaults and at equal or better error (the tables below give the rest)."""
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
            f"final orientation error ({number(s['default_orientation_error_deg'], 2)}° against "
            f"{number(s['chapter_orientation_error_deg'], 2)}°)"
        )
        if "ratio_best_matching" in s:
            line += (
                f"; at equal or better error the fastest rbi run (rtol {s['best_matching_rtol']:g}) is "
                f"{_times(s['ratio_best_matching'])} faster"
            )
        lines.append(line + ".")
    return lines


def _kernel_speedup(k: dict | None, case: dict) -> dict | None:
    """The kernel section's measurement of ``case``'s body, in the form of the work-precision
    speed-up, so that the headline quotes the numbers the Targets table and the kernel table
    show (the work-precision sweep times the same runs again, with other repeats)."""
    if not k or k["case"]["spec"] != case["spec"] or k["case"]["duration"] != case["duration"]:
        return None
    return speedup(k["chapter"], k["default"], k.get("best_matching"))


@dataclass
class Section:
    """One part of the report, built once and drawn twice: as rich tables by ``rbi bench``
    and as Markdown for docs/performance.md (:func:`markdown`). ``title`` (none: it continues
    the section before), ``notes`` (prose; code in backticks), the ``columns``' headers
    (``quantity [unit]``), ``rows`` of text cells, the heading ``level``, the columns aligned
    ``left`` (None: the first) and those never wrapped."""

    title: str
    notes: str = ""
    columns: list[str] = field(default_factory=list)
    rows: list[list[str]] = field(default_factory=list)
    level: int = 2
    left: tuple | None = None
    no_wrap: tuple = ()

    def justify(self, column: str) -> str:
        """How ``column`` is aligned: ``"left"`` (text) or ``"right"`` (numbers)."""
        return "left" if column in (self.columns[:1] if self.left is None else self.left) else "right"


def report_sections(result: dict, plot_link: str | None = None) -> list[Section]:
    """Every section of the report that ``result`` measured, in the order of docs/performance.md;
    ``plot_link``: where the work-precision plot is, relative to the page."""
    writers = {
        "targets": _targets_sections,
        "kernel": _kernel_sections,
        "sweep": _sweep_sections,
        "workprecision": partial(_workprecision_sections, plot_link=plot_link),
        "throughput": _throughput_sections,
        "latency": _latency_sections,
        "cad": _cad_sections,
        "uncertainty": _uncertainty_sections,
    }
    return [s for name, write in writers.items() if result.get(name) for s in write(result[name])]


def markdown(result: dict, command: str, plot_link: str | None) -> str:
    """docs/performance.md: how it was made, on what, the headline, then every section."""
    out = _preamble(result, command)
    for s in report_sections(result, plot_link):
        if s.title:
            out += ["", "#" * s.level + " " + s.title]
        if s.notes:
            out += ["", s.notes]
        if s.rows:
            out += ["", _md_table(s.columns, s.rows)]
    return "\n".join(out) + "\n"


def _md_table(headers: list[str], rows: list[list[str]]) -> str:
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
    out += ["| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |" for row in rows]
    return "\n".join(out)


def _preamble(result: dict, command: str) -> list[str]:
    """How the page was made, on what machine, and the headline."""
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
        *(f"- {fact}" for fact in machine_facts(result)),
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
    return out + [f"- {line}" for line in headline(result)]


def machine_facts(result: dict) -> list[str]:
    """What the numbers were measured on, one fact a line (the page's list; the terminal's
    first line)."""
    m = result["machine"]
    return [
        f"Date: {m['date']}",
        f"Machine: {m['cpu']}, {m['cores']} cores, {m['platform']}",
        f"Software: Python {m['python']}, numpy {m['numpy']}, scipy {m['scipy']}, kernel: {m.get('kernel')}",
        f"Load average (1 min) when the run started: {m.get('load_average_1min')}",
        f"Run: {'quick (`--quick`, shortened cases)' if result['quick'] else 'full'}",
    ]


# --- the sections ----------------------------------------------------------------------------


def _targets_sections(rows: list[dict]) -> list[Section]:
    notes = (
        "Each speed target (kernel, start-up, large specs, sweep) with the baseline it was measured "
        "against in this same run."
    )
    left = ("area", "target", "met", "baseline (same run)", "detail")
    table = _table(TARGET_COLUMNS, rows)
    return [Section("Targets", notes, *table, left=left, no_wrap=("measured", "limit", "met"))]


def _kernel_sections(k: dict) -> list[Section]:
    """The compiled kernel against the chapter's set-up and the minimal loop, each tolerance."""
    case, chapter, loop = k["case"], k["chapter"], k["minimal_loop"]
    notes = (
        f"`{case['spec']}`, ω₀ = {vector_text(case['omega0'], brackets='()')} rad/s, {case['duration']:g} s, "
        f"{case['samples']} samples, in this process with the compiled kernel loaded. The chapter's set-up "
        f"took {number(chapter['seconds'], 3)} s ({chapter['steps']:,} steps, final orientation error "
        f"{number(chapter['orientation_error_deg'], 2)}°); `simulate` at its defaults (rtol "
        f"{k['default']['rtol']:g}) {number(k['default']['seconds'], 3)} s; the minimal loop "
        f"(`rbi.sim._dop853.integrate_minimal`: the same DOP853 steps without chunking, step budget, counters "
        f"or the result object, called on prepared arrays) {number(loop['seconds'], 3)} s with "
        f"{loop['steps']:,} steps (same steps: {loop['same_steps']}, same samples bit "
        f"for bit: {loop['same_samples']}). Errors are against rbi at rtol 1e-14. Each tolerance of rbi's "
        "method against the chapter's set-up (★); the fastest at the chapter's error or better is the target:"
    )
    case = {"runs": [chapter, *k["trials"]], "default": k["default"]}
    return [work_section("The kernel against its baselines", notes, case)]


def _sweep_sections(sw: dict) -> list[Section]:
    """Sweep throughput on a grid, and the resident memory of a long streaming sweep."""
    g, mem = sw["grid"], sw["memory"]
    grid = (
        f"Grid: spin {g['spin'][0]:g}–{g['spin'][1]:g} rad/s × {g['spin'][2]}, tilt {g['tilt_deg'][0]:g}–"
        f"{g['tilt_deg'][1]:g}° × {g['tilt_deg'][2]}, {g['duration']:g} s a run, default rtol, on "
        f"{sw['cores']} cores: `{sw['sweep']['command']}` ran in this process in "
        f"{number(sw['sweep']['seconds'], 3)} s ({number(sw['sweep']['runs_per_second'], 3)} runs/s, "
        f"{_times(sw['ratio_to_single'])} the single-run rate). The single-run rate is `simulate` called "
        f"for {sw['single_run']['runs']} grid points one after another in this process; the process loop is "
        f"`rbi simulate FILE --spin S --tilt T --duration {g['duration']:g}` for "
        f"{sw['process_loop']['runs']} grid points."
    )
    out = [Section("Sweep throughput and memory", grid)]
    if "error" in mem:
        return out + [Section("", f"Memory: the child sweep failed: {mem['error']}")]
    notes = (
        f"Memory: `{mem['command']}` as a child process: peak resident memory "
        f"{number(mem['peak_rss_mb'], 3)} MB over {mem['rows_written']:,} rows streamed in "
        f"{number(mem['seconds'], 3)} s; resident memory sampled while it ran (flat means bounded):"
    )
    columns = [
        ("time [s]", _num("seconds")),
        ("RSS [MB]", _num("rss_mb")),
        ("CSV written [MB]", _num("csv_bytes", scale=2**-20)),
    ]
    return out + [Section("", notes, *_table(columns, mem["samples"]))]


def _workprecision_sections(wp: dict, plot_link: str | None) -> list[Section]:
    """Work against precision: each case's error and time per method."""
    notes = (
        "Final orientation error (angle between the computed and the reference orientation at the "
        "last sample) and angular-velocity error against in-process time (one whole call of "
        "`rbi.sim.api.simulate`, with the compiled kernel already loaded; the median of repeated runs "
        'for the fast method). "rel. drift" is the largest relative '
        "change of any conserved quantity along the run (energy, vertical and spin angular momentum for "
        "the top; energy and the angular-momentum vector for the free body). The chapter's set-up is "
        "scipy `solve_ivp` RK45 at rtol 1e-8, atol 1e-10 with a Python right-hand side "
        "(`--method rk45`); the last column is its time divided by each row's. " + METHOD_NOTE
    )
    out = [Section("Work against precision", notes)]
    for case in wp["cases"]:
        title = (
            f"{case['name']}: `{case['spec']}`, ω₀ = {vector_text(case['omega0'], brackets='()')} rad/s, "
            f"tilt {case['tilt_deg']:g}°, {case['duration']:g} s, {case['samples']} samples"
        )
        notes = (
            f"Reference: {reference_text(case)}. Loading the compiled kernel cost "
            f"{number(case['kernel_load_seconds'], 3)} s once in this process (not in any time below)."
        )
        out.append(work_section(title, notes, case, level=3))
    if plot_link:
        out.append(Section("", f"![Final orientation error against in-process time]({plot_link})"))
    return out


def _throughput_sections(tp: dict) -> list[Section]:
    """Mass-property throughput: point clouds and specs of many solid parts."""
    clouds = (
        'Random point masses (seeded). "mass+CoM+inertia" is `rbi.core.mass.combine` on arrays in memory; '
        '"total" adds the principal axes. "from … spec" is the whole load of a spec file naming the cloud '
        f"(`point_cloud: {{file: cloud.csv}}`: YAML, validation, reading the cloud, the reduction) plus the "
        f"principal axes, as `rbi principal` does after start-up; the CSV holds `{tp['csv_format']}` numbers. "
        f"Time grows as size^{number(tp['scaling_exponent'], 3)} from 10⁴ points up (1 = linear)."
    )
    parts = (
        "Cones, cylinders (by density) and point masses in turn, one YAML flow mapping per line. Parsing uses "
        "libyaml's C parser; validation is pydantic; translation builds one mass element per part in Python. "
        '"same as JSON" is the whole load of the same spec written as one JSON object (JSON is valid YAML; '
        "rbi reads it with Python's json module when the file starts with `{`). "
        '"core" is the vectorised reduction (mass, CoM, inertia, principal axes) of the translated parts.'
    )
    return [
        Section("Mass-property throughput", clouds, *_table(CLOUD_COLUMNS, tp["point_clouds"])),
        Section("Specs of many solid parts", parts, *_table(PARTS_COLUMNS, tp["solid_parts"]), level=3),
    ]


def _latency_sections(lat: dict) -> list[Section]:
    """Whole-process latency of each command, and where the start-up goes."""
    compiled = ", rbi's bytecode having been compiled first, as `pip install` does."
    notes = (
        f"Each command ran once untimed (warm OS file caches), then repeatedly, in turn; the "
        f"medians of CPU time (user + system, which other work on the machine disturbs less; "
        f"the targets are on it) and of wall time are compared with `{lat['baseline']}` "
        f"measured in the same rounds" + (compiled if lat.get("bytecode_compiled") else ".")
    )
    out = [Section("Whole-process latency", notes, *_table(LATENCY_COLUMNS, lat["commands"]))]
    imports = lat.get("imports")
    if not imports or "error" in imports:
        return out
    notes = (
        f"`{imports['command']}`: the time each of the {imports['modules']} imported modules takes itself "
        f'(Python\'s "self" column, so a package counts once whoever imports it first), smallest of '
        f"{imports['repeats']} runs, summed by package. `-X importtime` adds its own overhead, so these add up "
        "to more than the import part of a plain run; the shares are what to compare. The rest of a run is "
        "the interpreter's own start-up and the work itself (reading and validating the spec, about a "
        "millisecond for a small one, then printing)."
    )
    total = imports["total_ms"]
    groups = sorted(imports["groups_ms"].items(), key=lambda item: -item[1])
    rows = [[name, number(ms, 3), f"{100 * ms / total:.0f}%"] for name, ms in groups]
    rows.append(["all imports", number(total, 3), "100%"])
    title = "Where `rbi inertia`'s start-up goes"
    return out + [Section(title, notes, ["imported", "time [ms]", "share"], rows, level=3)]


def _cad_sections(cad: dict) -> list[Section]:
    """CAD solids: the STEP plate against its STL, time and error side by side (or why not measured)."""
    if cad.get("error"):
        notes = f"CAD solids: {cad['error']}"
    else:
        a, b, c = cad["plate_mm"]
        notes = (
            f"CAD solids: a {a:g} × {b:g} × {c:g} mm plate with {cad['holes']} holes of radius "
            f"{cad['hole_radius_mm']:g} mm, read as STEP (exact geometry) and as STL, whole load cold; "
            "errors relative, against the closed form"
        )
    return [Section("CAD solids: STEP against STL", notes + ".", *_table(CAD_COLUMNS, cad.get("files", [])))]


def _uncertainty_sections(u: dict) -> list[Section]:
    """What the uncertainty targets time (their numbers are in the Targets table)."""
    notes = (
        f'`rbi.load(spec).uncertainty(method="linear")` (the budget of `rbi uncertainty`: mass, centre of '
        f"mass, inertia and principal moments) of a generated spec of {u['parts']:,} parts (cones, cylinders by "
        "density and point masses; ± 1 % on each mass, density and radius, ± 0.001 on each coordinate), "
        "against `rbi.load(spec).principal()` of the same spec without ±, each a whole load in this process, "
        f'timed in turn, medians of {u["rounds"]} rounds; and `body.uncertainty(method="monte-carlo", '
        f"samples={u['draws']})` of `bodies/top_bolted_toleranced.yaml` loaded once: "
        f"{number(u['linear_cpu_s'], 3)} s of CPU time against {number(u['plain_cpu_s'], 3)} s "
        f"({_times(u['ratio_linear_to_plain'])}), and {number(u['monte_carlo_s'], 3)} s for the draws."
    )
    return [Section("Uncertainty of the inputs", notes)]


# --- the tables' columns: (header, the cell of one record) -----------------------------------------


def _table(columns: list[tuple], records) -> tuple[list, list[list[str]]]:
    """The headers and the rows of a table of ``records``, from ``(header, cell)`` pairs; a
    header is a string or a ``(quantity, unit)`` pair, ``cell`` turns a record into its text."""
    return [h for h, _ in columns], [[cell(r) for _, cell in columns] for r in records]


def _num(key: str, digits: int = 3, scale: float = 1.0):
    return lambda r: number(None if r.get(key) is None else scale * r[key], digits)


def _count(key: str):
    return lambda r: "—" if r.get(key) is None else f"{r[key]:,}"


TARGET_COLUMNS = [
    ("area", itemgetter("area")),
    ("target", itemgetter("target")),
    ("measured", lambda r: _shown(r, "measured")),
    ("limit", lambda r: f"{r['comparison']} {_shown(r, 'limit')}"),
    ("met", lambda r: {True: "yes", False: "NO", None: "—"}[r["met"]]),
    ("baseline (same run)", itemgetter("baseline")),
    ("detail", itemgetter("detail")),
]
CAD_COLUMNS = [
    ("file", itemgetter("file")),
    ("triangles", _count("triangles")),
    ("MB", _num("bytes", scale=1e-6)),
    ("load [s]", _num("seconds")),
    ("volume err", _num("volume_error", 2)),
    ("CoM err", _num("com_error", 2)),
    ("inertia err", _num("inertia_error", 2)),
    ("estimate", _num("integration_error", 2)),
]
"""Errors are relative to the closed form; the estimate is the integration's own (STEP only)."""


def reference_text(case: dict) -> str:
    ref = case["reference"]
    if ref["method"] == "exact":
        return "closed form (Euler–Poinsot)"
    check = ref.get("check", {})
    return (
        f"rbi at rtol {ref['rtol']:g}; scipy DOP853 at rtol {check.get('rtol', 0):g} differs from it by "
        f"{number(check.get('orientation_difference_deg'), 2)}°"
    )


def _method(r: dict) -> str:
    if r.get("default_settings"):
        return "rbi defaults"
    return METHOD_NAMES[r["method"]] + (" ★" if r.get("chapter_setup") else "")


def work_section(title: str, notes: str, case: dict, level: int = 2) -> Section:
    """The table of each run of a work-precision case: its error, drift, cost and speed against
    the chapter's."""
    chapter = next((r for r in case["runs"] if r["chapter_setup"]), None)

    def speedup(r):
        return _times(chapter["seconds"] / r["seconds"] if chapter and r["seconds"] > 0 else None)

    columns = [
        ("method", _method),
        ("rtol", lambda r: f"{r['rtol']:g}"),
        ("orient. error [deg]", _num("orientation_error_deg", 2)),
        ("ω error [rad/s]", _num("omega_error", 2)),
        ("rel. drift", _num("drift", 2)),
        ("steps", _count("steps")),
        ("RHS evals", _count("rhs_evals")),
        ("time [s]", _num("seconds", 2)),
        ("chapter ÷ this", speedup),
    ]
    table = _table(columns, case["runs"] + [case["default"]])
    return Section(title, notes, *table, level=level, left=("method",), no_wrap=("method",))


CLOUD_COLUMNS = [
    ("points", _count("points")),
    ("mass [ms]", _num("mass_s", scale=1e3)),
    ("CoM [ms]", _num("com_s", scale=1e3)),
    ("+inertia [ms]", _num("combine_s", scale=1e3)),
    ("principal [ms]", _num("principal_s", scale=1e3)),
    ("total [ms]", _num("total_s", scale=1e3)),
    ("ns/point", _num("ns_per_point")),
    ("CSV spec [ms]", _num("load_csv_s", scale=1e3)),
    (".npy spec [ms]", _num("load_npy_s", scale=1e3)),
    ("CSV [MB]", _num("csv_megabytes")),
]
PARTS_COLUMNS = [
    ("parts", _count("parts")),
    ("YAML [MB]", _num("yaml_megabytes")),
    ("parse YAML [s]", _num("read_yaml_s")),
    ("validate [s]", _num("validate_s")),
    ("translate [s]", _num("translate_s")),
    ("load total [s]", _num("load_total_s")),
    ("µs/part", _num("us_per_part")),
    ("same as JSON [s]", _num("load_total_json_s")),
    ("core [s]", _num("core_s", 2)),
]
LATENCY_COLUMNS = [
    ("command", itemgetter("command")),
    ("CPU median [s]", lambda r: "failed" if "error" in r else _num("cpu_median_s")(r)),
    ("× numpy import (CPU)", lambda r: "" if "error" in r else _times(r.get("cpu_ratio_to_numpy_import"))),
    ("wall median [s]", lambda r: "" if "error" in r else _num("median_s")(r)),
    ("wall best [s]", lambda r: "" if "error" in r else _num("best_s")(r)),
    ("× numpy import (wall)", lambda r: "" if "error" in r else _times(r.get("ratio_to_numpy_import"))),
    ("wall spread", lambda r: r["error"] if "error" in r else f"{100 * r['spread']:.0f}%"),
]


def _seconds(row: dict) -> float | None:
    return row.get("cpu_median_s", row.get("median_s"))


# --- the result: JSON and CSV ----------------------------------------------------------------


CSV_FIELDS = ("method", "rtol", "chapter_setup", "default_settings", "orientation_error_deg", "omega_error")
CSV_FIELDS += ("drift", "steps", "rhs_evals", "seconds")


class Report(Result):
    """A run of ``rbi bench`` (the dict :func:`rbi.bench.suite.run` returns) as rbi's results
    are: its JSON object and its CSV rows; the CLI draws its tables (:func:`report_sections`)."""

    def __init__(self, result: dict) -> None:
        self.result = result

    def to_dict(self) -> dict:
        return self.result

    def csv_rows(self) -> list[dict]:
        """The rows of every measured section, in the order they ran: one row per work-precision
        run (its ``case`` first), one per target of a section that has targets, and one per
        record of each other section's tables (a list of records, such as throughput's
        ``point_clouds``), its ``section`` and ``table`` first, the numbers as the JSON has them;
        such a section without such a list (one that failed: its ``error``) gives one row of its
        own values. Every row has every column (empty where it has none)."""
        rows = []
        for name, section in self.result.items():
            if name == "workprecision":
                rows += [
                    {"case": case["name"]} | {key: r.get(key, False) for key in CSV_FIELDS}
                    for case in section["cases"]
                    for r in case["runs"] + [case["default"]]
                ]
            elif name in SECTION_TARGETS:
                rows += [t for t in self.result.get("targets", []) if t["area"] == SECTION_TARGETS[name][0]]
            elif name != "machine" and isinstance(section, dict):
                tables = {
                    k: v for k, v in section.items() if v and isinstance(v, list) and isinstance(v[0], dict)
                }
                rows += [{"section": name, "table": k} | r for k, records in tables.items() for r in records]
                rows += [] if tables else [{"section": name} | section]
        columns = dict.fromkeys(key for row in rows for key in row)
        return [{key: row.get(key) for key in columns} for row in rows]
