"""Output files: every path a command writes is checked before any work and written
atomically, only once the run has succeeded.

The rules (see docs/security.md):

- ``-`` means standard output, for commands that can stream text there.
- The format follows the extension; an extension the command cannot write is refused.
- An existing path must be a regular file (or a symbolic link to one, which is written
  through: the link stays, its target is replaced). Devices, FIFOs, sockets, folders and
  dangling links are refused, as are the input spec and a path named twice in one run.
- The file is written to a temporary file in the same folder, then renamed over the target,
  so a reader never sees half a file and a failed or interrupted run leaves nothing behind.
  A new file gets the ordinary permissions (``0666`` less the umask); a replaced file keeps
  its mode.
- One run writes a file at a time: the write and the rename hold the lock ``rbi sweep`` holds
  while it streams rows there (:mod:`rbi.files.lock`, the file ``.NAME.rbi-lock``, removed
  after). A run on an output another run is writing is refused when the path is checked, before
  any work, or at the latest before it writes.

Every refusal is an :class:`rbi.errors.InputError` (exit 2, one line).
"""

from __future__ import annotations

import contextlib
import os
import stat
import sys
import tempfile
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import IO

from rbi.errors import InputError
from rbi.files import lock
from rbi.files.safe import NAME_MAX, creating, remove, replacing, standing
from rbi.files.safe import kind as _kind
from rbi.files.safe import shown as _shown

STDOUT = "-"
STDOUT_ALIASES = ("/dev/stdout", "/dev/fd/1", "/proc/self/fd/1")
"""Paths that name standard output itself: written as a stream like ``-`` (replacing them
would need root, and would replace the device rather than print)."""


@dataclass(frozen=True)
class OutputTarget:
    """A checked output path. ``path``: where the bytes go (a link's target already resolved);
    ``given``: the path as the user wrote it; ``option``: the option that named it;
    ``format``: the extension without its dot, lower case (``"csv"``, ``"png"`` ...), or
    the command's stream format for standard output."""

    given: str
    path: str
    option: str
    format: str

    @property
    def is_stdout(self) -> bool:
        return self.given == STDOUT


Destination = str | os.PathLike[str] | OutputTarget
"""Where a picture or a file of rows goes: a path (its extension gives the format), or a target
`output_target` has already checked (a caller's own messages then name it)."""


def output_target(
    path: str,
    option: str,
    formats: Sequence[str],
    *,
    inputs: Sequence[str] = (),
    stdout_format: str | None = None,
) -> OutputTarget:
    """Check one output path before any work is done; :class:`InputError` if rbi must not
    (or cannot) write there.

    formats: extensions the command can write, without dots (``("csv",)``). inputs: files the
    run reads (the spec), which are never overwritten. stdout_format: the format written for
    ``-``; None when the command cannot stream to standard output.
    """
    if path == STDOUT or path in STDOUT_ALIASES:
        if stdout_format is None:
            raise InputError(f"{option}: this output cannot go to standard output ({path!r}); name a file")
        return OutputTarget(STDOUT, STDOUT, option, stdout_format)
    if not path or not path.strip():
        raise InputError(f"{option}: the path is empty")
    if "\0" in path:
        raise InputError(f"{option}: the path contains a NUL character")
    shown = _shown(path)
    for part in path.split(os.sep):
        if len(os.fsencode(part)) > NAME_MAX:
            raise InputError(f"{option}: {shown}: a file or folder name is longer than {NAME_MAX} bytes")
    real = _resolved(path, option)
    extension = os.path.splitext(path)[1].lower().lstrip(".")
    if extension not in formats:
        wanted = ", ".join("." + f for f in formats)
        got = f"'.{extension}'" if extension else "no extension"
        raise InputError(f"{option}: {shown}: cannot write {got} (this output is written as {wanted})")
    folder = os.path.dirname(real) or "."
    if not os.path.isdir(folder):
        raise InputError(f"{option}: {shown}: folder {_shown(folder)} does not exist")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise InputError(f"{option}: {shown}: folder {_shown(folder)} is not writable")
    _probe(folder, option, shown)
    for source in inputs:
        if _same_file(real, source):
            raise InputError(
                f"{option}: {shown}: is an input of this run ({_shown(source)}); "
                "rbi never overwrites its input"
            )
    lock.check_free(real, f"{option}: {shown}")
    return OutputTarget(path, real, option, extension)


def check_distinct(targets: Sequence[OutputTarget | None]) -> None:
    """InputError when two outputs of one run name the same file (only one would survive)."""
    seen: dict[str, OutputTarget] = {}
    for target in targets:
        if target is None or target.is_stdout:
            continue
        key = os.path.normcase(os.path.abspath(target.path))
        if key in seen:
            first = seen[key]
            raise InputError(
                f"{target.option}: {_shown(target.given)}: is also the {first.option} output of "
                "this run; give each output its own file"
            )
        seen[key] = target


@contextlib.contextmanager
def atomic_path(target: OutputTarget) -> Iterator[str]:
    """A temporary path beside the target for a writer that wants a file name (matplotlib,
    pillow); renamed over the target when the block ends without an exception, removed
    otherwise. The target's lock is held throughout (InputError, exit 2, when another run
    holds it; kept as it is when this thread holds it: a sweep writing its own output)."""
    if target.is_stdout:
        raise ValueError("a path writer cannot write to standard output: atomic_path needs a file target")
    what = f"{target.option}: {_shown(target.given)}"
    with (
        lock.writing(target.path, what),
        replacing(target.path, what, suffix="." + target.format, mode=_mode_for(target.path)) as (_, temp),
    ):
        yield temp  # the writer opens the file by its name


@contextlib.contextmanager
def open_output(target: OutputTarget, binary: bool = False) -> Iterator[IO]:
    """A file object to stream the output into (standard output for ``-``); the file appears
    at the target only when the block ends without an exception."""
    if target.is_stdout:
        stream = sys.stdout.buffer if binary else sys.stdout
        yield stream
        stream.flush()
        return
    with atomic_path(target) as temp:
        mode = "wb" if binary else "w"
        with open(temp, mode, **({} if binary else {"encoding": "utf-8", "newline": ""})) as handle:
            yield handle


def write_output(
    target: OutputTarget, content: str | bytes | None = None, writer: Callable[[str], None] | None = None
) -> None:
    """Write ``content`` (text or bytes), or let ``writer(temp_path)`` write the file, to the
    target atomically."""
    if writer is not None:
        with atomic_path(target) as temp:  # ValueError for standard output
            writer(temp)
        return
    with open_output(target, binary=isinstance(content, bytes)) as handle:
        handle.write("" if content is None else content)


def _resolved(path: str, option: str) -> str:
    """The file the bytes will land in: ``path`` itself, or a symbolic link's final target
    when that is a regular file. Refuses anything else that already stands there."""
    shown = _shown(path)
    info = standing(path, f"{option}: {shown}")
    if info is None:
        return os.path.abspath(path)
    link = stat.S_ISLNK(info.st_mode)
    real = os.path.realpath(path) if link else os.path.abspath(path)
    if link:
        try:
            info = os.stat(real)
        except OSError:
            raise InputError(
                f"{option}: {shown}: is a symbolic link to nothing; rbi writes only to regular files"
            ) from None
    if not stat.S_ISREG(info.st_mode):
        raise InputError(
            f"{option}: {shown}: is a {'symbolic link to a ' * link}{_kind(info.st_mode)}, not a regular "
            "file; rbi will not replace it"
        )
    return real


def _probe(folder: str, option: str, shown: str) -> None:
    """Create and remove an empty temporary file in ``folder``: proves before any work that the
    output can be written there (``os.access`` says yes to root even on /sys or a read-only
    file system)."""
    with creating(f"{option}: {shown}"):
        fd, temp = tempfile.mkstemp(prefix=".rbi-", suffix=".probe", dir=folder)
    os.close(fd)
    remove(temp)


def _same_file(a: str, b: str) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.realpath(a) == os.path.realpath(b)


def _mode_for(path: str) -> int | None:
    """Permissions for the file about to be written: those of the file it replaces, or None
    for a new one (:func:`rbi.files.safe.replacing` gives it ``0666`` less the umask)."""
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        return None
