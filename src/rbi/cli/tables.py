"""Rich building blocks shared by the commands' tables (imported only for table output)."""

from __future__ import annotations

from collections.abc import Sequence

from rich import box
from rich.console import Group
from rich.markup import escape
from rich.table import Table

from rbi.cli.render import matrix_digits, number, terminal_safe, without_noise
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
    """A table of (quantity, unit, value) rows. ``title`` and every cell are plain text (the
    title carries the body's name or path, a quantity may hold brackets: ``final q [w, x, y, z]``
    was shown as ``final q``, rich reading ``[w, x, y, z]`` as a style), never rich markup."""
    table = titled(title)
    table.add_column("quantity")
    rows = [(escape(name), escape(unit), escape(value)) for name, unit, value in rows]
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
