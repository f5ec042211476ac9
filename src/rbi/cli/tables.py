"""Rich building blocks shared by the commands' tables (imported only for table output)."""

from __future__ import annotations

from collections.abc import Sequence

from rich import box
from rich.console import Group
from rich.table import Table
from rich.text import Text

from rbi.cli.terminal import ERROR_HANDLER, ascii_only, terminal_safe


class SafeTable(Table):
    """A rich Table whose title, headers and cells are text, never rich markup (a name such as
    ``top [v2]`` or a quantity ``final q [w, x, y, z]`` is shown as written), without a control
    character (escaped as in :func:`rbi.cli.terminal.terminal_safe`, once, here, before the
    layout so columns stay aligned), and which spells rbi's symbols in ASCII (``kg*m^2``,
    ``deg``) when standard output cannot encode them. Every table rbi prints is built on it
    (:func:`titled`)."""

    def __init__(self, *args, title=None, **kwargs):
        super().__init__(*args, title=_cell(title), **kwargs)

    def add_column(self, header="", *args, **kwargs):
        super().add_column(_cell(header), *args, **kwargs)

    def add_row(self, *renderables, **kwargs):
        super().add_row(*(_cell(r) for r in renderables), **kwargs)


def _cell(value):
    """A table string as safe text (other renderables pass unchanged)."""
    if not isinstance(value, str):
        return value
    value = terminal_safe(value)
    if ascii_only():
        value = value.encode("ascii", errors=ERROR_HANDLER).decode("ascii")
    return Text(value)


def titled(title: str) -> Table:
    """An empty table in rbi's style; the title is text (see :class:`SafeTable`)."""
    return SafeTable(title=title, box=box.SIMPLE_HEAD, title_justify="left", show_edge=False)


def quantities(title: str, rows: Sequence[tuple[str, str, str]]) -> Table:
    """A table of (quantity, unit, value) rows; ``title`` and every cell are text."""
    table = titled(title)
    table.add_column("quantity")
    table.add_column("unit", style="dim")
    table.add_column("value", justify="right")
    for name, unit, value in rows:
        table.add_row(name, unit, value)
    table.rbi_layout = "quantities"  # stacked as `quantity [unit]  value` when too wide (see stacked)
    return table


def drawn(rows) -> Group:
    """A result's tables (its ``rows()``: :class:`rbi.reprs.Rows`) in rbi's style, stacked.
    Every title, header and cell is text (never read as markup), made safe once here."""
    return Group(*(_drawn(each) for each in rows))


def _drawn(rows) -> Table:
    cells = [tuple(_text(cell) for cell in row) for row in rows.cells]
    if rows.kind == "quantities":
        table = quantities(rows.title, [])
        for row in cells:
            table.add_row(*row)
        return table
    table = titled(rows.title)
    for i, header in enumerate(rows.columns):
        justify = "left" if i < rows.left or (rows.kind == "check" and not header) else "right"
        if rows.kind == "parts":  # the label over its unit; numbers never wrap, names fold
            header = Text(header, justify=justify) if i else "part"
            table.add_column(header, justify=justify, no_wrap=i >= rows.left, overflow="fold")
            continue
        style = "bold" if rows.kind == "matrix" and i == 0 else None
        table.add_column(header, justify=justify, style=style)
    for row in cells:
        table.add_row(*row)
    if rows.total is not None:
        table.add_section()
        table.add_row(*(_text(cell) for cell in rows.total))
    return table


def _text(cell: str) -> Text:
    """A cell as text; a check's ``FAIL`` in bold red."""
    text = _cell(cell)
    if cell == "FAIL":
        text.stylize("bold red")
    return text
