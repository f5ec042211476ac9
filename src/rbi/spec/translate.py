"""The one place where validated spec models become core inputs (plain floats and arrays).

A body's parts become one :class:`~rbi.core.mass.MassProperties` stack (:func:`stacked_parts`):
the parts of the common shapes a stack per shape, whole-array (:data:`BUILDERS`; a box then
turned, a pattern's copies then combined, part by part); every other part (files, the other
shapes) and any whose numbers fail there one by one (:func:`part_element`, which builds one
part of a common shape as a stack of one), naming the part in its errors."""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbi.core import shapes
from rbi.core.inertia import parallel_axis_to_com, re_express
from rbi.core.mass import MassProperties
from rbi.core.rotation import (
    axis_angle_matrix,
    euler_matrix,
    numbers,
    quaternion_to_matrix,
    radians,
    scalar,
    vector_length,
    without_rounding_noise,
)
from rbi.core.validity import inertia_problem
from rbi.formats.paths import spec_relative_file
from rbi.formats.point_cloud import cloud_element
from rbi.spec import models
from rbi.spec.errors import InputError, part_label
from rbi.spec.holes import check_holes
from rbi.spec.materials import density_in_units
from rbi.spec.pattern import patterned
from rbi.spec.plausibility import unit_warnings
from rbi.spec.plus_minus import limit_warnings
from rbi.spec.units import LENGTH_UNITS_IN_M, convert_body, unit_labels
from rbi.spec.volumes import one_volume


@dataclass(frozen=True)
class LoadedBody:
    """A validated body in the core's terms (all numbers in the file's own units).

    props: mass properties (CoM and inertia in the body frame). pivot: the fixed point, body
    frame, or None. elements: the parts' mass properties, one stack in file order (a hole's
    mass and inertia negative; the point cloud last).
    """

    path: str
    name: str | None
    length_unit: str
    mass_unit: str
    props: MassProperties
    pivot: np.ndarray | None
    elements: MassProperties
    part_names: list[str | None]
    spec: Any = field(repr=False)
    """The validated :class:`~rbi.spec.models.BodySpec` the body was built from."""
    expect: dict[str, Any] | None = None
    spin_axis: np.ndarray | None = None
    warnings: list[str] = field(default_factory=list)
    """Lines about the spec a user should see (units that look wrong: :mod:`rbi.spec.plausibility`)."""
    files: tuple[str, ...] = ()
    """The files the spec names that were read (mesh and STEP parts, the point cloud), each once,
    as absolute paths: what no output of a run on this body may replace."""

    @property
    def units(self) -> dict[str, str]:
        return {"length": self.length_unit, "mass": self.mass_unit}

    @property
    def labels(self) -> dict[str, str]:
        return unit_labels(self.length_unit, self.mass_unit)

    def point(self, about: str | Sequence[float]) -> np.ndarray | None:
        """The reference point ``about`` as (3,) body coordinates, length unit: ``"com"`` the
        centre of mass, ``"origin"`` (0, 0, 0), ``"pivot"`` the spec's pivot (None when it has
        none: each caller says so, in :data:`rbi.spec.points.NO_PIVOT`'s words), or the point
        (x, y, z) itself. ``about`` is one of :data:`~rbi.spec.points.REFERENCE_POINTS` as
        :func:`~rbi.spec.points.reference_name` gives it, or a point."""
        if not isinstance(about, str):
            return np.asarray(about, dtype=float)
        return {"com": self.props.center_of_mass, "origin": np.zeros(3), "pivot": self.pivot}[about]


def _solid_mass(part, volume: float, units: models.Units) -> float:
    """The part's mass: given, or density × volume (a material name is looked up and
    converted to the file's units)."""
    if part.mass is not None:
        return part.mass
    density = part.density
    if isinstance(density, str):
        density = density_in_units(density, units.length, units.mass)
    return density * volume


def rotation_matrix(rotation: models.Rotation | None) -> np.ndarray | None:
    """Matrix (part axes -> body axes) of a spec ``rotation``; None for no rotation.

    Rounding left by sin/cos of exact quarter turns is set to zero
    (:func:`rbi.core.rotation.without_rounding_noise`), so that a box turned by 90° keeps exact
    zero products of inertia.
    """
    if rotation is None:
        return None
    if rotation.quaternion is not None:
        R = quaternion_to_matrix(numbers(rotation.quaternion))
    elif rotation.euler_deg is not None:
        R = euler_matrix(radians(rotation.euler_deg), rotation.sequence)
    else:
        R = axis_angle_matrix(numbers(rotation.axis), radians(rotation.angle_deg))
    return without_rounding_noise(R)


def custom_element(part: models.CustomPart) -> MassProperties:
    """The given inertia turned into body axes, then moved from ``about`` to the centre of
    mass. Raises ValueError (``field: what is wrong``) when either is not physical."""
    given = numbers(part.inertia)
    problem = inertia_problem(given.real)
    if problem is not None:
        raise ValueError(f"inertia: {problem.message}")
    R = rotation_matrix(part.rotation)
    inertia = given if R is None else re_express(given, R)
    com = numbers(part.center_of_mass)
    if part.about is not None:
        offset = com - numbers(part.about)
        inertia = parallel_axis_to_com(inertia, part.mass, offset)
        if not np.all(np.isfinite(inertia)) or not np.isfinite(np.sum(np.abs(inertia))):
            raise ValueError(
                f"about: numbers too large: moving the inertia from `about`, "
                f"{float(np.max(np.abs(offset))):.3g} away, to the centre of mass overflows (beyond "
                f"{np.finfo(float).max:.3g}); `about` is the point the inertia was taken about, near the part"
            )
        problem = inertia_problem(inertia.real, scale=0.5 * float(np.trace(given.real)))
        if problem is not None:
            shift = float(part.mass) * float(offset @ offset)
            raise ValueError(
                f"inertia: about the centre of mass (moved there from `about`): {problem.message}: "
                f"an inertia taken about `about` exceeds the one about the centre of mass by mass × "
                f"offset² = {shift:.6g} on the axes across the offset, so the given one is too small; "
                "is `about` the point it was taken about?"
            )
    return MassProperties(part.mass, com, 0.5 * (inertia + inertia.T))


def mesh_element(part: models.MeshPart, units: models.Units, spec_path: str) -> MassProperties:
    """The mesh's mass in the body, as ``part.inertia`` places it (the enclosed solid, the convex
    hull's solid, or the surface): ``scale``, then ``rotation`` about the mesh origin, then the
    origin moved to ``position``. Raises ValueError naming the file (as written in the spec)
    and what is wrong with it."""
    from rbi.formats.mesh_file import read_mesh_solid  # heavy: scipy (rbi.core.mesh), not for `rbi inertia`

    file = _part_file(part, spec_path)
    try:
        solid = read_mesh_solid(file, part.inertia, part.repair)
    except ValueError as exc:
        raise ValueError(f"file: {part.file}: {exc}") from None
    part._mesh_notes = _mesh_notes(part, solid, units)
    # scale: complex in a complex step (rbi.spec.uncertain)
    element, measure = _file_solid(part, solid.unit, scalar(part.scale), units)
    part._enclosed_volume = None if part.inertia == "shell" else measure
    return element


def _file_solid(part, unit: MassProperties, scale: Any, units: models.Units) -> tuple[MassProperties, Any]:
    """A mesh's or STEP file's solid in the body, and its measure (its volume, or a shell's
    area): ``unit``, the solid at density 1 in the file's length unit about the file's origin
    (its mass the measure), scaled by ``scale`` to the spec's length unit and given the part's
    mass (or density × measure), turned by ``rotation`` about that origin, moved to ``position``."""
    measure = unit.mass * scale ** (2 if getattr(part, "inertia", None) == "shell" else 3)
    mass = _solid_mass(part, measure, units)
    # inertia per density scales as scale⁵ (scale⁴ for a surface), the density as 1 / measure
    inertia = unit.inertia_about_com * (mass / unit.mass * scale * scale)
    props = MassProperties(mass, unit.center_of_mass * scale, inertia)  # file axes about its origin
    return props.transformed(rotation_matrix(part.rotation), part.position), measure


def assembly_element(part: models.AssemblyPart, units: models.Units) -> MassProperties:
    """A sub-assembly (read by :func:`rbi.spec.load.read_assemblies`) as one mass element of
    one copy: its mass properties in ``units``, scaled to the measured ``mass`` when given
    (every part's mass and inertia alike), its axes turned by ``rotation``, its origin moved to
    ``position``."""
    props = convert_body(part._loaded, units.length, units.mass).props
    factor = 1.0 if part.mass is None else part.mass / props.mass
    return props.scaled(factor).transformed(rotation_matrix(part.rotation), part.position)


def _part_file(part, spec_path: str):
    """The file a mesh or STEP part names, beside the spec (:func:`rbi.formats.paths.spec_relative_file`);
    ValueError (``file: NAME: what is wrong``) when it may not be read."""
    try:
        return spec_relative_file(spec_path, part.file, f"file: {part.file}")
    except InputError as exc:
        raise ValueError(str(exc)) from None


def step_element(part: models.StepPart, units: models.Units, spec_path: str) -> MassProperties:
    """The STEP file's solid (or solids, ``solid:`` unset) in the body: integrated on the exact
    boundary representation in metres (:mod:`rbi.formats.step`), converted to the spec's length
    unit, turned by ``rotation`` about the file's origin, that origin moved to ``position``.
    Raises ValueError naming the file (as written in the spec) and what is wrong with it."""
    from rbi.formats.step import read_step, require_cad, select_solids  # heavy: 10 ms, not for `rbi inertia`

    require_cad()
    file = _part_file(part, spec_path)
    try:
        step = read_step(file)
        chosen = [step.solids[i] for i in select_solids(step, part.solid)]
    except ValueError as exc:
        raise ValueError(
            f"file: {part.file}: {exc}" if not str(exc).startswith("solid:") else str(exc)
        ) from None
    per_metre = 1.0 / LENGTH_UNITS_IN_M[units.length]
    part._integration_error = max(s.integration_error for s in chosen)
    props = MassProperties.sum(s.props for s in chosen)  # unit density, metres: mass is the volume
    element, part._step_volume = _file_solid(part, props, per_metre, units)
    return element


def _mesh_notes(part: models.MeshPart, solid, units: models.Units) -> tuple[str, ...]:
    """What a reader of the numbers should know about the mesh: the surface repair added, and
    pieces that overlap (their shared space counted twice)."""
    notes = []
    if solid.added_faces:
        from rbi.core.mesh import surface_area  # heavy: scipy, not for `rbi inertia`

        scale = scalar(part.scale).real
        added = solid.added_area * scale * scale
        share = solid.added_area / surface_area(solid.vertices, solid.faces)
        notes.append(
            f"file: {part.file}: repair added {solid.added_faces} triangle{'s' * (solid.added_faces != 1)} "
            f"closing holes, {added:.6g} {units.length}² ({100 * share:.3g}% of the surface)"
        )
    notes.extend(f"file: {part.file}: {note}" for note in solid.notes)
    return tuple(notes)


def part_element(part, units: models.Units, spec_path: str) -> MassProperties:
    """One written part's mass element in file units: built from its fields (a mesh read from
    its file beside the spec), then, with a ``pattern``, every copy combined into one. A part of
    a shape of :data:`BUILDERS` is built as a stack of one."""
    if type(part) in BUILDERS:
        one = BUILDERS[type(part)](Columns([part], np.zeros(1, int), {}), units)
        return _as_written(part, *(x[0] for x in one))
    element = ELEMENTS[type(part)](part, units, spec_path)
    if part.pattern is not None and part.pattern.count > 1:
        element = patterned(element, part.pattern)
    return element


def _solid(build: Callable[[Any, float], MassProperties]) -> Callable[..., MassProperties]:
    """A closed-form solid's element from its fields and ``units``: ``build`` given the part and
    the mass of one copy (its ``mass``, or its density times
    :func:`rbi.spec.volumes.one_volume`)."""
    return lambda part, units, _: build(part, _solid_mass(part, one_volume(part), units))


ELEMENTS: dict[type, Callable[[Any, models.Units, str], MassProperties]] = {
    models.SphericalShellPart: _solid(
        lambda p, m: shapes.spherical_shell(m, p.outer_radius, p.inner_radius, p.center)
    ),
    models.TubePart: _solid(lambda p, m: shapes.tube(m, p.outer_radius, p.inner_radius, p.start, p.end)),
    models.FrustumPart: _solid(lambda p, m: shapes.frustum(m, p.start_radius, p.end_radius, p.start, p.end)),
    models.EllipsoidPart: _solid(
        lambda p, m: shapes.ellipsoid(m, p.semi_axes, p.center, rotation_matrix(p.rotation))
    ),
    models.TorusPart: _solid(lambda p, m: shapes.torus(m, p.major_radius, p.minor_radius, p.center, p.axis)),
    models.HemispherePart: _solid(lambda p, m: shapes.hemisphere(m, p.radius, p.center, p.axis)),
    models.CapsulePart: _solid(lambda p, m: shapes.capsule(m, p.radius, p.start, p.end)),
    models.PrismPart: _solid(lambda p, m: shapes.prism(m, p.outline, p.holes, p.start, p.end, p.x_axis)),
    models.RodPart: lambda p, units, path: shapes.rod(p.mass, p.start, p.end),
    models.CustomPart: lambda p, units, path: custom_element(p),
    models.MeshPart: mesh_element,
    models.StepPart: step_element,
    models.AssemblyPart: lambda p, units, path: assembly_element(p, units),
}
"""Each part not built as a stack (:data:`BUILDERS`) from its fields, ``units`` and the spec's
path, in file units: the other closed-form solids (:mod:`rbi.core.shapes`), the parts whose
mass is given (rods, custom parts), and the files' solids (meshes, STEP files, sub-assemblies)."""


# --- the parts of the common shapes, a stack per shape ----------------------------------


class Columns:
    """Parts' fields as columns, what the builders below (:data:`BUILDERS`) read: row r is part
    ``parts[index[r]]``, with its own values but where ``values`` (by field, or ``(field,
    component)``) gives a column (Monte Carlo draws and the steps of sensitivities,
    :mod:`rbi.spec.uncertain`). The parts are of one shape and give their mass alike (``mass``,
    a density, or one material: :func:`given_by`)."""

    def __init__(self, parts: list, index: np.ndarray, values: dict[tuple[Any, ...], np.ndarray]) -> None:
        self.parts, self.index, self.values = parts, np.asarray(index), values
        self.part, self.n = parts[0], len(self.index)

    def __len__(self) -> int:
        return self.n

    def column(self, field: str) -> np.ndarray:
        nominal = np.array([getattr(p, field) for p in self.parts], dtype=float)[self.index]
        given = {key[1:]: v for key, v in self.values.items() if key[0] == field}
        if not given:
            return nominal
        column = nominal.astype(np.result_type(nominal, *given.values()))
        for at, v in given.items():
            column[(slice(None), *at)] = v
        return column

    def masses(self, units: models.Units, volume: np.ndarray) -> np.ndarray:
        if self.part.mass is None and isinstance(self.part.density, str):  # one material
            return _solid_mass(self.part, volume, units)
        return self.column("mass") if self.part.mass is not None else self.column("density") * volume


def _axes(d: np.ndarray) -> tuple[np.ndarray, Any, np.ndarray]:
    """Each row's unit vector and length as :func:`rbi.core.shapes.axis_between` gives them
    (``unit_vector``'s arithmetic, without its refusal: an overflowing row gives NaN, a part
    :func:`_finite_element` reports), and its length as the part's volume takes it
    (:func:`rbi.spec.volumes.one_volume`: numpy's norm)."""
    largest = np.max(np.abs(d), axis=-1, keepdims=True)
    scaled = d / largest
    unit = scaled / np.sqrt(np.sum(scaled * scaled, axis=-1, keepdims=True))
    return unit, vector_length(d), np.sqrt(np.sum(d * d, axis=-1))


def _points(parts, units):
    return parts.column("mass"), parts.column("position"), np.zeros((len(parts), 3, 3))


def _cylinders(parts, units):
    radius = parts.column("radius")
    start, end = parts.column("start"), parts.column("end")
    u, length, norm = _axes(end - start)
    mass = parts.masses(units, shapes.cylinder_volume(radius, norm))
    axial, transverse = shapes.cylinder_moments(mass, radius, length)
    return mass, shapes.middle(start, end), shapes.axisymmetric_inertia(axial, transverse, u)


def _cones(parts, units):
    radius = parts.column("radius")
    apex, base = parts.column("apex"), parts.column("base")
    u, height, norm = _axes(base - apex)
    mass = parts.masses(units, shapes.cone_volume(radius, norm))
    com = shapes.cone_center_of_mass(apex, u, height)
    axial, transverse = shapes.cone_moments(mass, radius, height)
    return mass, com, shapes.axisymmetric_inertia(axial, transverse, u)


def _spheres(parts, units):
    radius = parts.column("radius")
    # one sphere at a time, as rbi.spec.volumes.one_volume takes it: Python's r ** 3, which numpy's
    # power of an array may round apart
    volume = np.array([shapes.sphere_volume(r) for r in radius.tolist()])
    mass = parts.masses(units, volume)
    return mass, parts.column("center"), shapes.sphere_inertia(mass, radius)


def _boxes(parts, units):
    size = parts.column("size")
    mass = parts.masses(units, shapes.box_volume(size))
    return mass, parts.column("center"), shapes.box_inertia(mass, size)


BUILDERS = {
    models.PointPart: _points,
    models.CylinderPart: _cylinders,
    models.ConePart: _cones,
    models.SpherePart: _spheres,
    models.BoxPart: _boxes,
}
"""Each stacked part model's ``(parts, units) -> (mass (n,), com (n, 3), inertia (n, 3, 3))``: a
part's own solid, before its ``rotation`` (a box's) and ``pattern`` (:func:`_as_written`)."""


def _as_written(part: Any, mass: Any, com: np.ndarray, inertia: np.ndarray) -> MassProperties:
    """One part of a shape of :data:`BUILDERS` from its built row: a box turned about its centre
    by its ``rotation``, then, with a ``pattern``, every copy combined into one."""
    if "rotation" in _fields(type(part)) and part.rotation is not None:
        inertia = shapes.turned(inertia, rotation_matrix(part.rotation))
    element = MassProperties(mass, com, inertia)
    if part.pattern is not None and part.pattern.count > 1:
        element = patterned(element, part.pattern)
    return element


@functools.cache
def _fields(kind: type) -> set[str]:
    return set(getattr(kind, "model_fields", {}))


def plain_part(part: Any) -> bool:
    """Whether a part of a batched shape is its :data:`BUILDERS` row as it stands (no pattern, no
    rotation to apply after; fields looked up only where the model has them: a missing
    attribute on a pydantic model is slow to ask for)."""
    fields = _fields(type(part))
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


def _finite_element(index: int, part, units: models.Units, path: str) -> MassProperties:
    """One part's mass properties (file units); InputError naming the part when its numbers are
    wrong or overflow a double."""
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # overflow is reported just below
            element = part_element(part, units, path)
    except ValueError as exc:
        raise InputError(f"{path}: {part_label(index, part)}: {exc}") from None
    if not _finite(element.mass, element.center_of_mass, element.inertia_about_com):
        raise InputError(
            f"{path}: {part_label(index, part)}: numbers too large: mass or inertia overflows "
            f"(beyond {np.finfo(float).max:.3g}); is the unit of its sizes or density right?"
        )
    if element.mass != 0 and moments_lost(element.inertia_about_com, part.shape):
        raise InputError(
            f"{path}: {part_label(index, part)}: numbers too small: its moments of inertia underflow "
            f"(below {SMALLEST_MOMENT:.2g}, where a double keeps fewer than 9 digits); is the unit of "
            "its sizes or mass right?"
        )
    return element


def _finite(mass: Any, com: np.ndarray, inertia: np.ndarray) -> Any:
    """Whether a mass, centre of mass and inertia (or each row of a stack of them) are finite."""
    return np.isfinite(mass) & np.all(np.isfinite(com), axis=-1) & np.all(np.isfinite(inertia), axis=(-2, -1))


def given_by(part: Any) -> Any:
    """How a part gives its mass, alike for the parts of one :class:`Columns`: its ``mass``, a
    density number, or the density of one material (by name)."""
    if part.mass is not None:
        return "mass"
    return ("material", part.density) if isinstance(part.density, str) else "density"


def stacked_parts(spec: models.BodySpec, path: str) -> tuple[MassProperties, list[int]]:
    """Every part's mass element (file units; a hole's mass and inertia negative) as one stack in
    file order, and the holes' indices. The parts of the common shapes are built a stack per
    shape and way of giving the mass (:data:`BUILDERS` on :class:`Columns`), then each turned or
    patterned part as written (:func:`_as_written`); the other parts, and any whose numbers fail
    there, one by one (:func:`_finite_element`, which names the part)."""
    parts = spec.parts
    mass, com, inertia = np.zeros(len(parts)), np.zeros((len(parts), 3)), np.zeros((len(parts), 3, 3))
    built = np.zeros(len(parts), dtype=bool)
    groups: dict[tuple[type, Any], list[int]] = {}
    for i, part in enumerate(parts):
        if type(part) in BUILDERS:
            groups.setdefault((type(part), given_by(part)), []).append(i)
    for (kind, _), indices in groups.items():
        chosen = [parts[i] for i in indices]
        with np.errstate(all="ignore"):
            m, c, I = BUILDERS[kind](Columns(chosen, np.arange(len(chosen)), {}), spec.units)
            for r in [r for r, part in enumerate(chosen) if not plain_part(part)]:
                try:
                    element = _as_written(chosen[r], m[r], c[r], I[r])
                except ValueError:  # a pattern of massless copies: refused below, the part named
                    m[r] = np.nan
                    continue
                m[r], c[r], I[r] = element.mass, element.center_of_mass, element.inertia_about_com
            ok = _finite(m, c, I) & ~moments_lost(I, chosen[0].shape)
        rows = np.asarray(indices)[ok]
        mass[rows], com[rows], inertia[rows], built[rows] = m[ok], c[ok], I[ok], True
    for i in np.flatnonzero(~built).tolist():
        element = _finite_element(i, parts[i], spec.units, path)
        mass[i], com[i], inertia[i] = element.mass, element.center_of_mass, element.inertia_about_com
    holes = [i for i, part in enumerate(parts) if "subtract" in _fields(type(part)) and part.subtract]
    mass[holes], inertia[holes] = -mass[holes], -inertia[holes]
    return MassProperties(mass, com, inertia), holes


def body_from_spec(spec: models.BodySpec, path: str):
    """Translate a validated :class:`~rbi.spec.models.BodySpec` into a
    :class:`LoadedBody`."""
    elements, holes = stacked_parts(spec, path)
    part_names = [p.name for p in spec.parts]
    if spec.point_cloud is not None:  # the whole cloud enters as one part, reduced vectorised
        elements = MassProperties.concatenate([elements, cloud_element(path, spec.point_cloud.file)])
        part_names.append("point_cloud")
    if holes:
        check_holes(path, spec, elements, holes)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            props = elements.sum()
    except ValueError as exc:
        raise InputError(f"{path}: {exc}") from None
    if not _finite(props.mass, props.center_of_mass, props.inertia_about_com):
        raise InputError(f"{path}: numbers too large: the body's mass, centre of mass or inertia overflows")
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
        spin_axis=None if spec.spin_axis is None else np.asarray(spec.spin_axis, dtype=float),
        warnings=_warnings(spec, path),
        files=files_named(spec, path),
    )


def _warnings(spec: models.BodySpec, path: str) -> list[str]:
    """The spec's unit slips, its mesh notes (each naming the part; set when a mesh is read),
    every sub-assembly's warnings and the ± that reach past their field's least value."""
    meshes = [(i, part) for i, part in enumerate(spec.parts) if isinstance(part, models.MeshPart)]
    notes = [f"{path}: {part_label(i, part)}: {note}" for i, part in meshes for note in part._mesh_notes]
    inner = [w for part in spec.parts if isinstance(part, models.AssemblyPart) for w in part._loaded.warnings]
    return unit_warnings(spec, path) + notes + inner + limit_warnings(spec, path)


def files_named(spec: models.BodySpec, path: str) -> tuple[str, ...]:
    """The files the spec at ``path`` names (mesh and STEP parts' ``file``, then the point
    cloud's), each once, as absolute paths found beside the spec as they were read."""
    named = [part.file for part in spec.parts if isinstance(part, (models.MeshPart, models.StepPart))]
    if spec.point_cloud is not None:
        named.append(spec.point_cloud.file)
    found = [os.path.abspath(spec_relative_file(path, file, f"{path}: file: {file}")) for file in named]
    for part in spec.parts:  # a sub-assembly's file and the files it reads
        if isinstance(part, models.AssemblyPart):
            found.extend((os.path.abspath(part._loaded.path), *part._loaded.files))
    return tuple(dict.fromkeys(found))
