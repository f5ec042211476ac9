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

from functools import partial
from pathlib import Path

import numpy as np

from rbi.bench import Progress, workprecision
from rbi.bench.timing import in_turn, measure
from rbi.sim._dop853 import integrate_minimal
from rbi.sim.api import sample_times, simulate

TRIAL_RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
"""Tolerances tried for the fastest run at the chapter's error or better."""

TARGETS = {"ratio_default": 3000.0, "ratio_best_matching": 6000.0, "ratio_to_minimal_loop": 1.3}


def minimal_loop_call(scene, q0, omega0, duration: float, samples: int, rtol: float):
    """``(call, out)``: a no-argument call of the minimal loop on arrays prepared once (as a
    hand-written program would hold them), which returns its step count, and the samples it
    writes."""

    t = sample_times(duration, samples)
    q0 = np.asarray(q0, dtype=float)
    start = np.concatenate((q0 / np.linalg.norm(q0), np.asarray(omega0, dtype=float)))
    inertia = np.ascontiguousarray(scene.inertia, dtype=float)
    inertia_inv = np.ascontiguousarray(scene.inertia_inv, dtype=float)
    c = np.ascontiguousarray(scene.gravity_moment, dtype=float)
    omega_ref = max(scene.natural_rate, 0.0)
    y = start.copy()
    out = np.empty((t.size, 7))

    def call():
        y[:] = start
        return integrate_minimal(y, t, inertia, inertia_inv, c, rtol, omega_ref, out)

    return call, out


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    """The work-precision case of the bolted top, with rbi's method at :data:`TRIAL_RTOLS` and
    the chapter's set-up only, then rbi at its defaults and the minimal loop timed in turn."""
    case = workprecision.cases(quick)[0]
    tolerances = {"rk45": [workprecision.CHAPTER[1]], "default": list(TRIAL_RTOLS)}
    runs = workprecision.run_case(case, quick, progress, tolerances)
    chapter = next(r for r in runs["runs"] if r["chapter_setup"])
    trials = [
        r | {"no_worse": workprecision.no_worse(r, chapter)}
        for r in runs.pop("runs")
        if not r["chapter_setup"]
    ]
    best = workprecision.best_matching(trials, chapter)

    progress("kernel: rbi at its defaults and the minimal loop")
    scene, q0, omega0 = workprecision.scene_of(case)
    default = simulate(scene, q0, omega0, case.duration, case.samples)
    call, out = minimal_loop_call(scene, q0, omega0, case.duration, case.samples, default.rtol)
    steps = call()
    min_seconds = 0.3 if quick else 1.5
    default_call = partial(simulate, scene, q0, omega0, case.duration, case.samples)
    timings = in_turn([partial(measure, f, 5, 2000, min_seconds / 5) for f in (default_call, call)], 5)
    default_s, minimal_s = (t.median for t in timings)
    same_samples = bool(np.array_equal(out[:, :4], default.q) and np.array_equal(out[:, 4:], default.omega))
    return {
        "case": {key: value for key, value in runs.items() if key not in ("default", "speedup")},
        "chapter": chapter,
        "default": runs["default"] | {"seconds": default_s},
        "minimal_loop": {
            "seconds": minimal_s,
            "steps": steps,
            "same_steps": steps == default.steps,
            "same_samples": same_samples,
        },
        "trials": trials,
        "best_matching": best,
        "ratio_default": chapter["seconds"] / default_s,
        "ratio_best_matching": chapter["seconds"] / best["seconds"] if best else None,
        "ratio_to_minimal_loop": default_s / minimal_s,
        "targets": TARGETS,
    }
