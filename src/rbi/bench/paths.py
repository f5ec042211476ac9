"""Where the benchmark finds the example bodies and the ``rbi`` command it times."""

from __future__ import annotations

import sys
from pathlib import Path


def bodies_folder() -> Path:
    """The bundled example bodies (``bodies/`` of the source checkout)."""
    here = Path(__file__).resolve()
    for parent in here.parents:
        candidate = parent / "bodies" / "top_bolted.yaml"
        if candidate.is_file():
            return candidate.parent
    raise FileNotFoundError("rbi bench needs the example bodies (bodies/top_bolted.yaml) of a source checkout")


def rbi_command() -> list[str]:
    """The installed ``rbi`` script next to this Python, else ``python -m rbi``."""
    script = Path(sys.executable).with_name("rbi")
    return [str(script)] if script.is_file() else [sys.executable, "-m", "rbi"]
