"""Changing numeric fields of a parsed spec by path, for sweeps and tolerance studies.

A path names one number in the spec as written: ``parts.NAME.FIELD`` or
``parts.NAME.FIELD[i]`` for a vector component (``parts.bolt.mass``,
``parts.bolt.position[0]``), deeper fields with more dots (``parts.disc.rotation.angle_deg``),
a part by its index where it has no name (``parts.2.mass``), and top-level fields
(``pivot[2]``). The changed spec goes through the same validation and translation as any file,
so a varied radius changes the mass of a part given by density, and its inertia.
"""

from __future__ import annotations

import copy
import re
from dataclasses import dataclass
from typing import Any

from rbi.errors import ArgumentError, literal
from rbi.spec.errors import field_text
from rbi.spec.plus_minus import PLUS_MINUS, parse_plus_minus

_TOKEN = re.compile(r"([^.\[\]]+)|\[(-?\d+)\]")


OPTIONAL_NUMBERS = {"assembly": ("mass",)}
"""Numbers a part may leave out that a sweep may still set: a sub-assembly's measured ``mass``
(left out, the parts' own masses add up)."""


@dataclass(frozen=True)
class FieldPath:
    """A resolved path: ``text`` as written, ``steps`` the keys and list indices that reach the
    number in the parsed spec."""

    text: str
    steps: tuple[Any, ...]

    def holder(self, raw: Any) -> Any:
        """The list or mapping of ``raw`` that holds the number (the one its last step names)."""
        node = raw
        for step in self.steps[:-1]:
            node = node[step]
        return node


def parse_path(text: str) -> list[Any]:
    """Split ``parts.bolt.position[0]`` into ``["parts", "bolt", "position", 0]``; ValueError
    when it is not a path."""
    if not text or len(text) > 300:
        raise ValueError("must be a field path such as parts.bolt.mass")
    tokens: list[Any] = []
    position = 0
    for match in _TOKEN.finditer(text):
        if match.start() != position and text[position : match.start()] != ".":
            raise ValueError(
                f"cannot read {text!r} as a field path (near {text[position : match.start() + 1]!r})"
            )
        name, index = match.groups()
        tokens.append(name if name is not None else int(index))
        position = match.end()
    if position != len(text) or not tokens:
        raise ValueError(f"cannot read {text!r} as a field path")
    return tokens


def resolve(raw: Any, text: str) -> FieldPath:
    """The path ``text`` in the parsed spec ``raw``, checked to end at a number;
    :class:`ArgumentError` (of ``vary``) naming the path and what is there instead."""
    try:
        tokens = parse_path(text)
    except ValueError as exc:
        raise ArgumentError("vary", literal(exc, quoted=False), item=text) from None
    steps: list[Any] = []
    node = raw
    k = 0
    while k < len(tokens):
        token, where = tokens[k], _written(tokens[:k])
        if isinstance(node, list):
            index, used = _named_entry(node, tokens, k)
            if index is None:
                index, used = _list_index(node, token), 1
            if index is None:
                names = [p.get("name") for p in node if isinstance(p, dict) and p.get("name") is not None]
                known = f" (parts: {literal(', '.join(map(str, names[:12])), quoted=False)})" if names else ""
                raise ArgumentError(
                    "vary", f"{literal(where, quoted=False)} has no entry {literal(token)}{known}", item=text
                )
            steps.append(index)
            node = node[index]
            k += used
            continue
        if isinstance(node, dict):
            if k == len(tokens) - 1 and token in OPTIONAL_NUMBERS.get(node.get("shape"), ()):
                return FieldPath(text, (*steps, token))
            if not isinstance(token, str) or token not in node:
                fields = literal(", ".join(sorted(map(str, node))), quoted=False)
                raise ArgumentError(
                    "vary",
                    f"{literal(_written(tokens[: k + 1]), quoted=False)}: no such field in the spec (fields here: {fields})",
                    item=text,
                )
            steps.append(token)
            node = node[token]
            k += 1
        else:
            raise ArgumentError(
                "vary", f"{literal(where, quoted=False)} is a single value, not a list or mapping", item=text
            )
    if isinstance(node, str) and PLUS_MINUS.search(node):  # "VALUE ± U": the run sets the value
        return FieldPath(text, tuple(steps))
    if isinstance(node, bool) or not isinstance(node, (int, float)):
        held = type(node).__name__ if isinstance(node, (dict, list)) else literal(node)
        raise ArgumentError("vary", f"must name a number in the spec (it holds {held})", item=text)
    return FieldPath(text, tuple(steps))


def _written(tokens: list[Any]) -> str:
    return field_text(tokens) or "the spec"


def _named_entry(items: list, tokens: list[Any], k: int) -> tuple[int | None, int]:
    """The entry of ``items`` whose name is the longest run of name tokens from ``k`` joined by
    dots (a part named ``bolt.1`` is ``parts.bolt.1.mass``), and how many tokens it took."""
    names = {item.get("name"): i for i, item in enumerate(items) if isinstance(item, dict)}
    run = 0
    while k + run < len(tokens) and isinstance(tokens[k + run], str):
        run += 1
    for used in range(run, 1, -1):
        index = names.get(".".join(tokens[k : k + used]))
        if index is not None:
            return index, used
    return None, 1


def _list_index(items: list, token: Any) -> int | None:
    if isinstance(token, int):
        return token if -len(items) <= token < len(items) else None
    matches = [i for i, item in enumerate(items) if isinstance(item, dict) and item.get("name") == token]
    if len(matches) == 1:
        return matches[0]
    if token.isdigit() and int(token) < len(items):
        return int(token)
    return None


def with_values(raw: Any, paths: list[FieldPath], values) -> Any:
    """A copy of ``raw`` with the number at each path replaced by the matching value (None:
    a number the spec leaves out stays out)."""
    changed = copy.deepcopy(raw)
    for path, value in zip(paths, values):
        if value is None:
            continue
        path.holder(changed)[path.steps[-1]] = float(value)
    return changed


def current_values(raw: Any, paths: list[FieldPath]) -> list[float | None]:
    """The numbers at ``paths`` in ``raw`` as written; None for one the spec leaves out
    (:data:`OPTIONAL_NUMBERS`)."""
    values: list[float | None] = []
    for path in paths:
        node, step = path.holder(raw), path.steps[-1]
        # a list holds its components by index (``step in node`` would test its values)
        present = step < len(node) if isinstance(node, list) else step in node
        written = node[step] if present else None
        values.append(parse_plus_minus(written)[0] if isinstance(written, str) else _number(written))
    return values


def _number(written: Any) -> float | None:
    return None if written is None else float(written)
