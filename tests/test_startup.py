"""What each command loads at start-up (issue 9): checked on sys.modules of a fresh Python that
runs the command, so that a stray top-level import shows up here rather than as a slow start."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

BODIES = Path(__file__).resolve().parents[1] / "bodies"

PROBE = """
import json, sys
from rbi.cli.app import main
sys.argv = ["rbi", *json.loads(sys.argv[1])]
try:
    main()
except SystemExit as exc:
    status = exc.code
else:
    status = 0
print("\\nMODULES " + json.dumps(sorted(sys.modules)), file=sys.stderr)
print("STATUS " + json.dumps(status), file=sys.stderr)
"""


def loaded(*args: str) -> tuple[set[str], object, str]:
    proc = subprocess.run(
        [sys.executable, "-c", PROBE, json.dumps([str(a) for a in args])],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = proc.stderr.splitlines()
    modules = json.loads(next(line for line in lines if line.startswith("MODULES "))[8:])
    status = json.loads(next(line for line in lines if line.startswith("STATUS "))[7:])
    return set(modules), status, proc.stdout


def _any(modules: set[str], package: str) -> bool:
    return any(m == package or m.startswith(package + ".") for m in modules)


@pytest.mark.parametrize("args", [["--help"], ["--version"], ["-h"]])
def test_help_and_version_load_no_numpy_and_no_command_module(args):
    modules, status, out = loaded(*args)
    assert status in (0, None)
    assert out.strip()
    for package in (
        "numpy",
        "pydantic",
        "yaml",
        "rich",
        "scipy",
        "rbi.spec.models",
        "rbi.spec.load",
        "rbi.sim",
        "rbi.core",
    ):
        assert not _any(modules, package), package
    assert not [m for m in modules if m.startswith("rbi.cli.") and m.endswith("_command")]


@pytest.mark.parametrize("fmt", ["json", "table"])
def test_inertia_loads_no_scipy_matplotlib_or_kernel(fmt):
    modules, status, out = loaded("inertia", BODIES / "top.yaml", "--format", fmt)
    assert status in (0, None)
    assert "0.5" in out
    for package in ("scipy", "matplotlib", "rbi.sim", "rbi.sweeps", "rbi.bench", "trimesh", "xml", "pyexpat"):
        assert not _any(modules, package), package
    if fmt == "json":
        assert not _any(modules, "rich")  # rich only when a table is printed


def test_simulate_of_a_symmetric_top_loads_no_scipy_or_matplotlib():
    modules, status, out = loaded(
        "simulate", BODIES / "top.yaml", "--spin", "200", "--tilt", "10", "--format", "json"
    )
    assert status in (0, None)
    assert json.loads(out)
    assert "rbi.sim._dop853" in modules
    for package in ("scipy", "matplotlib", "rbi.sweeps", "rbi.bench"):
        assert not _any(modules, package), package


def test_the_collector_paused_while_a_command_or_a_name_is_imported_is_on_again_after():
    import gc

    import rbi.api
    from rbi.cli.app import build_command

    # on at the start whatever earlier tests left (a sweep chunk abandoned past its stop time
    # keeps its pause in a daemon thread), and as it was at the end
    was = gc.isenabled()
    gc.enable()
    try:
        build_command("inertia")
        rbi.api.__getattr__("load")
        assert gc.isenabled()
    finally:
        if not was:
            gc.disable()


def test_at_exit_what_the_run_built_is_frozen_so_the_last_collections_skip_it():
    probe = (
        "import atexit, gc, sys\n"
        "atexit.register(lambda: print('frozen', gc.get_freeze_count() > 0))\n"  # runs after rbi's
        "from rbi.cli.app import main\n"
        "sys.argv = ['rbi', 'inertia', sys.argv[1]]\n"
        "main()\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", probe, str(BODIES / "top.yaml")], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 0
    assert "0.5" in proc.stdout
    assert proc.stdout.rstrip().endswith("frozen True")
