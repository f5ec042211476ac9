"""The volume of each solid part of a spec (one copy, and all copies of a ``pattern``), in the
file's length unit cubed: the one table the translation, the parts report and the unit-slip
rule read."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from rbi.core import shapes
from rbi.core.rotation import numbers, scalar
from rbi.spec import models


def _length(start, end) -> float:
    """|end − start|, file length unit."""
    d = numbers(np.subtract(end, start))
    return scalar(np.sqrt(np.sum(d * d)) if d.dtype.kind == "c" else np.linalg.norm(d))


PART_VOLUMES: dict[type, Callable[[object], float]] = {
    models.ConePart: lambda p: shapes.cone_volume(p.radius, _length(p.apex, p.base)),
    models.CylinderPart: lambda p: shapes.cylinder_volume(p.radius, _length(p.start, p.end)),
    models.BoxPart: lambda p: shapes.box_volume(p.size),
    models.SpherePart: lambda p: shapes.sphere_volume(p.radius),
    models.SphericalShellPart: lambda p: shapes.spherical_shell_volume(p.outer_radius, p.inner_radius),
    models.TubePart: lambda p: shapes.tube_volume(p.outer_radius, p.inner_radius, _length(p.start, p.end)),
    models.FrustumPart: lambda p: shapes.frustum_volume(
        p.start_radius, p.end_radius, _length(p.start, p.end)
    ),
    models.EllipsoidPart: lambda p: shapes.ellipsoid_volume(p.semi_axes),
    models.TorusPart: lambda p: shapes.torus_volume(p.major_radius, p.minor_radius),
    models.HemispherePart: lambda p: shapes.hemisphere_volume(p.radius),
    models.CapsulePart: lambda p: shapes.capsule_volume(p.radius, _length(p.start, p.end)),
    models.PrismPart: lambda p: shapes.prism_volume(p.outline, p.holes, p.start, p.end),
    models.MeshPart: lambda p: p._enclosed_volume,  # known once the mesh has been read
    models.StepPart: lambda p: p._step_volume,  # known once the STEP file has been read
}
"""Volume (L³) of each solid part model; points, rods and custom parts have none."""


def one_volume(part) -> float | None:
    """The volume of one copy of a solid part (L³); inf when it overflows a double, None for a
    mesh or STEP part not yet read."""
    one = PART_VOLUMES[type(part)](part)
    return one if one is None else scalar(one)


def part_volume(part) -> float | None:
    """The part's volume in the file's length unit cubed (all copies of a ``pattern``), or None
    for a part without one (or a mesh not yet read)."""
    one = one_volume(part) if type(part) in PART_VOLUMES else None
    if one is None:
        return None
    return float(one) * (1 if part.pattern is None else part.pattern.count)
