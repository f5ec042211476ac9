"""``shape: assembly`` part by part: each sub-assembly of a body replaced by its own parts
(``rbi parts --expand``). The sub-assemblies are read by :func:`rbi.spec.load.read_assemblies`
and translated as one part each by :func:`rbi.spec.translate.assembly_element`."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.core.mass import MassProperties
from rbi.errors import InputError
from rbi.spec import models
from rbi.spec.pattern import copy_motions
from rbi.spec.translate import rotation_matrix
from rbi.spec.units import LENGTH_UNITS_IN_M, convert_body

MAX_EXPANDED = 1_000_000
"""Most parts ``rbi parts --expand`` lists (patterns of patterns multiply)."""


def expanded(loaded, expand: bool = True) -> list[tuple[str, Any, MassProperties, float]]:
    """``(name, part, element, length)`` of every part of a :class:`~rbi.spec.translate.LoadedBody`
    in file order (``part`` None for the point cloud), each sub-assembly replaced by its parts
    when ``expand``, named ``ASSEMBLY/PART`` (``ASSEMBLY[i]/PART`` for the copies of a pattern)
    and placed in the body (its units); ``length`` is the part's spec's length unit in the body's
    (for its volume). InputError past :data:`MAX_EXPANDED` parts."""
    spec = loaded.spec
    parts = list(spec.parts) if spec is not None else []
    ratio = (
        1.0 if spec is None else LENGTH_UNITS_IN_M[spec.units.length] / LENGTH_UNITS_IN_M[loaded.length_unit]
    )
    rows: list[tuple[str, Any, MassProperties, float]] = []
    for i, element in enumerate(loaded.elements):
        part = parts[i] if i < len(parts) else None
        name = loaded.part_names[i] or f"parts[{i}]"
        if not expand or not isinstance(part, models.AssemblyPart):
            rows.append((name, part, element, ratio))
            continue
        sub = convert_body(part._loaded, loaded.length_unit, loaded.mass_unit)
        inner = expanded(sub)
        R, position = rotation_matrix(part.rotation), np.asarray(part.position, dtype=float)
        motions = copy_motions(part.pattern)
        scale = 1.0 if part.mass is None else element.mass / (sub.props.mass * len(motions))
        if len(rows) + len(inner) * len(motions) > MAX_EXPANDED:
            raise InputError(f"{loaded.path}: more than {MAX_EXPANDED:,} parts to list")
        for k, (Rc, tc) in enumerate(motions):
            copy = name if len(motions) == 1 else f"{name}[{k}]"
            for sub_name, sub_part, sub_element, length in inner:
                placed = sub_element.scaled(scale).transformed(R, position * ratio)
                rows.append((f"{copy}/{sub_name}", sub_part, placed.transformed(Rc, tc * ratio), length))
    return rows
