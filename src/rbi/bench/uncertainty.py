"""Uncertainty of the inputs (issue 37), through the public API, each against a baseline measured
in the same run:

- the linear budget (``rbi.load(spec).uncertainty(method="linear")``, the law of propagation of
  JCGM 100) of a generated spec of 1,000 parts (cones, cylinders by density, point masses) with
  ± on every number, against the plain computation of the same spec without them
  (``rbi.load(spec).principal()``), each a whole load, timed in turn over five rounds: target ≤ 5×
  in CPU time (which the machine's other work disturbs less than the wall time, also recorded);
- 100,000 Monte Carlo draws (JCGM 101) of the toleranced bolted top
  (``bodies/top_bolted_toleranced.yaml``): target under 1 s (absolute), the median of repeated
  calls after a first one (whose time, imports included, is recorded beside it).

A quick run uses 200 parts (the same 100,000 draws).
"""

from __future__ import annotations

import re
import tempfile
from pathlib import Path
from statistics import median

import rbi
from rbi.bench import Progress
from rbi.bench.paths import bodies_folder
from rbi.bench.throughput import parts_yaml
from rbi.bench.timing import measure, time_once

TARGETS = {"ratio_linear_to_plain": 5.0, "monte_carlo_s": 1.0}


def toleranced(text: str) -> str:
    """``text`` (a spec of :func:`rbi.bench.throughput.parts_yaml`) with ± on every number of its
    parts: 1 % on a mass, density or radius, ± 0.001 on each coordinate."""
    scalars = re.compile(r"((?:mass|density|radius): [-0-9.e]+)")
    coordinates = re.compile(r"(-?[0-9][0-9.e-]*)(?=[,\]])")
    lines = text.splitlines(keepends=True)
    return "".join(coordinates.sub(r"\1 ± 0.001", scalars.sub(r"\1 ± 1%", line)) for line in lines)


def planned_steps(quick: bool) -> int:
    return 2


def run(quick: bool, progress: Progress = lambda _: None) -> dict:
    parts, draws = 200 if quick else 1000, 100_000
    progress(f"uncertainty: linear budget of {parts:,} toleranced parts")
    with tempfile.TemporaryDirectory(prefix="rbi-bench-") as tmp:
        plain, marked = Path(tmp) / "parts.yaml", Path(tmp) / "parts_toleranced.yaml"
        plain.write_text(parts_yaml(parts))
        marked.write_text(toleranced(plain.read_text()))
        plain_call = lambda: rbi.load(plain).principal()  # noqa: E731
        linear_call = lambda: rbi.load(marked).uncertainty()  # noqa: E731
        linear_call()  # imports and first calls outside the timings
        # in turn, so that a change in the machine's load hits both alike
        rounds = [(measure(plain_call, 1), measure(linear_call, 1)) for _ in range(5)]
    progress(f"uncertainty: {draws:,} Monte Carlo draws of the toleranced bolted top")
    top = rbi.load(bodies_folder() / "top_bolted_toleranced.yaml")

    def monte_carlo():
        return top.uncertainty(method="monte-carlo", samples=draws, seed=1)

    first_s, _ = time_once(monte_carlo)
    mc = measure(monte_carlo, min_repeats=3)
    return {
        "parts": parts,
        "plain_s": median(p.median for p, _ in rounds),
        "linear_s": median(u.median for _, u in rounds),
        "plain_cpu_s": (plain_cpu := median(p.cpu_median for p, _ in rounds)),
        "linear_cpu_s": (linear_cpu := median(u.cpu_median for _, u in rounds)),
        "rounds": len(rounds),
        "ratio_linear_to_plain": linear_cpu / plain_cpu,
        "draws": draws,
        "monte_carlo_s": mc.median,
        "monte_carlo_cpu_s": mc.cpu_median,
        "monte_carlo_first_s": first_s,
        "monte_carlo_repeats": mc.repeats,
        "targets": TARGETS,
    }
