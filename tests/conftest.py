"""Shared test fixtures: paths to the bundled bodies and a runner for the installed CLI."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BODIES = ROOT / "bodies"


def run_rbi(*args: str, check: bool = False) -> subprocess.CompletedProcess:
    """Run the CLI in a subprocess exactly as a user would (``python -m rbi``)."""
    proc = subprocess.run([sys.executable, "-m", "rbi", *map(str, args)], capture_output=True, text=True, timeout=300)
    if check and proc.returncode != 0:
        raise AssertionError(f"rbi {' '.join(map(str, args))} exited {proc.returncode}: {proc.stderr}")
    return proc


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
