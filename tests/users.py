"""Running a command as an ordinary user in tests (root ignores file permissions)."""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
import sys

import pytest

ROOT_WITHOUT_CAPABILITIES = ["--inh-caps=-all", "--bounding-set=-all", "--no-new-privs"]
NOBODY = ["--reuid=nobody", "--regid=nogroup", "--clear-groups"]


def as_ordinary_user() -> list[str]:
    """A command prefix under which file permissions hold, as for any ordinary user (empty when
    the tests do not run as root): the user ``nobody`` when it can run this checkout's rbi,
    else root without capabilities (when the checkout sits in a folder only root may read,
    such as /root or a mkdtemp folder: as the owner, root still reads it, but no longer writes
    where the mode forbids it). Skips the test when root can do neither here."""
    if os.geteuid() != 0:
        return []
    setpriv = shutil.which("setpriv")
    if setpriv is None:
        pytest.skip("running as root without setpriv: cannot drop to an ordinary user")
    for way in (NOBODY, ROOT_WITHOUT_CAPABILITIES):
        if _runs_rbi(setpriv, tuple(way)):
            return [setpriv, *way]
    pytest.skip("running as root: neither nobody nor root without capabilities can run rbi here")


@functools.cache
def _runs_rbi(setpriv: str, way: tuple[str, ...]) -> bool:
    """Whether ``setpriv way`` can start this Python and import rbi from here."""
    probe = [setpriv, *way, sys.executable, "-c", "import rbi.cli.app"]
    try:
        return subprocess.run(probe, capture_output=True, timeout=60, cwd="/").returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False
