"""Translating many plain parts at once: the parts of the common shapes (point, cylinder, cone,
sphere, box without rotation) that carry no ``pattern`` are gathered by shape and their mass
elements computed with whole-array arithmetic by the closed forms of :mod:`rbi.core.shapes`
(its volume, centre-of-mass and inertia functions take arrays), so the same numbers to within a
rounding or two of the lengths (tested against the per-part path in
``tests/spec/test_translate_batch.py``).

:func:`batch_elements` returns the elements it could build, by part index; every other part
(other shapes, patterns, rotations, a density naming an unknown material, any part whose
numbers fail) is left to the per-part path of :func:`rbi.spec.translate.body_from_spec`, which
then reports errors naming the part exactly as before.

Used for specs of at least :data:`MIN_PARTS` parts (below that the per-part path is as fast).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from rbi.core import shapes
from rbi.core.mass import MassProperties
from rbi.core.rotation import vector_length
from rbi.spec import models
from rbi.spec.materials import density_in_units

MIN_PARTS = 64
"""Specs with fewer parts are translated part by part."""


def _densities(parts: list, units: models.Units) -> tuple[np.ndarray, np.ndarray]:
    """``(mass_given, density)`` per part (NaN where not given); ``density`` NaN also where a
    material name cannot be looked up (the per-part path will say why)."""
    n = len(parts)
    mass = np.full(n, np.nan)
    density = np.full(n, np.nan)
    looked_up: dict[str, float] = {}
    for i, part in enumerate(parts):
        if part.mass is not None:
            mass[i] = part.mass
            continue
        d = part.density
        if isinstance(d, str):
            if d not in looked_up:
                try:
                    looked_up[d] = density_in_units(d, units.length, units.mass)
                except (ValueError, KeyError):
                    looked_up[d] = math.nan
            d = looked_up[d]
        density[i] = math.nan if d is None else d
    return mass, density


class Columns:
    """One part's fields as columns of ``n`` values, for the builders below: the part's own
    value everywhere but where ``values`` (by field, or ``(field, component)``) gives a column
    (Monte Carlo draws and the steps of sensitivities, :mod:`rbi.spec.uncertain`)."""

    def __init__(self, part: Any, n: int, values: dict[tuple[Any, ...], np.ndarray]) -> None:
        self.part, self.n, self.values = part, n, values

    def __len__(self) -> int:
        return self.n

    def column(self, field: str) -> np.ndarray:
        nominal = getattr(self.part, field)
        if isinstance(nominal, (list, tuple)):
            return np.stack(
                [self.values.get((field, j), np.full(self.n, float(x))) for j, x in enumerate(nominal)], 1
            )
        return self.values.get((field,), np.full(self.n, float(nominal)))

    def masses(self, units: models.Units, volume: np.ndarray) -> np.ndarray:
        if self.part.mass is not None:
            return self.column("mass")
        if isinstance(self.part.density, str):
            return density_in_units(self.part.density, units.length, units.mass) * volume
        return self.column("density") * volume


def _solid_masses(parts: Any, units: models.Units, volume: np.ndarray) -> np.ndarray:
    if isinstance(parts, Columns):
        return parts.masses(units, volume)
    given, density = _densities(parts, units)
    return np.where(np.isnan(given), density * volume, given)


def _vectors(parts: Any, field: str) -> np.ndarray:
    if isinstance(parts, Columns):
        return parts.column(field)
    return np.array([getattr(p, field) for p in parts], dtype=float).reshape(len(parts), 3)


def _scalars(parts: Any, field: str) -> np.ndarray:
    if isinstance(parts, Columns):
        return parts.column(field)
    return np.array([getattr(p, field) for p in parts], dtype=float)


def _points(parts, units):
    masses = _scalars(parts, "mass")
    return masses, _vectors(parts, "position"), np.zeros((len(parts), 3, 3))


def _cylinders(parts, units):
    radius = _scalars(parts, "radius")
    start, end = _vectors(parts, "start"), _vectors(parts, "end")
    d = end - start
    length = vector_length(d)
    mass = _solid_masses(parts, units, shapes.cylinder_volume(radius, length))
    axial, transverse = shapes.cylinder_moments(mass, radius, length)
    u = d / length[:, None]
    return mass, shapes.middle(start, end), shapes.axisymmetric_inertia(axial, transverse, u)


def _cones(parts, units):
    radius = _scalars(parts, "radius")
    apex, base = _vectors(parts, "apex"), _vectors(parts, "base")
    d = base - apex
    height = vector_length(d)
    mass = _solid_masses(parts, units, shapes.cone_volume(radius, height))
    u = d / height[:, None]
    com = shapes.cone_center_of_mass(apex, u, height)
    axial, transverse = shapes.cone_moments(mass, radius, height)
    return mass, com, shapes.axisymmetric_inertia(axial, transverse, u)


def _spheres(parts, units):
    radius = _scalars(parts, "radius")
    mass = _solid_masses(parts, units, shapes.sphere_volume(radius))
    return mass, _vectors(parts, "center"), shapes.sphere_inertia(mass, radius)


def _boxes(parts, units):
    size = _vectors(parts, "size")
    mass = _solid_masses(parts, units, shapes.box_volume(size))
    return mass, _vectors(parts, "center"), shapes.box_inertia(mass, size)


BUILDERS = {
    models.PointPart: _points,
    models.CylinderPart: _cylinders,
    models.ConePart: _cones,
    models.SpherePart: _spheres,
    models.BoxPart: _boxes,
}
"""Each batched part model's ``(parts, units) -> (mass (n,), com (n, 3), inertia (n, 3, 3))``."""


def _fields(kind: type) -> set[str]:
    return set(getattr(kind, "model_fields", {}))


def plain_part(part: Any) -> bool:
    """Whether a part of a batched shape may be built by :data:`BUILDERS` (no pattern, no rotation)."""
    return _plain(part, _fields(type(part)))


def _plain(part: Any, fields: set[str]) -> bool:
    """No pattern of more than one copy, no rotation (fields looked up only where the model has
    them: a missing attribute on a pydantic model is slow to ask for)."""
    if "pattern" in fields and part.pattern is not None and part.pattern.count > 1:
        return False
    return "rotation" not in fields or part.rotation is None


WITHOUT_OWN_MOMENTS = ("point", "custom", "assembly")
"""Shapes whose moments about their own centre may be zero: a point mass, and moments given as
written. Every other shape with a mass has moments of its own."""


SMALLEST_MOMENT = 1e9 * float(np.finfo(float).smallest_subnormal)
"""Below this (4.9e-315) a double keeps fewer than 9 significant digits: moments there have lost
their digits or vanished (subnormal moments above it, such as a ball of the smallest normal mass,
keep 12 and are computed)."""


def moments_lost(inertia: np.ndarray, shape: str) -> np.ndarray:
    """Whether the moments of solids of ``shape`` (inertia ``(..., 3, 3)`` about their own centre)
    underflowed: all below :data:`SMALLEST_MOMENT`, so they would print as zeros or as digits-less
    subnormals (a mass of 1e-300 with a size of 1e-160: the true moments are 1e-620)."""
    largest = np.max(np.abs(np.diagonal(inertia, axis1=-2, axis2=-1)), axis=-1)
    return np.asarray((shape not in WITHOUT_OWN_MOMENTS) & (largest < SMALLEST_MOMENT))


def batch_elements(parts: list, units: models.Units) -> tuple[dict[int, MassProperties], set[int]]:
    """``(elements, holes)``: the mass elements (file units, as written: not negated) of the
    plain parts of the batched shapes, by index in ``parts``, and which of those indices are
    holes (``subtract: true``). Parts left out go through the per-part path; so do elements
    whose numbers are not all finite or whose moments underflowed (:func:`moments_lost`), so
    that the per-part path reports them naming the part."""
    groups: dict[type, list[int]] = {}
    fields_of: dict[type, set[str]] = {}
    for i, part in enumerate(parts):
        kind = type(part)
        if kind not in BUILDERS:
            continue
        fields = fields_of.get(kind)
        if fields is None:
            fields = fields_of[kind] = _fields(kind)
        if _plain(part, fields):
            groups.setdefault(kind, []).append(i)
    out: dict[int, MassProperties] = {}
    holes: set[int] = set()
    for kind, indices in groups.items():
        chosen = [parts[i] for i in indices]
        with np.errstate(all="ignore"):
            mass, com, inertia = BUILDERS[kind](chosen, units)
            finite = (
                np.isfinite(mass)
                & np.all(np.isfinite(com), axis=1)
                & np.all(np.isfinite(inertia), axis=(1, 2))
                & ~moments_lost(inertia, chosen[0].shape)
            )
        masses = mass.tolist()
        ok = finite.tolist()
        for k, i in enumerate(indices):
            if ok[k]:
                out[i] = MassProperties(masses[k], com[k], inertia[k])
        if "subtract" in fields_of[kind]:
            holes.update(i for i, part in zip(indices, chosen) if part.subtract and i in out)
    return out, holes
