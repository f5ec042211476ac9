"""Shared test fixtures: paths to the bundled bodies and a runner for the installed CLI; the
hypothesis profile every run uses."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import settings

# The suite gives the same verdict on every machine and every run: hypothesis draws the same
# examples each time (derandomize) and keeps no database of past failures between runs.
# Every case it ever found is kept in its test as an explicit @example. To hunt for new cases
# locally: HYPOTHESIS_PROFILE=explore .venv/bin/python -m pytest tests/hardening
settings.register_profile("fixed", derandomize=True, database=None, print_blob=True)
settings.register_profile("explore", derandomize=False, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "fixed"))

ROOT = Path(__file__).resolve().parents[1]
BODIES = ROOT / "bodies"


def run_rbi(*args: str, check: bool = False) -> subprocess.CompletedProcess:
    """Run the CLI in a subprocess exactly as a user would (``python -m rbi``)."""
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", *map(str, args)], capture_output=True, text=True, timeout=300
    )
    if check and proc.returncode != 0:
        raise AssertionError(f"rbi {' '.join(map(str, args))} exited {proc.returncode}: {proc.stderr}")
    return proc


def run_rbi_inprocess(*args: str) -> subprocess.CompletedProcess:
    """Run ``rbi.cli.app.main`` in this process (fast; for the many error and format cases)
    with stdout and stderr captured; the same result shape as :func:`run_rbi`."""
    import contextlib
    import io

    from rbi.cli.app import main

    out, err = io.StringIO(), io.StringIO()
    argv = ["rbi", *map(str, args)]
    saved, sys.argv = sys.argv, argv
    code = 0
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        sys.argv = saved
    return subprocess.CompletedProcess(argv, code, out.getvalue(), err.getvalue())


def one_line_exit_2(proc, *words):
    """The CLI refused bad input the contract's way: exit 2, one line, no traceback, naming
    each of ``words``."""
    assert proc.returncode == 2, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr
    for word in words:
        assert word in proc.stderr, proc.stderr


@pytest.fixture
def bodies() -> Path:
    return BODIES


@pytest.fixture
def write_spec(tmp_path):
    """Write YAML text to a file in a temporary folder and return its path."""

    def write(text: str, name: str = "body.yaml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path

    return write
