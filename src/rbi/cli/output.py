"""Output paths of the commands: :func:`rbi.api.output_target` and the one checked writer
every file rbi creates goes through (see docs/security.md)."""

from __future__ import annotations

from rbi.api import check_distinct, output_target, write_output

__all__ = ["check_distinct", "output_target", "write_output"]
