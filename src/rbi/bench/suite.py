"""Running the benchmark sections in one process and collecting their results."""

from __future__ import annotations

from importlib import import_module

from rbi.bench import Progress, report
from rbi.bench.timing import machine

NAMES = ("kernel", "workprecision", "throughput", "largespec", "latency", "sweep", "cad", "robotaudit")
NAMES += ("uncertainty",)
SECTIONS = {name: import_module(f"rbi.bench.{name}") for name in NAMES}
"""Every section by name, in the order they run."""


def planned_steps(quick: bool, sections) -> int:
    """How many times the sections will call ``progress`` (for a progress bar's total)."""
    return sum(SECTIONS[name].planned_steps(quick) for name in sections)


def run(quick: bool, sections, progress: Progress = lambda _: None, command: str = "rbi bench") -> dict:
    """``{"quick", "machine", "<section>": ..., "command", "targets", "headline"}`` for the chosen
    sections, measured now (``command``: the command line that asked for them)."""
    result = {"quick": quick, "machine": machine()}
    for name in SECTIONS:
        if name in sections:
            result[name] = SECTIONS[name].run(quick, progress)
    result["command"] = command
    return result | {"targets": report.targets(result), "headline": report.headline(result)}
