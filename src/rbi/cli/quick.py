"""A start-up shortcut for the commands people run most and script the most (`inertia`,
`principal`, `parts`, `check`): a plain command line is read here and the command's report
runs without importing typer (about a fifth of `rbi inertia`'s whole time; see
docs/performance.md).

"Plain" means: FILEs and the options listed in :data:`COMMANDS`, each spelled as `--name
VALUE`, `--name=VALUE`, `-n VALUE` or `-nVALUE`, with a choice spelled exactly as listed. For
anything else (`--help`, an unknown or misspelt option, a missing value, a choice not listed,
`--`, no FILE) :func:`run` returns None and typer reads the command line as always, so every
message, help text and edge case stays typer's. ``tests/cli/test_quick.py`` checks that the
options here are those the typer commands declare, with the same defaults, and that both
paths print the same bytes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

FORMATS = ("table", "json", "csv")


@dataclass(frozen=True)
class Opt:
    """One option: its spellings, the keyword it fills, the values it may take (None: any
    text) and whether it may be repeated (a list)."""

    flags: tuple[str, ...]
    keyword: str
    choices: tuple[str, ...] | None = None
    repeated: bool = False


_FORMAT = Opt(("--format", "-f"), "fmt", FORMATS)
_ABOUT = Opt(("--about", "-a"), "about")
_UNITS = Opt(("--units", "-u"), "units")

COMMANDS: dict[str, tuple[str, str, tuple[Opt, ...]]] = {
    # command: (module, function taking (files, **keywords) and returning the exit status, options)
    "inertia": (
        "rbi.cli.mass_reports",
        "inertia",
        (
            _ABOUT,
            Opt(("--rotate", "-r"), "rotate", repeated=True),
            Opt(("--axis",), "axis"),
            Opt(("--products",), "products", ("tensor", "cad")),
            _UNITS,
            _FORMAT,
        ),
    ),
    "principal": ("rbi.cli.mass_reports", "principal", (_ABOUT, _UNITS, _FORMAT)),
    "parts": ("rbi.cli.parts_report", "parts", (_FORMAT,)),
    "check": ("rbi.cli.check_report", "check", (_FORMAT,)),
}


def parse(args: Sequence[str]) -> tuple[str, list[str], dict] | None:
    """``(command, files, keywords)`` for a plain command line, else None."""
    if not args or args[0] not in COMMANDS:
        return None
    command, rest = args[0], list(args[1:])
    options = {flag: opt for opt in COMMANDS[command][2] for flag in opt.flags}
    files: list[str] = []
    keywords: dict = {}
    while rest:
        token = rest.pop(0)
        if token == "-" or not token.startswith("-"):
            files.append(token)
            continue
        if token.startswith("--"):
            name, equals, value = token.partition("=")
            if not equals:
                value = None
        else:
            name, value = token[:2], (token[2:] or None)
        opt = options.get(name)
        if opt is None:
            return None
        if value is None:
            if not rest:
                return None
            value = rest.pop(0)
        if opt.choices is not None and value not in opt.choices:
            return None
        if opt.repeated:
            keywords.setdefault(opt.keyword, []).append(value)
        else:
            keywords[opt.keyword] = value
    if not files:
        return None
    return command, files, keywords


def run(args: Sequence[str]) -> int | None:
    """Run a plain command line (see :func:`parse`) and return its exit status; None when the
    command line is not plain (typer takes it)."""
    parsed = parse(args)
    if parsed is None:
        return None
    import importlib

    from rbi.cli.fast_params import quiet_pydantic_plugins

    command, files, keywords = parsed
    module, function, _ = COMMANDS[command]
    quiet_pydantic_plugins()
    return getattr(importlib.import_module(module), function)(files, **keywords)
