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
from functools import partial
from pathlib import Path

import rbi
from rbi.bench import Progress
from rbi.bench.largespec import spec_text
from rbi.bench.paths import bodies_folder
from rbi.bench.timing import clocked, in_turn, measure

TARGETS = {"ratio_linear_to_plain": 5.0, "monte_carlo_s": 1.0}


def toleranced(text: str) -> str:
    """``text`` (a spec of :func:`rbi.bench.largespec.spec_text`) with ± on every number of its
    parts: 1 % on a mass, density or radius, ± 0.001 on each coordinate."""
    scalars = re.compile(r"((?:mass|density|radius): [-0-9.e]+)")
    coordinates = re.compile(r"(-?[0-9][0-9.e-]*)(?=[,\]])")
    lines = text.splitlines(keepends=True)
    return "".join(coordinates.sub(r"\1 ± 0.001", scalars.sub(r"\1 ± 1%", line)) for line in lines)


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    parts, draws = 200 if quick else 1000, 100_000
    progress(f"uncertainty: linear budget of {parts:,} toleranced parts")
    plain, marked = folder / "parts.yaml", folder / "parts_toleranced.yaml"
    plain.write_text(spec_text(parts, "cone,cylinder,point", seed=1))
    marked.write_text(toleranced(plain.read_text()))
    plain_call = lambda: rbi.load(plain).principal()  # noqa: E731
    linear_call = lambda: rbi.load(marked).uncertainty()  # noqa: E731
    linear_call()  # imports and first calls outside the timings
    plain_timing, linear = in_turn([partial(measure, plain_call, 1), partial(measure, linear_call, 1)], 5)
    progress(f"uncertainty: {draws:,} Monte Carlo draws of the toleranced bolted top")
    top = rbi.load(bodies_folder() / "top_bolted_toleranced.yaml")
    monte_carlo = partial(top.uncertainty, method="monte-carlo", samples=draws, seed=1)
    first_s = clocked(monte_carlo)[0]
    mc = measure(monte_carlo, min_repeats=3)
    return {
        "parts": parts,
        "plain_s": plain_timing.median,
        "linear_s": linear.median,
        "plain_cpu_s": plain_timing.cpu_median,
        "linear_cpu_s": linear.cpu_median,
        "rounds": linear.repeats,
        "ratio_linear_to_plain": linear.cpu_median / plain_timing.cpu_median,
        "draws": draws,
        "monte_carlo_s": mc.median,
        "monte_carlo_cpu_s": mc.cpu_median,
        "monte_carlo_first_s": first_s,
        "monte_carlo_repeats": mc.repeats,
        "targets": TARGETS,
    }
