"""`rbi export` (placeholder: to be implemented)."""

from __future__ import annotations

from rbi.spec.errors import InputError


def export() -> None:
    """Export the inertial element (stub)."""
    raise InputError("rbi export is not implemented yet")
