"""Pydantic models of the YAML body spec (see docs/spec.md).

Numbers are strict: text such as ``"0.04"`` is refused rather than converted, and NaN or
infinity are refused everywhere. Unknown fields are refused so that a misspelt field is
reported instead of silently ignored. Parts form a discriminated union on ``shape``.
"""

from __future__ import annotations

import re
import unicodedata
from typing import Annotated, Any, Literal, Union, get_args

import numpy as np
from pydantic import (
    BeforeValidator,
    Field,
    PlainValidator,
    PrivateAttr,
    ValidationError,
    create_model,
    model_validator,
)

from rbi.core.polygon import MAX_VERTICES, polygon_problem
from rbi.spec.expect import Expect
from rbi.spec.fields import BuiltWhenUsed as _BuiltWhenUsed
from rbi.spec.fields import Density, Flag, InertiaMatrix, NonNegative, Number, Positive, Vector3
from rbi.spec.fields import StrictModel as _Strict
from rbi.spec.materials import canonical_name, unknown_material_message

PositiveVector3 = Annotated[list[Positive], Field(min_length=3, max_length=3)]

LengthUnit = Literal["m", "cm", "mm", "in", "ft"]
MassUnit = Literal["kg", "g", "lb"]


class Units(_Strict):
    """Units of every number in the file, inputs and outputs alike."""

    length: LengthUnit = Field("m", description="Length unit: m, cm, mm, in or ft.")
    mass: MassUnit = Field("kg", description="Mass unit: kg, g or lb.")


class Pattern(_BuiltWhenUsed):
    """Copies of a part: ``count`` equal copies turned evenly about the line along ``axis``
    through ``through`` (the part as written is the first), or ``count`` copies in a row,
    each ``step`` further on. ``mass`` and ``density`` are per copy."""

    count: int = Field(
        strict=True,
        ge=1,
        le=100_000,
        description="Number of copies, the part as written included (1 to 100000).",
    )
    axis: Vector3 | None = Field(
        None, description="Direction of the line the copies turn about (need not be unit length)."
    )
    through: Vector3 | None = Field(None, description="A point on that line (default [0, 0, 0]).")
    step: Vector3 | None = Field(None, description="Offset from one copy to the next, for a row of copies.")

    @model_validator(mode="after")
    def _one_form(self):
        circular = self.axis is not None or self.through is not None
        if circular == (self.step is not None):
            raise ValueError(
                "give either {count, axis, through} (copies turned about a line) or {count, step} "
                "(copies in a row)" + (" (got both)" if circular else " (got neither axis nor step)")
            )
        if circular and self.axis is None:
            raise ValueError("axis: missing required field (the direction of the line the copies turn about)")
        return _nonzero(self, "axis", "the direction of the line the copies turn about")


SHAPE_MODELS: dict[str, type[_Part]] = {}
"""Every part model by its ``shape`` tag, in the order the models are defined below: each model
with a ``shape`` field is listed when its class is made (:meth:`_Part.__pydantic_init_subclass__`)."""


class _Part(_BuiltWhenUsed):
    name: str | None = Field(
        None, description="A name for the part, shown in tables and error messages; unique within the body."
    )
    pattern: Pattern | None = Field(
        None, description="Repeat this part: copies about an axis line or in a row."
    )

    @classmethod
    def __pydantic_init_subclass__(cls, **kwargs: Any) -> None:
        """A model with a ``shape`` tag (a ``Literal``) goes into :data:`SHAPE_MODELS` under it."""
        if "shape" in cls.model_fields:
            SHAPE_MODELS[get_args(cls.model_fields["shape"].annotation)[0]] = cls


class _Solid(_Part):
    """A solid with either a total ``mass`` or a ``density`` (mass per length³, or a built-in
    material name). ``subtract: true`` makes it a hole: its material is removed."""

    mass: Positive | None = Field(
        None,
        description="Mass of the solid (per copy with a pattern), in the file's mass unit; give this or density.",
    )
    density: Density | None = Field(
        None,
        description="Mass per length³ in the file's units, or a built-in material name; give this or mass.",
    )
    subtract: Flag = Field(False, description="Remove this solid's material (a hole) instead of adding it.")
    material: str | None = Field(
        None,
        description="A built-in material name (steel, aluminium 6061, ...): the same as density: NAME.",
    )

    @model_validator(mode="before")
    @classmethod
    def _material_is_a_density(cls, data: Any):
        """``material: NAME`` is another way to write ``density: NAME`` (a built-in material,
        stored in kg/m³ and converted to the file's units): the part keeps one density."""
        if not isinstance(data, dict) or data.get("material") is None:
            return data
        data = dict(data)
        material = data.pop("material")
        for other in ("density", "mass"):
            if data.get(other) is not None:
                raise ValueError(f"material, {other}: give one of them (material: NAME is density: NAME)")
        if not isinstance(material, str) or canonical_name(material) is None:
            raise ValueError(f"material: {unknown_material_message(str(material))}")
        data["density"] = material
        return data

    @model_validator(mode="after")
    def _mass_or_density(self):
        if (self.mass is None) == (self.density is None):
            given = "both" if self.mass is not None else "neither"
            raise ValueError(f"mass, density: give exactly one of `mass` or `density` ({given} given)")
        return self


def _apart(first: str, second: str) -> Any:
    """The model check that the points ``first`` and ``second`` differ (the part has a length)."""

    def check(self):
        if np.array_equal(np.asarray(getattr(self, first)), np.asarray(getattr(self, second))):
            raise ValueError(f"{first}, {second}: must be different points (the length would be 0)")
        return self

    return model_validator(mode="after")(check)


def _without_volume(what: str) -> Any:
    """The check, before the fields', that a part without volume (``what``) has no ``density``
    and no ``subtract``: it takes ``mass`` only."""

    def check(cls, data: Any) -> Any:
        if isinstance(data, dict) and "density" in data:
            raise ValueError(f"density: {what} takes `mass` only (it has no volume)")
        if isinstance(data, dict) and "subtract" in data:
            raise ValueError(f"subtract: only solids with a volume can be subtracted, not {what}")
        return data

    return model_validator(mode="before")(classmethod(check))


class ConePart(_Solid):
    """Solid right circular cone: ``apex`` (tip) to ``base`` (centre of the base disc)."""

    shape: Literal["cone"] = Field(description="A solid right circular cone.")
    radius: Positive = Field(description="Radius of the base disc.")
    apex: Vector3 = Field(description="The tip, body frame.")
    base: Vector3 = Field(description="Centre of the base disc, body frame.")

    _has_height = _apart("apex", "base")


class CylinderPart(_Solid):
    """Solid circular cylinder between the centres of its end faces ``start`` and ``end``."""

    shape: Literal["cylinder"] = Field(description="A solid circular cylinder.")
    radius: Positive = Field(description="Radius of the cylinder.")
    start: Vector3 = Field(description="Centre of one end face, body frame.")
    end: Vector3 = Field(description="Centre of the other end face, body frame.")

    _has_length = _apart("start", "end")


class PointPart(_Part):
    """A point mass at ``position``."""

    shape: Literal["point"] = Field(description="A point mass.")
    mass: Positive = Field(description="Mass, in the file's mass unit.")
    position: Vector3 = Field(description="Where the mass is, body frame.")

    _no_density = _without_volume("a point mass")


# --- shapes added for engineering parts (docs/spec.md gives each closed form) ---------------


_ROTATION_FORMS = (("axis", "angle_deg"), ("quaternion",), ("euler_deg", "sequence"))
"""The three ways of writing a rotation, by their fields."""


class Rotation(_BuiltWhenUsed):
    """How the part's own axes are turned into body axes, in one of three forms: ``axis`` and
    ``angle_deg`` (right-hand rule); ``quaternion`` ``[w, x, y, z]`` (normalised); or
    ``euler_deg`` with a ``sequence`` of three axis letters (lower case: fixed axes, upper
    case: moving axes, as scipy's ``Rotation.from_euler``). The part turns about its own centre."""

    axis: Vector3 | None = Field(
        None, description="Axis of an axis-angle rotation (need not be unit length)."
    )
    angle_deg: Number | None = Field(
        None, description="Angle of an axis-angle rotation, degrees, right-hand rule."
    )
    quaternion: Annotated[list[Number], Field(min_length=4, max_length=4)] | None = Field(
        None, description="Unit quaternion [w, x, y, z] (scalar first), part axes to body axes; normalised."
    )
    euler_deg: Vector3 | None = Field(
        None, description="Three Euler angles, degrees, applied in `sequence` order."
    )
    sequence: str | None = Field(
        None,
        pattern=r"^([xyz]{3}|[XYZ]{3})$",
        description="Axes of the Euler angles: lower case = fixed (extrinsic) axes, upper case = moving (intrinsic).",
    )

    @model_validator(mode="after")
    def _one_form(self):
        forms = [form for form in _ROTATION_FORMS if any(getattr(self, name) is not None for name in form)]
        if len(forms) != 1:
            raise ValueError(
                "give exactly one form: {axis, angle_deg}, {quaternion} or {euler_deg, sequence}"
                + (f" (got {' and '.join(', '.join(form) for form in forms)})" if forms else " (got none)")
            )
        if any(getattr(self, name) is None for name in forms[0]):
            raise ValueError(f"{', '.join(forms[0])}: give both")
        if self.axis is not None:
            _nonzero(self, "axis", "the direction to turn about")
        if self.quaternion is not None and not any(self.quaternion):
            raise ValueError(
                "quaternion: must not be zero [0, 0, 0, 0]: the identity (no turn) is [1, 0, 0, 0], "
                "scalar first; any length"
            )
        return self


def _turned_by(whose: str, about: str) -> Any:
    """The optional ``rotation`` field of a part: how ``whose`` axes are turned into body axes,
    ``about`` saying about which point (and the default)."""
    return Field(None, description=f"How the {whose} axes are turned into body axes{about}.")


def _hollow(what: str) -> Any:
    """The model check of a hollow solid (``what``): its bore fits inside, and a thin wall has a mass."""

    def check(part):
        if part.inner_radius > part.outer_radius:
            raise ValueError(
                f"inner_radius: must not exceed outer_radius ({part.inner_radius!r} > {part.outer_radius!r})"
            )
        if part.inner_radius == part.outer_radius and part.density is not None:
            raise ValueError(
                f"density: a thin-walled {what} (inner_radius = outer_radius) has no volume; give its `mass`"
            )
        return part

    return model_validator(mode="after")(check)


class BoxPart(_Solid):
    """Solid rectangular box: edges ``size = [a, b, c]`` along its own x, y, z axes, centred on
    ``center``, turned by ``rotation``."""

    shape: Literal["box"] = Field(description="A solid rectangular box.")
    center: Vector3 = Field(description="Centre of the box, body frame.")
    size: PositiveVector3 = Field(description="Edge lengths [a, b, c] along the box's own x, y, z axes.")
    rotation: Rotation | None = _turned_by("box's", " (about its centre); default: aligned")


class SpherePart(_Solid):
    """Solid sphere."""

    shape: Literal["sphere"] = Field(description="A solid sphere.")
    center: Vector3 = Field(description="Centre of the sphere, body frame.")
    radius: Positive = Field(description="Radius of the sphere.")


class SphericalShellPart(_Solid):
    """Thick spherical shell between ``inner_radius`` and ``outer_radius`` (equal radii: a thin
    shell, given by `mass`)."""

    shape: Literal["spherical_shell"] = Field(
        description="A hollow sphere (thick, or thin with equal radii)."
    )
    center: Vector3 = Field(description="Centre of the shell, body frame.")
    outer_radius: Positive = Field(description="Outer radius.")
    inner_radius: NonNegative = Field(
        description="Inner radius, at most outer_radius (equal: a thin shell, given by mass)."
    )

    _radii = _hollow("shell")


class TubePart(_Solid):
    """Hollow circular cylinder (outer and inner radius) between the centres of its end faces."""

    shape: Literal["tube"] = Field(description="A hollow circular cylinder.")
    start: Vector3 = Field(description="Centre of one end face, body frame.")
    end: Vector3 = Field(description="Centre of the other end face, body frame.")
    outer_radius: Positive = Field(description="Outer radius.")
    inner_radius: NonNegative = Field(description="Inner radius (the bore), at most outer_radius.")

    _has_length = _apart("start", "end")
    _radii = _hollow("tube")


class FrustumPart(_Solid):
    """Solid truncated cone: a disc of ``start_radius`` centred on ``start``, one of
    ``end_radius`` on ``end``."""

    shape: Literal["frustum"] = Field(description="A solid truncated cone.")
    start: Vector3 = Field(description="Centre of the disc of start_radius, body frame.")
    end: Vector3 = Field(description="Centre of the disc of end_radius, body frame.")
    start_radius: NonNegative = Field(description="Radius at start (0 for a cone's tip).")
    end_radius: NonNegative = Field(description="Radius at end (0 for a cone's tip).")

    _has_length = _apart("start", "end")

    @model_validator(mode="after")
    def _radii(self):
        if self.start_radius == 0 and self.end_radius == 0:
            raise ValueError("start_radius, end_radius: at least one must be greater than 0")
        return self


class EllipsoidPart(_Solid):
    """Solid ellipsoid: ``semi_axes = [a, b, c]`` along its own x, y, z axes, turned by
    ``rotation``."""

    shape: Literal["ellipsoid"] = Field(description="A solid ellipsoid.")
    center: Vector3 = Field(description="Centre of the ellipsoid, body frame.")
    semi_axes: PositiveVector3 = Field(
        description="Semi-axes [a, b, c] along the ellipsoid's own x, y, z axes."
    )
    rotation: Rotation | None = _turned_by("ellipsoid's", " (about its centre); default: aligned")


class RodPart(_Part):
    """Thin straight rod (a line mass) from ``start`` to ``end``: `mass` only."""

    shape: Literal["rod"] = Field(description="A thin straight rod (a line mass).")
    mass: Positive = Field(description="Mass, in the file's mass unit.")
    start: Vector3 = Field(description="One end, body frame.")
    end: Vector3 = Field(description="The other end, body frame.")

    _no_density = _without_volume("a thin rod")
    _has_length = _apart("start", "end")


class CustomPart(_Part):
    """Mass properties given directly: ``inertia`` about ``about`` (default: the centre of mass)
    in the part's axes, turned into body axes by ``rotation``."""

    shape: Literal["custom"] = Field(description="Mass properties given directly (e.g. from CAD).")
    mass: Positive = Field(description="Mass, in the file's mass unit.")
    center_of_mass: Vector3 = Field(description="Centre of mass, body frame.")
    inertia: InertiaMatrix = Field(
        description="Inertia about `about` in the part's axes, mass·length² (products of inertia with the minus sign inside)."
    )
    about: Vector3 | None = Field(
        None, description="Point the inertia is given about, body frame; default: the centre of mass."
    )
    rotation: Rotation | None = _turned_by("part's", "; default: aligned")

    _no_density = _without_volume("a custom part")


def _nonzero(part: Any, name: str, meaning: str) -> Any:
    """``part`` unless its direction ``name`` (when given) is the zero vector; ``meaning`` says
    what the direction is."""
    if getattr(part, name) is not None and not any(getattr(part, name)):
        raise ValueError(
            f"{name}: must not be the zero vector [0, 0, 0]: give {meaning}, e.g. [0, 0, 1] for z "
            "(any length)"
        )
    return part


class TorusPart(_Solid):
    """Solid torus (a ring): a disc of ``minor_radius`` swept around ``axis`` at
    ``major_radius`` from ``center``."""

    shape: Literal["torus"] = Field(description="A solid torus (a ring).")
    center: Vector3 = Field(description="Centre of the ring (on its axis).")
    axis: Vector3 = Field(description="Direction of the ring's axis of symmetry (need not be unit length).")
    major_radius: Positive = Field(description="Distance from the centre to the middle of the tube.")
    minor_radius: Positive = Field(description="Radius of the tube; at most major_radius.")

    @model_validator(mode="after")
    def _checks(self):
        _nonzero(self, "axis", "the direction of the ring's axis of symmetry")
        if self.minor_radius > self.major_radius:
            raise ValueError(
                f"minor_radius: must not exceed major_radius ({self.minor_radius!r} > "
                f"{self.major_radius!r}; the tube would pass through the axis)"
            )
        return self


class HemispherePart(_Solid):
    """Solid hemisphere: flat face centred on ``center``, dome towards ``axis``."""

    shape: Literal["hemisphere"] = Field(description="A solid hemisphere.")
    center: Vector3 = Field(description="Centre of the flat face.")
    axis: Vector3 = Field(description="Direction from the flat face into the dome (need not be unit length).")
    radius: Positive = Field(description="Radius of the sphere it is half of.")

    _has_direction = model_validator(mode="after")(
        lambda self: _nonzero(self, "axis", "the direction from the flat face into the dome")
    )


class CapsulePart(_Solid):
    """Capsule: a solid cylinder from ``start`` to ``end`` with a hemispherical cap of the
    same ``radius`` on each end."""

    shape: Literal["capsule"] = Field(description="A cylinder with a hemispherical cap on each end.")
    start: Vector3 = Field(
        description="Centre of one end face of the cylinder (where a cap's flat face sits)."
    )
    end: Vector3 = Field(description="Centre of the other end face; |end - start| is the cylinder's length.")
    radius: Positive = Field(description="Radius of the cylinder and of both caps.")

    _has_length = _apart("start", "end")


class MeshPart(_Solid):
    """A closed triangle mesh read from ``file`` (STL binary or ASCII, OBJ, PLY): the solid it
    encloses. Mesh coordinates are multiplied by ``scale``, turned by ``rotation`` about the
    mesh's own origin, then that origin is put at ``position``."""

    shape: Literal["mesh"] = Field(description="The solid a closed triangle mesh encloses.")
    file: str = Field(
        min_length=1, description="Mesh file (.stl, .obj, .ply, .dae, .msh), relative to the spec's folder."
    )
    scale: Positive = Field(
        1.0, description="Mesh units to the spec's length unit (e.g. 0.001 for a mesh in mm in a spec in m)."
    )
    position: Vector3 = Field([0.0, 0.0, 0.0], description="Where the mesh's own origin goes, body frame.")
    rotation: Rotation | None = _turned_by("mesh's", " (about its origin)")
    inertia: Literal["exact", "convex", "shell"] = Field(
        "exact",
        description=(
            "Where the mass goes, as MuJoCo names it: exact = the solid the closed mesh encloses; convex = "
            "the solid convex hull of its vertices; shell = spread evenly over the surface (give mass, not density)."
        ),
    )
    repair: Flag = Field(
        False,
        description=(
            "Close holes of three or four edges (trimesh's fill_holes) before integrating; the area added is reported."
        ),
    )

    _enclosed_volume: float | None = PrivateAttr(None)  # L³ in the spec's units, set when the file is read
    _mesh_notes: tuple[str, ...] = PrivateAttr(())  # what repair added, overlapping pieces: set when read

    @model_validator(mode="after")
    def _shell_takes_a_mass(self):
        if self.inertia == "shell" and self.density is not None:
            raise ValueError(
                "density: with inertia: shell the mass lies on the surface, which has no volume "
                "for a density to fill: give mass instead"
            )
        return self


def _solid_choice(value: Any) -> Any:
    """``solid:`` is a name (non-empty text) or a 0-based index (a whole number, 0 or more)."""
    if value is None or (isinstance(value, str) and value.strip()):
        return value
    if isinstance(value, int) and not isinstance(value, bool) and value >= 0:
        return value
    raise ValueError(
        f"must be a solid's name or its 0-based index (a whole number, 0 or more), got {value!r}"
    )


class StepPart(_Solid):
    """The solid (or solids) of a STEP file (ISO 10303-21: AP203, AP214, AP242) read from ``file``,
    integrated on the exact boundary representation. The file's own length unit is honoured;
    its axes are turned by ``rotation`` about the file's origin, then that origin is put at
    ``position``. Needs the optional extra ``cad``."""

    shape: Literal["step"] = Field(description="The solid or solids of a STEP file (CAD).")
    file: str = Field(min_length=1, description="STEP file (.step, .stp), relative to the spec's folder.")
    solid: Annotated[str | int | None, BeforeValidator(_solid_choice)] = Field(
        None,
        description=(
            "Which solid: its name in the file's product tree (as `rbi import` lists them) or its "
            "0-based index in file order; default: every solid of the file together."
        ),
    )
    position: Vector3 = Field([0.0, 0.0, 0.0], description="Where the file's origin goes, body frame.")
    rotation: Rotation | None = _turned_by("file's", " (about its origin)")

    _step_volume: float | None = PrivateAttr(None)  # L³ in the spec's units, set when the file is read
    _integration_error: float | None = PrivateAttr(None)  # relative, set when the file is read

    @model_validator(mode="after")
    def _step_checks(self):
        if not self.file.lower().endswith((".step", ".stp")):
            raise ValueError(f"file: {self.file!r} is not a STEP file name: it must end in .step or .stp")
        return self


Point2 = Annotated[list[Number], Field(min_length=2, max_length=2)]
Polygon = Annotated[list[Point2], Field(min_length=3, max_length=MAX_VERTICES)]


class PrismPart(_Solid):
    """A straight extrusion of a simple polygon ``outline`` (either winding) less its ``holes``
    from ``start`` to ``end``. Outline coordinates are along the prism's own x axis (``x_axis``)
    and y axis (z × x, z from ``start`` to ``end``), origin at ``start``."""

    shape: Literal["prism"] = Field(description="A straight extrusion of a polygon with holes.")
    outline: Polygon = Field(description="The section's vertices [[x, y], ...] in order, either winding.")
    holes: list[Polygon] = Field([], description="Polygons cut out of the section, each inside the outline.")
    start: Vector3 = Field(description="Where the section's origin starts, body frame.")
    end: Vector3 = Field(description="Where it ends; the extrusion runs from start to end.")
    x_axis: Vector3 | None = Field(
        None,
        description="The section's x axis, body frame (made perpendicular to end - start); default: body x "
        "(body y when the extrusion runs along x).",
    )

    _has_length = _apart("start", "end")

    @model_validator(mode="after")
    def _simple(self):
        _nonzero(self, "x_axis", "the direction of the outline's x axis")
        with np.errstate(over="ignore", invalid="ignore"):  # huge numbers: refused once translated
            problem = polygon_problem(self.outline, self.holes)
        if problem is not None:
            raise ValueError(problem)
        return self


class AssemblyPart(_Part):
    """The parts of another spec ``file`` as one part: its units converted to this spec's, its
    frame turned by ``rotation`` and its origin put at ``position``; ``mass``, when given, scales
    every part's mass and inertia to that total."""

    shape: Literal["assembly"] = Field(description="The parts of another spec file (a sub-assembly).")
    file: str = Field(min_length=1, description="The spec file, relative to this spec's folder.")
    position: Vector3 = Field(
        [0.0, 0.0, 0.0], description="Where the sub-assembly's origin goes, body frame."
    )
    rotation: Rotation | None = _turned_by("sub-assembly's", " (about its origin)")
    mass: Positive | None = Field(
        None, description="Measured total mass (per copy): every part's mass and inertia scaled to it."
    )

    _loaded: Any = PrivateAttr(None)  # the sub-assembly as read, in its own units: set when translated


Part = Annotated[Union[tuple(SHAPE_MODELS.values())], Field(discriminator="shape")]  # noqa: UP007 (a union built at run time)
"""A part of any shape, as one discriminated union (what the JSON Schema describes)."""


def _part_of_its_shape(value: Any) -> _Part:
    """Validate one part with the model of its ``shape`` only, reporting problems exactly as
    the union :data:`Part` does (same error types, context and locations, the shape tag
    included), so that a spec builds only the part models it uses."""
    if isinstance(value, _Part):
        return value
    if not isinstance(value, dict):
        raise _union_error("model_attributes_type", value)
    if "shape" not in value:
        raise _union_error("union_tag_not_found", value, {"discriminator": "'shape'"})
    tag = value["shape"] if isinstance(value["shape"], str) else str(value["shape"])
    model = SHAPE_MODELS.get(tag)
    if model is None:
        raise _union_error(
            "union_tag_invalid",
            value,
            {
                "discriminator": "'shape'",
                "tag": tag,
                "expected_tags": ", ".join(f"'{t}'" for t in SHAPE_MODELS),
            },
        )
    try:
        return model.model_validate(value)
    except ValidationError as exc:
        raise ValidationError.from_exception_data(
            "Part",
            [
                {key: e[key] for key in ("type", "input", "ctx") if key in e} | {"loc": (tag, *e["loc"])}
                for e in exc.errors(include_url=False)
            ],
        ) from None


def _union_error(kind: str, value: Any, ctx: dict | None = None) -> ValidationError:
    return ValidationError.from_exception_data(
        "Part", [{"type": kind, "loc": (), "input": value, **({"ctx": ctx} if ctx else {})}]
    )


PartOfItsShape = Annotated[Any, PlainValidator(_part_of_its_shape)]
"""How :class:`BodySpec` reads a part: as :data:`Part`, building only the model of its shape."""


class PointCloudRef(_Strict):
    """Many point masses from one file (see :mod:`rbi.formats.point_cloud`): a ``.csv`` with the
    columns mass,x,y,z or a ``.npy`` (N, 4) array; path relative to the spec's folder."""

    file: str = Field(
        min_length=1,
        description="A .csv (columns mass,x,y,z) or .npy (N×4) file, relative to the spec's folder.",
    )


PARTS_DESCRIPTION = "The parts, each placed in the body frame."
EXPECT_DESCRIPTION = "Expected values that `rbi check` compares with the computed ones."


def _expectations(value: Any) -> Expect | None:
    return value if value is None or isinstance(value, Expect) else Expect.model_validate(value)


ExpectationsWhenGiven = Annotated[Any, PlainValidator(_expectations)]
"""How :class:`BodySpec` reads ``expect:``: as ``Expect | None``, its models built only for a
spec that has the block."""


class BodySpec(_Strict):
    """A rigid body: parts placed in the body frame (and/or a point cloud), an optional fixed pivot."""

    name: str | None = Field(None, description="Name of the body, shown in titles.")
    units: Units = Field(Units(), description="Units of every number in the file (default m and kg).")
    pivot: Vector3 | None = Field(
        None, description="The fixed point a top turns about, body frame; without it the body is free."
    )
    spin_axis: Vector3 | None = Field(
        None,
        description="The body-frame direction the body spins about (need not be unit length): --spin turns "
        "about it and the tilt and precession reported are its own. Default: the symmetry axis "
        "when the body has one, else z.",
    )
    parts: list[PartOfItsShape] = Field(default_factory=list, description=PARTS_DESCRIPTION)
    point_cloud: PointCloudRef | None = Field(None, description="Many point masses read from one file.")
    expect: ExpectationsWhenGiven = Field(None, description=EXPECT_DESCRIPTION)
    _uncertain: tuple = PrivateAttr(())  # the numbers written with ±: rbi.spec.plus_minus.UncertainInput

    @model_validator(mode="after")
    def _spin_axis_has_a_direction(self):
        if self.spin_axis is not None and not any(self.spin_axis):
            raise ValueError(
                "spin_axis: must not be zero [0, 0, 0]: give a direction in body axes, e.g. [0, 1, 0]"
            )
        return self

    @model_validator(mode="after")
    def _has_mass(self):
        if not self.parts and self.point_cloud is None:
            raise ValueError("parts: must be a non-empty list of parts (or give a point_cloud: {file: ...})")
        return self

    @model_validator(mode="after")
    def _unique_names(self):
        """Part names are distinct, also after Unicode normalisation (NFC): two names that differ
        only in how an accent is encoded look the same in every table and path."""

        seen: dict[str, int] = {}
        for i, part in enumerate(self.parts):
            if part.name is None:
                continue
            key = unicodedata.normalize("NFC", part.name)
            if key in seen:
                first = seen[key]
                how = (
                    "also"
                    if self.parts[first].name == part.name
                    else "written with other Unicode code points but looking the same as"
                )
                free = next(
                    f"{part.name}-{n}"
                    for n in range(2, len(self.parts) + 3)
                    if unicodedata.normalize("NFC", f"{part.name}-{n}") not in seen
                )
                raise ValueError(
                    f"parts[{i}] ({part.name}): name: duplicate part name: {part.name!r} is {how} the name "
                    f"of parts[{first}]; each part needs its own name (e.g. {free!r}) or none"
                )
            seen[key] = i
        return self


def body_spec_json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of :class:`BodySpec`, each part described as :data:`Part`
    (the union of every shape) rather than as the validator that picks one; descriptions as
    editors show them (see :func:`_for_editors`)."""

    described = create_model(
        "BodySpec",
        __base__=BodySpec,
        __doc__=BodySpec.__doc__,
        parts=(list[Part], Field(default_factory=list, description=PARTS_DESCRIPTION)),
        expect=(Expect | None, Field(None, description=EXPECT_DESCRIPTION)),
    )
    schema = _for_editors(described.model_json_schema(mode="validation"))
    schema["$defs"] = {
        name: _for_editors(node, True) if name.endswith("Part") or name in ("Rotation", "Pattern") else node
        for name, node in schema["$defs"].items()
    }
    schema["properties"]["uncertainty"] = UNCERTAINTY_KIND
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "rbi body spec",
    } | {k: v for k, v in schema.items() if k != "title"}


UNCERTAIN_NUMBER = {
    "type": "string",
    "pattern": r"(±|\+-)",
    "description": 'a number with its standard uncertainty: "VALUE ± U", "VALUE +- U" or "VALUE ± P%"',
}
"""What a number of a part may also be (issue 37): text holding one ±, read by rbi.spec.uncertain."""

UNCERTAINTY_KIND = {
    "enum": ["standard", "tolerance"],
    "description": "how a ± of the parts reads: one standard uncertainty (default), or a tolerance limit",
}
"""The top-level ``uncertainty:`` key."""


def _for_editors(node: Any, uncertain: bool = False) -> Any:
    """``node`` as editors show it: each description in plain text (:func:`_plain`) and, with
    ``uncertain``, every ``{"type": "number"}`` schema widened to a number or
    :data:`UNCERTAIN_NUMBER`."""
    if isinstance(node, list):
        return [_for_editors(value, uncertain) for value in node]
    if not isinstance(node, dict):
        return node
    if uncertain and node.get("type") == "number":  # its words stay on the property, as editors look for them
        said = {key: node[key] for key in ("title", "description", "default") if key in node}
        return said | {"anyOf": [{k: v for k, v in node.items() if k not in said}, UNCERTAIN_NUMBER]}
    return {
        key: _plain(value)
        if key == "description" and isinstance(value, str)
        else _for_editors(value, uncertain)
        for key, value in node.items()
    }


def _plain(description: str) -> str:
    """A description as editors show it: the docstrings' reStructuredText literals (double
    backquotes) and Sphinx roles (:mod:`x`) written as plain `x`, line breaks joined."""
    description = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", description).replace("``", "`")
    return re.sub(r"\s*\n\s*", " ", description).strip()
