"""Opening, reading and creating the files rbi keeps beside an output (sidecars, partial files,
locks) without ever following a symbolic link, waiting on a FIFO or reading a device.

Every function here opens with ``O_NOFOLLOW | O_NONBLOCK`` and checks the open file itself
(``fstat``), not the name, so nothing can be swapped in between a check and a use:

- a symbolic link (even to a regular file), a FIFO, a device, a socket or a folder where a
  regular file is expected is an :class:`~rbi.errors.InputError`, found without reading a byte
  and without blocking (a FIFO with no writer opens at once with ``O_NONBLOCK``);
- a file owned by another user is refused (it was planted: rbi created its own);
- a read is capped: a sidecar linked to ``/dev/zero`` or grown to gigabytes is refused by its
  size before anything is allocated;
- new files are created exclusively (``O_CREAT | O_EXCL | O_NOFOLLOW``, or ``mkstemp`` in the
  target folder for temporary names), so no name another user could have planted is written.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import BinaryIO

from rbi.errors import InputError
from rbi.text import visible

NAME_MAX = 255
"""Longest file name (one path component), in bytes, on the file systems rbi writes to."""

_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_NONBLOCK = getattr(os, "O_NONBLOCK", 0)
_KEPT = getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_NOCTTY", 0)
"""Flags of every open here: not inherited by child processes, never the controlling terminal."""


def shown(path: str | os.PathLike) -> str:
    """A path as it may appear in a one-line message: hidden characters escaped by rbi's one
    escaper for the terminal (:func:`rbi.text.visible`)."""
    return visible(os.fspath(path))


def reason(exc: OSError) -> str:
    """Why an operation failed, in the system's words (``No space left on device``), also for
    the OSErrors of libraries that only put the errno in their message (pyarrow)."""

    number = exc.errno
    if not number:
        found = re.search(r"\[errno (\d+)\]", str(exc), re.IGNORECASE)
        number = int(found[1]) if found else None
    return os.strerror(number) if number else (exc.strerror or str(exc))


_KINDS = (
    (stat.S_ISLNK, "symbolic link"),
    (stat.S_ISDIR, "folder"),
    (stat.S_ISCHR, "device"),
    (stat.S_ISBLK, "device"),
    (stat.S_ISFIFO, "FIFO (named pipe)"),
    (stat.S_ISSOCK, "socket"),
)


def kind(mode: int) -> str:
    """What a file of this ``st_mode`` is, in words."""
    return next((name for test, name in _KINDS if test(mode)), "special file")


def existing_regular(path: str | os.PathLike, what: str, *, own: bool = True) -> bool:
    """Whether a regular file (of this user, when ``own``) stands at ``path`` (False: nothing
    there). InputError for anything else there: a symbolic link (never followed), a FIFO, a
    device, a socket, a folder, or a file of another user. ``what`` prefixes the message."""
    info = standing(path, what)
    if info is not None:
        check_regular(info, path, what, own=own)
    return info is not None


def open_regular(path: str | os.PathLike, what: str, flags: int = os.O_RDONLY, mode: int = 0o777) -> int:
    """A descriptor of the existing regular file at ``path`` (or one created with ``mode``, when
    ``flags`` has ``O_CREAT``), opened with ``flags`` without following a link or blocking;
    InputError for anything else (see :func:`existing_regular`). The caller closes it."""
    try:
        fd = os.open(path, flags | _NOFOLLOW | _NONBLOCK | _KEPT, mode)
    except FileNotFoundError:
        raise InputError(f"{what}: does not exist") from None
    except OSError as exc:
        if exc.errno in (errno.ELOOP, errno.EMLINK):
            raise InputError(f"{what}: is a symbolic link; rbi never follows one here") from None
        if exc.errno == errno.ENXIO:  # a FIFO opened for writing with no reader
            raise InputError(
                f"{what}: is a {kind(stat.S_IFIFO)}, not a regular file; rbi will not use it"
            ) from None
        raise InputError(f"{what}: cannot open: {reason(exc)}") from None
    return _checked(fd, lambda info: check_regular(info, path, what))


def _checked(fd: int, check: Callable[[os.stat_result], None]) -> int:
    """``fd`` once ``check`` passed its open file's ``fstat`` (else ``fd`` is closed and the
    error raised), set back to blocking."""
    try:
        check(os.fstat(fd))
        if _NONBLOCK:
            os.set_blocking(fd, True)
    except BaseException:
        os.close(fd)
        raise
    return fd


def _read_at_most(fd: int, limit: int) -> bytes | None:
    """All bytes of the open file ``fd``, or None when it holds more than ``limit`` (its size
    is checked first, and the read stops one byte past ``limit`` for a file that grows)."""
    if os.fstat(fd).st_size > limit:
        return None
    chunks, size = [], 0
    while size <= limit:
        block = os.read(fd, min(limit + 1 - size, 1 << 24))
        if not block:
            break
        chunks.append(block)
        size += len(block)
    return None if size > limit else b"".join(chunks)


def read_capped(path: str | os.PathLike, limit: int, what: str) -> bytes:
    """The bytes of the regular file at ``path`` that rbi wrote itself (a sidecar: never a link,
    of this user), at most ``limit`` of them; InputError when it holds more or is anything else."""
    fd = open_regular(path, what)
    try:
        data = _read_at_most(fd, limit)
    finally:
        os.close(fd)
    if data is None:
        raise InputError(f"{what}: is larger than the {limit:,} bytes rbi writes there; not read")
    return data


class InputFileRefused(ValueError):
    """Why an input file was not read, as one phrase without its path (the caller names it)."""


def read_input_file(path: str | os.PathLike, limit: int, what: str, hint: str = "") -> bytes:
    """The bytes of an input file a user named, at most ``limit`` of them, opened and refused as
    :func:`open_input_file` says (and refused again while reading one that grows past ``limit``)."""
    with open_input_file(path, what, limit, hint) as stream:
        try:
            data = _read_at_most(stream.fileno(), limit)
        except OSError as exc:
            raise InputFileRefused(f"cannot read: {reason(exc)}") from None
    if data is None:
        raise InputFileRefused(_too_large(what, f"more than {limit:,} bytes", limit, hint))
    return data


def open_input_file(path: str | os.PathLike, what: str, limit: int | None = None, hint: str = "") -> BinaryIO:
    """An input file a user named (a ``what``: ``"spec"``, ``"mesh"``, ``"robot file"``; links
    are followed, since users link their own files), open for reading in binary (the caller
    closes it: ``with``). Refused before a byte is read, and without blocking, checking the open
    file itself: a missing file, a folder, FIFO, device or socket, and a file larger than
    ``limit`` by its size (``hint`` is added to that message). :class:`InputFileRefused` says why."""
    try:
        fd = os.open(path, os.O_RDONLY | _NONBLOCK | _KEPT)
    except FileNotFoundError:
        raise InputFileRefused("no such file") from None
    except OSError as exc:
        raise InputFileRefused(f"cannot read: {reason(exc)}") from None
    except ValueError:  # os.open's 'embedded null byte'
        raise InputFileRefused("not a usable path (it contains a NUL character)") from None

    def check(info: os.stat_result) -> None:
        if not stat.S_ISREG(info.st_mode):
            noun = what if what.endswith("file") else f"{what} file"
            raise InputFileRefused(f"not a regular file but a {kind(info.st_mode)}; give a {noun}")
        if limit is not None and info.st_size > limit:
            raise InputFileRefused(_too_large(what, f"{info.st_size:,} bytes", limit, hint))

    try:
        return os.fdopen(_checked(fd, check), "rb")
    except OSError as exc:
        raise InputFileRefused(f"cannot read: {reason(exc)}") from None


def _too_large(what: str, size: str, limit: int, hint: str) -> str:
    return f"file too large for a {what} ({size}; rbi reads at most {limit:,}{hint})"


def create_exclusive(path: str | os.PathLike, what: str, mode: int = 0o666) -> int:
    """A descriptor (read and write) of a new file created at ``path``: ``O_CREAT | O_EXCL |
    O_NOFOLLOW``, so nothing that already stands there (a planted link or file) is ever
    written. ``mode`` is reduced by the umask. InputError when the name is taken."""
    with creating(what, "not written"):
        fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL | _NOFOLLOW | _KEPT, mode)
    return fd


@contextlib.contextmanager
def creating(what: str, unused: str = "not written") -> Iterator[None]:
    """Make a new file or folder in the block: a name already taken (``FileExistsError``) is an
    InputError ``what: something appeared at this path ...; unused``, any other OSError one
    ``what: cannot write: ...``."""
    try:
        yield
    except FileExistsError:
        raise InputError(
            f"{what}: something appeared at this path while rbi was creating it; {unused}"
        ) from None
    except OSError as exc:
        raise InputError(f"{what}: cannot write: {reason(exc)}") from None


def write_all(fd: int, data: bytes) -> None:
    """Write every byte of ``data`` to ``fd`` (``os.write`` may write fewer)."""
    view = memoryview(data)
    while view:
        written = os.write(fd, view)
        view = view[written:]


@contextlib.contextmanager
def replacing(
    path: str | os.PathLike, what: str, suffix: str = ".tmp", mode: int | None = None
) -> Iterator[tuple[int, str]]:
    """A new temporary file beside ``path`` (``mkstemp``: a private name, created exclusively),
    yielded as ``(descriptor, name)`` (the descriptor stays this function's to close; a writer
    may also open the file by its name); when the block ends without an exception it is flushed,
    given ``mode`` (default ``0666`` less the umask) and renamed over ``path``; otherwise it is
    removed and ``path`` is as it was. An OSError is an InputError ``what: cannot write: ...``."""
    folder = os.path.dirname(os.fspath(path)) or "."
    with creating(what):
        fd, temporary = tempfile.mkstemp(prefix=".rbi-", suffix=suffix, dir=folder)
    try:
        try:
            yield fd, temporary
            os.fsync(fd)
        finally:
            os.close(fd)
        os.chmod(temporary, 0o666 & ~_umask() if mode is None else mode)
        os.replace(temporary, path)
    except OSError as exc:
        remove(temporary)
        raise InputError(f"{what}: cannot write: {reason(exc)}") from None
    except BaseException:
        remove(temporary)
        raise


def replace_small(path: str | os.PathLike, data: bytes, what: str) -> None:
    """Put ``data`` at ``path`` atomically (see :func:`replacing`). Refuses (InputError) when
    something other than a regular file of this user stands at ``path``."""
    existing_regular(path, what)
    with replacing(path, what) as (fd, _):
        write_all(fd, data)


def remove(path: str | os.PathLike) -> None:
    """Remove the name ``path`` if it is there (a link is removed, never its target)."""
    with contextlib.suppress(FileNotFoundError, NotADirectoryError):
        os.unlink(path)


def existing_private_folder(path: str | os.PathLike, what: str) -> bool:
    """Whether a folder of this user (not a link to one) stands at ``path``; False when nothing
    does; InputError for anything else."""
    info = standing(path, what)
    if info is None:
        return False
    if not stat.S_ISDIR(info.st_mode):
        raise InputError(f"{what}: is a {kind(info.st_mode)}, not the folder rbi keeps there; not used")
    _check_owner(info, what)
    return True


def make_private_folder(path: str | os.PathLike, what: str) -> None:
    """Create the folder ``path`` readable by this user only (``mkdir`` is exclusive: a name
    already taken is an InputError, never reused)."""
    with creating(what, "not used"):
        os.mkdir(path, 0o700)


def remove_private_folder(path: str | os.PathLike) -> None:
    """Remove a folder made by :func:`make_private_folder` and what is in it, never following a
    link inside it."""

    if existing_private_folder(path, shown(path)):
        shutil.rmtree(path)


def beside(out: str | os.PathLike, suffix: str) -> Path:
    """The hidden file ``.NAME<suffix>`` in the folder of ``out`` (NAME: its file name). When
    that would pass the 255-byte limit of a file name, NAME is shortened to what fits and
    followed by ``~`` and 16 hex digits of its SHA-256, so each output keeps its own file."""

    out = Path(out)
    name = os.fsencode(out.name)
    candidate = b"." + name + os.fsencode(suffix)
    if len(candidate) <= NAME_MAX:
        return out.with_name(os.fsdecode(candidate))
    digest = b"~" + hashlib.sha256(name).hexdigest()[:16].encode()
    room = NAME_MAX - 1 - len(digest) - len(os.fsencode(suffix))
    cut = name[:room]
    while cut and len(cut) < len(name) and (name[len(cut)] & 0xC0) == 0x80:
        cut = cut[:-1]  # never split a UTF-8 character
    return out.with_name(os.fsdecode(b"." + cut + digest + os.fsencode(suffix)))


def check_regular(info: os.stat_result, path, what: str, *, own: bool = True) -> None:
    """InputError unless ``info`` (of ``path``) is a regular file (of this user, when ``own``)."""
    if not stat.S_ISREG(info.st_mode):
        raise InputError(
            f"{what}: is a {kind(info.st_mode)}, not a regular file; rbi will not read or replace it"
        )
    if own:
        _check_owner(info, what)


def _check_owner(info: os.stat_result, what: str) -> None:
    if hasattr(os, "geteuid") and info.st_uid != os.geteuid():
        raise InputError(f"{what}: belongs to another user (rbi created its own); not used")


def standing(path: str | os.PathLike, what: str) -> os.stat_result | None:
    """What stands at ``path`` (``lstat``: a link is not followed), or None when nothing does;
    any other OSError is an InputError ``what: cannot use this path: ...``."""
    try:
        return os.lstat(path)
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise InputError(f"{what}: cannot use this path: {reason(exc)}") from None


def _umask() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return umask
