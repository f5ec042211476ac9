"""Rich building blocks shared by the commands' tables (imported only for table output)."""

from __future__ import annotations

from collections.abc import Sequence

from rich import box
from rich.console import Group
from rich.markup import escape
from rich.table import Table

from rbi.cli.render import matrix_digits, number, terminal_safe, vector_text, without_noise
from rbi.cli.terminal import ERROR_HANDLER, ascii_only


def plain_text(text: str) -> str:
    """Text from a spec (a name) shown as it is: not read as rich markup (``top [v2]``), and
    with control characters escaped so a name cannot drive the terminal."""
    return escape(terminal_safe(text))


class SafeTable(Table):
    """A rich Table whose title, headers and cells never carry a control character (escaped as
    in :func:`rbi.cli.render.terminal_safe`, before the layout so columns stay aligned), and
    which spells rbi's symbols in ASCII (``kg*m^2``, ``deg``) when standard output cannot
    encode them. Every table rbi prints is built on it (:func:`titled`)."""

    def __init__(self, *args, title=None, **kwargs):
        super().__init__(*args, title=_cell(title), **kwargs)

    def add_column(self, header="", *args, **kwargs):
        super().add_column(_cell(header), *args, **kwargs)

    def add_row(self, *renderables, **kwargs):
        super().add_row(*(_cell(r) for r in renderables), **kwargs)


def _cell(value):
    """A table string made safe (other renderables pass unchanged)."""
    if not isinstance(value, str):
        return value
    value = terminal_safe(value)
    if ascii_only():
        value = value.encode("ascii", errors=ERROR_HANDLER).decode("ascii")
    return value


def titled(title: str) -> Table:
    """An empty table in rbi's style; the title is plain text (see :func:`plain_text`)."""
    return SafeTable(title=plain_text(title), box=box.SIMPLE_HEAD, title_justify="left", show_edge=False)


def quantities(title: str, rows: Sequence[tuple[str, str, str]]) -> Table:
    """A table of (quantity, unit, value) rows. ``title`` is plain text (it carries the body's
    name or path, which must not be read as rich markup)."""
    table = titled(title)
    table.add_column("quantity")
    rows = [(name, escape(unit), escape(value)) for name, unit, value in rows]
    table.add_column("unit", style="dim")
    table.add_column("value", justify="right")
    for name, unit, value in rows:
        table.add_row(name, unit, value)
    table.rbi_layout = "quantities"  # stacked as `quantity [unit]  value` when too wide (see stacked)
    return table


def matrix(
    title: str,
    values,
    unit: str,
    row_labels: Sequence[str] = ("x", "y", "z"),
    column_labels: Sequence[str] = ("x", "y", "z"),
) -> Table:
    """A 3×3 matrix with a common power-of-ten scale written once in the title."""
    values = without_noise(values)
    scale, scale_text = matrix_digits(values)
    table = titled(title)
    table.add_column(unit_header("", unit, scale_text).strip(), style="bold")
    for label in column_labels:
        table.add_column(label, justify="right")
    for label, row in zip(row_labels, values):
        table.add_row(label, *(number(v / scale, 7) for v in row))
    return table


def unit_header(label: str, unit: str, scale_text: str = "") -> str:
    """A column header such as ``moment [kg·m²] ×10⁻⁴`` (brackets escaped from rich markup)."""
    return escape(f"{label} [{unit}]") + (f" {scale_text}" if scale_text else "")


def stack(*renderables) -> Group:
    return Group(*renderables)


def vector(v, scale: float = 0.0) -> str:
    """A vector for a table cell; entries below 1e-12 of ``scale`` (a position: the body's
    size, :func:`rbi.cli.render.body_size`) or of its largest entry print as 0."""
    return vector_text(v, scale=scale)


# --- fitting the terminal ---------------------------------------------------------------------


def fitted(renderable, console):
    """``renderable`` laid out for ``console``'s width, so that no number is cut, split across
    lines or shortened to ``…``: each table's title goes on a line of its own (a long title
    wraps as text, not squeezed to the table's width), and a table wider than the terminal is
    printed stacked instead (:func:`stacked`). Groups are fitted part by part; anything else
    passes unchanged."""
    from rich.console import Group

    if isinstance(renderable, Group):
        return Group(*(fitted(part, console) for part in renderable.renderables))
    if not isinstance(renderable, Table):
        return renderable
    title, renderable.title = renderable.title, None
    if not _cells_intact(renderable, console):
        renderable.title = title
        return stacked(renderable, console.width)
    return Group(_line(title), renderable) if title else renderable


def _cells_intact(table: Table, console) -> bool:
    """Whether ``table`` at ``console``'s width shows every cell whole on one line (headers may
    wrap; a cell folded, wrapped or shortened to ``…`` is not whole)."""
    from rich.text import Text

    lines = [
        "".join(segment.text for segment in line)
        for line in console.render_lines(table, console.options, pad=False)
    ]
    for column in table.columns:
        for cell in column._cells:
            text = (
                cell.plain
                if isinstance(cell, Text)
                else Text.from_markup(cell).plain
                if isinstance(cell, str)
                else None
            )
            if text and not any(text in line for line in lines):
                return False
    return True


def _line(text):
    from rich.text import Text

    return text if isinstance(text, Text) else Text.from_markup(text) if isinstance(text, str) else text


def _plain(cell) -> str:
    """A cell or header as the text it shows (markup read, lines joined by a space)."""
    from rich.text import Text

    if isinstance(cell, Text):
        text = cell.plain
    elif isinstance(cell, str):
        text = Text.from_markup(cell).plain
    else:
        text = str(cell)
    return " ".join(text.split())


def stacked(table: Table, width: int):
    """The rows of ``table`` one below the other, for a terminal too narrow for its columns.

    A quantity/unit/value table (:func:`quantities`) gives one line a row, ``quantity [unit]``
    on the left and the value on the right, or the value on the next line when both do not fit
    on one. Any other table gives, per row, its first cell as a heading and then one line
    ``header: value`` for each other column. Values are never wrapped."""
    from rich.console import Group
    from rich.padding import Padding
    from rich.text import Text

    headers = [_plain(column.header) for column in table.columns]
    rows = list(zip(*[[_plain(cell) for cell in column._cells] for column in table.columns]))
    lines = [_line(table.title)] if table.title else []
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
