"""Sweep rows on disk: streamed as runs finish, in run order, resumable.

The rows file always holds runs ``0 .. k-1`` complete (a row is written whole and flushed with
its chunk), so an interrupted sweep keeps every finished run and ``--resume`` starts at run
``k``. A small settings file beside it (``.NAME.rbi-sweep.json``) records what the rows are of
(spec content, options, columns); a resume with other settings is refused, and the settings
file is removed once the sweep is complete.

CSV: floats written with Python's shortest round-trip repr (no digits lost); empty cells for
undefined values. A text cell that a spreadsheet would run as a formula (starting with ``=``,
``+``, ``-``, ``@``, tab or carriage return) is prefixed with ``'``. Parquet (``pyarrow``,
optional): one row group per chunk; the footer is written when the sweep ends or is
interrupted, and a resume rewrites the file with the kept rows first.
"""

from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path
from typing import Any

from rbi.spec.errors import InputError

FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def settings_path(out: Path) -> Path:
    return out.with_name(f".{out.name}.rbi-sweep.json")


def csv_cell(value: Any) -> Any:
    """A CSV cell: empty for None/NaN; text that a spreadsheet would evaluate made inert."""
    if value is None or (isinstance(value, float) and value != value):
        return ""
    if isinstance(value, str) and value.startswith(FORMULA_STARTS):
        return "'" + value
    return value


class RowWriter:
    """Appends rows to ``path`` (CSV or Parquet), creating it with a header when new."""

    def __init__(self, path: Path, columns: list[str], format: str, kept_rows: list[list[Any]] | None = None):
        self.path = Path(path)
        self.columns = columns
        self.format = format
        self._parquet = None
        if format == "csv":
            new = not self.path.exists() or self.path.stat().st_size == 0
            self._file = open(self.path, "a", newline="", encoding="utf-8")
            self._csv = csv.writer(self._file, lineterminator="\n")
            if new:
                self._csv.writerow(columns)
                self._file.flush()
        else:
            import pyarrow.parquet as pq

            self._schema = _arrow_schema(columns)
            self._temporary = self.path.with_name(f".{self.path.name}.rbi-partial")
            self._parquet = pq.ParquetWriter(self._temporary, self._schema)
            if kept_rows:
                self._write_parquet(kept_rows)

    def write(self, rows: list[list[Any]]) -> None:
        if not rows:
            return
        if self.format == "csv":
            self._csv.writerows([csv_cell(v) for v in row] for row in rows)
            self._file.flush()
            os.fsync(self._file.fileno())
        else:
            self._write_parquet(rows)

    def _write_parquet(self, rows):
        import pyarrow as pa

        table = pa.Table.from_pylist([dict(zip(self.columns, row)) for row in rows], schema=self._schema)
        self._parquet.write_table(table)

    def close(self) -> None:
        if self.format == "csv":
            self._file.close()
        elif self._parquet is not None:
            self._parquet.close()
            os.replace(self._temporary, self.path)
            self._parquet = None


def _arrow_schema(columns: list[str]):
    import pyarrow as pa

    types = {"run": pa.int64(), "steps": pa.int64(), "status": pa.string()}
    return pa.schema([(name, types.get(name, pa.float64())) for name in columns])


def kept_rows(path: Path, columns: list[str], format: str) -> list[list[Any]]:
    """The complete rows already in ``path`` (runs 0 .. k-1), for a resume. A trailing partial
    CSV line (a run killed mid-write) is cut off. InputError when the file is not rows of this
    sweep."""
    if format == "parquet":
        import pyarrow.parquet as pq

        try:
            table = pq.read_table(path)
        except Exception as exc:  # pyarrow raises several types for a damaged file
            raise InputError(f"{path}: cannot resume: not a readable Parquet file ({type(exc).__name__})") from None
        if table.column_names != columns:
            raise InputError(f"{path}: cannot resume: its columns are not those of this sweep")
        rows = [[row[c] for c in columns] for row in table.to_pylist()]
    else:
        data = path.read_bytes()
        end = data.rfind(b"\n") + 1
        if end < len(data):
            with open(path, "r+b") as handle:  # a partial last line: drop it
                handle.truncate(end)
            data = data[:end]
        reader = csv.reader(io.StringIO(data.decode("utf-8", errors="replace")))
        header = next(reader, None)
        if header is None:
            return []
        if header != columns:
            raise InputError(f"{path}: cannot resume: its columns are not those of this sweep "
                             f"(expected {','.join(columns)})")
        rows = [row for row in reader if row]
    for k, row in enumerate(rows):
        if str(row[0]) != str(k) or len(row) != len(columns):
            raise InputError(f"{path}: cannot resume: row {k + 2} is not run {k} of this sweep")
    return rows


def check_settings(out: Path, settings: dict[str, Any], resume: bool) -> None:
    """On resume, InputError unless the settings file beside ``out`` matches ``settings``."""
    side = settings_path(out)
    if not resume:
        return
    if not side.exists():
        raise InputError(f"{out}: cannot resume: no unfinished sweep there (the settings file {side.name} is "
                         "missing: the sweep finished, or the file was not written by rbi sweep)")
    try:
        recorded = json.loads(side.read_text())
    except (OSError, ValueError):
        raise InputError(f"{out}: cannot resume: {side.name} is unreadable") from None
    if recorded != json.loads(json.dumps(settings)):
        changed = sorted(k for k in set(recorded) | set(settings) if recorded.get(k) != settings.get(k))
        raise InputError(f"{out}: cannot resume: the sweep there was made with other settings "
                         f"({', '.join(changed)} differ)")


def write_settings(out: Path, settings: dict[str, Any]) -> None:
    side = settings_path(out)
    temporary = side.with_name(side.name + ".tmp")
    temporary.write_text(json.dumps(settings, sort_keys=True))
    os.replace(temporary, side)


def remove_settings(out: Path) -> None:
    try:
        settings_path(out).unlink()
    except FileNotFoundError:
        pass
