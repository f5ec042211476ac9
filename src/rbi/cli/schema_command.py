"""`rbi schema` (placeholder: to be implemented)."""

from __future__ import annotations

from rbi.spec.errors import InputError


def schema() -> None:
    """Print the JSON schema (stub)."""
    raise InputError("rbi schema is not implemented yet")


def validate() -> None:
    """Validate spec files (stub)."""
    raise InputError("rbi validate is not implemented yet")
