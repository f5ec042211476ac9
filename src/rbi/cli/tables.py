"""Rich building blocks shared by the commands' tables (imported only for table output)."""

from __future__ import annotations

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
    (:func:`drawn`)."""

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


def drawn(rows) -> Group:
    """A result's tables (its ``rows()``: :class:`rbi.reprs.Rows`) in rbi's style, stacked.
    Every title, header and cell is text (never read as markup), made safe once here."""
    return Group(*(_drawn(each) for each in rows))


def _drawn(rows) -> Table:
    table = rows.rich(_cell, box=box.SIMPLE_HEAD, title_justify="left", show_edge=False)
    table.rbi_layout = rows.kind  # quantities are stacked as `quantity [unit]  value` when too wide
    return table
