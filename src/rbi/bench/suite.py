"""Running the benchmark: the chosen sections in one process, their results collected, then the
plot and the Markdown page written (what ``rbi bench`` calls; it only parses and prints); and a
description of the machine it ran on."""

from __future__ import annotations

import os
import platform
import sys
import tempfile
from collections.abc import Callable
from datetime import UTC, datetime
from functools import partial
from importlib import import_module
from pathlib import Path

import numpy

from rbi.bench import report
from rbi.bench.paths import bodies_folder
from rbi.errors import SpecError
from rbi.files.output import check_distinct, output_target, write_output
from rbi.sim.compiled import integrator

NAMES = ("kernel", "workprecision", "throughput", "largespec", "latency", "sweep", "cad", "robotaudit")
NAMES += ("uncertainty",)
SECTIONS = {name: import_module(f"rbi.bench.{name}") for name in NAMES}
"""Every section by name, in the order they run."""


def chosen(only: str | None) -> list[str]:
    """The sections a comma-separated ``only`` names (None: all); SpecError naming ``--only``."""
    if only is None:
        return list(NAMES)
    names = [s.strip().lower() for s in only.split(",") if s.strip()]
    if not names or any(s not in NAMES for s in names):
        raise SpecError(f"--only: expected a comma-separated list of {', '.join(NAMES)} (got {only!r})")
    return names


def run(
    quick: bool = False,
    only: str | None = None,
    plot: str | None = None,
    write_docs: str | None = None,
    progress: Callable[[int, int, str], None] = lambda *_: None,
) -> dict:
    """``{"quick", "machine", "<section>": ..., "command", "targets", "headline"}`` for the sections
    ``only`` names (:func:`chosen`), measured now; ``progress(sections done, sections, what)``
    as each measurement starts. The outputs are checked before any measurement (SpecError naming
    the option) and written after: ``plot``, the work-precision plot (.png, .svg, .pdf);
    ``write_docs``, the report as Markdown (docs/performance.md)."""
    sections = chosen(only)
    if plot and "workprecision" not in sections:
        raise SpecError("--plot: needs the workprecision section (drop --only or include it)")
    plot_target = output_target(plot, "--plot", ("png", "svg", "pdf")) if plot else None
    docs_target = output_target(write_docs, "--write-docs", ("md",)) if write_docs else None
    check_distinct([plot_target, docs_target])
    bodies_folder()  # SpecError now, not after minutes of measurement
    options = (("--only", only), ("--write-docs", write_docs), ("--plot", plot))
    command = " ".join(["rbi", "bench"] + ["--quick"] * quick + [w for o in options if o[1] for w in o])
    result = {"quick": quick, "machine": machine()}
    for done, name in enumerate(n for n in NAMES if n in sections):
        with tempfile.TemporaryDirectory(prefix=f"rbi-bench-{name}-") as folder:
            result[name] = SECTIONS[name].run(quick, partial(progress, done, len(sections)), Path(folder))
    result["command"] = command
    result |= {"targets": report.targets(result), "headline": report.headline(result)}
    if plot_target:
        write_output(
            plot_target, writer=lambda temp: SECTIONS["workprecision"].plot(result["workprecision"], temp)
        )
    if docs_target:
        link = os.path.relpath(Path(plot).resolve(), Path(write_docs).resolve().parent) if plot else None
        write_output(docs_target, report.markdown(result, command, link))
    return result


def machine() -> dict:
    """What the numbers were measured on: CPU, core count, load, Python and library versions."""
    import scipy  # loaded only by the commands that need it (start-up cost)

    return {
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "cpu": _cpu_model(),
        "cores": os.cpu_count(),
        "load_average_1min": _load_average(),
        "platform": platform.platform(),
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "scipy": scipy.__version__,
        "executable": sys.executable,
        "kernel": integrator().how,
    }


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
