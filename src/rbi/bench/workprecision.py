"""Work against precision: how the error of a simulated motion falls as each method is given
more work, and what the seed chapter's set-up costs for the accuracy it reaches.

Two cases:

- the bolted top (``bodies/top_bolted.yaml``, upright, 200 rad/s about body z, 4 s), a heavy
  top with no closed form: the reference is rbi's own integrator at rtol 1e-14, checked
  against scipy's DOP853 at rtol 1e-13 (an independent integrator; their difference is
  reported as the reference's own uncertainty);
- a torque-free asymmetric body (``bodies/tbar.yaml``, ω₀ = (12, 16, 20) rad/s, 4 s): the
  reference is the closed form (Euler–Poinsot, :mod:`rbi.sim.exact`).

For each method × tolerance: the error of the final orientation (degrees) and angular
velocity (rad/s) against the reference, the largest relative drift of the conserved
quantities, accepted steps, right-hand-side evaluations, and the in-process time of the whole
:func:`rbi.sim.api.simulate` call (the compiled kernel already loaded; the median of repeated
runs for the fast methods). The chapter's set-up is ``rk45`` at rtol 1e-8 (atol 1e-10).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from rbi.bench import Progress
from rbi.bench.paths import bodies_folder
from rbi.bench.timing import measure
from rbi.runs.run import scene_of as body_scene
from rbi.sim.api import simulate
from rbi.sim.compiled import integrator
from rbi.sim.diagnostics import conserved_quantities, orientation_error_deg
from rbi.sim.scene import initial_state
from rbi.spec.load import load_body
from rbi.viz.labels import pyplot

CHAPTER = ("rk45", 1e-8)
"""The seed chapter's set-up: scipy solve_ivp RK45, rtol 1e-8, atol 1e-10, Python right-hand side."""

FINAL_ERRORS = ("orientation_error_deg", "omega_error")
"""The errors at the last sample that a run must not exceed to be as good as another."""


@dataclass(frozen=True)
class Case:
    name: str
    spec: str  # file name in bodies/
    omega0: tuple[float, float, float]
    tilt_deg: float
    duration: float
    samples: int
    reference: str  # "tight" (rbi at rtol 1e-14, checked by scipy DOP853) or "exact"


def cases(quick: bool) -> list[Case]:
    top_duration = 0.5 if quick else 4.0
    top_samples = int(round(120 * top_duration)) + 1  # 120 a second, and the start
    return [
        Case("bolted top", "top_bolted.yaml", (0.0, 0.0, 200.0), 0.0, top_duration, top_samples, "tight"),
        Case("free asymmetric body", "tbar.yaml", (12.0, 16.0, 20.0), 0.0, 4.0, 481, "exact"),
    ]


SWEEPS = {
    True: {"default": [1e-8, 1e-11], "rk45": [1e-8], "dop853": [1e-10]},
    False: {
        "default": [1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13],
        "rk45": [1e-6, 1e-7, 1e-8, 1e-9, 1e-10],
        "dop853": [1e-6, 1e-8, 1e-10, 1e-12],
    },
}
"""Tolerances tried for each method: quick run, full run."""


def scene_of(case: Case):

    scene = body_scene(load_body(bodies_folder() / case.spec), None)
    q0, omega0 = initial_state(case.tilt_deg, case.omega0)
    return scene, q0, omega0


def errors(scene, trajectory, reference) -> dict:

    drifts = {
        name: item["drift"]
        for name, item in conserved_quantities(scene, trajectory.q, trajectory.omega).items()
    }
    return {
        "orientation_error_deg": float(orientation_error_deg(trajectory.q[-1], reference.q[-1])),
        "omega_error": float(np.linalg.norm(trajectory.omega[-1] - reference.omega[-1])),
        "max_orientation_error_deg": float(np.max(orientation_error_deg(trajectory.q, reference.q))),
        "drift": max(drifts.values()),
        "drifts": drifts,
    }


def reference_of(case: Case, scene, q0, omega0, quick: bool) -> tuple[object, dict]:

    if case.reference == "exact":
        ref = simulate(scene, q0, omega0, case.duration, case.samples, method="exact")
        return ref, {"method": "exact", "description": ref.integrator}
    ref = simulate(scene, q0, omega0, case.duration, case.samples, method="default", rtol=1e-14)
    check_rtol = 1e-12 if quick else 1e-13
    check = simulate(scene, q0, omega0, case.duration, case.samples, method="dop853", rtol=check_rtol)
    return ref, {
        "method": "default",
        "rtol": 1e-14,
        "check": {
            "method": "dop853",
            "rtol": check_rtol,
            "orientation_difference_deg": float(orientation_error_deg(check.q[-1], ref.q[-1])),
            "omega_difference": float(np.linalg.norm(check.omega[-1] - ref.omega[-1])),
        },
    }


def run_case(case: Case, quick: bool, progress: Progress, tolerances: dict | None = None) -> dict:
    """Each method at each of its ``tolerances`` (default: :data:`SWEEPS`) and rbi at its
    default settings on ``case``: errors against the reference, cost, and the median
    in-process time of the whole :func:`rbi.sim.api.simulate` call over repeats (a run of the
    compiled method takes about a millisecond, too short to time once on a busy machine), and their
    :func:`speedup` (None when the chapter's set-up was not among ``tolerances``)."""
    load_seconds = integrator().load_seconds  # compile or load once, outside every timing
    scene, q0, omega0 = scene_of(case)
    progress(f"{case.name}: reference")
    reference, reference_info = reference_of(case, scene, q0, omega0, quick)

    def row(method: str, rtol: float | None, min_seconds: float, **flags) -> dict:
        timing = measure(
            lambda: simulate(scene, q0, omega0, case.duration, case.samples, method=method, rtol=rtol),
            min_repeats=1,
            max_repeats=500,
            min_seconds=min_seconds,
        )
        trajectory = timing.result
        return {
            "method": method,
            "rtol": trajectory.rtol,
            **flags,
            **errors(scene, trajectory, reference),
            "steps": trajectory.steps,
            "rhs_evals": trajectory.rhs_evals,
            "seconds": timing.median,
            "repeats": timing.repeats,
        }

    rows = []
    for method, rtols in (tolerances or SWEEPS[quick]).items():
        for rtol in rtols:
            progress(f"{case.name}: {method} rtol {rtol:g}")
            is_chapter = (method, rtol) == CHAPTER
            min_seconds = 0.3 if method == "default" else (2.0 if is_chapter and not quick else 0.0)
            rows.append(row(method, rtol, min_seconds, chapter_setup=is_chapter))
    progress(f"{case.name}: rbi default settings")
    default_row = row("default", None, 0.3, chapter_setup=False, default_settings=True)
    chapter = next((r for r in rows if r["chapter_setup"]), None)
    return asdict(case) | {
        "spec": f"bodies/{case.spec}",
        "omega0": list(case.omega0),
        "reference": reference_info,
        "kernel_load_seconds": load_seconds,
        "runs": rows,
        "default": default_row,
        "speedup": speedup(chapter, default_row, best_matching(rows, chapter)) if chapter else None,
    }


def no_worse(errors: dict, chapter: dict) -> bool:
    """Whether the final orientation error (deg) and ω error (rad/s) of ``errors`` are no
    larger than the chapter's set-up's (``chapter``)."""
    return all(errors[key] <= chapter[key] for key in FINAL_ERRORS)


def speedup(chapter: dict, default: dict, best: dict | None) -> dict:
    """The chapter's time over rbi's, (a) with rbi's default settings (``default``), (b) for
    ``best``, the fastest run of rbi's default method whose final errors are no larger than the
    chapter's (None: no run was); each record holds seconds and final errors."""
    quoted = (("chapter", chapter), ("default", default))
    out = {f"{who}_{key}": run[key] for who, run in quoted for key in ("seconds", *FINAL_ERRORS)} | {
        "default_no_worse": no_worse(default, chapter),
        "ratio_default": chapter["seconds"] / default["seconds"],
        "ratio_error": chapter["orientation_error_deg"] / max(default["orientation_error_deg"], 1e-300),
    }
    if best:
        out.update(best_matching_rtol=best["rtol"], ratio_best_matching=chapter["seconds"] / best["seconds"])
    return out


def best_matching(rows: list[dict], chapter: dict) -> dict | None:
    """The fastest of ``rows`` run with rbi's default method whose final errors are no larger than
    the chapter's set-up's (None: none is)."""
    matching = [r for r in rows if r["method"] == "default" and no_worse(r, chapter)]
    return min(matching, key=lambda r: r["seconds"], default=None)


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    return {
        "chapter_setup": {"method": CHAPTER[0], "rtol": CHAPTER[1], "atol": CHAPTER[1] / 100},
        "cases": [run_case(case, quick, progress) for case in cases(quick)],
    }


def plot(result: dict, path: str | Path) -> None:
    """Log–log plot of the final orientation error against in-process time, one panel per
    case, one line per method; the chapter's set-up and rbi's defaults are marked."""
    plt = pyplot()

    styles = {
        "default": ("rbi default method (compiled DOP853)", "C0", "o"),
        "rk45": ("scipy RK45, Python RHS", "C3", "s"),
        "dop853": ("scipy DOP853, Python RHS", "C2", "^"),
    }
    cases_ = result["cases"]
    fig, axes = plt.subplots(1, len(cases_), figsize=(6.2 * len(cases_), 4.8), squeeze=False)
    floor = 1e-14
    for ax, case in zip(axes[0], cases_):
        _plot_case(ax, case, styles, floor)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.suptitle("rbi work-precision: error against time (lower left is better)")
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _plot_case(ax, case: dict, styles: dict, floor: float) -> None:
    """One panel of :func:`plot`: each method's error against time, the chapter's set-up and
    rbi's defaults marked; errors below ``floor`` drawn at it."""
    for method, (label, colour, marker) in styles.items():
        rows = sorted((r for r in case["runs"] if r["method"] == method), key=lambda r: r["rtol"])
        if not rows:
            continue
        x = [r["seconds"] for r in rows]
        y = [max(r["orientation_error_deg"], floor) for r in rows]
        ax.loglog(x, y, marker=marker, color=colour, label=label)
        for r, xi, yi in zip(rows, x, y):
            ax.annotate(
                f"{r['rtol']:.0e}",
                (xi, yi),
                textcoords="offset points",
                xytext=(4, 3),
                fontsize=7,
                color=colour,
            )
    chapter = next((r for r in case["runs"] if r["chapter_setup"]), None)
    d = case["default"]
    marks = [(d, "P", "C0", 12, f"rbi defaults (rtol {d['rtol']:g})", {"markeredgecolor": "k"})]
    if chapter:
        marks.insert(0, (chapter, "*", "k", 14, "the chapter's set-up (RK45, rtol 1e-8)", {}))
    for row, marker, colour, size, label, edge in marks:
        y = max(row["orientation_error_deg"], floor)
        ax.loglog([row["seconds"]], [y], marker, color=colour, markersize=size, label=label, **edge)
    omega = ", ".join(f"{w:g}" for w in case["omega0"])
    ax.set_title(f"{case['name']} ({case['spec']}, ω₀ = ({omega}) rad/s, {case['duration']:g} s)", fontsize=9)
    ax.set_xlabel("in-process time of one simulate() call [s]")
    ax.set_ylabel("final orientation error [deg]")
    ax.grid(True, which="both", alpha=0.3)
