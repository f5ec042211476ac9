"""Parts of the common shapes (cone, cylinder, sphere, box, point) built as ``rbi`` builds them:
a spec of one part, validated and translated by the stacked path of :mod:`rbi.spec.translate`
(the one path of every spec). Each helper takes a part's numbers in the order the closed-form
checks of the core write them, SI, body frame."""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.core.mass import MassProperties
from rbi.spec.load import spec_from_raw
from rbi.spec.translate import part_element


def part(shape: str, **fields: Any) -> MassProperties:
    """The mass element of one part of ``shape`` with ``fields`` (numbers or arrays)."""
    written = {key: np.asarray(value, dtype=float).tolist() for key, value in fields.items()}
    spec = spec_from_raw("<test>", {"parts": [{"shape": shape, **written}]})
    return part_element(spec.parts[0], spec.units, "<test>")


def cone(mass, radius, apex, base) -> MassProperties:
    return part("cone", mass=mass, radius=radius, apex=apex, base=base)


def cylinder(mass, radius, start, end) -> MassProperties:
    return part("cylinder", mass=mass, radius=radius, start=start, end=end)


def sphere(mass, radius, center) -> MassProperties:
    return part("sphere", mass=mass, radius=radius, center=center)


def point(mass, position) -> MassProperties:
    return part("point", mass=mass, position=position)


def box(mass, size, center, rotation=None) -> MassProperties:
    """A box with edges ``size`` along its own axes, turned by the matrix ``rotation`` (part
    axes to body axes) about its ``center``."""
    aligned = part("box", mass=mass, size=size, center=[0.0, 0.0, 0.0])
    return aligned.transformed(rotation=rotation, translation=center)
