"""One writer per output: an exclusive ``fcntl`` lock on a lock file beside it.

``rbi sweep --out F`` holds the lock ``.F.rbi-lock`` for as long as it writes ``F`` (and its
sidecars); a second run on the same output, in this process or another, is refused at once
(:class:`~rbi.errors.InputError`, exit 2) instead of writing the same rows twice. The lock file
is opened without following links or blocking and must be a regular file of this user; the
kernel releases the lock when the process ends, however it ends, so a killed run never leaves
a stale lock (only an empty file, which the next run reuses).
"""

from __future__ import annotations

import fcntl
import os

from rbi.errors import InputError
from rbi.files import safe


class OutputLock:
    """The held lock of ``out``; :meth:`release` (or leaving the ``with`` block) gives it up
    and removes the lock file. ``what`` prefixes messages (usually the option and path)."""

    SUFFIX = ".rbi-lock"

    def __init__(self, out: str | os.PathLike, what: str) -> None:

        self.path = safe.beside(out, self.SUFFIX)
        label = f"{what}: lock file {safe.shown(self.path.name)}"
        flags = (
            os.O_RDWR
            | os.O_CREAT
            | getattr(os, "O_NOFOLLOW", 0)
            | getattr(os, "O_NONBLOCK", 0)
            | getattr(os, "O_CLOEXEC", 0)
        )
        safe.existing_regular(self.path, label)
        try:
            self._fd = os.open(self.path, flags, 0o600)
        except OSError as exc:
            raise InputError(f"{label}: cannot open: {safe.reason(exc)}") from None
        try:
            info = os.fstat(self._fd)
            safe.check_regular(info, self.path, label)
            try:
                fcntl.flock(self._fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                raise InputError(
                    f"{what}: another rbi run is writing this file now; wait for it to end "
                    "(two runs on one output would write its rows twice)"
                ) from None
            # the name must still be this file: a run that just finished removes it, and a third
            # run could have created a new one that it holds
            try:
                current = os.lstat(self.path)
            except FileNotFoundError:
                current = None
            if current is None or (current.st_dev, current.st_ino) != (info.st_dev, info.st_ino):
                raise InputError(f"{what}: another rbi run is writing this file now; wait for it to end")
        except BaseException:
            os.close(self._fd)
            raise

    def release(self) -> None:
        if self._fd < 0:
            return
        safe.remove(self.path)  # while still held: no other run holds this inode
        os.close(self._fd)
        self._fd = -1

    def __enter__(self) -> OutputLock:
        return self

    def __exit__(self, *exc) -> None:
        self.release()
