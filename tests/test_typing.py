"""mypy, as configured in pyproject.toml ([tool.mypy]: the checked files, and every function of
rbi.core and rbi.api annotated), finds no error."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_mypy_finds_no_error_in_the_checked_modules():
    pytest.importorskip("mypy", reason="mypy is a test dependency: pip install -e '.[test]'")
    proc = subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", "/dev/null"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-2000:]


def test_the_typing_rule_sees_an_unannotated_core_function(tmp_path):
    pytest.importorskip("mypy")
    probe = tmp_path / "probe.py"
    probe.write_text("def unannotated(x):\n    return x\n")
    proc = subprocess.run(
        [sys.executable, "-m", "mypy", "--disallow-untyped-defs", "--cache-dir", "/dev/null", str(probe)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 1 and "no-untyped-def" in proc.stdout
