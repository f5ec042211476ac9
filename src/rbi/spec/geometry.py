"""What each part looks like, for pictures: the solids of a spec as a few drawable primitives,
derived from the validated models in this one place.

Every solid is one of:

- ``{"kind": "frustum", "start", "end", "start_radius", "end_radius", "inner_radius"}``: cones,
  cylinders, tubes, frusta and rods (a rod gets a radius of 1 % of its length);
- ``{"kind": "ellipsoid", "center", "semi_axes", "rotation"}``: spheres, shells, ellipsoids;
- ``{"kind": "box", "center", "size", "rotation"}``: boxes, and any part without a drawable
  shape of its own (custom parts, point clouds, shapes added later), drawn as the uniform box
  with the same mass and principal moments about the same centre (``"stand_in": true``);
- ``{"kind": "point", "position"}``: point masses.

Each also has ``name``, ``shape`` (as written), ``hole`` (a subtracted solid) and ``mass``.
Coordinates are body-frame, in the file's length unit; ``rotation`` is a 3×3 matrix (rows),
part axes to body axes.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rbi.spec import models

ROD_RADIUS_FRACTION = 0.01


def part_geometry(body) -> list[dict[str, Any]]:
    """The drawable primitives of a :class:`~rbi.spec.load.LoadedBody`, one per part in file
    order (a point cloud as one stand-in box)."""
    spec = body.spec
    out = []
    parts = list(spec.parts) if spec is not None else []
    for index, element in enumerate(body.elements):
        part = parts[index] if index < len(parts) else None
        shape = part.shape if part is not None else "point_cloud"
        item = _primitive(part) if part is not None else None
        if item is None:
            item = _stand_in(element)
        item |= {"name": body.part_names[index] if index < len(body.part_names) else None, "shape": shape,
                 "hole": bool(getattr(part, "subtract", False)), "mass": float(element.mass)}
        out.append(item)
    return out


def _vector(v) -> list[float]:
    return [float(x) for x in v]


def _primitive(part) -> dict[str, Any] | None:
    from rbi.spec.translate import rotation_matrix

    if isinstance(part, models.ConePart):
        return _frustum(part.apex, part.base, 0.0, part.radius)
    if isinstance(part, models.CylinderPart):
        return _frustum(part.start, part.end, part.radius, part.radius)
    if isinstance(part, models.TubePart):
        return _frustum(part.start, part.end, part.outer_radius, part.outer_radius, part.inner_radius)
    if isinstance(part, models.FrustumPart):
        return _frustum(part.start, part.end, part.start_radius, part.end_radius)
    if isinstance(part, models.RodPart):
        radius = ROD_RADIUS_FRACTION * float(np.linalg.norm(np.subtract(part.end, part.start)))
        return _frustum(part.start, part.end, radius, radius)
    if isinstance(part, models.SpherePart):
        return _ellipsoid(part.center, [part.radius] * 3, None)
    if isinstance(part, models.SphericalShellPart):
        return _ellipsoid(part.center, [part.outer_radius] * 3, None)
    if isinstance(part, models.EllipsoidPart):
        return _ellipsoid(part.center, part.semi_axes, rotation_matrix(part.rotation))
    if isinstance(part, models.BoxPart):
        R = rotation_matrix(part.rotation)
        return {"kind": "box", "center": _vector(part.center), "size": _vector(part.size),
                "rotation": (np.eye(3) if R is None else R).tolist()}
    if isinstance(part, models.PointPart):
        return {"kind": "point", "position": _vector(part.position)}
    return None


def _frustum(start, end, start_radius, end_radius, inner_radius=0.0) -> dict[str, Any]:
    return {"kind": "frustum", "start": _vector(start), "end": _vector(end), "start_radius": float(start_radius),
            "end_radius": float(end_radius), "inner_radius": float(inner_radius)}


def _ellipsoid(center, semi_axes, R) -> dict[str, Any]:
    return {"kind": "ellipsoid", "center": _vector(center), "semi_axes": _vector(semi_axes),
            "rotation": (np.eye(3) if R is None else R).tolist()}


def _stand_in(element) -> dict[str, Any]:
    """The uniform box with the element's mass and principal moments about its centre of mass:
    edges a_k² = 6 (I_i + I_j − I_k) / m along the principal axes."""
    from rbi.core.inertia import principal_axes

    mass = abs(float(element.mass))
    moments, axes = principal_axes(np.sign(element.mass) * np.asarray(element.inertia_com, dtype=float))
    if mass == 0.0:
        size = np.zeros(3)
    else:
        total = float(np.sum(moments))
        size = np.sqrt(np.maximum(6.0 * (total - 2.0 * moments) / mass, 0.0))
    return {"kind": "box", "center": _vector(element.com), "size": size.tolist(), "rotation": axes.T.tolist(),
            "stand_in": True}
