"""The simulation kernel's speed targets, each against a baseline measured in the same run.

On the bolted top (``bodies/top_bolted.yaml``, upright, 200 rad/s, 4 s, 481 samples; 0.5 s in a
quick run), in this process, with the compiled kernel already loaded:

- ``rbi.sim.api.simulate`` at its defaults against the seed chapter's set-up (scipy RK45, rtol
  1e-8, atol 1e-10, Python right-hand side; :mod:`rbi.sim.baselines`): target ≥ 3,000×;
- the fastest rbi tolerance whose final orientation and ω errors are no larger than the
  chapter's (errors against rbi at rtol 1e-14) against the same chapter run: target ≥ 6,000×;
- ``simulate`` at defaults against :func:`rbi.sim._dop853.integrate_minimal`, the smallest loop
  that takes the same DOP853 steps (checked here: same step count, same samples bit for bit),
  called directly on prepared arrays: target ≤ 1.3× (what ``simulate`` adds around the kernel:
  checks, arrays, chunking for progress and Ctrl-C, the result object).
"""

from __future__ import annotations

import statistics
from collections.abc import Callable

import numpy as np

from rbi.bench import Progress, workprecision
from rbi.bench.timing import measure
from rbi.sim._dop853 import integrate_minimal
from rbi.sim.api import DEFAULT_RTOL, sample_times, simulate
from rbi.sim.compiled import integrator

TRIAL_RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
"""Tolerances tried for the fastest run at the chapter's error or better."""

TARGETS = {"ratio_default": 3000.0, "ratio_best_matching": 6000.0, "ratio_to_minimal_loop": 1.3}


def _median_seconds(call: Callable[[], object], min_seconds: float) -> float:
    """Median time of ``call`` over at least 5 runs and ``min_seconds`` (at most 2000 runs)."""
    return measure(call, min_repeats=5, max_repeats=2000, min_seconds=min_seconds).median


def minimal_loop_call(scene, q0, omega0, duration: float, samples: int, rtol: float):
    """``(call, result)``: a no-argument call of the minimal loop on arrays prepared once (as a
    hand-written program would hold them), and where it writes ``(y, out)``."""

    t = sample_times(duration, samples)
    q0 = np.asarray(q0, dtype=float)
    start = np.concatenate((q0 / np.linalg.norm(q0), np.asarray(omega0, dtype=float)))
    inertia = np.ascontiguousarray(scene.inertia, dtype=float)
    inertia_inv = np.ascontiguousarray(scene.inertia_inv, dtype=float)
    c = np.ascontiguousarray(scene.gravity_moment, dtype=float)
    omega_ref = max(scene.natural_rate, 0.0)
    y = start.copy()
    out = np.empty((t.size, 7))
    steps = [0]

    def call():
        y[:] = start
        steps[0] = integrate_minimal(y, t, inertia, inertia_inv, c, rtol, omega_ref, out)

    return call, (y, out, steps)


def planned_steps(quick: bool) -> int:
    return 4


def run(quick: bool, progress: Progress = lambda _: None) -> dict:

    integrator()  # load once, outside every timing
    case = workprecision.cases(quick)[0]
    scene, q0, omega0 = workprecision.scene_of(case)
    min_seconds = 0.3 if quick else 1.5

    progress("kernel: reference and the chapter's set-up")
    reference, _ = workprecision.reference_of(case, scene, q0, omega0, quick)
    chapter, chapter_times = _chapter_runs(scene, q0, omega0, case, quick)
    chapter_s = statistics.median(chapter_times)
    chapter_err = workprecision.errors(scene, chapter, reference)

    def simulate_call(rtol=None):
        return lambda: simulate(scene, q0, omega0, case.duration, case.samples, rtol=rtol)

    progress("kernel: rbi at its defaults and the minimal loop")
    default = simulate_call()()
    default_err = workprecision.errors(scene, default, reference)
    call, (_, out, steps) = minimal_loop_call(scene, q0, omega0, case.duration, case.samples, DEFAULT_RTOL)
    call()
    default_s, minimal_s = _interleaved_medians(simulate_call(), call, min_seconds)

    progress("kernel: the fastest tolerance at the chapter's error or better")
    trials = _tolerance_trials(simulate_call, scene, reference, chapter_err, min_seconds)
    matching = [t for t in trials if t["no_worse"]]
    best = min(matching, key=lambda t: t["seconds"]) if matching else None

    progress("kernel: done")
    return {
        "case": _case_entry(case),
        "chapter": _entry(
            chapter_s, chapter.steps, workprecision.CHAPTER[1], chapter_err, len(chapter_times)
        ),
        "default": _entry(default_s, default.steps, default.rtol, default_err),
        "minimal_loop": _minimal_loop_entry(minimal_s, steps[0], out, default),
        "trials": trials,
        "best_matching": best,
        "ratio_default": chapter_s / default_s,
        "ratio_best_matching": chapter_s / best["seconds"] if best else None,
        "ratio_to_minimal_loop": default_s / minimal_s,
        "targets": TARGETS,
    }


def _entry(seconds: float, steps: int, rtol: float, err: dict, repeats: int | None = None) -> dict:
    """A timed run as the result records it: its median seconds (over ``repeats`` runs, when
    given), accepted steps, tolerance and final orientation (deg) and ω (rad/s) errors."""
    timed = {"seconds": seconds} | ({} if repeats is None else {"repeats": repeats})
    errors = {key: err[key] for key in ("orientation_error_deg", "omega_error")}
    return timed | {"steps": steps, "rtol": rtol} | errors


def _tolerance_trials(simulate_call, scene, reference, chapter_err: dict, min_seconds: float) -> list[dict]:
    """Each of :data:`TRIAL_RTOLS`: its errors against ``reference``, and its time where its
    error is no worse than the chapter's set-up (``chapter_err``)."""
    trials = []
    for rtol in TRIAL_RTOLS:
        trajectory = simulate_call(rtol)()
        err = workprecision.errors(scene, trajectory, reference)
        no_worse = workprecision.no_worse(err, chapter_err)
        seconds = _median_seconds(simulate_call(rtol), min_seconds / 3) if no_worse else None
        trials.append(
            {
                "rtol": rtol,
                "orientation_error_deg": err["orientation_error_deg"],
                "omega_error": err["omega_error"],
                "steps": trajectory.steps,
                "no_worse": no_worse,
                "seconds": seconds,
            }
        )
    return trials


def _chapter_runs(scene, q0, omega0, case, quick: bool) -> tuple:
    """``(trajectory, seconds of each run)`` of the chapter's set-up on ``case``: it takes
    seconds, so the median of three in a full run (one in a quick run)."""
    chapter_times = []
    for _ in range(1 if quick else 3):
        chapter, seconds, _ = workprecision.timed_run(scene, q0, omega0, case, *workprecision.CHAPTER, 0.0)
        chapter_times.append(seconds)
    return chapter, chapter_times


def _case_entry(case) -> dict:
    """The bench case as the result records it."""
    return {
        "name": case.name,
        "spec": f"bodies/{case.spec}",
        "omega0": list(case.omega0),
        "duration": case.duration,
        "samples": case.samples,
    }


def _interleaved_medians(first, second, min_seconds: float) -> tuple[float, float]:
    """Median seconds of two calls timed in turn, five rounds each, so that a change in the
    machine's load hits both alike."""
    first_times, second_times = [], []
    for _ in range(5):
        first_times.append(_median_seconds(first, min_seconds / 5))
        second_times.append(_median_seconds(second, min_seconds / 5))
    return statistics.median(first_times), statistics.median(second_times)


def _minimal_loop_entry(seconds: float, steps: int, out: np.ndarray, default) -> dict:
    """The minimal loop's time, and whether it took the same steps and gave the same samples
    (``out``: its [q, ω] rows) as rbi's ``default`` trajectory."""
    same_samples = bool(np.array_equal(out[:, :4], default.q) and np.array_equal(out[:, 4:], default.omega))
    return {
        "seconds": seconds,
        "steps": steps,
        "same_steps": steps == default.steps,
        "same_samples": same_samples,
    }
