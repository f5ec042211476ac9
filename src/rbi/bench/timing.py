"""Timing helpers and a description of the machine a benchmark ran on."""

from __future__ import annotations

import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from datetime import UTC, datetime
from typing import NamedTuple

import numpy

from rbi.sim.compiled import integrator


class Timing(NamedTuple):
    """Repeated wall-clock timings of one call, seconds, and what its last run returned."""

    median: float
    best: float
    repeats: int
    result: object = None


def measure(
    call: Callable[[], object], min_repeats: int = 3, max_repeats: int = 50, min_seconds: float = 0.2
) -> Timing:
    """Time ``call`` at least ``min_repeats`` times and until ``min_seconds`` have been spent
    (at most ``max_repeats`` times); the median resists the other users of a shared machine."""
    times: list[float] = []
    spent = 0.0
    result = None
    while len(times) < min_repeats or (spent < min_seconds and len(times) < max_repeats):
        start = time.perf_counter()
        result = call()
        elapsed = time.perf_counter() - start
        times.append(elapsed)
        spent += elapsed
    return Timing(statistics.median(times), min(times), len(times), result)


def time_once(call: Callable[[], object]) -> tuple[float, object]:
    """``(seconds, result)`` of one call."""
    start = time.perf_counter()
    result = call()
    return time.perf_counter() - start, result


def machine() -> dict:
    """What the numbers were measured on: CPU, core count, load, Python and library versions."""
    import scipy  # loaded only by the commands that need it (start-up cost)

    info = {
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "cpu": _cpu_model(),
        "cores": os.cpu_count(),
        "load_average_1min": _load_average(),
        "platform": platform.platform(),
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "scipy": scipy.__version__,
        "executable": sys.executable,
    }

    info["kernel"] = integrator().how
    return info


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as stream:
            for line in stream:
                if line.lower().startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _load_average() -> float | None:
    try:
        return round(os.getloadavg()[0], 2)
    except (OSError, AttributeError):
        return None
