"""Output paths of the commands: a thin front of :mod:`rbi.files.output`, the one checked
writer every file rbi creates goes through (see docs/security.md)."""

from __future__ import annotations

from rbi.files.output import (
    STDOUT,
    STDOUT_ALIASES,
    OutputTarget,
    atomic_path,
    check_distinct,
    open_output,
    output_target,
    write_output,
)

__all__ = [
    "STDOUT",
    "STDOUT_ALIASES",
    "OutputTarget",
    "atomic_path",
    "check_distinct",
    "open_output",
    "output_target",
    "write_output",
]
