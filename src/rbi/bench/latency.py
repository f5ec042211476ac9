"""Whole-process latency: how long a user waits for ``rbi --help``, ``rbi inertia`` and
``rbi simulate``, compared with starting the same Python and importing numpy (the floor for any
numpy program), and what a first ``rbi simulate`` in a fresh HOME costs against a later one.

Each command runs once untimed (so the OS file cache is warm, as on a machine that has run rbi
before), then ``repeats`` rounds in which every command runs once; the medians of wall and CPU time
are reported, and their ratios to those of ``python -c "import numpy"`` measured in the same
rounds. The targets are on CPU time, which other work on a shared machine disturbs less.
"""

from __future__ import annotations

import compileall
import os
import re
import statistics
import subprocess
import sys
import tempfile
from functools import partial
from pathlib import Path
from resource import RUSAGE_CHILDREN

from rbi.bench import Progress
from rbi.bench.paths import bodies_folder, rbi_command
from rbi.bench.throughput import random_cloud, write_cloud
from rbi.bench.timing import in_turn, measure, run_process

REPEATS = {True: 3, False: 21}
"""Rounds of the timed commands: quick run, full run."""


SIMULATE_TOP = "rbi simulate bodies/top.yaml --spin 200 --tilt 10"

TARGETS = {
    "rbi inertia bodies/top.yaml": 2.5,
    "rbi inertia bodies/top.yaml --format json": 3.0,
    "rbi --help": 1.3,
    SIMULATE_TOP: 2.5,
}
"""Limits on whole-process CPU time, as multiples of ``python -c "import numpy"``'s (issue 9;
issue 24 for ``rbi inertia``: 3x, with typer parsing every command line and no patch of a
dependency's internals; issue 36: 2.5x for ``rbi inertia bodies/top.yaml``)."""

PER_FILE_TARGET_MS = 5.0
"""Issue 21: each additional file in one ``rbi inertia`` process costs at most this (ms)."""

MANY_FILES = 600
"""Files in the many-files run (the bundled bodies over and over): enough that their own time
(a few seconds) stands well above the noise of one process's start-up."""

ONE_FILE = "rbi inertia bodies/top.yaml --format json"

JSON_UNSAID = ("rbi principal bodies/top_bolted.yaml", "rbi simulate bodies/top_bolted.yaml --spin 200")
"""Commands timed with ``--format json``, which their labels leave out."""

LABELLED = ("rbi --help", "rbi --version", "rbi inertia bodies/top.yaml", ONE_FILE)
LABELLED += (JSON_UNSAID[0], SIMULATE_TOP, JSON_UNSAID[1])
"""The rbi commands timed as their labels spell them, in order (the many-files run goes after ONE_FILE)."""

FIRST_RUN_TARGET = 1.3
"""Issue 9: the first ``rbi simulate`` with a fresh HOME at most this multiple of a later one."""


def commands(bodies: Path, cloud_specs: dict[str, Path] | None) -> list[tuple[str, list[str]]]:
    """(label, argv) of every timed command; the first is the baseline (this Python, the one rbi
    runs on)."""
    rbi, as_json = rbi_command(), ["--format", "json"]
    out = [('python -c "import numpy"', [sys.executable, "-c", "import numpy"])]
    for label in LABELLED:  # its words after "rbi", a body named bodies/NAME the bundled one
        words = [str(bodies / w[7:]) if w.startswith("bodies/") else w for w in label.split()[1:]]
        out.append((label, rbi + words + as_json * (label in JSON_UNSAID)))
    out.insert(5, many_files_command(bodies, rbi))  # after ONE_FILE
    for kind, key in (("CSV", "csv"), (".npy", "npy")) if cloud_specs else ():
        label = f"rbi principal (cloud of {cloud_specs['points']:,} points, {kind})"
        out.append((label, rbi + ["principal", str(cloud_specs[key]), *as_json]))
    return out


def many_files_command(bodies: Path, rbi: list[str]) -> tuple[str, list[str]]:
    """The bundled YAML bodies in turn, :data:`MANY_FILES` paths, in one ``rbi inertia``."""
    found = [str(path) for path in sorted(bodies.glob("*.yaml"))]
    files = [found[i % len(found)] for i in range(MANY_FILES)]
    return (
        f"rbi inertia (the bundled bodies in turn: {len(files)} files) --format json",
        rbi + ["inertia", *files, "--format", "json"],
    )


def per_file_cost(rows: list[dict], files: int) -> dict:
    """The cost of each file after the first in one ``rbi inertia`` process: (time of the
    many-files run − time of the one-file run) ÷ (files − 1), from the medians of the same
    rounds."""
    one = next((r for r in rows if r["command"] == ONE_FILE), {})
    many = next((r for r in rows if r["command"].startswith("rbi inertia (the bundled bodies")), {})
    if "median_s" not in one or "median_s" not in many:
        return {
            "error": one.get("error") or many.get("error") or "not measured",
            "target_ms": PER_FILE_TARGET_MS,
        }
    per_file = (many["median_s"] - one["median_s"]) / (files - 1)
    return {
        "files": files,
        "one_file_median_s": one["median_s"],
        "many_files_median_s": many["median_s"],
        "per_file_ms": 1000 * per_file,
        "target_ms": PER_FILE_TARGET_MS,
        "ratio_to_one_file_process": per_file / one["median_s"],
    }


IMPORT_GROUPS = {
    "numpy": "numpy",
    "pydantic (and pydantic-core, typing helpers)": "pydantic pydantic_core annotated_types typing_extensions "
    "typing_inspection",
    "rbi's spec models (built by pydantic as they are defined)": "rbi.spec.models rbi.spec.expect rbi.spec.fields",
    "PyYAML": "yaml _yaml",
    "rich (tables)": "rich",
    "typer and click": "typer click",
    "rbi, other modules": "rbi",
    "the rest of the standard library": "",
}
"""Each group of imported modules and the packages (or modules) in it: a module belongs to the
group of its longest dotted prefix listed; any other, to the last group."""
GROUP_OF = {prefix: group for group, prefixes in IMPORT_GROUPS.items() for prefix in prefixes.split()}


def import_breakdown(bodies: Path, repeats: int) -> dict:
    """Where ``rbi inertia bodies/top.yaml``'s start-up goes, from ``python -X importtime``: each
    imported module's own time (its "self" column, so a package is counted once whoever
    imported it first), the smallest of ``repeats`` runs, summed by :data:`IMPORT_GROUPS`."""

    argv = [sys.executable, "-X", "importtime", "-m", "rbi", "inertia", str(bodies / "top.yaml")]
    best: dict[str, int] = {}
    for _ in range(repeats):
        proc = subprocess.run(argv, capture_output=True, text=True, timeout=600)
        if proc.returncode != 0:
            return {"error": f"exit {proc.returncode}"}
        seen = {m[2]: int(m[1]) for m in re.finditer(r"import time:\s+(\d+) \|\s+\d+ \| *(\S+)", proc.stderr)}
        best = seen if not best else {name: min(us, best.get(name, us)) for name, us in seen.items()}
    groups = dict.fromkeys(IMPORT_GROUPS, 0)
    for module, us in best.items():
        words = module.split(".")
        prefixes = (".".join(words[:n]) for n in range(len(words), 0, -1))
        group = next((GROUP_OF[p] for p in prefixes if p in GROUP_OF), "the rest of the standard library")
        groups[group] += us
    return {
        "command": "python -X importtime -m rbi inertia bodies/top.yaml",
        "repeats": repeats,
        "modules": len(best),
        "groups_ms": {name: us / 1000 for name, us in groups.items()},
        "total_ms": sum(best.values()) / 1000,
    }


def first_run(bodies: Path, repeats: int) -> dict:
    """The first ``rbi simulate`` in a fresh, empty HOME (and cache folder) against the run just
    after it in the same HOME, ``repeats`` times with a new HOME each time; medians and their
    ratio. Nothing is compiled or cached at run time, so the two should match (the package's own
    files are installed and in the OS file cache either way)."""

    argv = dict(commands(bodies, None))[SIMULATE_TOP]
    firsts, laters, messages = [], [], []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory(prefix="rbi-bench-home-") as home:
            env = dict(
                os.environ, HOME=home, XDG_CACHE_HOME=f"{home}/.cache", XDG_CONFIG_HOME=f"{home}/.config"
            )
            seconds, _, proc = run_process(argv, env)
            if proc.returncode != 0:
                return {"error": failure(proc)}
            firsts.append(seconds)
            laters.append(run_process(argv, env)[0])
            messages.append(proc.stderr)
            left = sorted(str(p.relative_to(home)) for p in Path(home).rglob("*"))
    first, later = statistics.median(firsts), statistics.median(laters)
    return {
        "command": SIMULATE_TOP,
        "first_median_s": first,
        "later_median_s": later,
        "ratio": first / later,
        "repeats": repeats,
        "target": FIRST_RUN_TARGET,
        "files_left_in_home": left,
        "compiling_line": any("compil" in m.lower() for m in messages),
    }


def failure(proc: subprocess.CompletedProcess) -> str:
    """``exit N: <the last line of stderr>`` of a process that failed."""
    return f"exit {proc.returncode}: {(proc.stderr.strip().splitlines() or [''])[-1]}"


def compile_bytecode() -> bool:
    """Write rbi's own bytecode (``.pyc``) where it is missing or stale, as ``pip install``
    does, so that no timed run compiles rbi's sources (an editable checkout run with
    ``PYTHONDONTWRITEBYTECODE`` would recompile every changed module in every run: tens of
    milliseconds). Whether every module compiled (False also when the folder is read-only)."""

    package = Path(__file__).resolve().parents[1]
    try:
        return bool(compileall.compile_dir(str(package), quiet=2))  # quiet=2: prints nothing
    except OSError:
        return False


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    repeats = REPEATS[quick]
    bodies = bodies_folder()
    bytecode = compile_bytecode()
    rows, timed = [], []
    cloud = None
    if not quick:  # a full run also times `rbi principal` of a cloud of 10⁶ points (its CSV and .npy specs)
        n = 10**6
        cloud = dict(write_cloud(folder, *random_cloud(n)), points=n)
    for label, argv in commands(bodies, cloud):
        progress(f"latency: {label}")
        proc = run_process(argv)[2]  # warm-up (and a check that it works)
        if proc.returncode:
            rows.append({"command": label, "error": failure(proc)})
            continue
        rows.append({"command": label})
        timed.append(partial(measure, partial(run_process, argv), 1, 1, 0.0, RUSAGE_CHILDREN))
    # round-robin: each round times every command once, so a change in the machine's load
    # during the run hits the baseline and the commands alike
    for row, t in zip([r for r in rows if "error" not in r], in_turn(timed, repeats)):
        row |= {"median_s": t.median, "best_s": t.best, "spread": t.spread, "cpu_median_s": t.cpu_median}
        row["repeats"] = t.repeats
    progress("latency: first rbi simulate in a fresh HOME")
    first = first_run(bodies, 3 if quick else 7)
    progress("latency: where rbi inertia's start-up goes (python -X importtime)")
    imports = import_breakdown(bodies, 3 if quick else 7)
    for row in rows:
        for key, ratio in (
            ("median_s", "ratio_to_numpy_import"),
            ("cpu_median_s", "cpu_ratio_to_numpy_import"),
        ):
            if rows[0].get(key) and key in row:
                row[ratio] = row[key] / rows[0][key]
        if row["command"] in TARGETS:
            row["target"] = TARGETS[row["command"]]
    return {
        "baseline": rows[0]["command"],
        "commands": rows,
        "first_run": first,
        "per_file": per_file_cost(rows, MANY_FILES),
        "imports": imports,
        "bytecode_compiled": bytecode,
    }
