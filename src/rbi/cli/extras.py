"""How --help says that an option needs an optional package: one phrase, written only on the
options (and forms of an option) that need it."""

from __future__ import annotations


def needs(package: str, extra: str) -> str:
    """``needs matplotlib: pip install '.[plot]' in rbi's source folder``."""
    return f"needs {package}: pip install '.[{extra}]' in rbi's source folder"
