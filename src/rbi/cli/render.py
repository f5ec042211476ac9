"""Rendering: a result of the API (:class:`rbi.Result`) as JSON, CSV or rich tables fitted to
the terminal; progress bars."""

from __future__ import annotations

import contextlib
import json
import os
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from typing import Any

import rbi
from rbi.cli.terminal import say, terminal_safe


class Document(rbi.Result):
    """A row given as a dict (``data``, made JSON-ready by :class:`rbi.Result`): its CSV is
    the one object, flattened (several files' rows, :mod:`rbi.cli.each_file`)."""

    def __init__(self, data: dict[str, Any]) -> None:
        self.data = data

    def to_dict(self) -> dict[str, Any]:
        return self.data


def rich_console(stderr: bool = False):
    """A rich Console on stdout (``stderr``: on stderr). It prints text as given: text from data
    is escaped once, where it becomes rich text (:class:`rbi.cli.tables.SafeTable`'s cells and
    titles, :func:`note`), before any layout."""
    from rich.console import Console  # rich only when something is drawn: JSON never loads it (~25 ms)

    # rich's own NO_COLOR handling drops colours but keeps bold, dim and italic escapes;
    # NO_COLOR users get plain text.
    color_system = None if os.environ.get("NO_COLOR") else "auto"
    return Console(stderr=stderr, highlight=False, color_system=color_system)


def emit_result(
    fmt: str, result: Any, *, table: Callable[[], Any] | None = None, file: str | None = None
) -> None:
    """Write a result of the API (:class:`rbi.Result`) to stdout in the chosen format: its
    ``to_dict()`` as one JSON object (``file`` first when given), its CSV or its tables
    (``table()`` when given, else its rows drawn as rbi's). A result holds finite numbers only:
    the API refuses one that overflowed (JSON has no NaN)."""
    data = result.to_dict() if file is None else {"file": file, **result.to_dict()}
    if fmt == "json":
        sys.stdout.write(json.dumps(data, allow_nan=False) + "\n")
        return
    say_warnings(data.get("warnings", ()))
    if fmt == "csv":
        sys.stdout.write(result.to_csv())
    else:
        print_table(tables_of(result) if table is None else table())


def note(text: str, style: str | None = None) -> Any:
    """Prose under or between tables (a run's notes, the bench's headline) as rich text: escaped
    once, here (as a cell is in :class:`rbi.cli.tables.SafeTable`), its own line breaks kept."""
    from rich.text import Text  # not at top level: `rbi inertia --format json` would load rich.text too

    return Text(terminal_safe(text, keep="\n"), style=style)


def tables_of(result: Any) -> Any:
    """A result's rows (``result.rows()``) drawn as rbi's tables."""
    from rbi.cli.tables import drawn  # heavy: rich (~25 ms), which JSON and CSV never load

    return drawn(result.rows())


def say_warnings(warnings: Iterable[str]) -> None:
    """Each warning about a body (``Body.warnings``: units that look wrong ...) as one line
    ``rbi: warning: ...`` on stderr; JSON output carries them as ``"warnings"`` instead."""
    for warning in warnings:
        say(f"warning: {warning}")


def print_table(renderable) -> None:
    """Print a table (or a group of them) on stdout fitted to the terminal's width: no number
    cut, split or shortened (see :func:`fitted`)."""
    console = rich_console()
    console.print(fitted(renderable, console))


# --- progress (rich is imported when a bar is first drawn) -----------------------------------


class ProgressBar:
    """rbi's one progress bar: ``what`` (the description), a bar, the count (``12/40 unit``, or
    a percentage when ``unit`` is None) and the time left (``elapsed``: the time taken). It
    is drawn on standard error (``stdout``: standard output) once ``delay`` seconds have passed
    since it was made, and it is gone when closed (``transient``), so the result is all that
    stays. :func:`progress_bar` gives one only on a terminal.

    Lower layers never see it: they call ``update(done, total)`` or ``bar(fraction)`` (a
    simulation's callback), and ``close()`` ends it."""

    def __init__(
        self,
        what: str,
        unit: str | None = None,
        *,
        stdout: bool = False,
        delay: float = 0.0,
        elapsed: bool = False,
    ) -> None:
        self.what, self.unit, self.total = what, unit, 1.0
        self.stdout, self.delay, self.elapsed = stdout, delay, elapsed
        self.start = time.perf_counter()
        self.bar = self.task = None

    def update(self, done: float, total: float | None = None, what: str | None = None) -> None:
        """Move the bar to ``done`` of ``total`` (the last total given when None)."""
        self.total = self.total if total is None else total
        if self.bar is None:
            if time.perf_counter() - self.start < self.delay:
                return
            self._draw()
        self.bar.update(self.task, completed=done, total=self.total, description=what or self.what)

    def __call__(self, fraction: float) -> None:
        """A simulation's progress callback: ``fraction`` of the run done."""
        self.update(min(max(fraction, 0.0), 1.0), 1.0)

    def _draw(self) -> None:
        # not at top level: `rbi inertia` would load rich.progress too
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeElapsedColumn,
            TimeRemainingColumn,
        )

        if self.unit is None:
            count = [TextColumn("{task.percentage:>3.0f}%")]
        else:
            count = [MofNCompleteColumn(), *([TextColumn(self.unit)] if self.unit else [])]
        self.bar = Progress(
            TextColumn("{task.description}"),
            BarColumn(),
            *count,
            TimeElapsedColumn() if self.elapsed else TimeRemainingColumn(),
            console=rich_console(stderr=not self.stdout),
            transient=True,
        )
        self.task = self.bar.add_task(self.what, total=self.total)
        self.bar.start()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()
            self.bar = None


@contextlib.contextmanager
def progress_bar(
    what: str, unit: str | None = None, *, show: bool = True, **options
) -> Iterator[ProgressBar | None]:
    """A :class:`ProgressBar` (closed on leaving the block) when ``show`` and the stream it is
    drawn on is a terminal, else None (a pipe or a log file gets nothing)."""
    stream = sys.stdout if options.get("stdout") else sys.stderr
    bar = ProgressBar(what, unit, **options) if show and stream is not None and stream.isatty() else None
    try:
        yield bar
    finally:
        if bar is not None:
            bar.close()


# --- fitting the terminal (rich imported inside: JSON and CSV never load it, ~25 ms) ---------


def fitted(renderable, console):
    """``renderable`` laid out for ``console``'s width, so that no number is cut, split across
    lines or shortened to ``…``: each table's title goes on a line of its own (a long title
    wraps as text, not squeezed to the table's width), and a table wider than the terminal is
    printed stacked instead (:func:`stacked`). Groups are fitted part by part; anything else
    passes unchanged."""
    # not at top level: `rbi inertia --format json` would load rich.console and rich.table too
    from rich.console import Group
    from rich.segment import Segment, Segments
    from rich.table import Table

    if isinstance(renderable, Group):
        return Group(*(fitted(part, console) for part in renderable.renderables))
    if not isinstance(renderable, Table):
        return renderable
    title, renderable.title = renderable.title, None
    plain_lines = _long_table_lines(renderable, console) if renderable.row_count > LONG_TABLE_ROWS else None
    if plain_lines is not None:
        body = Segments([segment for line in plain_lines for segment in (Segment(line), Segment.line())])
        return Group(title, body) if title else body
    lines = _lines_if_intact(renderable, console)
    if lines is None:
        renderable.title = title
        return stacked(renderable, console.width)
    body = Segments([segment for line in lines for segment in (*line, Segment.line())])
    return Group(title, body) if title else body


LONG_TABLE_ROWS = 500
"""Tables longer than this (a robot of 10⁵ links) are laid out by :func:`_long_table_lines`
when they fit the terminal: rich takes about a millisecond a row, 100 s for such a robot."""


def _long_table_lines(table, console) -> list[str] | None:
    """The lines rich prints for ``table`` (rbi's style, :func:`rbi.cli.tables.drawn`: no edge,
    a rule under the header, one space of padding, one between columns; no title), made
    directly, when every cell is plain text on one line and the columns at their natural widths
    fit ``console``; else None (rich lays it out). Plain text: rich's header style is left out,
    as it is for any output that is not a terminal."""
    # not at top level: `rbi inertia --format json` would load rich too
    from rich import box
    from rich.cells import cell_len

    if table.box is not box.SIMPLE_HEAD or table.show_edge or not table.show_header or table.show_footer:
        return None
    if tuple(table.padding) != (0, 1, 0, 1) or not (console.encoding or "").lower().startswith("utf"):
        return None
    columns = []
    for column in table.columns:
        if column.justify not in ("left", "right") or column.width or column.min_width or column.max_width:
            return None
        texts = [_cell_text(cell) for cell in (column.header, *column.cells)]
        if any(text is None or "\n" in text for text in texts):
            return None
        lengths = list(map(cell_len, texts))
        columns.append((column.justify, texts, lengths, max(lengths)))
    width = sum(w + 2 for *_, w in columns) + len(columns) - 1
    if width > console.width:
        return None

    def cell(justify: str, text: str, pad: int) -> str:
        return f" {text}{' ' * pad} " if justify == "left" else f" {' ' * pad}{text} "

    rows = [
        " ".join(cell(j, texts[i], w - lengths[i]) for j, texts, lengths, w in columns)
        for i in range(len(columns[0][1]))
    ]
    return [rows[0], "─" * width, *rows[1:]]


def _lines_if_intact(table, console):
    """``table`` rendered at ``console``'s width (lines of rich segments) when it shows every
    cell whole on one line (headers may wrap between words, never inside one: a path like
    ``parts.stem.radius`` stays whole; a cell folded, wrapped or shortened to ``…`` is not
    whole), else None. The lines are what gets printed: a table is laid out once."""
    rendered = console.render_lines(table, console.options, pad=False)
    lines = ["".join(segment.text for segment in line) for line in rendered]
    rows = zip(*[[_cell_text(cell) for cell in column.cells] for column in table.columns])
    if not _rows_in_order(rows, lines):
        return None
    for column in table.columns:
        if any(not any(word in line for line in lines) for word in _plain(column.header).split()):
            return None
    return rendered


def _cell_text(cell) -> str | None:
    """The text a cell shows, or None for a renderable that is not text (a table rbi prints is
    a :class:`rbi.cli.tables.SafeTable`, whose strings are rich Text: never markup)."""
    # not at top level: `rbi inertia --format json` would load rich.text too
    from rich.text import Text

    return cell.plain if isinstance(cell, Text) else None


def _rows_in_order(rows, lines: list[str]) -> bool:
    """Whether each row's non-empty cells all stand whole on one line, the rows' lines in the
    rows' order (a cell that wrapped, folded or was cut to ``…`` is on no line whole). One pass
    down the lines: a table of 10,000 rows is checked in linear time."""
    at = 0
    for row in rows:
        cells = [text for text in row if text]
        if not cells:
            continue
        while at < len(lines) and not all(text in lines[at] for text in cells):
            at += 1
        if at == len(lines):
            return False
        at += 1
    return True


def _plain(cell) -> str:
    """A cell or header as the text it shows (lines joined by a space)."""
    text = _cell_text(cell)
    return " ".join((str(cell) if text is None else text).split())


def stacked(table, width: int):
    """The rows of ``table`` one below the other, for a terminal too narrow for its columns.

    A quantity/unit/value table (:func:`rbi.cli.tables.quantities`) gives one line a row, ``quantity [unit]``
    on the left and the value on the right, or the value on the next line when both do not fit
    on one. Any other table gives, per row, its first cell as a heading and then one line
    ``header: value`` for each other column. Values are never wrapped."""
    # not at top level: `rbi inertia --format json` would load rich.console, rich.padding and rich.text too
    from rich.console import Group
    from rich.padding import Padding
    from rich.text import Text

    headers = [_plain(column.header) for column in table.columns]
    rows = list(zip(*[[_plain(cell) for cell in column.cells] for column in table.columns]))
    lines = [table.title] if table.title else []
    if getattr(table, "rbi_layout", None) == "quantities":
        for name, unit, value in rows:
            left = f" {name}" + (f" [{unit}]" if unit else "")
            if len(left) + 2 + len(value) <= width:
                lines.append(Text(left + " " * (width - len(left) - len(value)) + value, no_wrap=True))
            elif len(value) + 3 <= width:
                lines += [Text(left), Text(" " * (width - len(value)) + value, no_wrap=True)]
            else:  # longer than a line: wrapped between words (a number is one word), never cut
                lines += [Text(left), Padding(Text(value), (0, 0, 0, 3))]
        return Group(*lines)
    label = max((len(h) for h in headers[1:]), default=0)
    for row in rows:
        if not any(row):  # a spacer row (before a total)
            continue
        heading = f"{headers[0]} {row[0]}" if row[0].isdigit() and headers[0] else row[0] or headers[0]
        lines.append(Text(f" {heading}", style="bold"))  # `run 3`, `I1`, `beam`
        for header, value in zip(headers[1:], row[1:]):
            if not value:
                continue
            shown = f"   {header + ':':<{label + 1}} {value}" if header else f"   {value}"
            if len(shown) <= width:
                lines.append(Text(shown, no_wrap=True))
            else:  # a long text on lines of its own, wrapped between words (a number is one word)
                lines += [Text(f"   {header}:"), Padding(Text(value), (0, 0, 0, 5))]
    return Group(*lines)
