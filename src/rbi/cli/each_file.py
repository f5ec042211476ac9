"""Several FILEs in one run (`rbi inertia`, `principal`, `parts`, `check`).

A command describes what one file gives (:class:`FileReport`); :func:`report_each` runs it on
every file and writes the output:

- one file: exactly the one-file output (an error raises, and the CLI exits 2 as always);
- several: tables one section per file, each headed ``==> FILE <==``; ``--format json`` one
  JSON object per line (JSON Lines), ``{"file": FILE, ...the one-file keys}``; ``--format csv``
  one header and one row per file, ``file`` first. A bad file prints its one error line on
  stderr and the others are still processed.

The exit status is the worst over the files: 2 if any file was bad input, else 1 if any check
failed, else 0. FILE ``-`` (standard input) is called ``<stdin>`` in the output.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from rbi.api import SpecError
from rbi.cli.option_values import error_line
from rbi.cli.render import (
    emit,
    fitted,
    flatten,
    refuse_non_finite,
    say_warnings,
    stdout_console,
    tables_of,
    to_csv,
    to_json,
)
from rbi.cli.terminal import ReaderLeft, say, status_kept

STDIN = "-"
STDIN_LABEL = "<stdin>"


@dataclass
class FileReport:
    """What one file gives.

    result: the one-file JSON object. table: builds the rich renderable (called only for table
    output). csv_rows: the one-file CSV rows (default ``[result]``). summary: the file's one
    CSV row among several (default the first of ``csv_rows``). failed: a check failed (exit 1).
    """

    result: dict[str, Any]
    table: Callable[[], Any]
    csv_rows: list[dict[str, Any]] | None = None
    summary: dict[str, Any] | None = None
    failed: bool = False

    @classmethod
    def of(cls, result: Any, failed: bool = False) -> FileReport:
        """What a result of the API gives (:class:`rbi.reprs.Result`: its ``to_dict()``, its
        tables' rows, its CSV rows and its row among several files')."""
        return cls(
            result.to_dict(), lambda: tables_of(result), result.csv_rows(), result.csv_summary(), failed
        )

    def summary_row(self) -> dict[str, Any]:
        if self.summary is not None:
            return self.summary
        return (self.csv_rows or [self.result])[0]


def file_label(file: str) -> str:
    """How a FILE argument is named in output and messages (``-`` is ``<stdin>``)."""
    return STDIN_LABEL if file == STDIN else file


def report_each(files: Sequence[str], report: Callable[[str], FileReport], fmt: str) -> int:
    """Run ``report`` on each of ``files`` and write the output in ``fmt`` (table, json or
    csv); returns the exit status (0, 1 when a check failed, 2 when a file was bad input)."""

    if len(files) == 1:
        one = report(files[0])
        with status_kept(int(one.failed)):
            emit(fmt, one.result, one.table, csv_rows=one.csv_rows, source=file_label(files[0]))
        return int(one.failed)
    return _Several(fmt).run(files, report)


class _Several:
    """The output of several files, written file by file as each is done."""

    def __init__(self, fmt: str) -> None:
        self.fmt = fmt
        self.header: list[str] | None = None
        self.sections = 0

    def run(self, files: Sequence[str], report: Callable[[str], FileReport]) -> int:

        status = 0  # the worst so far: 2 once a file was bad input, else 1 once a check failed
        try:
            for file in files:
                try:
                    one = report(file)
                    refuse_non_finite(one.result, file_label(file))
                except SpecError as exc:
                    status = 2
                    sys.stdout.flush()  # what earlier files printed comes before this file's error line
                    say(error_line(exc))
                    continue
                status = max(status, int(one.failed))
                self.write(file_label(file), one)
        except ReaderLeft as exc:  # the reader left: the run ends with the status known by then
            exc.status = max(exc.status, status)
            raise
        return status

    def write(self, label: str, one: FileReport) -> None:

        if self.fmt != "json":
            sys.stdout.flush()  # the warning line follows what earlier files printed
            say_warnings(one.result.get("warnings", ()))
        if self.fmt == "json":
            sys.stdout.write(to_json({"file": label} | one.result) + "\n")
        elif self.fmt == "csv":
            self._csv_row({"file": label} | one.summary_row())
        else:
            console = stdout_console()
            if self.sections:
                console.print()
            console.print(f"==> {label} <==", markup=False, highlight=False)
            console.print(fitted(one.table(), console))
            self.sections += 1
        sys.stdout.flush()

    def _csv_row(self, row: dict[str, Any]) -> None:
        """One CSV row under the first file's header (a column the first file lacked is left
        out, one it had and this file lacks is empty)."""

        flat = flatten(row)
        first = self.header is None
        if first:
            self.header = list(flat)
        text = to_csv([{key: flat.get(key) for key in self.header}])
        sys.stdout.write(text if first else text.split("\n", 1)[1])
