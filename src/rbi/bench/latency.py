"""Whole-process latency: how long a user waits for ``rbi inertia`` and ``rbi simulate``,
compared with starting Python and importing numpy (the floor for any numpy program).

Each command runs once untimed (so the OS file cache is warm, as on
a machine that has run rbi before), then ``repeats`` times; the median is reported, and the
ratio to the median of ``python -c "import numpy"`` measured in the same run.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Callable

import numpy as np

from rbi.bench.paths import bodies_folder, rbi_command
from rbi.bench.throughput import random_cloud, write_cloud

QUICK_REPEATS = 3
FULL_REPEATS = 11

Progress = Callable[[str], None]


def commands(bodies: Path, cloud_specs: dict[str, Path] | None) -> list[tuple[str, list[str]]]:
    """(label, argv) of every timed command; the first is the baseline."""
    rbi = rbi_command()
    out = [
        ('python -c "import numpy"', [sys.executable, "-c", "import numpy"]),
        ("rbi inertia bodies/top.yaml", rbi + ["inertia", str(bodies / "top.yaml"), "--format", "json"]),
        ("rbi principal bodies/top_bolted.yaml", rbi + ["principal", str(bodies / "top_bolted.yaml"), "--format", "json"]),
        ("rbi simulate bodies/top_bolted.yaml --spin 200",
         rbi + ["simulate", str(bodies / "top_bolted.yaml"), "--spin", "200", "--format", "json"]),
    ]
    if cloud_specs:
        n = cloud_specs["points"]
        out.append((f"rbi principal (cloud of {n:,} points, CSV)", rbi + ["principal", str(cloud_specs["csv"]), "--format", "json"]))
        out.append((f"rbi principal (cloud of {n:,} points, .npy)", rbi + ["principal", str(cloud_specs["npy"]), "--format", "json"]))
    return out


def time_process(argv: list[str]) -> tuple[float, int, str]:
    """Wall seconds, exit status and the last line of stderr of one run."""
    start = time.perf_counter()
    proc = subprocess.run(argv, capture_output=True, text=True, timeout=600)
    elapsed = time.perf_counter() - start
    last = proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else ""
    return elapsed, proc.returncode, last


def planned_steps(quick: bool) -> int:
    return 4 if quick else 6


def run(quick: bool, progress: Progress = lambda _: None) -> dict:
    repeats = QUICK_REPEATS if quick else FULL_REPEATS
    bodies = bodies_folder()
    rows = []
    with tempfile.TemporaryDirectory(prefix="rbi-bench-") as tmp:
        cloud = None
        if not quick:
            n = 10**6
            masses, positions = random_cloud(n)
            cloud = dict(write_cloud(Path(tmp), masses, positions), points=n)
        for label, argv in commands(bodies, cloud):
            progress(f"latency: {label}")
            _, status, message = time_process(argv)  # warm-up (and a check that it works)
            if status != 0:
                rows.append({"command": label, "error": f"exit {status}: {message}"})
                continue
            times = [time_process(argv)[0] for _ in range(repeats)]
            rows.append({"command": label, "median_s": statistics.median(times), "best_s": min(times),
                         "spread": spread(times), "repeats": repeats})
    baseline = rows[0].get("median_s")
    for row in rows:
        if baseline and "median_s" in row:
            row["ratio_to_numpy_import"] = row["median_s"] / baseline
    return {"baseline": rows[0]["command"], "commands": rows}


def spread(values: list[float]) -> float:
    """Relative spread (max − min) / median of repeated timings: how noisy the machine was."""
    values = np.asarray(values, dtype=float)
    return float((values.max() - values.min()) / np.median(values))
