"""How rbi's result objects show themselves in a notebook (``_repr_html_``) and a rich console
(``__rich__``): one table of text cells, a title and column names, drawn the same way for every
object (a body, its principal axes, a part, a trajectory, a sweep, an audit).

Standard library only at import (rich is imported when a table is drawn), so every layer may
use it. Text from outside (names in a spec or a robot file) is shown as text, never read as
markup or HTML.
"""

from __future__ import annotations

from collections.abc import Sequence
from html import escape
from typing import Any

QUANTITY_COLUMNS = ("quantity", "unit", "value")
"""The columns of a summary: what, in which unit, how much."""


def rich_table(title: str, rows: Sequence[Sequence[str]], columns: Sequence[str] = QUANTITY_COLUMNS) -> Any:
    """A :class:`rich.table.Table` of text cells; the last column of a summary (its values) and
    every column after the first of other tables are right-aligned."""
    # not at top level: `rbi inertia --format json` would load rich.table and rich.text too
    from rich.table import Table
    from rich.text import Text

    table = Table(title=Text(title))  # Text: a name holding [brackets] is shown, not read as markup
    for i, name in enumerate(columns):
        table.add_column(name, justify="right" if _right(columns, i) else "left")
    for row in rows:
        table.add_row(*(Text(str(cell)) for cell in row))
    return table


def html_table(title: str, rows: Sequence[Sequence[str]], columns: Sequence[str] = QUANTITY_COLUMNS) -> str:
    """The same table as HTML (every cell escaped)."""
    align = [' style="text-align:right"' if _right(columns, i) else "" for i in range(len(columns))]
    head = "".join(f"<th>{escape(name)}</th>" for name in columns)
    body = "".join(
        "<tr>" + "".join(f"<td{a}>{escape(str(cell))}</td>" for a, cell in zip(align, row)) + "</tr>"
        for row in rows
    )
    return f"<table><caption>{escape(title)}</caption><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _right(columns: Sequence[str], i: int) -> bool:
    if tuple(columns) == QUANTITY_COLUMNS:
        return i == 2
    return i > 0


class TableRepr:
    """A mix-in: ``__rich__`` and ``_repr_html_`` from :meth:`_table` (title, rows, columns)."""

    def _table(self) -> tuple[str, Sequence[Sequence[str]], Sequence[str]]:
        raise NotImplementedError

    def __rich__(self) -> Any:
        return rich_table(*self._table())

    def _repr_html_(self) -> str:
        return html_table(*self._table())
