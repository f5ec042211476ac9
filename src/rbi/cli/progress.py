"""Progress of a long run on standard error: a bar with the count and the time left, drawn only
when standard error is a terminal (a pipe or a log file gets nothing), and gone when the run
ends (``transient``), so the one-line result is all that stays."""

from __future__ import annotations

import sys


class StderrProgress:
    """``update(done, total)`` draws or moves the bar; ``close()`` removes it. ``what`` names
    the run (``gif``), ``unit`` what is counted (``frames``)."""

    def __init__(self, what: str, unit: str) -> None:
        self.what, self.unit = what, unit
        self.bar = self.task = None

    def update(self, done: int, total: int) -> None:
        if self.bar is None:
            from rich.console import Console
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

            self.bar = Progress(
                TextColumn(self.what),
                BarColumn(),
                MofNCompleteColumn(),
                TextColumn(self.unit),
                TimeRemainingColumn(),
                console=Console(stderr=True),
                transient=True,
            )
            self.task = self.bar.add_task(self.what, total=total)
            self.bar.start()
        self.bar.update(self.task, completed=done, total=total)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()
            self.bar = None


def stderr_progress(what: str, unit: str) -> StderrProgress | None:
    """A :class:`StderrProgress` when standard error is a terminal, else None (as ``rbi
    sweep`` does)."""
    stream = sys.stderr
    return StderrProgress(what, unit) if stream is not None and stream.isatty() else None
