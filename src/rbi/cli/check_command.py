"""`rbi check` (placeholder: to be implemented)."""

from __future__ import annotations

from rbi.spec.errors import InputError


def check() -> None:
    """Check expectations (stub)."""
    raise InputError("rbi check is not implemented yet")
