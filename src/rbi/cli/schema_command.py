"""`rbi schema` (the JSON Schema of the spec) and `rbi validate` (check many spec files)."""

from __future__ import annotations

import json
import sys

import typer

from rbi.api import spec_schema
from rbi.api import validate as problems_of
from rbi.cli.each_file import file_label
from rbi.cli.options import (
    DocumentFormat,
    DocumentFormatOption,
    FormatOption,
    OutputFormat,
    PackagePathOption,
    argument,
)
from rbi.cli.render import emit, terminal_safe
from rbi.cli.terminal import status_kept


def schema(format: DocumentFormatOption = DocumentFormat.table) -> None:
    """Print the JSON Schema of the YAML spec (for editors: see docs/schema.md).

    \b
    Examples:
      rbi schema --format json > rbi-spec.schema.json
      # then, first line of a spec, for YAML language servers:
      # yaml-language-server: $schema=rbi-spec.schema.json
    """

    indent = 2 if format is DocumentFormat.table else None
    sys.stdout.write(json.dumps(spec_schema(), indent=indent, ensure_ascii=False) + "\n")


def validate(
    files: argument(
        list[str],
        "Body specs (YAML or JSON; - reads one from standard input) or robot files "
        "(.urdf, .sdf, MJCF .xml, .xacro) to check.",
        "FILE...",
    ),
    package_path: PackagePathOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Check spec files without computing anything: one line per problem; exit 2 if any file fails.

    \b
    Examples:
      rbi validate bodies/*.yaml
      rbi validate top.yaml wheel.yaml --format json
    """

    problems = problems_of(files, package_paths=package_path)
    reports = [{"file": file_label(path), "problems": found} for path, found in zip(files, problems)]
    bad = [r for r in reports if r["problems"]]
    count = sum(len(r["problems"]) for r in reports)
    with status_kept(2 if bad else 0):  # a reader that left does not make the files valid
        if format is OutputFormat.table:
            for report in reports:
                for line in report["problems"]:
                    print(terminal_safe(line))
            summary = (
                f"{len(files)} file(s) valid"
                if not bad
                else f"{len(bad)} of {len(files)} file(s) invalid, {count} problem(s)"
            )
            print(f"rbi: {summary}", file=sys.stderr)
        else:
            result = {"ok": not bad, "files": [r | {"ok": not r["problems"]} for r in reports]}
            rows = [
                {"file": r["file"], "ok": not r["problems"], "problem": line}
                for r in reports
                for line in (r["problems"] or [""])
            ]
            emit(format.value, result, lambda: None, csv_rows=rows)
    if bad:
        raise typer.Exit(2)
