"""Where the benchmark finds the example bodies and the ``rbi`` command it times."""

from __future__ import annotations

import sys
from pathlib import Path

from rbi.errors import SpecError

BENCH_BODIES = ("top.yaml", "top_bolted.yaml", "tbar.yaml", "top_bolted_toleranced.yaml")
"""The example bodies the benchmark simulates; shipped inside the package (``rbi/data/bodies``,
copies of the source checkout's ``bodies/``), so ``rbi bench`` works after ``pip install .``."""


def bodies_folder() -> Path:
    """The example bodies inside the installed package (``rbi/data/bodies``); SpecError when
    any is missing."""
    folder = Path(__file__).resolve().parents[1] / "data" / "bodies"
    missing = [name for name in BENCH_BODIES if not (folder / name).is_file()]
    if missing:
        raise SpecError(
            f"rbi bench needs the example bodies {', '.join(missing)} in {folder}; "
            "this installation of rbi is incomplete: reinstall it"
        )
    return folder


def rbi_command() -> list[str]:
    """The installed ``rbi`` script next to this Python, else ``python -m rbi``."""
    script = Path(sys.executable).with_name("rbi")
    return [str(script)] if script.is_file() else [sys.executable, "-m", "rbi"]
