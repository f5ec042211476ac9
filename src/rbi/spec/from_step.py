"""A spec for a STEP file (what ``rbi import FILE.step`` prints): one ``shape: step`` part per
solid of the file, named after the solid, in SI units (the reader honours the file's own
length unit, so the spec needs no scale)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rbi.core.validity import finite
from rbi.errors import ArgumentError, InputError, literal
from rbi.formats.step import read_step
from rbi.reprs import Result, Rows
from rbi.spec.materials import canonical_name, density_in_units, unknown_material_message
from rbi.spec.yaml_writer import comment, dump
from rbi.text import number

DEFAULT_DENSITY = 1000.0
"""Density (kg/m³) of the imported parts when none is given: water's, a placeholder to replace."""


@dataclass(frozen=True)
class StepImport(Result):
    """What importing a STEP file gives (an :class:`rbi.Result`): ``spec`` (a plain dict, keys
    in the order YAML prints them, every part filled with ``density`` kg/m³ or the ``material``
    name), the file's ``solids`` (:class:`rbi.formats.step.StepSolid`, unit density, metres),
    its declared length ``unit``, and ``density`` (kg/m³, the material's when one was named).
    Its JSON, CSV and table all come from :meth:`csv_rows`, one row a solid."""

    spec: dict[str, Any]
    solids: tuple
    unit: str
    density: float
    placeholder: bool
    path: str = ""

    def yaml(self) -> str:
        """The spec as YAML text under a comment header: what ``rbi import FILE.step`` prints."""

        lines = [
            f"rbi import of {os.path.basename(self.path)}: one part per solid, integrated on the exact STEP geometry;",
            "SI units (the file's own length unit is honoured), the file's origin and axes.",
        ]
        if self.placeholder:
            lines.append(
                f"density: {self.density:g} kg/m³ is a placeholder: give yours (--density D or --material NAME)."
            )
        return comment(*lines) + dump(self.spec)

    def csv_rows(self) -> list[dict[str, Any]]:
        """Each solid at the spec's density, SI: what ``rbi import FILE.step --format csv``
        prints, one row a solid."""
        return [
            {
                "name": solid.name,
                "index": i,
                "volume": solid.volume,
                **solid.props.scaled(self.density).to_dict(),
                "integration_error": solid.integration_error,
            }
            for i, solid in enumerate(self.solids)
        ]

    def rows(self) -> list[Rows]:
        """One table: each solid's volume and mass at the spec's density."""
        cells = [(row["name"], number(row["volume"], 6), number(row["mass"], 6)) for row in self.csv_rows()]
        title = f"{self.path}: {len(cells)} solid(s) at {self.density:g} kg/m³"
        return [Rows(title, ("solid", "volume [m³]", "mass [kg]"), cells)]

    def to_dict(self) -> dict[str, Any]:
        """What ``rbi import FILE.step --format json`` prints, less ``"file"``."""
        return {
            "format": "step",
            "file_unit": self.unit,
            "units": {"length": "m", "mass": "kg"},
            "density": self.density,
            "solids": self.csv_rows(),
        }


def _fill(density: float | None, material: str | None) -> float | str:
    """What fills every solid: ``material``, ``density`` (kg/m³) or the placeholder density;
    ArgumentError naming the parameter when either is wrong or both are given."""
    if density is not None and material is not None:
        raise ArgumentError(("density", "material"), "give one of them, not both")
    if density is not None and not (finite(density) and density > 0):
        raise ArgumentError("density", f"must be a positive number (kg/m³), got {literal(density)}")
    if material is not None and (not isinstance(material, str) or canonical_name(material) is None):
        raise ArgumentError("material", literal(unknown_material_message(str(material)), quoted=False))
    return material if material is not None else density if density is not None else DEFAULT_DENSITY


def import_step(
    path: str | os.PathLike,
    *,
    density: float | None = None,
    material: str | None = None,
    relative_to: str | os.PathLike | None = None,
) -> StepImport:
    """Read a STEP file as ``rbi import FILE.step`` does (needs the extra
    ``cad``): its solids integrated on the exact geometry, and a spec with one ``shape:
    step`` part per solid naming the file relative to the folder ``relative_to`` (default: the
    current folder), where the spec will be saved. ``density`` (kg/m³) or ``material`` (a
    built-in name) fills every part (default 1000 kg/m³, a placeholder). Returns a `StepImport`:
    ``.spec`` (SI units, the file's origin and axes), ``.solids`` (``.props`` at unit density
    in metres), ``.unit`` (the file's), ``.density`` (kg/m³). SpecError (its line starting with
    ``path``): unreadable, not STEP, no closed solid, OpenCascade missing; ArgumentError naming
    ``density`` or ``material``."""

    fill = _fill(density, material)
    home = os.path.abspath(relative_to) if relative_to is not None else os.getcwd()
    file = os.path.abspath(path)
    if not os.path.isfile(file):
        what = "not a regular file" if os.path.exists(file) else "no such file"
        raise InputError(f"{path}: {what}", file=str(path))
    try:
        step = read_step(Path(file))
    except ValueError as exc:
        raise InputError(f"{path}: {exc}", file=str(path)) from None
    written = os.path.relpath(file, home)
    parts = [
        {"name": solid.name, "shape": "step", "file": written, "solid": solid.name, "density": fill}
        for solid in step.solids
    ]
    spec = {"name": Path(file).stem, "units": {"length": "m", "mass": "kg"}, "parts": parts}
    kg_per_m3 = density_in_units(material, "m", "kg") if material is not None else float(fill)
    placeholder = density is None and material is None
    return StepImport(spec, step.solids, step.unit, kg_per_m3, placeholder, os.fspath(path))
