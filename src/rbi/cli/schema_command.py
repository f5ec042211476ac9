"""`rbi schema` (the JSON Schema of the spec) and `rbi validate` (check many spec files)."""

from __future__ import annotations

import sys
from typing import Annotated, Any

import typer

from rbi.cli.audit_command import PackagePathOption
from rbi.cli.options import FormatOption, OutputFormat


def spec_schema() -> dict[str, Any]:
    """JSON Schema (draft 2020-12) of a body spec, generated from the pydantic models."""
    from rbi.spec.models import body_spec_json_schema

    schema = _plain_descriptions(body_spec_json_schema())
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "rbi body spec",
    } | {k: v for k, v in schema.items() if k != "title"}


def _plain_descriptions(node: Any) -> Any:
    """Descriptions as editors show them: the docstrings' reStructuredText literals (double
    backquotes) and Sphinx roles (:mod:`x`) written as plain `x`, line breaks joined."""
    import re

    if isinstance(node, dict):
        out = {}
        for key, value in node.items():
            if key == "description" and isinstance(value, str):
                value = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", value).replace("``", "`")
                value = re.sub(r"\s*\n\s*", " ", value).strip()
            out[key] = _plain_descriptions(value)
        return out
    if isinstance(node, list):
        return [_plain_descriptions(v) for v in node]
    return node


def schema(format: FormatOption = OutputFormat.table) -> None:
    """Print the JSON Schema of the YAML spec (for editors: see docs/schema.md).

    \b
    Examples:
      rbi schema --format json > rbi-spec.schema.json
      # then, first line of a spec, for YAML language servers:
      # yaml-language-server: $schema=rbi-spec.schema.json
    """
    import json

    from rbi.spec.errors import InputError

    if format is OutputFormat.csv:
        raise InputError("--format csv: the schema is a JSON document; use --format table (indented) or json")
    indent = 2 if format is OutputFormat.table else None
    sys.stdout.write(json.dumps(spec_schema(), indent=indent, ensure_ascii=False) + "\n")


def file_problems(path: str, package_paths: dict | None = None) -> list[str]:
    """Every problem found in one spec file, one line each (empty when it is valid):
    unreadable or malformed YAML, each field the models refuse, then the first problem met
    while building the body (an unphysical custom inertia, a hole removing too much)."""
    from rbi.formats.robot_files import is_robot_file, robot_file_problems
    from rbi.spec.errors import InputError
    from rbi.spec.load import read_yaml, spec_label, validation_messages
    from rbi.spec.translate import body_from_spec

    if is_robot_file(path):  # URDF, SDF, MJCF: every link whose inertia is not physical
        return robot_file_problems(path, package_paths)
    try:
        raw = read_yaml(path)
    except InputError as exc:
        return [str(exc)]
    spec, problems = validation_messages(spec_label(path), raw)
    if problems:
        return problems
    try:
        body_from_spec(spec, spec_label(path))
    except InputError as exc:
        return [str(exc)]
    return []


def validate(
    files: Annotated[
        list[str], typer.Argument(help="Spec files (YAML) to check.", show_default=False, metavar="FILE...")
    ],
    package_path: PackagePathOption = None,
    format: FormatOption = OutputFormat.table,
) -> None:
    """Check spec files without computing anything: one line per problem; exit 2 if any file fails.

    \b
    Examples:
      rbi validate bodies/*.yaml
      rbi validate top.yaml wheel.yaml --format json
    """
    from rbi.cli.render import emit, terminal_safe
    from rbi.formats.robot_paths import parse_package_paths

    packages = parse_package_paths(package_path)
    reports = [{"file": path, "problems": file_problems(path, packages)} for path in files]
    bad = [r for r in reports if r["problems"]]
    count = sum(len(r["problems"]) for r in reports)
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
