"""A spec for a STEP file (what ``rbi import FILE.step`` prints): one ``shape: step`` part per
solid of the file, named after the solid, in SI units (the reader honours the file's own
length unit, so the spec needs no scale)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

DEFAULT_DENSITY = 1000.0
"""Density (kg/m³) of the imported parts when none is given: water's, a placeholder to replace."""


def step_spec(
    path: Path, file_in_spec: str, density: float | None = None, material: str | None = None
) -> dict[str, Any]:
    """The spec (a plain dict, keys in the order YAML prints them) of the STEP file at
    ``path``, which the spec names ``file_in_spec``. ``density`` (kg/m³) or ``material`` (a
    built-in name) fill every part; with neither, :data:`DEFAULT_DENSITY`. Raises
    ``ValueError`` from the reader for a file it cannot read."""
    from rbi.formats.step import read_step

    step = read_step(path)
    fill: float | str = (
        material if material is not None else density if density is not None else DEFAULT_DENSITY
    )
    parts = [
        {"name": solid.name, "shape": "step", "file": file_in_spec, "solid": solid.name, "density": fill}
        for solid in step.solids
    ]
    return {"name": Path(path).stem, "units": {"length": "m", "mass": "kg"}, "parts": parts}
