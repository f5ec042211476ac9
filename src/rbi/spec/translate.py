"""The one place where validated spec models become core inputs (plain floats and arrays)."""

from __future__ import annotations

from typing import Callable

import numpy as np

from rbi.core import shapes
from rbi.core.inertia import combine_elements
from rbi.spec import models
from rbi.spec.errors import InputError


def _solid_mass(part, volume: float) -> float:
    return part.mass if part.mass is not None else part.density * volume


def cone_element(part: models.ConePart) -> shapes.MassElement:
    height = float(np.linalg.norm(np.subtract(part.base, part.apex)))
    mass = _solid_mass(part, shapes.cone_volume(part.radius, height))
    return shapes.cone(mass, part.radius, part.apex, part.base)


def cylinder_element(part: models.CylinderPart) -> shapes.MassElement:
    length = float(np.linalg.norm(np.subtract(part.end, part.start)))
    mass = _solid_mass(part, shapes.cylinder_volume(part.radius, length))
    return shapes.cylinder(mass, part.radius, part.start, part.end)


def point_element(part: models.PointPart) -> shapes.MassElement:
    return shapes.point(part.mass, part.position)


ELEMENT_BUILDERS: dict[type, Callable[..., shapes.MassElement]] = {
    models.ConePart: cone_element,
    models.CylinderPart: cylinder_element,
    models.PointPart: point_element,
}


def part_label(index: int, part) -> str:
    return f"parts[{index}]" + (f" ({part.name})" if part.name else "")


def body_from_spec(spec: models.BodySpec, path: str):
    """Translate a validated :class:`~rbi.spec.models.BodySpec` into a
    :class:`~rbi.spec.load.LoadedBody`."""
    from rbi.spec.load import LoadedBody

    elements = []
    for i, part in enumerate(spec.parts):
        element = ELEMENT_BUILDERS[type(part)](part)
        if not (np.isfinite(element.mass) and np.all(np.isfinite(element.inertia_com))):
            raise InputError(f"{path}: {part_label(i, part)}: numbers too large: mass or inertia overflows")
        elements.append(element)
    part_names = [p.name for p in spec.parts]
    if spec.point_cloud is not None:  # the whole cloud enters as one part, reduced vectorised
        from rbi.spec.point_cloud import cloud_element

        elements.append(cloud_element(path, spec.point_cloud.file))
        part_names.append("point_cloud")
    try:
        props = combine_elements(elements)
    except ValueError as exc:
        raise InputError(f"{path}: {exc}") from None
    pivot = None if spec.pivot is None else np.asarray(spec.pivot, dtype=float)
    return LoadedBody(
        path=path,
        name=spec.name,
        length_unit=spec.units.length,
        mass_unit=spec.units.mass,
        props=props,
        pivot=pivot,
        elements=elements,
        part_names=part_names,
        expect=spec.expect,
        spec=spec,
    )
