"""rbi.cli.quick (a plain `rbi inertia|principal|parts|check FILE...` read without typer): the
options it knows are exactly those typer declares, with the same defaults, and both paths print
the same bytes and exit with the same status."""

from __future__ import annotations

import inspect
import json
import subprocess
import sys

import pytest

from rbi.cli import quick
from rbi.cli.app import _build_command
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi


def _typer_options(command: str) -> dict[str, tuple]:
    """The typer command's options: keyword -> (spellings, choices or None, repeated, default)."""
    out = {}
    for param in _build_command(command).params:
        if param.param_type_name != "option":
            continue
        annotation = param.type_descriptor.annotation
        choices = [member.value for member in annotation] if hasattr(annotation, "__members__") else None
        default = param.default.value if hasattr(param.default, "value") else param.default
        out[param.name] = (
            frozenset(param.opts + param.secondary_opts),
            None if choices is None else tuple(choices),
            bool(param.multiple),
            default,
        )
    return out


@pytest.mark.parametrize("command", list(quick.COMMANDS))
def test_the_options_are_those_typer_declares_with_the_same_defaults(command):
    module, function, options = quick.COMMANDS[command]
    implementation = getattr(__import__(module, fromlist=[function]), function)
    defaults = {name: p.default for name, p in inspect.signature(implementation).parameters.items()}
    declared = _typer_options(command)
    keyword_of = {"format": "fmt"}  # typer's `format` option fills the report's `fmt`
    assert {keyword_of.get(name, name) for name in declared} == {opt.keyword for opt in options}
    for name, (spellings, choices, repeated, default) in declared.items():
        opt = next(o for o in options if o.keyword == keyword_of.get(name, name))
        assert frozenset(opt.flags) == spellings, name
        assert opt.choices == choices, name
        assert opt.repeated == repeated, name
        assert defaults[opt.keyword] == default, name


LINES = [
    ["inertia", BODIES / "top_bolted.yaml"],
    [
        "inertia",
        BODIES / "top_bolted.yaml",
        "-fjson",
        "--about",
        "-0.01,0,0.02",
        "-r",
        "y:30",
        "--rotate=x:-15",
    ],
    [
        "inertia",
        BODIES / "top.yaml",
        BODIES / "top_bolted.yaml",
        "--axis",
        "1,1,0",
        "--products",
        "cad",
        "-f",
        "csv",
    ],
    ["inertia", BODIES / "top.yaml", "--units", "mm,g", "--format", "json"],
    ["inertia", BODIES / "top.yaml", "--about", "pivot", "--about", "com"],
    ["principal", BODIES / "rocket.yaml", "-a", "origin", "-u", "SI"],
    ["principal", BODIES / "top.yaml", "nope.yaml", "--format", "json"],
    ["parts", BODIES / "wheel_with_holes.yaml", BODIES / "cubesat.yaml"],
    ["parts", BODIES / "top_bolted.yaml", "--format", "csv"],
    ["check", BODIES / "robot_link.yaml", BODIES / "top.yaml", "-f", "json"],
    ["inertia", BODIES / "top.yaml", "--axis", "0,0,0"],
]


@pytest.mark.parametrize(
    "args", LINES, ids=lambda a: " ".join(str(x).replace(str(BODIES) + "/", "") for x in a)
)
def test_same_bytes_and_status_as_typer(args, monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")
    assert quick.parse([str(a) for a in args]) is not None  # the quick path takes it
    fast = rbi(*args)
    typer = rbi(*args, "--")  # a trailing `--` is not plain: typer reads the same command line
    assert (fast.returncode, fast.stdout, fast.stderr) == (typer.returncode, typer.stdout, typer.stderr)


@pytest.mark.parametrize(
    "args",
    [
        [],
        ["inertia"],
        ["inertia", "--help"],
        ["inertia", "t.yaml", "-h"],
        ["inertia", "t.yaml", "--format", "xml"],
        ["inertia", "t.yaml", "--format", "JSON"],
        ["inertia", "t.yaml", "--formt", "json"],
        ["inertia", "t.yaml", "-f"],
        ["inertia", "t.yaml", "--"],
        ["momentum", "t.yaml", "--omega", "0,0,1"],
        ["parts", "t.yaml", "--about", "com"],
        ["check", "t.yaml", "-x"],
        ["--version"],
    ],
)
def test_anything_not_plain_is_left_to_typer(args):
    assert quick.parse(args) is None


def test_a_plain_inertia_loads_neither_typer_nor_package_metadata():
    code = (
        "import sys; from rbi.cli.app import main\n"
        "sys.argv = ['rbi', 'inertia', sys.argv[1], sys.argv[1], '--format', 'json']\n"
        "try:\n    main()\nexcept SystemExit:\n    pass\n"
        "print(' '.join(sorted(sys.modules)), file=sys.stderr)\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code, str(BODIES / "top.yaml")], capture_output=True, text=True, timeout=120
    )
    lines = proc.stdout.splitlines()
    assert len(lines) == 2 and json.loads(lines[0])["mass"] == pytest.approx(0.5)
    modules = set(proc.stderr.split())
    for package in ("typer", "click", "rich", "importlib.metadata", "email"):
        assert not any(m == package or m.startswith(package + ".") for m in modules), package
