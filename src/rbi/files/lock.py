"""One writer per output: an exclusive ``fcntl`` lock on a lock file beside it.

``rbi sweep --out F`` holds the lock ``.F.rbi-lock`` for as long as it writes ``F`` (and its
sidecars), and every other output is written holding it (:func:`writing`, used by
:mod:`rbi.files.output` around its write and rename); a second run on the same output, in this
process or another, is refused at once (:class:`~rbi.errors.InputError`, exit 2) instead of
writing over the first. The lock file is opened without following links or blocking and must
be a regular file of this user; it is removed when the lock is released, and the kernel
releases the lock when the process ends, however it ends, so a killed run never leaves a stale
lock (only an empty file, which the next run reuses).
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import threading
from collections.abc import Iterator

from rbi.errors import InputError
from rbi.files import safe

BUSY = "another rbi run is writing this file now; wait for it to end"

_held: dict[tuple[int, int], OutputLock] = {}
"""The locks this process holds, by the (device, inode) of their lock file."""
_held_guard = threading.Lock()


class OutputLock:
    """The held lock of ``out``; :meth:`release` (or leaving the ``with`` block) gives it up
    and removes the lock file. ``what`` prefixes messages (usually the option and path)."""

    SUFFIX = ".rbi-lock"

    def __init__(self, out: str | os.PathLike, what: str) -> None:

        self.path = safe.beside(out, self.SUFFIX)
        label = f"{what}: lock file {safe.shown(self.path.name)}"
        safe.existing_regular(self.path, label)
        self._fd = safe.open_regular(self.path, label, os.O_RDWR | os.O_CREAT, 0o600)
        try:
            info = os.fstat(self._fd)
            try:
                fcntl.flock(self._fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                raise InputError(f"{what}: {BUSY}") from None
            # the name must still be this file: a run that just finished removes it, and a third
            # run could have created a new one that it holds
            current = safe.standing(self.path, label)
            if current is None or (current.st_dev, current.st_ino) != (info.st_dev, info.st_ino):
                raise InputError(f"{what}: {BUSY}")
        except BaseException:
            os.close(self._fd)
            raise
        self._key = (info.st_dev, info.st_ino)
        self.owner = threading.current_thread()
        with _held_guard:
            _held[self._key] = self

    def release(self) -> None:
        if self._fd < 0:
            return
        with _held_guard:
            _held.pop(self._key, None)
        safe.remove(self.path)  # while still held: no other run holds this inode
        os.close(self._fd)
        self._fd = -1

    def __enter__(self) -> OutputLock:
        return self

    def __exit__(self, *exc) -> None:
        self.release()


@contextlib.contextmanager
def writing(out: str | os.PathLike, what: str) -> Iterator[None]:
    """Hold the lock of ``out`` for the block: taken here and released (its file removed) at the
    end, or, when this thread already holds it (a sweep writing its own output), left as it is.
    InputError when another run, or another thread of this process, holds it."""
    if _held_by_this_thread(out):
        yield
        return
    with OutputLock(out, what):
        yield


def check_free(out: str | os.PathLike, what: str) -> None:
    """Refuse (InputError) at once when another run holds the lock of ``out``, or when something
    other than a lock file of this user stands at its name. Creates nothing: when there is no
    lock file, nobody holds the lock."""
    if os.path.lexists(safe.beside(out, OutputLock.SUFFIX)):
        with writing(out, what):
            pass  # free: a file left by a killed run, removed again


def _held_by_this_thread(out: str | os.PathLike) -> bool:
    try:
        info = os.lstat(safe.beside(out, OutputLock.SUFFIX))
    except OSError:
        return False
    with _held_guard:
        lock = _held.get((info.st_dev, info.st_ino))
    return lock is not None and lock.owner is threading.current_thread()
