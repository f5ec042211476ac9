"""What each part looks like, for pictures: the solids of a spec as a few drawable primitives,
derived from the validated models in this one place.

Every solid is one of:

- ``{"kind": "frustum", "start", "end", "start_radius", "end_radius", "inner_radius"}``: cones,
  cylinders, tubes, frusta and rods (a rod gets a radius of 1 % of its length);
- ``{"kind": "ellipsoid", "center", "semi_axes", "rotation"}``: spheres, shells, ellipsoids;
- ``{"kind": "box", "center", "size", "rotation"}``: boxes, and any part without a drawable
  shape of its own (custom parts, point clouds, shapes added later), drawn as the uniform box
  with the same mass and principal moments about the same centre (``"stand_in": true``);
- ``{"kind": "torus", "center", "axis", "major_radius", "minor_radius"}``;
- ``{"kind": "hemisphere", "center", "axis", "radius"}`` (``center`` of the flat face, ``axis``
  unit, into the dome);
- ``{"kind": "capsule", "start", "end", "radius"}``;
- ``{"kind": "mesh", "vertices", "faces"}`` (body frame; a mesh of more than
  :data:`MAX_DRAWN_TRIANGLES` triangles is drawn as its stand-in box);
- ``{"kind": "point", "position"}``: point masses;
- ``{"kind": "points", "positions"}``: the points of a ``point_cloud`` file (a cloud of more
  than :data:`MAX_DRAWN_POINTS` points is drawn as its stand-in box).

A part with a ``pattern`` gives one primitive per copy, a sub-assembly one per part of each
copy. Each primitive also has ``part`` (the index of the written part it comes from), ``copy``
(which copy of its pattern), ``name``, ``shape`` (as written),
``hole`` (a subtracted solid) and ``mass`` (per copy).
Coordinates are body-frame, in the file's length unit; ``rotation`` is a 3×3 matrix (rows),
part axes to body axes.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from rbi.core.inertia import principal_axes
from rbi.core.polygon import trapezoids
from rbi.core.rotation import unit_vector
from rbi.core.shapes import prism_frame
from rbi.formats.paths import spec_relative_file
from rbi.formats.point_cloud import read_point_cloud
from rbi.spec import models
from rbi.spec.pattern import copy_motions
from rbi.spec.translate import rotation_matrix
from rbi.spec.units import LENGTH_UNITS_IN_M

ROD_RADIUS_FRACTION = 0.01
MAX_DRAWN_TRIANGLES = 20_000
"""Largest mesh drawn triangle by triangle (pages stay small); bigger ones get a stand-in box."""
MAX_DRAWN_POINTS = 5000
"""Largest point cloud drawn point by point."""
MAX_DRAWN_COPIES = 1000
"""Most copies of a patterned part drawn; beyond that the pattern is drawn as one stand-in box."""


def part_geometry(body) -> list[dict[str, Any]]:
    """The drawable primitives of a :class:`~rbi.spec.translate.LoadedBody` in file order: one per
    part, one per copy of a patterned part, and the point cloud's points."""
    spec = body.spec
    out = []
    parts = list(spec.parts)
    for index, element in enumerate(body.elements):
        part = parts[index] if index < len(parts) else None
        shape = part.shape if part is not None else "point_cloud"
        pattern = getattr(part, "pattern", None)
        count = 1 if pattern is None else int(pattern.count)
        assembly = isinstance(part, models.AssemblyPart)
        if part is None:
            items = [_cloud_points(spec, body.path)]
        elif count * (part_count(part._loaded, MAX_DRAWN_COPIES) if assembly else 1) > MAX_DRAWN_COPIES:
            items = [None]  # too many copies to draw (a sub-assembly's parts counted)
        elif assembly:
            items = _assembly(part, body.length_unit)
        else:
            items = [_primitive(part, body.path, body.length_unit)]
        copies = (
            [_stand_in(element)]
            if None in items
            else [
                moved(item, R, t) | {"copy": k}
                for k, (R, t) in enumerate(copy_motions(pattern))
                for item in items
            ]
        )
        for copy in copies:
            copy |= {
                "part": index,
                "name": body.part_names[index] if index < len(body.part_names) else None,
                "shape": shape,
                "hole": bool(copy.get("hole") or getattr(part, "subtract", False)),
                "mass": float(element.mass) / len(copies),
            }
            out.append(copy)
    return out


POINT_KEYS = ("start", "end", "center", "position")
LENGTH_KEYS = ("start_radius", "end_radius", "inner_radius", "radius", "major_radius", "minor_radius")
SIZE_KEYS = ("size", "semi_axes")


def moved(item: dict[str, Any], R: np.ndarray, t: np.ndarray, scale: float = 1.0) -> dict[str, Any]:
    """The primitive turned by ``R`` and moved by ``t`` (x -> R x + t), after its lengths were
    multiplied by ``scale`` (another length unit)."""
    out = dict(item)
    for key in LENGTH_KEYS + SIZE_KEYS:
        if key in out and scale != 1.0:
            out[key] = (np.asarray(out[key], dtype=float) * scale).tolist()
    for key in POINT_KEYS:
        if key in out:
            out[key] = (R @ (scale * np.asarray(out[key], dtype=float)) + t).tolist()
    for key in ("axis", "rotation"):  # directions and the part's axes turn, never move
        if key in out:
            out[key] = (R @ np.asarray(out[key], dtype=float)).tolist()
    for key in ("vertices", "positions"):
        if key in out:
            out[key] = (scale * np.asarray(out[key], dtype=float) @ R.T + t).tolist()
    return out


def part_count(body, most: int) -> int:
    """How many parts ``body`` (a :class:`~rbi.spec.translate.LoadedBody`) has once each
    pattern is copied and each sub-assembly replaced by its parts (the point clouds counted one
    each), counted until past ``most`` (a tree of sub-assemblies is not walked further): how
    many primitives :func:`part_geometry` gives, and rows ``rbi parts --expand`` lists."""
    total = int(body.spec.point_cloud is not None)
    for part in body.spec.parts:
        count = 1 if part.pattern is None else int(part.pattern.count)
        total += count * (part_count(part._loaded, most) if isinstance(part, models.AssemblyPart) else 1)
        if total > most:
            break
    return total


def _assembly(part, length_unit: str) -> list[dict[str, Any] | None]:
    """The sub-assembly's primitives in this body: its lengths in ``length_unit``, turned by
    ``rotation`` about its origin, that origin moved to ``position``."""
    sub = part._loaded
    R = rotation_matrix(part.rotation)
    scale = LENGTH_UNITS_IN_M[sub.length_unit] / LENGTH_UNITS_IN_M[length_unit]
    at = np.asarray(part.position, dtype=float)
    return [moved(item, np.eye(3) if R is None else R, at, scale) for item in part_geometry(sub)]


def _prism(part) -> dict[str, Any] | None:
    """The prism as triangles: both end faces cut into trapezoids, and a wall along each edge."""
    rings = [np.asarray(r, dtype=float) for r in [part.outline, *part.holes]]
    R, length = prism_frame(part.start, part.end, part.x_axis)
    flat = trapezoids(rings[0], rings[1:])
    edges = np.concatenate(
        [np.stack((r, np.roll(r, -1, axis=0), np.roll(r, -1, axis=0), r), axis=1) for r in rings]
    )
    quads = np.concatenate(
        [np.dstack((flat, np.full(flat.shape[:2], z))) for z in (0.0, length)]
        + [np.dstack((edges, np.tile([0.0, 0.0, length, length], (len(edges), 1))))]
    )
    if 2 * len(quads) > MAX_DRAWN_TRIANGLES:
        return None
    vertices = quads.reshape(-1, 3) @ R.T + np.asarray(part.start, dtype=float)
    faces = (4 * np.arange(len(quads))[:, None, None] + [[0, 1, 2], [0, 2, 3]]).reshape(-1, 3)
    return {"kind": "mesh", "vertices": vertices.tolist(), "faces": faces.tolist()}


def _vector(v) -> list[float]:
    return [float(x) for x in v]


def _primitive(part, spec_path: str, length_unit: str = "m") -> dict[str, Any] | None:
    """The drawable primitive of one written part (before its pattern), or None for a shape
    without one (drawn as its stand-in box)."""
    if isinstance(part, (models.MeshPart, models.StepPart)):
        return _file_mesh(part, spec_path, length_unit)
    draw = PRIMITIVES.get(type(part))
    return None if draw is None else draw(part)


def _rod(part) -> dict[str, Any]:
    radius = ROD_RADIUS_FRACTION * float(np.linalg.norm(np.subtract(part.end, part.start)))
    return _frustum(part.start, part.end, radius, radius)


def _matrix(rotation) -> list[list[float]]:
    """The part's rotation (part axes to body axes) as rows; the identity for none."""
    R = rotation_matrix(rotation)
    return (np.eye(3) if R is None else R).tolist()


def _fields(kind: str, part, **fields) -> dict[str, Any]:
    """``{"kind": kind, ...}`` with each field read from ``part`` as plain floats: ``name=
    "vector"`` (a point), ``"unit"`` (a direction, made unit), ``"number"``, ``"rotation"``."""
    read = {"vector": _vector, "unit": _unit, "number": float, "rotation": _matrix}
    return {"kind": kind} | {name: read[how](getattr(part, name)) for name, how in fields.items()}


PRIMITIVES: dict[type, Callable[[Any], dict[str, Any]]] = {
    models.ConePart: lambda p: _frustum(p.apex, p.base, 0.0, p.radius),
    models.CylinderPart: lambda p: _frustum(p.start, p.end, p.radius, p.radius),
    models.TubePart: lambda p: _frustum(p.start, p.end, p.outer_radius, p.outer_radius, p.inner_radius),
    models.FrustumPart: lambda p: _frustum(p.start, p.end, p.start_radius, p.end_radius),
    models.RodPart: _rod,
    models.SpherePart: lambda p: _ellipsoid(p.center, [p.radius] * 3, None),
    models.SphericalShellPart: lambda p: _ellipsoid(p.center, [p.outer_radius] * 3, None),
    models.EllipsoidPart: lambda p: _ellipsoid(p.center, p.semi_axes, p.rotation),
    models.BoxPart: lambda p: _fields("box", p, center="vector", size="vector", rotation="rotation"),
    models.PointPart: lambda p: _fields("point", p, position="vector"),
    models.TorusPart: lambda p: _fields(
        "torus", p, center="vector", axis="unit", major_radius="number", minor_radius="number"
    ),
    models.HemispherePart: lambda p: _fields("hemisphere", p, center="vector", axis="unit", radius="number"),
    models.CapsulePart: lambda p: _fields("capsule", p, start="vector", end="vector", radius="number"),
    models.PrismPart: _prism,
}
"""The drawable primitive of each closed-form shape from its fields (file units, body frame)."""


def _unit(v) -> list[float]:
    return unit_vector(v).tolist()


STEP_DEFLECTION = 0.01
"""How far the drawn facets of a STEP solid may stray from its surface, relative to the size of
each edge (the picture only: the mass properties use the exact geometry)."""


def _file_mesh(part, spec_path: str, length_unit: str) -> dict[str, Any] | None:
    """The triangles of a mesh part (scaled by ``scale``) or of a STEP part's solids (BRepMesh,
    for the picture only; the file's unit to the spec's), placed in the body as the mass
    properties place them: turned by ``rotation`` about the file's origin, that origin moved to
    ``position``; None for more than :data:`MAX_DRAWN_TRIANGLES` of them."""
    path = spec_relative_file(spec_path, part.file, f"file: {part.file}")
    if isinstance(part, models.MeshPart):
        from rbi.formats.mesh_file import read_mesh_solid  # heavy: scipy (rbi.core.mesh), for meshes only

        # cached: read once; convex: the hull is drawn
        solid = read_mesh_solid(path, part.inertia, part.repair)
        vertices, faces = np.asarray(solid.vertices, dtype=float) * float(part.scale), solid.faces
    else:
        from rbi.formats.step import read_step, select_solids, step_triangles  # heavy: 10 ms, for STEP only

        chosen = select_solids(read_step(path), part.solid)  # cached: read once for the mass properties
        vertices, faces = step_triangles(path, chosen, STEP_DEFLECTION)
        vertices = vertices / LENGTH_UNITS_IN_M[length_unit]
    if len(faces) > MAX_DRAWN_TRIANGLES:
        return None
    R = rotation_matrix(part.rotation)
    if R is not None:
        vertices = vertices @ R.T
    vertices = vertices + np.asarray(part.position, dtype=float)
    return {"kind": "mesh", "vertices": vertices.tolist(), "faces": np.asarray(faces, dtype=int).tolist()}


def _frustum(start, end, start_radius, end_radius, inner_radius=0.0) -> dict[str, Any]:
    radii = {"start_radius": start_radius, "end_radius": end_radius, "inner_radius": inner_radius}
    ends = {"kind": "frustum", "start": _vector(start), "end": _vector(end)}
    return ends | {key: float(radius) for key, radius in radii.items()}


def _ellipsoid(center, semi_axes, rotation) -> dict[str, Any]:
    axes = {"center": _vector(center), "semi_axes": _vector(semi_axes), "rotation": _matrix(rotation)}
    return {"kind": "ellipsoid"} | axes


def _cloud_points(spec, spec_path: str) -> dict[str, Any] | None:
    """The cloud's points (already read once for its mass properties), or None when there are
    too many to draw one by one."""
    label = f"{spec_path}: point_cloud: file: {spec.point_cloud.file}"
    _, positions = read_point_cloud(spec_relative_file(spec_path, spec.point_cloud.file, label), label)
    if len(positions) > MAX_DRAWN_POINTS:
        return None
    return {"kind": "points", "positions": np.asarray(positions, dtype=float).tolist()}


def _stand_in(element) -> dict[str, Any]:
    """The uniform box with the element's mass and principal moments about its centre of mass:
    edges a_k² = 6 (I_i + I_j − I_k) / m along the principal axes."""

    mass = abs(float(element.mass))
    moments, axes = principal_axes(np.sign(element.mass) * np.asarray(element.inertia_about_com, dtype=float))
    if mass == 0.0:
        size = np.zeros(3)
    else:
        total = float(np.sum(moments))
        size = np.sqrt(np.maximum(6.0 * (total - 2.0 * moments) / mass, 0.0))
    return {
        "kind": "box",
        "center": _vector(element.center_of_mass),
        "size": size.tolist(),
        "rotation": axes.T.tolist(),
        "stand_in": True,
    }
