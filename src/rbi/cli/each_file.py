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

import json
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from rbi import SpecError
from rbi.cli.option_values import error_line
from rbi.cli.render import (
    Document,
    emit_result,
    fitted,
    rich_console,
    say_warnings,
    tables_of,
)
from rbi.cli.terminal import say, status_kept, terminal_safe


@dataclass
class FileReport:
    """What one file gives: ``result``, a result of the API (:class:`rbi.Result`: its
    ``to_dict()``, CSV rows, tables' rows, and ``csv_summary()``, its row among several
    files'); ``failed``: a check failed (exit 1); ``table``: draws its tables, when not its
    rows drawn as rbi's."""

    result: Any
    failed: bool = False
    table: Callable[[], Any] | None = None


def report_each(files: Sequence[str], report: Callable[[str], FileReport], fmt: str) -> int:
    """Run ``report`` on each of ``files`` and write the output in ``fmt`` (table, json or
    csv); returns the exit status (0, 1 when a check failed, 2 when a file was bad input)."""

    if len(files) == 1:
        one = report(files[0])
        with status_kept(int(one.failed)):
            emit_result(fmt, one.result, table=one.table)
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
        for file in files:
            try:
                one = report(file)
                data = one.result.to_dict()
            except SpecError as exc:
                status = 2
                with status_kept(status):  # the reader left: the run ends with the status known by then
                    sys.stdout.flush()  # what earlier files printed comes before this file's error line
                say(error_line(exc))
                continue
            status = max(status, int(one.failed))
            with status_kept(status):
                self.write("<stdin>" if file == "-" else file, one, data)  # as messages name it
        return status

    def write(self, label: str, one: FileReport, data: dict[str, Any]) -> None:

        if self.fmt != "json":
            sys.stdout.flush()  # the warning line follows what earlier files printed
            say_warnings(data.get("warnings", ()))
        if self.fmt == "json":
            sys.stdout.write(json.dumps({"file": label} | data) + "\n")
        elif self.fmt == "csv":
            self._csv_row({"file": label} | one.result.csv_summary())
        else:
            console = rich_console()
            if self.sections:
                console.print()
            console.print(f"==> {terminal_safe(label)} <==", markup=False, highlight=False)
            console.print(fitted(tables_of(one.result) if one.table is None else one.table(), console))
            self.sections += 1
        sys.stdout.flush()

    def _csv_row(self, row: dict[str, Any]) -> None:
        """One CSV row under the first file's header (a column the first file lacked is left
        out, one it had and this file lacks is empty)."""

        flat = Document(row).flat_rows()[0]
        first = self.header is None
        if first:
            self.header = list(flat)
        text = Document({key: flat.get(key) for key in self.header}).to_csv()
        sys.stdout.write(text if first else text.split("\n", 1)[1])
