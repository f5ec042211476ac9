"""Sweep rows on disk: streamed as runs finish, in run order, resumable, one writer at a time.
The files beside an output ``F`` (``.F.rbi-lock``, ``.F.rbi-sweep.json``, ``.F.rbi-rows/``)
and what each guarantees are in docs/security.md ("Files rbi keeps beside an output"); names
are made by :func:`rbi.files.safe.beside`.

A CSV output holds runs ``0 .. k-1`` complete: a failed write is cut back to the last whole
chunk, and a kill mid-write leaves at most a partial last line, which ``--resume`` drops after
checking every whole row. ``--resume`` checks everything (the settings; each kept row's run
number, swept values, types and finiteness; no row past the grid) before it changes anything.
CSV cells follow :func:`rbi.text.csv_cell`; :func:`rbi.text.csv_text_read` reads a text cell back.
"""

from __future__ import annotations

import csv
import json
import math
import os
import tempfile
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from rbi.errors import InputError
from rbi.files import safe
from rbi.files.lock import OutputLock
from rbi.files.output import atomic_path
from rbi.text import csv_lines, csv_text_read

SETTINGS_SUFFIX = ".rbi-sweep.json"
ROWS_SUFFIX = ".rbi-rows"
SETTINGS_LIMIT = 1 << 20
"""Largest settings sidecar rbi reads, in bytes (it writes a few hundred)."""
PIECE_LIMIT = 256 << 20
"""Largest Parquet chunk file rbi reads back on --resume, in bytes."""
LINE_LIMIT = 1 << 20
"""Longest line of a CSV rows file rbi reads back on --resume, in bytes (a row is a few hundred)."""
INT_COLUMNS = ("run", "steps")
TEXT_COLUMNS = ("status",)
OPTIONAL_WHEN_OK = ("precession_rate_deg_s",)
"""Result columns that may be empty in an ok row (the precession rate of an axis that stood
vertical)."""
_CHECK_BATCH = 4096


def settings_path(out: str | os.PathLike) -> Path:
    return safe.beside(out, SETTINGS_SUFFIX)


def rows_folder(out: str | os.PathLike) -> Path:
    return safe.beside(out, ROWS_SUFFIX)


def csv_bytes(rows: Iterable[list[Any]]) -> bytes:
    """Rows as the CSV rows file holds them (UTF-8, one line a row, :func:`rbi.text.csv_cell`)."""
    return csv_lines(rows).encode("utf-8")


class SweepOutput:
    """The ``--out`` file of one sweep and the files beside it.

    target: the checked output (:func:`rbi.files.output.output_target`); columns: the row
    columns; plan: the sweep's :class:`~rbi.sweeps.plan.Plan` (to check kept rows); settings:
    what makes two sweeps the same (compared on resume). :meth:`open` takes the lock and
    starts or resumes; :meth:`write` adds rows; :meth:`finish` completes the output and
    removes the files beside it; :meth:`close` stops writing and keeps what is there.
    """

    def __init__(self, target, columns: list[str], plan, settings: dict[str, Any]) -> None:
        self.target = target
        self.path = Path(target.path)
        self.format = target.format
        self.columns = list(columns)
        self.plan = plan
        self.settings = json.loads(json.dumps({**settings, "format": self.format, "columns": self.columns}))
        self.done = 0
        self._lock = None
        self._fd = -1
        self._size = 0
        self._label = f"{target.option}: {safe.shown(target.given)}"

    # --- starting -------------------------------------------------------------------------

    def open(self, resume: bool, keep: bool) -> list[list[Any]]:
        """Lock the output and start it empty, or (``resume``) check what is there and continue
        after it. Returns the kept rows (typed) when ``keep``, else []."""

        self._lock = OutputLock(self.path, self._label)
        try:
            side = settings_path(self.path)
            safe.existing_regular(side, f"{self._label}: settings file {safe.shown(side.name)}")
            safe.existing_private_folder(rows_folder(self.path), self._folder_label())
            if resume:
                return self._resume(keep)
            self._start()
            return []
        except BaseException:
            self.close()
            raise

    def _start(self) -> None:
        side = settings_path(self.path)
        safe.remove(side)
        safe.remove_private_folder(rows_folder(self.path))
        safe.replace_small(
            side,
            json.dumps(self.settings, sort_keys=True).encode(),
            f"{self._label}: settings file {safe.shown(side.name)}",
        )
        if self.format == "csv":
            mode = None
            if safe.existing_regular(self.path, self._label, own=False):  # an output the user names: replaced
                mode = os.stat(self.path).st_mode & 0o7777
                safe.remove(self.path)
            self._fd = safe.create_exclusive(self.path, self._label)
            if mode is not None:
                os.fchmod(self._fd, mode)
            self._append(csv_bytes([self.columns]))
        else:
            safe.make_private_folder(rows_folder(self.path), self._folder_label())

    def _resume(self, keep: bool) -> list[list[Any]]:
        side = settings_path(self.path)
        side_label = f"{self._label}: cannot resume: settings file {safe.shown(side.name)}"
        if not safe.existing_regular(side, side_label):
            raise InputError(
                f"{self._label}: cannot resume: no unfinished sweep there (the settings file "
                f"{safe.shown(side.name)} is missing: the sweep finished, or the file was not written "
                "by rbi sweep)"
            )
        try:
            recorded = json.loads(safe.read_capped(side, SETTINGS_LIMIT, side_label).decode("utf-8"))
        except (UnicodeDecodeError, ValueError, RecursionError):
            raise InputError(f"{side_label}: is not a settings file rbi wrote") from None
        if recorded != self.settings:
            changed = sorted(
                k
                for k in set(recorded if isinstance(recorded, dict) else {}) | set(self.settings)
                if not isinstance(recorded, dict) or recorded.get(k) != self.settings.get(k)
            )
            raise InputError(
                f"{self._label}: cannot resume: the sweep there was made with other settings "
                f"({', '.join(changed[:6]) or 'all'} differ)"
            )
        if self.format == "csv":
            return self._resume_csv(keep)
        return self._resume_parquet(keep)

    def _resume_csv(self, keep: bool) -> list[list[Any]]:
        what = f"{self._label}: cannot resume"
        fd = safe.open_regular(self.path, what, os.O_RDWR)
        try:
            checker = RowCheck(self.columns, self.plan, what)
            kept: list[list[Any]] = []
            good_end = 0
            with os.fdopen(os.dup(fd), "rb") as handle:
                header = _line(handle, what, 1)
                if header == b"":  # killed between creating the file and writing its header
                    self._fd, fd = fd, -1
                    self._append(csv_bytes([self.columns]))
                    return []
                if not header.endswith(b"\n") or _csv_line(header, what, 1) != self.columns:
                    raise InputError(
                        f"{what}: its columns are not those of this sweep "
                        f"(expected {','.join(self.columns)[:200]})"
                    )
                good_end = len(header)
                fragment = b""
                batch: list[list[str]] = []
                line_number = 1
                while line := _line(handle, what, line_number + 1):
                    if not line.endswith(b"\n"):
                        fragment = line
                        break
                    line_number += 1
                    batch.append(_csv_line(line, what, line_number))
                    good_end += len(line)
                    if len(batch) >= _CHECK_BATCH:
                        kept.extend(checker.check(batch, text=True, keep=keep))
                        batch = []
                kept.extend(checker.check(batch, text=True, keep=keep))
            if fragment:  # a partial last line (a kill during a write): every whole row checked
                checker.check_fragment(fragment)
                os.ftruncate(fd, good_end)
            self.done = checker.count
            self._fd, fd = fd, -1
            self._size = good_end
            os.lseek(self._fd, good_end, os.SEEK_SET)
            return kept
        except OSError as exc:
            raise InputError(f"{what}: cannot read: {safe.reason(exc)}") from None
        finally:
            if fd >= 0:
                os.close(fd)

    def _resume_parquet(self, keep: bool) -> list[list[Any]]:
        folder = rows_folder(self.path)
        what = f"{self._label}: cannot resume"
        if not safe.existing_private_folder(folder, self._folder_label()):
            raise InputError(f"{what}: the folder of finished runs {safe.shown(folder.name)} is missing")
        checker = RowCheck(self.columns, self.plan, what)
        kept: list[list[Any]] = []
        schema = _arrow_schema(self.columns)
        for name in sorted(os.listdir(folder)):
            piece = folder / name
            if name.startswith(".rbi-"):
                safe.remove(piece)  # a chunk file whose write never finished
                continue
            if not (name.endswith(".parquet") and name[:-8].isdigit() and len(name) == 20):
                raise InputError(
                    f"{what}: {safe.shown(folder.name)} holds {safe.shown(name)[:80]}, a file rbi "
                    "did not write"
                )
            label = f"{what}: {safe.shown(folder.name)}/{name}"
            if int(name[:-8]) != checker.count:
                raise InputError(f"{label}: does not start at run {checker.count}")
            table = _read_piece(piece, label)
            if table.schema != schema:
                raise InputError(f"{label}: its columns are not those of this sweep")
            rows = [[row[c] for c in self.columns] for row in table.to_pylist()]
            kept.extend(checker.check(rows, text=False, keep=keep))
        self.done = checker.count
        return kept

    def _folder_label(self) -> str:
        return f"{self._label}: folder {safe.shown(rows_folder(self.path).name)}"

    # --- writing --------------------------------------------------------------------------

    def write(self, rows: list[list[Any]]) -> None:
        """Add finished rows (the next runs, in order). A failed write leaves the output as it
        was before it (InputError saying how many runs are kept)."""
        if not rows:
            return
        rows = [[None if isinstance(v, float) and v != v else v for v in row] for row in rows]  # NaN: empty
        try:
            if self.format == "csv":
                self._append(csv_bytes(rows))
            else:
                self._write_piece(rows)
        except OSError as exc:
            raise InputError(
                f"{self._label}: cannot write: {safe.reason(exc)}; {self.done:,} of {self.plan.size:,} "
                "runs are kept: make room and run the same command with --resume"
            ) from None
        self.done += len(rows)

    def _append(self, data: bytes) -> None:
        try:
            safe.write_all(self._fd, data)
            os.fsync(self._fd)
        except BaseException:
            try:  # never leave part of a chunk: cut back to the last whole one
                os.ftruncate(self._fd, self._size)
                os.lseek(self._fd, self._size, os.SEEK_SET)
            except OSError:
                pass
            raise
        self._size += len(data)

    def _write_piece(self, rows: list[list[Any]]) -> None:

        # pyarrow: optional (the 'parquet' extra), imported only when used
        import pyarrow as pa
        import pyarrow.parquet as pq

        folder = rows_folder(self.path)
        table = pa.Table.from_pylist(
            [dict(zip(self.columns, row)) for row in rows], schema=_arrow_schema(self.columns)
        )
        fd, temporary = tempfile.mkstemp(prefix=".rbi-", suffix=".parquet", dir=folder)
        try:
            with os.fdopen(fd, "wb") as handle:
                pq.write_table(table, handle)
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(temporary, folder / f"{int(rows[0][0]):012d}.parquet")
        except BaseException:
            safe.remove(temporary)
            raise

    # --- ending ---------------------------------------------------------------------------

    def finish(self) -> None:
        """The sweep is complete: the output gets its last form, the files beside it go."""
        try:
            if self.format == "parquet":
                try:
                    self._combine()
                except InputError as exc:
                    raise InputError(
                        f"{exc}; all {self.done:,} runs are kept: make room and run the same command "
                        "with --resume"
                    ) from None
            elif self._fd >= 0:
                os.fsync(self._fd)
            safe.remove(settings_path(self.path))
            safe.remove_private_folder(rows_folder(self.path))
        finally:
            self.close()

    def _combine(self) -> None:
        """Write the output from the chunk files, one row group each, atomically."""
        # pyarrow: optional (the 'parquet' extra), imported only when used
        import pyarrow.parquet as pq

        folder = rows_folder(self.path)
        names = sorted(n for n in os.listdir(folder) if n.endswith(".parquet") and not n.startswith("."))
        schema = _arrow_schema(self.columns)
        with atomic_path(self.target) as temporary:
            with pq.ParquetWriter(temporary, schema) as writer:
                for name in names:
                    writer.write_table(_read_piece(folder / name, f"{self._label}: {name}"))

    def close(self) -> None:
        """Stop writing (what is written stays, for --resume) and give up the lock."""
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1
        if self._lock is not None:
            self._lock.release()
            self._lock = None


class RowCheck:
    """Checks that rows read back are runs ``0, 1, 2, ...`` of this sweep: the columns, the
    run number, the swept values the plan gives that run (exactly), and result cells of the
    kinds the sweep writes (finite numbers or empty, whole steps, a status; an ok row has its
    figures, a failed one none). ``count``: rows checked so far."""

    def __init__(self, columns: list[str], plan, what: str) -> None:
        self.columns = columns
        self.plan = plan
        self.what = what
        self.count = 0
        self.swept = len(plan.names)
        self.tilts = [i for i, c in enumerate(columns) if c.endswith("_tilt_deg") and i > self.swept]

    def check(self, rows: list[list[Any]], text: bool, keep: bool) -> list[list[Any]]:
        if not rows:
            return []
        start = self.count
        if start + len(rows) > self.plan.size:
            raise InputError(f"{self.what}: it has more rows than the {self.plan.size:,} runs of this sweep")
        expected = self.plan.values(start, start + len(rows))
        typed_rows = []
        for offset, row in enumerate(rows):
            k = start + offset
            typed = self._typed(row, k, text)
            swept = typed[1 : 1 + self.swept]
            if any(v != float(e) for v, e in zip(swept, expected[offset])):
                raise InputError(
                    f"{self.what}: row of run {k} holds values that are not this sweep's run {k}"
                )
            self._check_results(typed, k)
            if keep:
                typed_rows.append(typed)
        self.count += len(rows)
        return typed_rows

    def check_fragment(self, fragment: bytes) -> None:
        """A partial last line is a cut-off row of the next run, or not this sweep's file."""
        first = fragment.split(b",", 1)[0]
        if (
            self.count >= self.plan.size
            or not str(self.count).encode().startswith(first)
            or fragment.count(b",") >= len(self.columns)
        ):
            raise InputError(f"{self.what}: its last line is not part of a row of this sweep")

    def _typed(self, row: list[Any], k: int, text: bool) -> list[Any]:
        if len(row) != len(self.columns):
            raise InputError(f"{self.what}: row of run {k} has {len(row)} cells, not {len(self.columns)}")
        typed = []
        for name, cell in zip(self.columns, row):
            value = _cell(name, cell, text)
            if value is _BAD:
                raise InputError(
                    f"{self.what}: row of run {k}: {name}: {safe.shown(str(cell))[:40]!r} is not a "
                    "value this sweep writes"
                )
            typed.append(value)
        if typed[0] != k:
            raise InputError(f"{self.what}: row {k + 2} is not run {k} of this sweep")
        return typed

    def _check_results(self, typed: list[Any], k: int) -> None:
        status = typed[-1]
        if status is None:
            raise InputError(f"{self.what}: row of run {k} has no status")
        first = 1 + self.swept
        for name, value in zip(self.columns[first:-1], typed[first:-1]):
            if status == "ok" and value is None and name not in OPTIONAL_WHEN_OK:
                raise InputError(f"{self.what}: row of run {k}: {name}: empty in a run marked ok")
            if status != "ok" and value is not None and name not in INT_COLUMNS:
                raise InputError(f"{self.what}: row of run {k}: {name}: a value in a failed run")
        for i in self.tilts:
            if typed[i] is not None and not 0.0 <= typed[i] <= 180.0:
                raise InputError(
                    f"{self.what}: row of run {k}: {self.columns[i]}: {typed[i]!r} is not an angle "
                    "between 0 and 180 degrees"
                )


_BAD = object()


def _cell(name: str, cell: Any, text: bool) -> Any:
    """A cell read back (``text``: a CSV cell, else a Parquet value), typed as the sweep wrote
    it, or _BAD."""
    if cell is None or (text and cell == ""):
        return None
    if name in TEXT_COLUMNS:
        if not text:
            return cell if isinstance(cell, str) else _BAD
        read = csv_text_read(cell)
        return _BAD if read is None else read
    if not text:  # a Parquet value: the type the sweep wrote
        if name in INT_COLUMNS:
            return cell if type(cell) is int and cell >= 0 else _BAD
        return cell if type(cell) is float and math.isfinite(cell) else _BAD
    if name in INT_COLUMNS:
        return int(cell) if cell.isascii() and cell.isdigit() and str(int(cell)) == cell else _BAD
    try:
        value = float(cell)
    except ValueError:
        return _BAD
    return value if math.isfinite(value) and repr(value) == cell else _BAD


def _line(handle, what: str, number: int) -> bytes:
    """The next line of a rows file (b"" at its end), at most :data:`LINE_LIMIT` bytes: a file
    with no newline for gigabytes is refused, never read whole."""
    line = handle.readline(LINE_LIMIT + 1)
    if len(line) > LINE_LIMIT:
        raise InputError(
            f"{what}: line {number} is longer than any line this sweep writes ({LINE_LIMIT:,} bytes)"
        )
    return line


def _csv_line(line: bytes, what: str, number: int) -> list[str]:
    try:
        text = line.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError(f"{what}: line {number} is not UTF-8 text; not a file this sweep wrote") from None
    if "\0" in text:
        raise InputError(f"{what}: line {number} holds a NUL byte; not a file this sweep wrote")
    return next(csv.reader([text]), [])


def _read_piece(path: Path, what: str):
    # pyarrow: optional (the 'parquet' extra), imported only when used
    import pyarrow as pa
    import pyarrow.parquet as pq

    data = safe.read_capped(path, PIECE_LIMIT, what)
    try:
        return pq.read_table(pa.BufferReader(data))
    except Exception as exc:  # pyarrow raises several types for a damaged file
        raise InputError(f"{what}: not a Parquet file rbi wrote ({type(exc).__name__})") from None


def _arrow_schema(columns: list[str]):
    # pyarrow: optional (the 'parquet' extra), imported only when used
    import pyarrow as pa

    types = dict.fromkeys(INT_COLUMNS, pa.int64()) | dict.fromkeys(TEXT_COLUMNS, pa.string())
    return pa.schema([(name, types.get(name, pa.float64())) for name in columns])
