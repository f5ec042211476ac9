"""The API is tested through its public names only, and the public names are all there is:
``import rbi`` is cheap, ``rbi.__all__`` lists the API, and nothing else is reachable as a
public name."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

import rbi

HERE = Path(__file__).resolve().parent
PROTOCOL_NAMES = {"_repr_html_"}  # IPython's display protocol, called by notebooks


def private_uses(path: Path) -> list[str]:
    """Imports of rbi's submodules, names imported from rbi or read from it that are not in
    ``rbi.__all__``, and attributes with a leading underscore (other than dunders and
    :data:`PROTOCOL_NAMES`) in the test file at ``path``."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if isinstance(node, ast.Import):
            found += [a.name for a in node.names if a.name.startswith("rbi.")]
        elif isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] == "rbi":
            if node.module != "rbi":
                found.append(node.module)
            found += [
                f"rbi.{a.name}" for a in node.names if node.module == "rbi" and a.name not in rbi.__all__
            ]
        elif isinstance(node, ast.Attribute):
            if (
                isinstance(node.value, ast.Name)
                and node.value.id == "rbi"
                and node.attr not in rbi.__all__
                and not node.attr.startswith("__")
            ):
                found.append(f"rbi.{node.attr}")
            elif (
                node.attr.startswith("_")
                and not node.attr.startswith("__")
                and node.attr not in PROTOCOL_NAMES
            ):
                found.append(f".{node.attr}")
    return found


@pytest.mark.parametrize("path", sorted(HERE.glob("*.py")), ids=lambda p: p.name)
def test_api_tests_use_public_names_only(path):
    assert private_uses(path) == []


def test_the_scanner_sees_private_uses(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text(
        "import rbi.api\nfrom rbi.spec import load\nfrom rbi import load, api\nimport rbi\n"
        "rbi.cli\nrbi.load('x')._loaded\nrbi.Body.__init__\nx._repr_html_()\n"
    )
    assert private_uses(probe) == ["rbi.api", "rbi.spec", "rbi.api", "rbi.cli", "._loaded"]


def test_all_lists_the_api_and_each_name_resolves():
    assert {"load", "Body", "simulate", "Trajectory", "SpecError"} <= set(rbi.__all__)
    for name in rbi.__all__:
        assert getattr(rbi, name) is not None
    assert rbi.SpecError.__mro__[1] is Exception


def test_names_outside_all_are_not_attributes():
    for name in ("api", "spec", "cli", "sim", "LoadedBody", "load_body"):
        if name in sys.modules.get("rbi").__dict__:  # a loaded submodule is bound by Python's import system
            continue
        with pytest.raises(AttributeError):
            getattr(rbi, name)


def test_import_rbi_alone_is_cheap():
    code = "import sys, rbi; print(sorted(m for m in ('numpy', 'pydantic', 'yaml', 'typer', 'rich', 'rbi.api') if m in sys.modules))"
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert proc.stdout.strip() == "[]"


def test_public_functions_and_classes_have_docstrings():
    for name in rbi.__all__:
        value = getattr(rbi, name)
        if callable(value):
            assert value.__doc__ and len(value.__doc__.strip()) > 20, name
