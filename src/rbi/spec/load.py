"""File -> YAML (safe) -> validated models -> core inputs, with every error as one line."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from rbi.core.inertia import MassProperties
from rbi.core.shapes import MassElement
from rbi.spec.errors import InputError, describe_error, format_location
from rbi.spec.units import unit_labels


@dataclass(frozen=True)
class LoadedBody:
    """A validated body in the core's terms (all numbers in the file's own units).

    props: mass properties (CoM and inertia in the body frame). pivot: the fixed point, body
    frame, or None. elements: each part's mass properties, in file order.
    """

    path: str
    name: str | None
    length_unit: str
    mass_unit: str
    props: MassProperties
    pivot: np.ndarray | None
    elements: list[MassElement]
    part_names: list[str | None]
    expect: dict[str, Any] | None = None
    spec: Any = field(default=None, repr=False)

    @property
    def units(self) -> dict[str, str]:
        return {"length": self.length_unit, "mass": self.mass_unit}

    @property
    def labels(self) -> dict[str, str]:
        return unit_labels(self.length_unit, self.mass_unit)


class _UniqueKeyLoader(getattr(yaml, "CSafeLoader", yaml.SafeLoader)):
    """Safe loader that refuses a key given twice in one mapping (PyYAML keeps the last).

    Built on libyaml's C parser where PyYAML has it: about 3 times faster on large specs
    (10⁴ parts), with the same line and column in syntax errors."""


def _construct_mapping(loader: _UniqueKeyLoader, node: yaml.MappingNode, deep: bool = False):
    seen: set[Any] = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if isinstance(key, (str, int, float, bool)) and key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, f"duplicate key {key!r}", key_node.start_mark)
        seen.add(key)
    return loader.construct_mapping(node, deep=deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
# PyYAML follows YAML 1.1, where `1e-3` and `7.8e3` (no dot, or no exponent sign) are text;
# read them as numbers, as YAML 1.2 and every user expects.
_UniqueKeyLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9_]+)[eE][-+]?[0-9]+$"),
    list("-+0123456789."),
)


def read_yaml(path: str | Path) -> Any:
    """Parsed YAML of a spec file; :class:`InputError` for a missing, empty, binary or
    malformed file."""
    path = str(path)
    try:
        data = Path(path).read_bytes()
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a directory, not a spec file") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror or exc}") from None
    if b"\x00" in data:
        raise InputError(f"{path}: not a text file (binary data)")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text (byte {exc.start})") from None
    if not text.strip():
        raise InputError(f"{path}: file is empty")
    parsed = _parse_json(text)
    if parsed is not _NOT_JSON:
        return parsed
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)  # noqa: S506 - a SafeLoader subclass
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
        problem = exc.problem or exc.context or "invalid YAML"
        raise InputError(f"{path}: YAML syntax error: {where}{problem}") from None
    except yaml.YAMLError as exc:
        raise InputError(f"{path}: YAML syntax error: {exc}") from None


_NOT_JSON = object()


def _parse_json(text: str) -> Any:
    """Fast path for a spec written as one JSON object (valid YAML too, and what a program that
    writes 10⁵ parts emits): the json module reads it about 100 times faster than PyYAML.
    Anything else — YAML, invalid JSON, a key given twice — returns ``_NOT_JSON`` and goes to
    the YAML parser, which reports the problem with its line and column."""
    if not text.lstrip().startswith("{"):
        return _NOT_JSON
    import json

    def unique(pairs):
        keys = [k for k, _ in pairs]
        if len(set(keys)) != len(keys):
            raise ValueError("duplicate key")
        return dict(pairs)

    try:
        return json.loads(text, object_pairs_hook=unique)
    except ValueError:
        return _NOT_JSON


def validation_messages(path: str, raw: Any) -> tuple[Any, list[str]]:
    """Validate parsed YAML: the spec model (or None) and one message line per problem."""
    from pydantic import ValidationError

    from rbi.spec.models import BodySpec

    if raw is None:
        return None, [f"{path}: file holds no YAML document"]
    if not isinstance(raw, dict):
        return None, [f"{path}: must be a mapping with a `parts` list at the top level (got {type(raw).__name__})"]
    try:
        return BodySpec.model_validate(raw), []
    except ValidationError as exc:
        errors = sorted(exc.errors(include_url=False), key=lambda e: e["type"] != "extra_forbidden")
        return None, [_format_error(path, err, raw) for err in errors]


def _format_error(path: str, error: dict[str, Any], raw: Any) -> str:
    part_label, field_path = format_location(tuple(error["loc"]), raw)
    message = describe_error(error, _known_fields(error["loc"], raw))
    pieces = [path] + ([part_label] if part_label else []) + field_path + [message]
    return ": ".join(pieces)


def _known_fields(loc: tuple[Any, ...], raw: Any) -> list[str]:
    """Field names valid where an unknown field was found (for 'did you mean'): walk the
    models along the error's location, through optional, list and union-of-shape fields."""
    from pydantic import BaseModel

    from rbi.spec.models import SHAPE_MODELS, BodySpec

    model: Any = BodySpec
    for item in loc[:-1]:
        if isinstance(item, int):
            continue
        if model is BodySpec and item == "parts":
            model = SHAPE_MODELS
            continue
        if model is SHAPE_MODELS:
            model = SHAPE_MODELS.get(item)
        elif isinstance(model, type) and issubclass(model, BaseModel) and item in model.model_fields:
            model = _model_inside(model.model_fields[item].annotation)
        else:
            model = None
        if model is None:
            return []
    return list(model.model_fields) if isinstance(model, type) and issubclass(model, BaseModel) else []


def _model_inside(annotation: Any) -> Any:
    """The pydantic model an annotation holds (``X | None``, ``list[X]``, ``Annotated[X, ...]``)."""
    from typing import get_args

    from pydantic import BaseModel

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        found = _model_inside(arg)
        if found is not None:
            return found
    return None


def load_spec(path: str | Path):
    """Read and validate a spec file; raises :class:`InputError` with the first problem."""
    path = str(path)
    return spec_from_raw(path, read_yaml(path))


def spec_from_raw(path: str, raw: Any):
    """Validate already parsed YAML (``raw``) of the spec file ``path``; raises
    :class:`InputError` with the first problem."""
    spec, problems = validation_messages(path, raw)
    if problems:
        more = f" (+{len(problems) - 1} more; `rbi validate {path}` lists all)" if len(problems) > 1 else ""
        raise InputError(problems[0] + more)
    return spec


def load_body(path: str | Path) -> LoadedBody:
    """Read, validate and translate a spec file into core inputs."""
    from rbi.spec.translate import body_from_spec

    path = str(path)
    return body_from_spec(load_spec(path), path)
