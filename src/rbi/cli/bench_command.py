"""`rbi bench` (placeholder: to be implemented)."""

from __future__ import annotations

from rbi.spec.errors import InputError


def bench() -> None:
    """Benchmarks (stub)."""
    raise InputError("rbi bench is not implemented yet")
