"""`rbi simulate` (placeholder: to be implemented)."""

from __future__ import annotations

from rbi.spec.errors import InputError


def simulate() -> None:
    """Simulate the body's motion (stub)."""
    raise InputError("rbi simulate is not implemented yet")
