"""Reference points by name (``com``, ``origin``, ``pivot``) and the words for what a reference
point may be: one list for the spec's ``about:`` fields, the API's ``about`` and the CLI's
``--about`` (:meth:`rbi.spec.translate.LoadedBody.point` resolves a name to a point). No
pydantic here: ``import rbi.api`` stays light."""

from __future__ import annotations

from typing import Any

REFERENCE_POINTS = ("com", "origin", "pivot")
"""The reference points by name (any case, spaces around): the centre of mass, (0, 0, 0) and the
spec's pivot."""

NO_PIVOT = "pivot needs a `pivot` in the spec, and there is none"
"""What asking a body without a pivot for its pivot says (after the file and the option or field)."""


def reference_name(value: Any) -> str | None:
    """``value`` as one of :data:`REFERENCE_POINTS` (any case, spaces around), or None."""
    name = value.strip().lower() if isinstance(value, str) else None
    return name if name in REFERENCE_POINTS else None


def reference_choices(point: str) -> str:
    """What a reference point may be, ``point`` the caller's way of writing one:
    ``com, origin, pivot or a point [x, y, z]``."""
    return f"{', '.join(REFERENCE_POINTS)} or a point {point}"
