"""Timing helpers (standard library only: :mod:`rbi.bench.largespec` imports them and loads no numpy)."""

from __future__ import annotations

import resource
import statistics
import subprocess
import time
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple


class Timing(NamedTuple):
    """Repeated timings of one call, seconds: the median and best wall-clock time, how many runs,
    what its last run returned, the median CPU time (:func:`clocked`'s) and the spread of the
    wall times, (max − min) / median: how noisy the machine was."""

    median: float
    best: float
    repeats: int
    result: Any = None
    cpu_median: float = 0.0
    spread: float = 0.0


def cpu_seconds(who: int = resource.RUSAGE_SELF) -> float:
    """User + system CPU seconds of this process's threads (``RUSAGE_SELF``) or of the children
    it has waited for (``RUSAGE_CHILDREN``): what a busy machine's other work disturbs least."""
    usage = resource.getrusage(who)
    return usage.ru_utime + usage.ru_stime


def clocked(call: Callable[[], Any], who: int = resource.RUSAGE_SELF) -> tuple[float, float, Any]:
    """``(wall seconds, CPU seconds, result)`` of one call (CPU as :func:`cpu_seconds` counts it)."""
    start, cpu = time.perf_counter(), cpu_seconds(who)
    result = call()
    return time.perf_counter() - start, cpu_seconds(who) - cpu, result


def measure(
    call: Callable[[], Any],
    min_repeats: int = 3,
    max_repeats: int = 50,
    min_seconds: float = 0.2,
    who: int = resource.RUSAGE_SELF,
) -> Timing:
    """Time ``call`` at least ``min_repeats`` times and until ``min_seconds`` have been spent
    (at most ``max_repeats`` times); the median resists the other users of a shared machine.
    ``who``: whose CPU time counts (:func:`cpu_seconds`)."""
    times: list[float] = []
    cpus: list[float] = []
    result = None
    while len(times) < min_repeats or (sum(times) < min_seconds and len(times) < max_repeats):
        wall, cpu, result = clocked(call, who)
        times.append(wall)
        cpus.append(cpu)
    return _timing(times, result, cpus)


def _timing(times: list[float], result: Any, cpus: list[float]) -> Timing:
    middle = statistics.median(times)
    spread = (max(times) - min(times)) / middle if middle > 0 else 0.0
    return Timing(middle, min(times), len(times), result, statistics.median(cpus), spread)


def in_turn(timings: Sequence[Callable[[], Timing]], rounds: int) -> list[Timing]:
    """Each of ``timings`` (a :func:`measure` of something) made once a round for ``rounds``
    rounds, so that a change in the machine's load hits them alike; per call, the medians (and
    the spread) of its rounds' medians, its best time and its last result."""
    per_call: list[list[Timing]] = [[] for _ in timings]
    for _ in range(rounds):
        for done, timing in zip(per_call, timings):
            done.append(timing())
    out = []
    for done in per_call:
        middle = _timing([t.median for t in done], done[-1].result, [t.cpu_median for t in done])
        out.append(middle._replace(best=min(t.best for t in done)))
    return out


def run_process(argv: list[str], env: dict | None = None) -> tuple[float, float, subprocess.CompletedProcess]:
    """``(wall seconds, CPU seconds, the completed process)`` of one run of ``argv`` (CPU: user +
    system of it and its children), its output captured as text."""
    return clocked(
        lambda: subprocess.run(argv, capture_output=True, text=True, timeout=600, env=env),
        resource.RUSAGE_CHILDREN,
    )
