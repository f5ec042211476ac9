"""Optional packages: how --help says that an option needs one (one phrase, written only on
the options that need it), and the refusal, before any work, when it is missing."""

from __future__ import annotations

import importlib.util

from rbi import SpecError


def needs(package: str, extra: str) -> str:
    """``needs matplotlib: pip install '.[plot]' in rbi's source folder``."""
    return f"needs {package}: pip install '.[{extra}]' in rbi's source folder"


def require_matplotlib(option: str = "--plot") -> None:
    """Refuse ``option`` (the one that asked for a picture) with the install command when
    matplotlib is missing."""
    try:
        import matplotlib  # noqa: F401  (the optional extra `plot`, loaded only when a picture is asked for)
    except ImportError:
        raise SpecError(
            f"{option}: needs matplotlib, which is not installed: pip install '.[plot]' from rbi's source folder, or pip install matplotlib"
        ) from None


def require(module: str, extra: str, option: str) -> None:
    """Refuse ``option`` with the install command when the optional package ``module`` is missing."""
    if importlib.util.find_spec(module) is None:
        raise SpecError(
            f"{option}: needs the optional package {module!r}: pip install '.[{extra}]' from rbi's "
            f"source folder, or pip install {module}"
        )
