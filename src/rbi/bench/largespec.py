"""Large specs (issue 9): the whole load of a YAML spec of 10⁵ point masses and of one of 10⁴
cylinders (``rbi.spec.load.load_body``: YAML, validation, translation, the mass-property sums)
against a bare ``yaml.load(f, Loader=yaml.CSafeLoader)`` of the same file in a plain Python,
measured in the same run (target: at most 0.5×). The measurement itself is
:func:`rbi.bench.yaml_load.yaml_load_ratio`; a quick run uses 10⁴ point masses and 10³
cylinders.
"""

from __future__ import annotations

from collections.abc import Callable

from rbi.bench.yaml_load import yaml_load_ratio

Progress = Callable[[str], None]

TARGET = 0.5


def cases(quick: bool) -> list[tuple[int, str]]:
    if quick:
        return [(10**4, "point"), (10**3, "cylinder")]
    return [(10**5, "point"), (10**4, "cylinder")]


def planned_steps(quick: bool) -> int:
    return len(cases(quick))


def run(quick: bool, progress: Progress = lambda _: None) -> dict:
    specs = []
    for n, shape in cases(quick):
        progress(f"large specs: {n:,} × {shape}")
        try:
            row = dict(yaml_load_ratio(n, shape))
        except Exception as exc:  # a failed measurement is a row, not the end of the bench
            row = {"error": f"{type(exc).__name__}: {exc}"}
        row.setdefault("n_parts", n)
        row.setdefault("shape", shape)
        specs.append(row)
    return {"target": TARGET, "specs": specs}
