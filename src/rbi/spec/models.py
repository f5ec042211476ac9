"""Pydantic models of the YAML body spec (see docs/spec.md).

Numbers are strict: text such as ``"0.04"`` is refused rather than converted, and NaN or
infinity are refused everywhere. Unknown fields are refused so that a misspelt field is
reported instead of silently ignored. Parts form a discriminated union on ``shape``.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, model_validator

Number = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Positive = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=0)]
Vector3 = Annotated[list[Number], Field(min_length=3, max_length=3)]

LengthUnit = Literal["m", "cm", "mm", "in", "ft"]
MassUnit = Literal["kg", "g", "lb"]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Units(_Strict):
    """Units of every number in the file, inputs and outputs alike."""

    length: LengthUnit = "m"
    mass: MassUnit = "kg"


class _Part(_Strict):
    name: str | None = None


class _Solid(_Part):
    """A solid with either a total ``mass`` or a ``density`` (mass per length³)."""

    mass: Positive | None = None
    density: Positive | None = None

    @model_validator(mode="after")
    def _mass_or_density(self):
        if (self.mass is None) == (self.density is None):
            given = "both" if self.mass is not None else "neither"
            raise ValueError(f"mass, density: give exactly one of `mass` or `density` ({given} given)")
        return self


def _distinct(a: list[float], b: list[float], names: str) -> None:
    if np.array_equal(np.asarray(a), np.asarray(b)):
        raise ValueError(f"{names}: must be different points (the length would be 0)")


class ConePart(_Solid):
    """Solid right circular cone: ``apex`` (tip) to ``base`` (centre of the base disc)."""

    shape: Literal["cone"]
    radius: Positive
    apex: Vector3
    base: Vector3

    @model_validator(mode="after")
    def _has_height(self):
        _distinct(self.apex, self.base, "apex, base")
        return self


class CylinderPart(_Solid):
    """Solid circular cylinder between the centres of its end faces ``start`` and ``end``."""

    shape: Literal["cylinder"]
    radius: Positive
    start: Vector3
    end: Vector3

    @model_validator(mode="after")
    def _has_length(self):
        _distinct(self.start, self.end, "start, end")
        return self


class PointPart(_Part):
    """A point mass at ``position``."""

    shape: Literal["point"]
    mass: Positive
    position: Vector3

    @model_validator(mode="before")
    @classmethod
    def _no_density(cls, data: Any):
        if isinstance(data, dict) and "density" in data:
            raise ValueError("density: a point mass takes `mass` only (it has no volume)")
        return data


SHAPE_MODELS: dict[str, type[_Part]] = {
    "cone": ConePart,
    "cylinder": CylinderPart,
    "point": PointPart,
}
"""Every part model by its ``shape`` tag; new shapes are added here."""

Part = Annotated[Union[tuple(SHAPE_MODELS.values())], Field(discriminator="shape")]


class PointCloudRef(_Strict):
    """Many point masses from one file (see :mod:`rbi.spec.point_cloud`): a ``.csv`` with the
    columns mass,x,y,z or a ``.npy`` (N, 4) array; path relative to the spec's folder."""

    file: Annotated[str, Field(min_length=1)]


class BodySpec(_Strict):
    """A rigid body: parts placed in the body frame (and/or a point cloud), an optional fixed pivot."""

    name: str | None = None
    units: Units = Units()
    pivot: Vector3 | None = None
    parts: list[Part] = Field(default_factory=list)
    point_cloud: PointCloudRef | None = None
    expect: dict[str, Any] | None = None

    @model_validator(mode="after")
    def _has_mass(self):
        if not self.parts and self.point_cloud is None:
            raise ValueError("parts: must be a non-empty list of parts (or give a point_cloud: {file: ...})")
        return self

    @model_validator(mode="after")
    def _unique_names(self):
        seen: dict[str, int] = {}
        for i, part in enumerate(self.parts):
            if part.name is None:
                continue
            if part.name in seen:
                raise ValueError(f"parts[{i}] ({part.name}): name: duplicate part name (also parts[{seen[part.name]}])")
            seen[part.name] = i
        return self
