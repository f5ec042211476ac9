"""Field types of the spec that accept more than one form (a number or a material name, a
matrix or its six components, a percentage or an absolute tolerance).

Each is validated by one plain function that raises ``ValueError`` with the message the user
sees (after ``file: part: field:``), and carries its own JSON Schema for ``rbi schema``.
"""

from __future__ import annotations

import math
import re
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, PlainValidator, WithJsonSchema

from rbi.core.validity import subnormal_problem
from rbi.errors import shown
from rbi.spec.checks import PERCENT
from rbi.spec.materials import ALIASES, MATERIAL_DENSITIES_SI, canonical_name, unknown_material_message
from rbi.spec.points import REFERENCE_POINTS, reference_choices, reference_name


def not_subnormal(value: float) -> float:
    """``value`` unless it is subnormal (:func:`rbi.core.validity.subnormal_problem`)."""
    problem = subnormal_problem(value)
    if problem:
        raise ValueError(problem)
    return value


Number = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Positive = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=0), AfterValidator(not_subnormal)]
Vector3 = Annotated[list[Number], Field(min_length=3, max_length=3)]


class StrictModel(BaseModel):
    """Base of every spec model: unknown fields refused, instances immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True)


class BuiltWhenUsed(StrictModel):
    """Base of the models of what a spec may leave out (the parts of each shape, patterns,
    rotations, the ``expect:`` block): pydantic builds a model's validator when it is first used
    rather than when the class is defined, so reading a spec builds only what it has (start-up
    time: see docs/performance.md)."""

    model_config = ConfigDict(extra="forbid", frozen=True, defer_build=True)


def _finite_number(value: Any, what: str = "a number") -> float:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise ValueError(f"must be {what} (got {shown(value)})")
    if not math.isfinite(value):
        raise ValueError(f"must be a finite number (got {value!r})")
    return float(value)


def _looks_numeric(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def read_by(check: Any, description: str, *forms: dict[str, Any]) -> Any:
    """A field type read by ``check`` (its ValueError is the message the user sees), which the
    JSON Schema describes as any of ``forms``."""
    return Annotated[
        Any, PlainValidator(check), WithJsonSchema({"anyOf": list(forms), "description": description})
    ]


# --- true or false ---------------------------------------------------------------------------


def _flag(value: Any) -> bool:
    if not isinstance(value, bool):
        raise ValueError(f"must be true or false (got {shown(value)})")
    return value


Flag = Annotated[Any, PlainValidator(_flag), WithJsonSchema({"type": "boolean"})]


# --- non-negative number -------------------------------------------------------------------


def _non_negative(value: float) -> float:
    if value < 0:
        raise ValueError(f"must not be negative (got {value!r})")
    return value


NonNegative = Annotated[
    float,
    Field(strict=True, allow_inf_nan=False, json_schema_extra={"minimum": 0}),
    AfterValidator(_non_negative),
]


# --- density: a number or a material name ----------------------------------------------------


def _density(value: Any) -> float | str:
    if isinstance(value, str):
        if _looks_numeric(value):
            raise ValueError(f"must be a number, not text (write {value.strip()} without quotes)")
        if canonical_name(value) is None:
            raise ValueError(unknown_material_message(value))
        return value
    number = _finite_number(value, "a number (mass per length³) or a material name such as steel")
    if number <= 0:
        raise ValueError(f"must be greater than 0 (got {value!r})")
    return not_subnormal(number)


def _material_names() -> list[str]:
    """Each built-in material name and alias once, as the tables write it (rbi accepts any case,
    and spaces, ``_`` or ``-`` alike)."""
    return sorted(set(MATERIAL_DENSITIES_SI) | set(ALIASES))


def _any_case_pattern(names: list[str]) -> str:
    """A regular expression matching any of ``names`` in any case, a space, ``_`` or ``-``
    standing for one another (JSON Schema patterns have no case-insensitive flag)."""

    def one(name: str) -> str:
        return "".join(
            f"[{c.lower()}{c.upper()}]" if c.isalpha() else "[ _-]" if c in " _-" else re.escape(c)
            for c in name
        )

    return "^(?:" + "|".join(one(name) for name in names) + ")$"


Density = read_by(
    _density,
    "Mass per length³ in the file's units, or a built-in material name (converted from kg/m³ to the file's units).",
    {"type": "number", "exclusiveMinimum": 0},
    {"type": "string", "enum": _material_names()},
    {
        "type": "string",
        "pattern": _any_case_pattern(_material_names()),
        "description": "A material name above in any case, with spaces, _ or - alike (e.g. Stainless_Steel).",
    },
)


# --- inertia matrix: 3×3 or six components -------------------------------------------------

_COMPONENTS = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
MATRIX_ROWS = (("ixx", "ixy", "ixz"), ("ixy", "iyy", "iyz"), ("ixz", "iyz", "izz"))
"""Where each of the six components stands in the symmetric matrix."""
_MATRIX_FORMS = (
    "a 3×3 matrix [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] or a mapping "
    "{ixx, iyy, izz, ixy, ixz, iyz}"
)


def _inertia_matrix(value: Any) -> list[list[float]]:
    if isinstance(value, dict):
        unknown = [k for k in value if k not in _COMPONENTS]
        if unknown:
            raise ValueError(f"{unknown[0]}: unknown component (expected {', '.join(_COMPONENTS)})")
        missing = [k for k in _COMPONENTS[:3] if k not in value]
        if missing:
            raise ValueError(f"{missing[0]}: missing required component")
        c = {k: _component(k, value.get(k, 0.0)) for k in _COMPONENTS}
        return [[c[k] for k in row] for row in MATRIX_ROWS]
    if not (
        isinstance(value, list)
        and len(value) == 3
        and all(isinstance(r, list) and len(r) == 3 for r in value)
    ):
        raise ValueError(f"must be {_MATRIX_FORMS} (got {shown(value)})")
    return [[_component(f"[{i}][{j}]", v) for j, v in enumerate(row)] for i, row in enumerate(value)]


def _component(name: str, value: Any) -> float:
    try:
        return _finite_number(value)
    except ValueError as exc:
        raise ValueError(f"{name}: {exc}") from None


_NUMBER_ROW = {"type": "array", "items": {"type": "number"}, "minItems": 3, "maxItems": 3}

InertiaMatrix = read_by(
    _inertia_matrix,
    "Inertia matrix (mass·length²): products are the matrix entries (ixy = −∫xy dm), as in `rbi inertia` and URDF.",
    {"type": "array", "items": _NUMBER_ROW, "minItems": 3, "maxItems": 3},
    {
        "type": "object",
        "properties": {
            k: {
                "type": "number",
                "description": f"I{k[1:]}, mass·length²"
                + (" (product of inertia, with the minus sign inside the matrix)" if k[1] != k[2] else ""),
            }
            for k in _COMPONENTS
        },
        "required": list(_COMPONENTS[:3]),
        "additionalProperties": False,
    },
)


# --- tolerance: a percentage or an absolute number -----------------------------------------


def _tolerance(value: Any) -> float | str:
    if isinstance(value, str):
        match = PERCENT.match(value)
        if not match or not math.isfinite(float(match.group(1))):
            raise ValueError(
                f"must be a percentage such as 1% or an absolute number in file units (got {shown(value)})"
            )
        return value.strip()
    _finite_number(value, "a percentage such as 1% or an absolute number in file units")
    return float(_non_negative(value))


Tolerance = read_by(
    _tolerance,
    "Absolute (file units) or a percentage of the expected value's magnitude, e.g. 1%.",
    {"type": "number", "minimum": 0},
    {"type": "string", "pattern": r"^\s*[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?\s*%\s*$"},
)


# --- reference point: com, origin, pivot or [x, y, z] ---------------------------------------


def _about(value: Any) -> str | list[float]:
    name = reference_name(value)
    if name is not None:
        return name
    if isinstance(value, list) and len(value) == 3:
        return [_component(f"[{i}]", v) for i, v in enumerate(value)]
    raise ValueError(f"must be {reference_choices('[x, y, z]')} (got {shown(value)})")


AboutPoint = read_by(
    _about,
    "Reference point: com, origin, pivot, or [x, y, z] in body coordinates.",
    {"type": "string", "enum": list(REFERENCE_POINTS)},
    {"type": "array", "items": {"type": "number"}, "minItems": 3, "maxItems": 3},
)
