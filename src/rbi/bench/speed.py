"""Speed check of ``rbi simulate`` against the seed chapter's set-up, in one run.

    python -m rbi.bench.speed [--spec bodies/top_bolted.yaml] [--repeat 20] [--first-run]

Integrates the spec (default: the bolted top) with spin 200 rad/s for 4 s, 481 samples:

- ``rk45``: the chapter's set-up (scipy RK45, rtol 1e-8, atol 1e-10, Python right-hand side),
  timed once;
- ``default``: rbi's compiled DOP853, timed ``--repeat`` times (the median is reported);

and prints each one's in-process time, its final-state error against a reference run (default
method at rtol 1e-14), the speed ratio, and the wall time of whole ``rbi simulate`` processes
(warm caches). ``--first-run`` also measures what a first run costs: building the
ahead-of-time kernel and compiling the just-in-time one, each into an empty temporary cache.
Timings on a shared machine are noisy; the ratio is measured in the same run.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from rbi.sim.api import simulate
from rbi.sim.diagnostics import orientation_error_deg
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.spec.load import load_body
from rbi.spec.units import gravity_in


def _scene(spec: str):

    body = load_body(spec)
    return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit))


def _errors(run, reference) -> dict[str, float]:

    return {
        "final_orientation_error_deg": float(orientation_error_deg(run.q[-1], reference.q[-1])),
        "final_omega_error_rad_s": float(np.max(np.abs(run.omega[-1] - reference.omega[-1]))),
    }


def _process_seconds(spec: str, repeat: int, env=None) -> list[float]:
    command = [sys.executable, "-m", "rbi", "simulate", spec, "--spin", "200"]
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run(command, capture_output=True, check=True, env=env)
        times.append(time.perf_counter() - start)
    return times


def _first_run_costs(spec: str) -> dict[str, float]:
    """Whole-process times of a first run with a fresh, empty HOME and cache folder, and of the
    run after it (the kernel is built at install time, so the two should match)."""
    with tempfile.TemporaryDirectory() as folder:
        env = dict(os.environ, HOME=folder, XDG_CACHE_HOME=os.path.join(folder, "cache"))
        return {
            "first_run_fresh_home_seconds": _process_seconds(spec, 1, env)[0],
            "second_run_seconds": _process_seconds(spec, 1, env)[0],
        }


def measure(spec: str, repeat: int, first_run: bool) -> dict:

    scene = _scene(spec)
    q0, w0 = initial_state(0.0, [0.0, 0.0, 200.0])
    reference = simulate(scene, q0, w0, 4.0, 481, rtol=1e-14)
    chapter = simulate(scene, q0, w0, 4.0, 481, method="rk45")
    fast_runs = [simulate(scene, q0, w0, 4.0, 481) for _ in range(repeat)]
    fast_seconds = statistics.median(r.wall_seconds for r in fast_runs)
    report = {
        "spec": spec,
        "rk45": {
            "seconds": chapter.wall_seconds,
            "steps": chapter.steps,
            "rhs_evals": chapter.rhs_evals,
            **_errors(chapter, reference),
        },
        "default": {
            "seconds_median": fast_seconds,
            "seconds_min": min(r.wall_seconds for r in fast_runs),
            "steps": fast_runs[0].steps,
            "rhs_evals": fast_runs[0].rhs_evals,
            "rtol": fast_runs[0].rtol,
            "kernel": fast_runs[0].integrator,
            **_errors(fast_runs[0], reference),
        },
        "speedup_median": chapter.wall_seconds / fast_seconds,
        "process_seconds": _process_seconds(spec, 5),
    }
    if first_run:
        report.update(_first_run_costs(spec))
    return report


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--spec", default=str(Path(__file__).resolve().parents[3] / "bodies" / "top_bolted.yaml")
    )
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("--first-run", action="store_true", help="also measure first-run (empty cache) costs")
    args = parser.parse_args()
    print(json.dumps(measure(args.spec, args.repeat, args.first_run), indent=1))


if __name__ == "__main__":
    main()
