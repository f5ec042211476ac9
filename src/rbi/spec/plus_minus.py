"""Numbers of a part written with their uncertainty: ``"0.04 ± 0.0005"``, ``"0.04 +- 0.0005"``,
``"7800 ± 1%"`` (JCGM 100, the GUM).

:func:`split_uncertain` reads them out of a parsed spec: the spec with each such string replaced
by its value (validated as any spec) and one :class:`UncertainInput` per number, named by its
path as ``rbi sweep --vary`` names it (``parts.bolt.position[0]``). U is a standard uncertainty,
or with a top-level ``uncertainty: tolerance`` the half-width of a uniform distribution
(standard uncertainty U/√3, GUM 4.3.7). A sub-assembly's ± are inputs of the body that holds it
(:func:`with_sub_assemblies`). What the inputs do to a body is :mod:`rbi.spec.uncertain`'s.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from rbi.errors import InputError, shown
from rbi.spec import models
from rbi.spec.errors import field_text, named_part

PLUS_MINUS = re.compile(r"±|\+/-|\+-")
_DECIMAL = re.compile(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
_WRITTEN = re.compile(rf"\s*({_DECIMAL.pattern})\s*(?:{PLUS_MINUS.pattern})\s*({_DECIMAL.pattern})\s*(%?)\s*")
"""``VALUE ± U`` as it is most often written, read at once (anything else piece by piece)."""
NOT_NUMBERS = frozenset({"name", "shape", "file", "sequence", "repair", "solid", "subtract", "count"})
"""Fields of a part that are not measured numbers: a ± there is refused."""
KINDS = {"standard": "normal", "tolerance": "uniform"}
"""The top-level ``uncertainty:`` values and the distribution each gives a ±."""


class UncertainInput(NamedTuple):
    """One number written with ±. ``path``: as ``rbi sweep --vary`` names it; ``part``: index in
    the spec's parts; ``steps``: the keys inside the part (``("position", 0)``); ``value`` and
    ``u`` (standard uncertainty) in the file's units; ``distribution``: ``"normal"`` or
    ``"uniform"`` (on value ± √3·u)."""

    path: str
    part: int
    steps: tuple[Any, ...]
    value: float
    u: float
    distribution: str

    def draws(self, rng: np.random.Generator, n: int) -> np.ndarray:
        """``n`` values drawn from the input's distribution (JCGM 101 §6)."""
        if self.distribution == "uniform":
            half = math.sqrt(3.0) * self.u
            return rng.uniform(self.value - half, self.value + half, n)
        return rng.normal(self.value, self.u, n)

    def share_below(self, limit: float) -> float:
        """The fraction of the input's distribution at or below ``limit`` (under its value)."""
        if self.u == 0:
            return 0.0
        if self.distribution == "uniform":
            half = math.sqrt(3.0) * self.u
            return max(0.0, (limit - self.value + half) / (2.0 * half))
        return 0.5 * math.erfc((self.value - limit) / (self.u * math.sqrt(2.0)))


REACH = 1e-3
"""The share of an input's distribution past the least value its field takes (a size, mass or
density at or below 0) above which the spec is warned about: a normal distribution within 3.1
standard uncertainties of that limit."""


def parse_plus_minus(text: str) -> tuple[float, float, bool]:
    """``(value, U, relative)`` of ``"VALUE ± U"`` (``relative``: U was written in %, and is
    returned as the absolute U). ValueError with the user's message when it is not that."""
    written = _WRITTEN.fullmatch(text)
    if written and math.isfinite(value := float(written[1])) and 0 <= (u := float(written[2])) < math.inf:
        return value, abs(value) * u / 100.0 if written[3] else u, bool(written[3])
    pieces = PLUS_MINUS.split(text)
    if len(pieces) != 2:
        raise ValueError(
            f'write one ± between a value and its uncertainty, e.g. "0.04 ± 0.001" (got {shown(text)})'
        )
    value_text, u_text = pieces[0].strip(), pieces[1].strip()
    relative = u_text.endswith("%")
    u_text = u_text.removesuffix("%").strip()
    numbers = []
    for written, what in ((value_text, "the value before ±"), (u_text, "the uncertainty after ±")):
        number = float(written) if _DECIMAL.fullmatch(written) else math.nan
        if not math.isfinite(number):
            raise ValueError(f"{what} must be a finite number (got {shown(written or text)})")
        numbers.append(number)
    value, u = numbers
    if u < 0:
        raise ValueError(f"the uncertainty after ± must not be negative (got {shown(text)})")
    return value, abs(value) * u / 100.0 if relative else u, relative


@dataclass(frozen=True)
class Split:
    """A spec read out of its ± strings: ``plain`` the parsed spec with values in their place,
    ``inputs`` the uncertain numbers in file order."""

    plain: Any
    inputs: tuple[UncertainInput, ...]


def _read_out(node: Any, steps: tuple[Any, ...], found: list) -> Any:
    """A copy of ``node`` (a part, or a list or mapping in it), each ± text's place listed in
    ``found`` (keys and indices from the part's index on)."""
    if isinstance(node, dict):
        return {key: _read_out(item, (*steps, key), found) for key, item in node.items()}
    if isinstance(node, list):
        return [_read_out(item, (*steps, k), found) for k, item in enumerate(node)]
    if isinstance(node, str) and (PLUS_MINUS.search(node) or node.lstrip().startswith("±")):
        found.append(steps)
    return node


def first_part_uncertain(raw: Any) -> bool:
    """Whether the first part of the parsed spec ``raw`` writes a number with ± (a spec is then
    read out of its ± before it is validated; checked on one part only, at no cost to others)."""
    parts, found = raw.get("parts") if isinstance(raw, dict) else None, []
    if isinstance(parts, list) and parts and isinstance(parts[0], dict):
        _read_out(parts[0], (0,), found)
    return bool(found)


def named_plus_minus(spec: models.BodySpec) -> bool:
    """Whether a part's name holds a ± (which :func:`split_uncertain` refuses)."""
    return any(part.name and ("±" in part.name or "+-" in part.name) for part in spec.parts)


def split_uncertain(raw: Any, path: str) -> Split | None:
    """The spec ``raw`` without its ± strings, or None when it has none and no top-level
    ``uncertainty``. InputError (``file: part: field: what is wrong``) for a ± that cannot be
    read or that stands on something other than a number of a part. ``raw`` is a mapping (the
    caller has refused anything else)."""
    parts = raw.get("parts")
    found: list[tuple[Any, ...]] = []
    plain = dict(raw)
    if isinstance(parts, list):
        plain["parts"] = [
            _read_out(part, (i,), found) if isinstance(part, dict) else part for i, part in enumerate(parts)
        ]
    if not found and "uncertainty" not in raw:
        return None
    kind = plain.pop("uncertainty", "standard")
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError(
            f"{path}: uncertainty: must be standard (± is one standard uncertainty) or tolerance "
            f"(± is a tolerance limit) (got {shown(kind)})",
            file=path,
            field="uncertainty",
        )
    distribution = KINDS[kind]
    divisor = math.sqrt(3.0) if distribution == "uniform" else 1.0  # GUM 4.3.7
    inputs, written = [], set(found)  # a set: one look-up per product of inertia, not a scan
    for index, *steps in found:
        node = plain["parts"][index]
        for step in steps[:-1]:
            node = node[step]
        field = field_text(steps)
        try:
            named = [step for step in steps if isinstance(step, str)]
            if named and named[-1] in NOT_NUMBERS:
                raise ValueError(f"± is for a number of a part, and `{named[-1]}` is not a measured number")
            twin = (index, "inertia", *steps[:0:-1])  # [j][i] of a custom part's matrix
            if steps[0] == "inertia" and len(steps) == 3 and steps[1] > steps[2] and twin in written:
                raise ValueError(
                    f"± also on inertia{field_text(twin[2:])}, the same product of inertia: write it once"
                )
            value, u, _ = parse_plus_minus(node[steps[-1]])
        except ValueError as exc:
            label = named_part(index, parts[index].get("name"))
            raise InputError(f"{path}: {label}: {field}: {exc}", file=path, part=label, field=field) from None
        node[steps[-1]] = value
        name = parts[index].get("name")  # parts.NAME (parts.INDEX without a name), as sweeps name parts
        where = f"parts.{name if isinstance(name, str) and name else index}.{field}"
        inputs.append(UncertainInput(where, index, tuple(steps), value, u / divisor, distribution))
    return Split(plain, tuple(inputs))


def with_sub_assemblies(spec: models.BodySpec) -> tuple[UncertainInput, ...]:
    """The spec's own uncertain inputs and, after each sub-assembly's own, the inputs of its
    file as its body has them (its sub-assemblies' included), named as ``rbi parts --expand``
    names the parts (``parts.ASSEMBLY/PART.mass``), with steps ``("file", j)``: its j-th."""
    assemblies = [(i, part) for i, part in enumerate(spec.parts) if isinstance(part, models.AssemblyPart)]
    if not assemblies:
        return spec._uncertain
    found = [each for each in spec._uncertain if each.steps[0] != "file"]
    for i, part in assemblies:
        prefix = f"parts.{part.name or i}/"
        inner = enumerate(part._loaded.spec._uncertain)
        found += [x._replace(path=prefix + x.path[6:], part=i, steps=("file", j)) for j, x in inner]
    return tuple(sorted(found, key=lambda each: each.part))


@functools.cache
def _schema(model: type) -> dict[str, Any]:
    return model.model_json_schema()


def _branches(node: dict[str, Any]) -> Any:
    """``node`` and, through ``anyOf`` (an optional field, a number or a material name), each
    schema it allows."""
    yield node
    for each in node.get("anyOf", ()):
        yield from _branches(each)


def lower_limit(part: Any, steps: tuple[Any, ...]) -> float | None:
    """The least value the spec allows at ``steps`` of ``part`` (its schema's ``minimum`` or
    ``exclusiveMinimum``: 0 for a size, mass or density), or None where there is none."""
    node = _schema(type(part))["properties"].get(steps[0], {})
    for step in steps[1:]:  # into a list (a size's components); a nested model has no limits
        if not isinstance(step, int):
            return None
        node = next((b["items"] for b in _branches(node) if "items" in b), {})
    limits = (
        b.get("minimum", b.get("exclusiveMinimum")) for b in _branches(node) if b.get("type") == "number"
    )
    return next((float(limit) for limit in limits if limit is not None), None)


def limit_warnings(spec: models.BodySpec, path: str) -> list[str]:
    """A warning for each of the spec's own inputs with ± whose distribution reaches past the
    least value its field takes by more than :data:`REACH` of it: Monte Carlo draws bodies
    there that no spec could be written for (a negative radius, a negative mass)."""
    out = []
    for x in spec._uncertain:
        limit = None if x.steps[0] == "file" else lower_limit(spec.parts[x.part], x.steps)
        share = 0.0 if limit is None else x.share_below(limit)
        if share > REACH:
            out.append(
                f"{path}: {x.path}: {100 * share:.2g}% of its {x.distribution} distribution ({x.value:g}, "
                f"u = {x.u:.3g}) lies below {limit:g}, where the spec allows no value: "
                "Monte Carlo draws there give bodies no spec could describe"
            )
    return out
