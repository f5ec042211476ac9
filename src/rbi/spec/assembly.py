"""``shape: assembly`` part by part: each sub-assembly of a body replaced by its own parts
(``rbi parts --expand``). The sub-assemblies are read by :func:`rbi.spec.load.read_assemblies`
and translated as one part each by :func:`rbi.spec.translate.assembly_element`."""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from rbi.core.mass import MassProperties
from rbi.errors import InputError
from rbi.spec import models
from rbi.spec.geometry import part_count
from rbi.spec.pattern import copy_motions
from rbi.spec.translate import rotation_matrix
from rbi.spec.units import LENGTH_UNITS_IN_M, convert_body

MAX_EXPANDED = 100_000
"""Most parts ``rbi parts --expand`` lists (patterns of patterns multiply)."""


class Expanded(NamedTuple):
    """The parts of a body, one a row: ``names``, ``parts`` (the spec models; None for the point
    cloud), ``elements`` (a stack, body frame and units) and ``lengths`` (each part's spec's
    length unit in the body's, for its volume)."""

    names: list[str]
    parts: list[Any]
    elements: MassProperties
    lengths: list[float]


def expanded(loaded, expand: bool = True, seen: dict | None = None) -> Expanded:
    """The parts of a :class:`~rbi.spec.translate.LoadedBody` in file order, each sub-assembly
    replaced by its parts when ``expand``, named ``ASSEMBLY/PART`` (``ASSEMBLY[i]/PART`` for the
    copies of a pattern) and placed in the body. InputError past :data:`MAX_EXPANDED` parts.
    ``seen``: the sub-assemblies expanded so far, by file and units (each is listed once)."""
    if expand and seen is None and part_count(loaded, MAX_EXPANDED) > MAX_EXPANDED:
        raise InputError(f"{loaded.path}: more than {MAX_EXPANDED:,} parts to list")
    spec = loaded.spec
    parts = list(spec.parts)
    ratio = LENGTH_UNITS_IN_M[spec.units.length] / LENGTH_UNITS_IN_M[loaded.length_unit]
    rows = Expanded([], [], MassProperties.concatenate(list(loaded.elements)), [])
    pieces = []
    for i, element in enumerate(loaded.elements):
        part = parts[i] if i < len(parts) else None
        name = loaded.part_names[i] or f"parts[{i}]"
        if not expand or not isinstance(part, models.AssemblyPart):
            rows.names.append(name)
            rows.parts.append(part)
            rows.lengths.append(ratio)
            pieces.append(rows.elements[i : i + 1])
            continue
        seen, key = {} if seen is None else seen, (id(part._loaded), loaded.length_unit, loaded.mass_unit)
        if key not in seen:  # in this body's units
            seen[key] = expanded(convert_body(part._loaded, *key[1:]), True, seen)
        inner, motions = seen[key], copy_motions(part.pattern)
        scale = 1.0 if part.mass is None else element.mass / (inner.elements.mass.sum() * len(motions))
        placed = inner.elements.scaled(scale).transformed(
            rotation_matrix(part.rotation), np.multiply(part.position, ratio)
        )
        for k, (R, t) in enumerate(motions):
            copy = name if len(motions) == 1 else f"{name}[{k}]"
            rows.names.extend(f"{copy}/{each}" for each in inner.names)
            rows.parts.extend(inner.parts)
            rows.lengths.extend(inner.lengths)
            pieces.append(placed.transformed(R, t * ratio))
    return rows._replace(elements=MassProperties.concatenate(pieces))
