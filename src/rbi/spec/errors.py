"""Input errors, each rendered as one line: ``file: part: field: what is wrong``."""

from __future__ import annotations

import difflib
import re
from typing import Any

from rbi.errors import (
    InputError,  # noqa: F401  (the spec layer's errors are InputErrors)
    shown,
)


def format_location(loc: tuple[Any, ...], raw: Any) -> tuple[str, list[str]]:
    """Split a pydantic error location into a part label (``parts[1] (stem)``) and the field
    path inside it. ``raw`` is the parsed YAML, used to find a part's name."""
    loc = list(loc)
    part_label = ""
    if len(loc) >= 2 and loc[0] == "parts" and isinstance(loc[1], int):
        index = loc[1]
        part_label = named_part(index, _part_field(raw, index, "name"))
        loc = loc[2:]
        if loc and isinstance(loc[0], str) and _part_field(raw, index, "shape") == loc[0]:
            loc = loc[1:]  # the discriminator tag pydantic inserts for a union member
    field = field_text(loc)
    return part_label, [field] if field else []


def field_text(steps: Any) -> str:
    """The keys and indices ``steps`` written as a field path: ``position[0]``, ``rotation.axis``."""
    text = ""
    for step in steps:
        text += f"[{step}]" if isinstance(step, int) else ("." if text else "") + str(step)
    return text


def _part_field(raw: Any, index: int, key: str) -> Any:
    """Field ``key`` of the part at ``index`` in the parsed YAML, or None."""
    parts = raw.get("parts") if isinstance(raw, dict) else None
    part = parts[index] if isinstance(parts, list) and 0 <= index < len(parts) else None
    return part.get(key) if isinstance(part, dict) else None


_MUST_BE = {
    "finite_number": "a finite number",
    **dict.fromkeys(("float_type", "float_parsing"), "a number"),
    **dict.fromkeys(("int_type", "int_from_float", "int_parsing"), "a whole number"),
    **dict.fromkeys(("model_type", "model_attributes_type", "dict_type"), "a mapping of fields"),
    "string_type": "text",
    "string_too_short": "a file name, not empty",
    "list_type": "a list of 3 numbers [x, y, z]",
    "greater_than": "greater than {gt:g}",
    "greater_than_equal": "at least {ge:g}",
    "less_than_equal": "at most {le:g}",
    "too_short": "a list of {min_length} numbers [x, y, z]",
    "too_long": "a list of {max_length} numbers [x, y, z]",
    "literal_error": "one of {expected}",
}
"""What a value the models refuse must be, by pydantic's error type (filled in from the error's
context)."""


def describe_error(error: dict[str, Any], known_fields: list[str] | None = None) -> str:
    """Plain-words message for one pydantic error dict."""
    kind = error["type"]
    ctx = error.get("ctx") or {}
    value = error.get("input")
    if kind == "missing":
        return "missing required field"
    if kind == "extra_forbidden":
        field = str(error["loc"][-1]) if error["loc"] else ""
        hint = difflib.get_close_matches(field, known_fields or [], n=1)
        return "unknown field" + (f" (did you mean '{hint[0]}'?)" if hint else "")
    if tuple(error["loc"]) == ("parts",) and kind in ("too_short", "list_type"):
        return f"must be a non-empty list of parts (got {shown(value)})"
    polygon = next((k for k in ("outline", "holes") if k in error["loc"]), None)
    if kind in ("too_short", "too_long", "list_type") and polygon is not None:  # a prism's polygons, points
        loc = tuple(error["loc"])
        depth = len(loc) - loc.index(polygon) - (polygon == "holes")  # 0: the holes, 1: a polygon, 2: a point
        if depth == 2:
            return f"must be a point [x, y] (got {shown(value)})"
        if kind == "list_type":
            listed = "polygons [[[x, y], ...], ...]" if depth == 0 else "points [[x, y], ...]"
            return f"must be a list of {listed} (got {shown(value)})"
        most = (
            f"at least {ctx.get('min_length')}" if kind == "too_short" else f"at most {ctx.get('max_length')}"
        )
        return f"must have {most} vertices (got {len(value) if isinstance(value, list) else shown(value)})"
    if kind in _MUST_BE:
        return f"must be {_MUST_BE[kind].format(**ctx)} (got {shown(value)})"
    if kind == "union_tag_invalid":
        shapes = re.findall(r"'([^']+)'", str(ctx.get("expected_tags", "")))
        hint = difflib.get_close_matches(str(ctx.get("tag")), shapes, n=1)
        return (
            f"shape: unknown shape {shown(ctx.get('tag'))}"
            + (f" (did you mean '{hint[0]}'?)" if hint else "")
            + f"; expected one of {ctx.get('expected_tags')}"
        )
    if kind == "union_tag_not_found":
        return "shape: missing required field (which solid is this part?)"
    if kind == "value_error":
        return str(ctx.get("error", error["msg"]))
    return error["msg"]


def part_label(index: int, part) -> str:
    """How messages name the part at ``index``: ``parts[2] (bolt)``."""
    return named_part(index, part.name)


def named_part(index: int, name: Any) -> str:
    """``parts[INDEX] (NAME)``; just ``parts[INDEX]`` unless ``name`` is text, not empty."""
    return f"parts[{index}]" + (f" ({name})" if isinstance(name, str) and name else "")
