"""How rbi's results present themselves: :class:`Result`, the base of every result the API
returns (a body, its principal axes, its parts, a momentum, a check, a trajectory, a sweep, an
audit). A result gives its rows once (:meth:`Result.rows`: tables of text cells, :class:`Rows`)
and its JSON object once (:meth:`Result.to_dict`); from those come ``print(result)`` and a rich
console's table (``__str__``, ``__rich__``), a notebook's (``_repr_html_``), ``to_pandas()``
and ``to_csv()``. The CLI prints ``to_dict()`` for ``--format json``, ``to_csv()`` for CSV and
draws the same rows as its tables.

Standard library only at import (rich is imported when a table is drawn), so every layer may
use it. Text from outside (names in a spec or a robot file) is shown as text, never read as
markup or HTML.
"""

from __future__ import annotations

import functools
import io
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from html import escape
from typing import Any, ClassVar, TypeVar, overload

from rbi.text import csv_lines

QUANTITY_COLUMNS = ("quantity", "unit", "value")
"""The columns of a summary: what, in which unit, how much."""


@dataclass(frozen=True)
class Rows:
    """One table of text cells, as every face of a result draws it.

    Attributes:
        title: the table's title.
        columns: the column names.
        cells: one tuple of text cells a row.
        total: a last row set off by a rule (a body's total under its parts), or None.
        left: how many leading columns are text, aligned left (the others hold numbers, right).
        kind: ``"quantities"`` (quantity, unit, value rows: stacked as ``quantity [unit]
            value`` where too wide), ``"matrix"`` (row labels then numbers) or ``"table"``.
        text_last: the last column is text too (an audit's flags), aligned left.
    """

    title: str
    columns: tuple[str, ...]
    cells: Sequence[tuple[str, ...]]
    total: tuple[str, ...] | None = None
    left: int = 1
    kind: str = "table"
    text_last: bool = False

    @classmethod
    def quantities(cls, title: str, cells: Iterable[tuple[str, str, str]]) -> Rows:
        """A table of (quantity, unit, value) rows."""
        return cls(title, QUANTITY_COLUMNS, list(cells), left=2, kind="quantities")

    def rich(self, text: Callable[[str], Any] | None = None, **style: Any) -> Any:
        """The table as a :class:`rich.table.Table` with the table options ``style`` (the CLI's
        box, edge and title's place): the first ``left`` columns aligned left, the others right;
        a quantity's unit dim, a matrix's row labels bold, a parts table's numbers never
        wrapped (its names fold), a check's verdict column left and its FAIL bold red. Title,
        headers and cells become rich text through ``text`` (default :class:`rich.text.Text`:
        a name holding [brackets] is text, never read as markup; the CLI's also escapes it)."""
        # not at top level: `rbi inertia --format json` would load rich.table and rich.text too
        from rich.table import Table
        from rich.text import Text

        text = text or Text

        def cell_text(cell: str) -> Any:
            shown = text(str(cell))
            if cell == "FAIL":  # a check's verdict
                shown.stylize("bold red")
            return shown

        table = Table(title=text(self.title), **style)
        parts = self.kind == "parts"  # its numbers never wrap, its names fold
        for i, name in enumerate(self.columns):
            left = self._left(i) or (self.kind == "check" and not name)
            table.add_column(
                Text("\n").join(map(text, name.split("\n"))),  # a label over its unit
                justify="left" if left else "right",
                style={("quantities", 1): "dim", ("matrix", 0): "bold"}.get((self.kind, i)),
                no_wrap=parts and not left,
                overflow="fold" if parts else "ellipsis",
            )
        check = self.kind == "check"  # only a check's verdict is styled; other cells skip the test (10⁵ rows)
        for row in self.cells:
            table.add_row(*(map(cell_text, row) if check else map(text, map(str, row))))
        if self.total is not None:
            table.add_section()
            table.add_row(*map(cell_text, self.total))
        return table

    def _left(self, i: int) -> bool:
        """Whether column ``i`` holds text, aligned left (the others hold numbers)."""
        return i < self.left or (self.text_last and i == len(self.columns) - 1)

    def html(self) -> str:
        """The same table as HTML (every cell escaped; ``total`` in the table's foot)."""
        align = ["" if self._left(i) else ' style="text-align:right"' for i in range(len(self.columns))]
        names = (escape(name).replace("\n", "<br>") for name in self.columns)  # a label over its unit
        head = "".join(f"<th>{name}</th>" for name in names)
        body = "".join(f"<tr>{_html_cells(align, row)}</tr>" for row in self.cells)
        foot = "" if self.total is None else f"<tfoot><tr>{_html_cells(align, self.total)}</tr></tfoot>"
        return (
            f"<table><caption>{escape(self.title)}</caption><thead><tr>{head}</tr></thead>"
            f"<tbody>{body}</tbody>{foot}</table>"
        )


def _html_cells(align: list[str], cells: Sequence[str]) -> str:
    return "".join(f"<td{a}>{escape(str(cell))}</td>" for a, cell in zip(align, cells))


def plain(value: Any) -> Any:
    """``value`` as JSON-ready data: numpy arrays and scalars as lists, floats and ints (their
    ``tolist()``), tuples as lists, ``-0.0`` as ``0.0``; JSON then carries each float's shortest
    round-tripping repr."""
    kind = type(value)  # the common exact types first (an audit's JSON has millions of values)
    if kind is float:
        return 0.0 if value == 0.0 else value
    if kind is str or kind is int or kind is bool or value is None:
        return value
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if hasattr(value, "tolist"):  # a numpy array or scalar: numpy is not imported here
        return plain(value.tolist())
    if isinstance(value, float):
        return 0.0 if value == 0.0 else float(value)
    return value


_XYZ = ("x", "y", "z")


def flatten(result: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested results as CSV columns: vectors get ``_x/_y/_z``, 3×3 matrices ``_xx … _zz``
    (``axes``: ``_1_x … _3_z``), nested mappings ``outer_inner``, other lists (and the moments
    and ``axes_deg``, per principal axis) ``_1, _2, …``."""
    out: dict[str, Any] = {}
    for key, value in plain(result).items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, prefix=f"{name}_"))
        elif not isinstance(value, list):
            out[name] = value
        elif len(value) == 3 and all(isinstance(r, list) and len(r) == 3 for r in value):
            for i, row in enumerate(value):
                for j, v in enumerate(row):
                    out[f"{name}_{i + 1}_{_XYZ[j]}" if key == "axes" else f"{name}_{_XYZ[i]}{_XYZ[j]}"] = v
        else:  # a vector's entries _x, _y, _z; other lists' (and the moments, axes_deg) _1, _2, ...
            vector = len(value) == 3 and not any(isinstance(v, list) for v in value)
            numbered = not vector or key.endswith(("moments", "axes_deg"))  # as the axes they qualify
            labels = range(1, len(value) + 1) if numbered else _XYZ
            out.update((f"{name}_{label}", v) for label, v in zip(labels, value))
    return out


def flat_rows(rows: Iterable[dict[str, Any]]) -> list[dict[str, Any]]:
    """Rows as CSV columns (:func:`flatten`); a row's ``warnings`` are not a column (the CLI
    says them on stderr)."""
    return [flatten({k: v for k, v in row.items() if k != "warnings"}) for row in rows]


def csv_text(rows: Iterable[dict[str, Any]]) -> str:
    """CSV text: a header from the first row's (flattened) keys, then one line a row, each cell
    through the one CSV cell rule (:func:`rbi.text.csv_cell`)."""
    flat = flat_rows(rows)
    if not flat:
        return ""
    return csv_lines((row.values() for row in flat), header=flat[0].keys())


def pandas_module(result: object) -> Any:
    """The pandas module, for ``result``'s ``to_pandas()``; ImportError saying how to install it."""
    try:
        # not at top level: importing pandas takes ~0.3 s, and only to_pandas needs it
        import pandas
    except ImportError:
        raise ImportError(
            f"{type(result).__name__}.to_pandas needs pandas, which is not installed: pip install pandas"
        ) from None
    return pandas


def json_ready(to_dict: Any) -> Any:
    """Marks a ``to_dict`` that builds JSON-ready data itself (an audit's millions of numbers):
    :class:`Result` then does not walk it again with :func:`plain`."""
    to_dict.json_ready = True
    return to_dict


class Result:
    """The base of rbi's results: a subclass gives :meth:`rows`, :meth:`to_dict` and, when
    its CSV has other rows than the one object, :meth:`csv_rows`; the faces follow.

    A subclass's ``to_dict`` may build its dict from numpy arrays and scalars: the class wraps
    it in :func:`plain`, so every result's ``to_dict()`` is JSON-ready, as the command prints it.
    """

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        own = cls.__dict__.get("to_dict")
        if own is not None and not getattr(own, "json_ready", False):

            @functools.wraps(own)
            def to_dict(self: Any, *args: Any, **kw: Any) -> dict[str, Any]:
                return plain(own(self, *args, **kw))

            cls.to_dict = json_ready(to_dict)  # type: ignore[method-assign]

    json_keys: ClassVar[tuple[str, ...]] = ()
    """The fields a subclass's ``to_dict()`` lists as they are, by name and in the order the
    contract gives them (see :meth:`json_fields`); declared once, so a new field is not in the
    JSON until it is named here."""

    def json_fields(self) -> dict[str, Any]:
        """The fields :attr:`json_keys` names, with their values, in that order."""
        return {key: getattr(self, key) for key in self.json_keys}

    def rows(self) -> list[Rows]:
        """The tables the result shows, as text cells: the one set of rows behind ``print()``,
        ``__rich__``, ``_repr_html_`` and the CLI's tables."""
        raise NotImplementedError

    def to_dict(self) -> dict[str, Any]:
        """The result as JSON-ready data (lists, floats, str, None): what the matching ``rbi``
        command prints with ``--format json``, less its ``"file"``."""
        raise NotImplementedError

    def csv_rows(self) -> list[dict[str, Any]]:
        """The rows of ``to_csv()`` and ``to_pandas()``, before flattening: the one object."""
        return [self.to_dict()]

    def csv_summary(self) -> dict[str, Any]:
        """The result's one CSV row among several files' (``rbi parts A B --format csv``)."""
        return self.csv_rows()[0]

    def to_csv(self) -> str:
        """The CSV the matching command prints with ``--format csv``: a header, then the rows."""
        return csv_text(self.csv_rows())

    def flat_rows(self) -> list[dict[str, Any]]:
        """The CSV's rows as its columns: vectors as ``_x/_y/_z``, matrices ``_xx … _zz``."""
        return flat_rows(self.csv_rows())

    def to_pandas(self) -> Any:
        """The CSV's rows as a :class:`pandas.DataFrame` (vectors as ``_x/_y/_z`` columns)."""
        rows = self.flat_rows()
        return pandas_module(self).DataFrame(rows, columns=list(rows[0]) if rows else None)

    def __rich__(self) -> Any:
        # not at top level: `rbi inertia --format json` would load rich.console too
        from rich.console import Group

        tables = [rows.rich() for rows in self.rows()]
        return tables[0] if len(tables) == 1 else Group(*tables)

    def _repr_html_(self) -> str:
        return "".join(rows.html() for rows in self.rows())

    def __str__(self) -> str:
        """The tables as text, 80 columns wide (``print(result)``)."""
        # not at top level: `rbi inertia --format json` would load rich.console too
        from rich.console import Console

        text = io.StringIO()
        Console(file=text, width=80, color_system=None, highlight=False).print(self.__rich__())
        return text.getvalue().rstrip("\n")


Item = TypeVar("Item")


class Results(Result, Sequence[Item]):
    """A result that is a sequence too (a body's parts, a spec's checks): ``len``, ``[i]`` and
    slices (a list), iteration, and ``==`` with another of its kind or a list of its items."""

    _items: list[Item]

    @overload
    def __getitem__(self, index: int) -> Item: ...
    @overload
    def __getitem__(self, index: slice) -> list[Item]: ...
    def __getitem__(self, index: int | slice) -> Item | list[Item]:
        return self._items[index]

    def __len__(self) -> int:
        return len(self._items)

    def __iter__(self) -> Iterator[Item]:
        return iter(self._items)

    def __eq__(self, other: object) -> bool:
        return list(self) == list(other) if isinstance(other, (type(self), list)) else NotImplemented

    __hash__ = None  # type: ignore[assignment]
