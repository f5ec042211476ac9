"""Running the benchmark sections in one process and collecting their results."""

from __future__ import annotations

from rbi.bench import Progress, cad, kernel, largespec, latency, robotaudit, sweep, throughput, workprecision
from rbi.bench.timing import machine

SECTIONS = {
    "kernel": kernel,
    "workprecision": workprecision,
    "throughput": throughput,
    "largespec": largespec,
    "latency": latency,
    "sweep": sweep,
    "cad": cad,
    "robotaudit": robotaudit,
}
"""Every section by name, in the order they run."""


def planned_steps(quick: bool, sections) -> int:
    """How many times the sections will call ``progress`` (for a progress bar's total)."""
    return sum(SECTIONS[name].planned_steps(quick) for name in sections)


def run(quick: bool, sections, progress: Progress = lambda _: None) -> dict:
    """``{"machine": ..., "<section>": ...}`` for the chosen sections, measured now."""
    result = {"quick": quick, "machine": machine()}
    for name in SECTIONS:
        if name in sections:
            result[name] = SECTIONS[name].run(quick, progress)
    return result
