"""Large specs (issue 9): the whole load of a YAML spec of 10⁵ point masses and of one of 10⁴
cylinders against a bare ``yaml.load(f, Loader=yaml.CSafeLoader)`` of the same file in a plain
Python, measured in the same run (target: at most 0.5×; a quick run uses 10⁴ point masses and
10³ cylinders).

:func:`yaml_load_ratio` writes a spec of many equal-kind parts (point masses or cylinders),
then times, each in a fresh Python process so that no import or heap state carries over:

- ``bare_s``: ``yaml.load(f, Loader=yaml.CSafeLoader)`` of the file in a plain Python (the
  garbage collector on, as any program has it), and nothing else;
- ``rbi_load_s``: rbi's read (bounded YAML reader), validation and translation of the file
  into core inputs — what every command does before its own work — with ``rbi_read_s``,
  ``rbi_validate_s`` and ``rbi_translate_s`` its steps;
- ``rbi_inertia_process_s``: the whole ``rbi inertia FILE --format json`` process, start-up
  included (wall clock seen from outside).

``ratio`` is ``rbi_load_s / bare_s``. Importing this module runs nothing.
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from rbi.bench import Progress
from rbi.bench.timing import run_process
from rbi.memory import collector_paused

SHAPES = {
    "point": "shape: point, mass: {m:.6g}, position: {a}",
    "cylinder": "shape: cylinder, density: {density:.6g}, radius: {radius:.6g}, start: {a}, end: {b}",
    "cone": "shape: cone, mass: {m:.6g}, radius: {radius:.6g}, apex: {a}, base: {b}",
}
"""Each kind of part :func:`spec_text` writes, as the flow mapping's text."""

TARGET = 0.5

_BARE = """
import sys, time, yaml
start = time.perf_counter()
with open(sys.argv[1]) as stream:
    yaml.load(stream, Loader=yaml.CSafeLoader)
print(time.perf_counter() - start)
"""

_RBI = (
    "import json, sys; from rbi.bench.largespec import load_steps; "
    "print(json.dumps(load_steps(sys.argv[1])[0]))"
)


def load_steps(path: str) -> tuple[dict, Any, Any]:
    """rbi's load of the spec at ``path`` step by step, the garbage collector paused as rbi's
    loader pauses it: the seconds of each step (``read``: the bounded YAML reader, ``validate``,
    ``translate``), the parsed YAML and the body."""
    from rbi.spec.load import read_yaml, validation_messages  # lazy: importing this module loads no numpy
    from rbi.spec.translate import body_from_spec  # lazy: numpy

    start = time.perf_counter()
    with collector_paused():
        raw = read_yaml(path)
        read = time.perf_counter()
        spec, problems = validation_messages(path, raw)
        if problems:
            raise RuntimeError(f"generated spec is invalid: {problems[0]}")
        validated = time.perf_counter()
        body = body_from_spec(spec, path)
        done = time.perf_counter()
    return {"read": read - start, "validate": validated - read, "translate": done - validated}, raw, body


def spec_text(n_parts: int, shapes: str, seed: int = 0) -> str:
    """A valid spec of ``n_parts`` parts cycling through ``shapes`` (comma-separated: point,
    cylinder by density, cone), one flow mapping a line, numbers with 6 significant digits
    (what a generating program writes)."""
    import numpy as np  # lazy: importing this module must load nothing a baseline would pay for

    kinds = shapes.split(",")
    if not set(kinds) <= set(SHAPES):
        raise ValueError(f"shape must be one of {SHAPES} (got {shapes!r})")
    rng = np.random.default_rng(seed)
    starts = rng.normal(size=(n_parts, 3))
    ends = starts + rng.normal(size=(n_parts, 3)) + [0.0, 0.0, 0.5]
    sizes = rng.uniform(0.1, 1.0, n_parts)

    def v(a) -> str:
        return f"[{a[0]:.6g}, {a[1]:.6g}, {a[2]:.6g}]"

    lines = [f"name: parts-{n_parts}", "units: {length: m, mass: kg}", "parts:"]
    for i, (m, a, b) in enumerate(zip(sizes, starts, ends)):
        part = SHAPES[kinds[i % len(kinds)]].format(m=m, density=1000 * m, radius=0.1 * m, a=v(a), b=v(b))
        lines.append(f"  - {{{part}}}")
    return "\n".join(lines) + "\n"


def _python(*args: str) -> tuple[float, str]:
    """``(wall seconds, standard output)`` of this Python run with ``args``; RuntimeError when it
    fails."""
    seconds, _, proc = run_process([sys.executable, *args])
    if proc.returncode != 0:
        raise RuntimeError(f"benchmark subprocess failed: {proc.stderr.strip()[-500:]}")
    return seconds, proc.stdout.strip()


def yaml_load_ratio(n_parts: int, shape: str) -> dict:
    """Seconds of PyYAML's bare ``CSafeLoader`` load and of rbi's load of the same spec of
    ``n_parts`` ``shape`` parts, each in a fresh process, and their ratio (see the module)."""
    with tempfile.TemporaryDirectory(prefix="rbi-yaml-bench-") as folder:
        path = Path(folder) / f"{shape}s.yaml"
        path.write_text(spec_text(n_parts, shape))
        bare_s = float(_python("-c", _BARE, str(path))[1])
        steps = json.loads(_python("-c", _RBI, str(path))[1])
        process_s = _python("-m", "rbi", "inertia", str(path), "--format", "json")[0]
        rbi_load_s = sum(steps.values())  # read, validate, translate
        return {
            "parts": n_parts,
            "shape": shape,
            "yaml_megabytes": path.stat().st_size / 1e6,
            "bare_s": bare_s,
            "rbi_load_s": rbi_load_s,
            **{f"rbi_{step}_s": seconds for step, seconds in steps.items()},
            "rbi_inertia_process_s": process_s,
            "ratio": rbi_load_s / bare_s,
        }


CASES = {True: [(10**4, "point"), (10**3, "cylinder")], False: [(10**5, "point"), (10**4, "cylinder")]}
"""The specs loaded, (parts, shape): quick run, full run."""


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    specs = []
    for n, shape in CASES[quick]:
        progress(f"large specs: {n:,} × {shape}")
        try:
            row = yaml_load_ratio(n, shape)
        except Exception as exc:  # a failed measurement is a row, not the end of the bench
            row = {"error": f"{type(exc).__name__}: {exc}"}
        specs.append(row | {"n_parts": n, "shape": shape})
    return {"target": TARGET, "specs": specs}
