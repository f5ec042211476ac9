"""Layering and start-up cost: the core stays pure numpy, and the mass-property commands never
load the integrators, the compiler or the plotting library."""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "rbi"


def imported_modules(path: Path) -> set[str]:
    """Every module a file imports, at any depth (function-level imports included); relative
    imports are resolved against the package."""
    tree = ast.parse(path.read_text(), filename=str(path))
    package = ".".join(path.relative_to(SRC.parent).with_suffix("").parts[:-1])
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                module = f"{base}.{node.module}" if node.module else base
            else:
                module = node.module
            found.add(module)
            found.update(f"{module}.{alias.name}" for alias in node.names)
    return found


def offending(layer: str, forbidden: tuple[str, ...]) -> dict[str, list[str]]:
    assert (SRC / layer).is_dir(), f"rbi has no package {layer!r}: the rule would scan nothing"
    bad = {}
    for path in sorted((SRC / layer).rglob("*.py")):
        hits = sorted(
            m for m in imported_modules(path) if any(m == f or m.startswith(f + ".") for f in forbidden)
        )
        if hits:
            bad[str(path.relative_to(SRC))] = hits
    return bad


def test_import_scanner_sees_function_level_and_relative_imports(tmp_path, monkeypatch):
    sample = SRC / "core" / "dynamics.py"
    assert "rbi.core.rotation" in imported_modules(sample)
    fake_src = tmp_path / "rbi"
    (fake_src / "core").mkdir(parents=True)
    probe = fake_src / "core" / "probe.py"
    probe.write_text("def f():\n    from ..spec import models\n    import rich.table\n")
    monkeypatch.setattr(sys.modules[__name__], "SRC", fake_src)
    assert {"rbi.spec", "rbi.spec.models", "rich.table"} <= imported_modules(probe)


def test_sim_imports_only_the_core_and_numerical_libraries():
    forbidden = ("rbi.spec", "rbi.cli", "rbi.bench", "pydantic", "typer", "rich", "yaml", "click")
    assert offending("sim", forbidden) == {}


def test_core_imports_no_spec_cli_or_interface_libraries():
    forbidden = ("rbi.spec", "rbi.cli", "rbi.sim", "pydantic", "typer", "rich", "yaml", "click")
    assert offending("core", forbidden) == {}


def test_spec_does_not_reach_up_into_the_cli():
    assert offending("spec", ("rbi.cli", "typer", "rich", "click")) == {}


PROBE = """
import json, sys
from typer.testing import CliRunner
from rbi.cli.app import app
body = sys.argv[1]
runs = [["inertia", body], ["inertia", body, "--format", "json", "--rotate", "y:30"],
        ["principal", body, "--format", "csv"], ["momentum", body, "--omega", "0,0,100"]]
codes = [CliRunner().invoke(app, args).exit_code for args in runs]
print(json.dumps({"codes": codes, "modules": sorted(sys.modules)}))
"""


@pytest.fixture(scope="module")
def modules_after_mass_commands():
    body = SRC.parents[1] / "bodies" / "top_bolted.yaml"
    proc = subprocess.run(
        [sys.executable, "-c", PROBE, str(body)], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["codes"] == [0, 0, 0, 0]
    return set(out["modules"])


@pytest.mark.parametrize("heavy", ["scipy.integrate", "numba", "matplotlib", "sympy", "hypothesis"])
def test_mass_commands_do_not_load_heavy_modules(modules_after_mass_commands, heavy):
    assert "rbi.core.inertia" in modules_after_mass_commands  # the probe really ran the commands
    loaded = sorted(m for m in modules_after_mass_commands if m == heavy or m.startswith(heavy + "."))
    assert loaded == []


def test_file_readers_know_nothing_of_specs_or_the_terminal():
    forbidden = (
        "rbi.spec",
        "rbi.cli",
        "rbi.sim",
        "rbi.sweeps",
        "rbi.viz",
        "pydantic",
        "typer",
        "rich",
        "click",
    )
    assert offending("formats", forbidden) == {}


def test_runs_know_nothing_of_the_cli_or_the_terminal():
    assert offending("runs", ("rbi.cli", "rbi.api", "typer", "rich", "click")) == {}


def test_the_api_is_below_the_cli():
    assert offending("api", ("rbi.cli", "typer", "click")) == {}


def test_the_file_writer_stands_below_every_layer_that_writes():
    """rbi.files (the one checked writer of every file rbi creates) needs only rbi.errors and
    rbi.text, so the sweep store, the API and the CLI can all write through it."""
    forbidden = (
        "rbi.spec",
        "rbi.cli",
        "rbi.core",
        "rbi.sim",
        "rbi.sweeps",
        "rbi.formats",
        "rbi.viz",
        "rbi.bench",
        "rbi.api",
        "pydantic",
        "typer",
        "rich",
        "yaml",
        "click",
        "numpy",
    )
    assert offending("files", forbidden) == {}


def test_the_sweep_package_never_reaches_up_into_the_cli():
    assert offending("sweeps", ("rbi.cli", "typer", "rich", "click")) == {}


def test_nothing_outside_the_cli_imports_the_cli():
    """Data flows one way: formats → spec → core → sim/sweep/viz/bench/runs → api → cli. Only
    ``python -m rbi`` (``rbi/__main__.py``, the CLI's entry point) starts from the CLI."""
    bad = {}
    for path in sorted(SRC.rglob("*.py")):
        relative = path.relative_to(SRC)
        if relative.parts[0] == "cli" or relative == Path("__main__.py"):
            continue
        hits = sorted(m for m in imported_modules(path) if m == "rbi.cli" or m.startswith("rbi.cli."))
        if hits:
            bad[str(relative)] = hits
    assert bad == {}


def package_lines() -> tuple[int, int]:
    """Lines of Python in ``rbi/cli`` and in the whole package (every ``.py`` file)."""

    def lines(paths):
        return sum(len(p.read_text().splitlines()) for p in paths)

    return lines((SRC / "cli").rglob("*.py")), lines(SRC.rglob("*.py"))


def test_the_cli_is_under_a_quarter_of_the_package():
    cli, total = package_lines()
    assert cli < 0.25 * total, f"cli/ has {cli:,} of {total:,} lines ({cli / total:.1%})"


MAX_CLI_FUNCTION_LINES = 60
"""A screen: a command function parses its options, calls the API and renders; anything longer
belongs below the CLI."""


def long_functions(folder: Path, limit: int) -> list[tuple[str, str, int]]:
    found = []
    for path in sorted(folder.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                length = node.end_lineno - node.lineno + 1
                if length > limit:
                    found.append((path.name, node.name, length))
    return found


def test_no_cli_function_is_longer_than_a_screen():
    assert long_functions(SRC / "cli", MAX_CLI_FUNCTION_LINES) == []


LONG_FUNCTIONS_LEFT: set[tuple[str, str]] = set()
"""Functions anywhere in rbi still longer than a screen (issue 24 asks for none). This list only
shrinks: a new long function fails the test below; an entry may be removed once it fits."""


def test_no_function_in_the_package_is_longer_than_a_screen_except_the_listed_ones():
    found = {(name, function) for name, function, _ in long_functions(SRC, MAX_CLI_FUNCTION_LINES)}
    assert found - LONG_FUNCTIONS_LEFT == set()


def test_the_size_rules_see_what_they_measure(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text("def short():\n    return 1\n\n\ndef long():\n" + "    x = 1\n" * 70)
    assert long_functions(tmp_path, MAX_CLI_FUNCTION_LINES) == [("probe.py", "long", 71)]
    cli, total = package_lines()
    assert 0 < cli < total and total > 10_000


def test_the_api_module_imports_nothing_heavy():
    """``rbi.api`` is imported by every command that loads a spec: its heavy dependencies (the
    spec models, the integrators, the terminal) are imported inside the functions that use them."""
    code = (
        "import sys, rbi.api; print(sorted({m.split('.')[0] for m in sys.modules} & "
        "{'scipy', 'pydantic', 'yaml', 'typer', 'rich', 'click', 'matplotlib', 'trimesh'}))"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_robot_audit_does_not_reach_up_into_the_cli():
    assert offending("robot", ("rbi.cli", "typer", "rich", "click")) == {}


def _lint_imports() -> subprocess.CompletedProcess:
    lint = Path(sys.executable).parent / "lint-imports"
    if not lint.exists():
        pytest.skip("import-linter is not installed (pip install -e '.[test]' installs it)")
    return subprocess.run(
        [str(lint), "--no-cache"], cwd=SRC.parents[1], capture_output=True, text=True, timeout=300
    )


def test_import_linter_contracts_in_pyproject_are_kept():
    proc = _lint_imports()
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-2000:]


def internal_import_cycles() -> list[list[str]]:
    """Every group of rbi modules that import each other in a circle, function-level imports
    included (grimp reads every import statement)."""
    grimp = pytest.importorskip("grimp")
    import networkx as nx

    graph = grimp.build_graph("rbi", cache_dir=None)
    edges = nx.DiGraph()
    for module in graph.modules:
        for imported in graph.find_modules_directly_imported_by(module):
            edges.add_edge(module, imported)
    return sorted(sorted(c) for c in nx.strongly_connected_components(edges) if len(c) > 1)


def test_the_cycle_finder_sees_a_cycle(tmp_path, monkeypatch):
    package = tmp_path / "rbi"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("def f():\n    from rbi import b\n")
    (package / "b.py").write_text("import rbi.a\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    for name in [m for m in sys.modules if m == "rbi" or m.startswith("rbi.")]:
        monkeypatch.delitem(sys.modules, name)
    assert internal_import_cycles() == [["rbi.a", "rbi.b"]]


def test_no_module_imports_itself_through_others():
    assert internal_import_cycles() == []


# --- the CLI is a client of the API (issue 24) ---------------------------------------------------

CLI_MAY_IMPORT = ("rbi", "rbi.api", "rbi.bench")
"""What of rbi a cli/ module may import besides cli/ itself (rbi.bench: the bench command)."""

NOT_YET_THROUGH_THE_API: dict[str, set[str]] = {}
"""cli/ modules that still import rbi's internals, and which: the commands not yet moved onto
public names of ``rbi.api``. This list only shrinks: an import not in it fails the test below
(an entry the code no longer needs may be removed at any time)."""

PRIVATE_READS_LEFT: set[tuple[str, str]] = {("app.py", "typer._click.exceptions")}
"""Private attributes and modules of other packages that cli/ still reads; only shrinks, as above
(rich's cells are read through ``Column.cells``). Left: typer 0.26 and later vendor click as
``typer._click`` and export neither ``NoSuchOption`` nor ``UsageError`` publicly."""


def cli_internal_imports(cli: Path) -> dict[str, set[str]]:
    """Each cli/ module's imports of rbi modules outside cli/ other than :data:`CLI_MAY_IMPORT`,
    function-level imports included (relative imports stay inside cli/)."""
    found: dict[str, set[str]] = {}
    for path in sorted(cli.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                modules = [node.module]
            elif isinstance(node, ast.Import):
                modules = [alias.name for alias in node.names]
            else:
                continue
            for module in modules:
                parts = module.split(".")
                if parts[0] != "rbi" or module in CLI_MAY_IMPORT or parts[1] in ("cli", "bench"):
                    continue
                found.setdefault(path.name, set()).add(module)
    return found


def cli_private_reads(cli: Path) -> set[tuple[str, str]]:
    """``(file, attribute)`` for every ``x._name`` read in cli/ where ``x`` is not ``self`` and
    not a module of cli/, every ``_name`` imported from a module outside cli/, and ``(file,
    module)`` for every import of a module outside cli/ whose dotted path has a ``_part``."""
    found = set()
    for path in sorted(cli.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            if (
                isinstance(node, ast.Attribute)
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
            ):
                if not (isinstance(node.value, ast.Name) and node.value.id in ("self", "cls")):
                    found.add((path.name, node.attr))
            elif isinstance(node, ast.ImportFrom) and node.module and not node.module.startswith("rbi.cli"):
                found |= {
                    (path.name, a.name)
                    for a in node.names
                    if a.name.startswith("_") and not a.name.startswith("__")
                }
                found |= {(path.name, node.module)} if _private_path(node.module) else set()
            elif isinstance(node, ast.Import):
                found |= {(path.name, a.name) for a in node.names if _private_path(a.name)}
    return found


def _private_path(module: str) -> bool:
    """Whether ``module`` is another package's private module (``typer._click.exceptions``)."""
    parts = module.split(".")
    return parts[:2] != ["rbi", "cli"] and any(p.startswith("_") and not p.startswith("__") for p in parts)


def test_the_cli_reaches_rbi_only_through_its_api_except_the_listed_modules():
    found = cli_internal_imports(SRC / "cli")
    new = {name: modules - NOT_YET_THROUGH_THE_API.get(name, set()) for name, modules in found.items()}
    assert {name: modules for name, modules in new.items() if modules} == {}


def test_the_cli_reads_no_private_attribute_except_the_listed_ones():
    assert cli_private_reads(SRC / "cli") - PRIVATE_READS_LEFT == set()


def test_the_cli_rules_see_an_internal_import_and_a_private_read(tmp_path):
    cli = tmp_path / "rbi" / "cli"
    cli.mkdir(parents=True)
    (cli / "probe.py").write_text(
        "import rbi\nfrom rbi import api\ndef f(body):\n    from rbi.spec.load import load_body\n"
        "    from rbi.formats.paths import _outside_allowed\n    return body._loaded, self_free()\n"
        "from typer._click.exceptions import UsageError\nimport rich._loop, rbi.cli.app\n"
    )
    assert cli_internal_imports(cli) == {"probe.py": {"rbi.spec.load", "rbi.formats.paths"}}
    assert cli_private_reads(cli) == {
        ("probe.py", "_loaded"),
        ("probe.py", "_outside_allowed"),
        ("probe.py", "typer._click.exceptions"),
        ("probe.py", "rich._loop"),
    }


def unused_definitions(root: Path) -> list[str]:
    """The top-level functions and classes of the modules under ``root`` that nothing under
    ``root`` names: no name, attribute, import or string (a listed public name) but its ``def``.
    A decorated one is used: its decorator registers it (``@app.callback()`` on cli/app's root)."""
    used: set[str] = set()
    defined = []
    for path in sorted(root.rglob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        defined += [
            f"{path.relative_to(root)}: {node.name}"
            for node in tree.body
            if isinstance(node, ast.FunctionDef | ast.ClassDef)
            and not node.name.startswith("__")
            and not node.decorator_list
        ]
        for node in ast.walk(tree):
            if isinstance(node, ast.Name):
                used.add(node.id)
            elif isinstance(node, ast.Attribute):
                used.add(node.attr)
            elif isinstance(node, ast.alias):
                used.add(node.name.rpartition(".")[2])
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                used.add(node.value)
    return [each for each in defined if each.rpartition(": ")[2] not in used]


def test_every_function_and_class_of_the_package_is_used_by_the_package():
    # core/mesh.mesh_problem and robot/audit.audit_link were called by tests only.
    assert unused_definitions(SRC) == []


def test_the_unused_finder_sees_an_unused_function(tmp_path):
    (tmp_path / "a.py").write_text(
        'def used():\n    """used() is not a use"""\n\n\ndef unused():\n    used()\n'
    )
    (tmp_path / "b.py").write_text(
        'NAMES = ("listed",)\n\n\ndef listed():\n    pass\n\n\n@register\ndef registered():\n    pass\n'
    )
    assert unused_definitions(tmp_path) == ["a.py: unused"]


# --- the CLI uses only rbi's public names (issue 36) ------------------------------------------


def cli_names_outside_all(cli: Path) -> set[tuple[str, str]]:
    """``(file, name)`` for every name a cli/ module imports from ``rbi`` or ``rbi.api`` that is
    not in ``rbi.__all__``, every other module of rbi it imports (``rbi.bench`` aside: the bench
    command), and ``(file, "numpy")`` / ``(file, "scipy")`` for those libraries."""
    import rbi

    public = set(rbi.__all__)
    found = set()
    for path in sorted(cli.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                modules, names = [node.module], [alias.name for alias in node.names]
            elif isinstance(node, ast.Import):
                modules, names = [alias.name for alias in node.names], []
            else:
                continue
            for module in modules:
                top = module.split(".")[0]
                if top in ("numpy", "scipy"):
                    found.add((path.name, top))
                elif module in ("rbi", "rbi.api"):
                    found.update((path.name, name) for name in names if name not in public and name != "api")
                    if "api" in names:
                        found.add((path.name, "rbi.api"))
                elif top == "rbi" and module.split(".")[1] not in ("cli", "bench"):
                    found.add((path.name, module))
    return found


CLI_NAMES_LEFT: set[tuple[str, str]] = set()
"""What cli/ still imports that is not a name of ``rbi.__all__`` (the ``rbi.api`` module
itself) or is numpy: only shrinks (an entry no longer needed may go at any
time; a new one fails the test below). The mass commands (inertia, principal, parts, momentum,
check, export, dynamics) import only ``rbi`` and its public names."""


def test_the_cli_imports_only_public_names_of_rbi_and_no_numpy_except_the_listed_ones():
    assert cli_names_outside_all(SRC / "cli") - CLI_NAMES_LEFT == set()


def test_rbi_offers_at_most_40_names():
    import rbi

    assert len(rbi.__all__) <= 40


def test_the_public_names_rule_sees_a_private_name_and_numpy(tmp_path):
    cli = tmp_path / "cli"
    cli.mkdir()
    (cli / "probe.py").write_text(
        "import numpy as np\nfrom rbi import load, number\nfrom rbi.api import output_target\n"
        "from rbi import api\nfrom rbi.spec import load as spec_load\nfrom rbi.cli import render\n"
    )
    assert cli_names_outside_all(cli) == {
        ("probe.py", "numpy"),
        ("probe.py", "number"),
        ("probe.py", "output_target"),
        ("probe.py", "rbi.api"),
        ("probe.py", "rbi.spec"),
    }
