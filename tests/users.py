"""Running a command as an ordinary user in tests (root ignores file permissions)."""

from __future__ import annotations

import os
import shutil

import pytest


def as_ordinary_user() -> list[str]:
    """A command prefix that drops to the user ``nobody`` when the tests run as root (empty
    otherwise); skips the test when root cannot drop privileges here."""
    if os.geteuid() != 0:
        return []
    setpriv = shutil.which("setpriv")
    if setpriv is None:
        pytest.skip("running as root without setpriv: cannot drop to an ordinary user")
    return [setpriv, "--reuid=nobody", "--regid=nogroup", "--clear-groups"]
