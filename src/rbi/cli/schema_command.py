"""`rbi schema` (the JSON Schema of the spec) and `rbi validate` (check many spec files)."""

from __future__ import annotations

import json
import sys
from typing import Literal

import typer

import rbi
from rbi.cli.options import FORMAT, PACKAGE_PATHS, OutputFormat, argument, command, option
from rbi.cli.render import emit_result
from rbi.cli.terminal import say, status_kept, terminal_safe


@command(
    option(
        Literal["table", "json"],
        "--format",
        "-f",
        default="table",
        help="table (indented JSON, for people) or json (on one line).",
    )
)
def schema(*, format: str) -> None:
    """Print the JSON Schema of the YAML spec (for editors: see docs/schema.md).

    \b
    Examples:
      rbi schema --format json > rbi-spec.schema.json
      # then, first line of a spec, for YAML language servers:
      # yaml-language-server: $schema=rbi-spec.schema.json
    """

    indent = 2 if format == "table" else None
    sys.stdout.write(json.dumps(rbi.spec_schema(), indent=indent, ensure_ascii=False) + "\n")


@command(PACKAGE_PATHS, FORMAT)
def validate(
    files: argument(
        list[str],
        "Body specs (YAML or JSON; - reads one from standard input) or robot files "
        "(.urdf, .sdf, MJCF .xml, .xacro) to check.",
        "FILE...",
    ),
    *,
    format: OutputFormat,
    **settings,
) -> None:
    """Check spec files without computing anything: one line per problem; exit 2 if any file fails.

    \b
    Examples:
      rbi validate bodies/*.yaml
      rbi validate top.yaml wheel.yaml --format json
    """

    validation = rbi.validate(files, **settings)
    with status_kept(0 if validation.ok else 2):  # a reader that left does not make the files valid
        if format is not OutputFormat.table:
            emit_result(format.value, validation)
        else:
            for problems in validation:
                for line in problems:
                    print(terminal_safe(line))
            say(validation.summary)
    if not validation.ok:
        raise typer.Exit(2)
