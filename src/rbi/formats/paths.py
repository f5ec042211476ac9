"""Files a spec names (``point_cloud.file``, ``mesh.file``): where they are, and whether rbi may
read them.

A path in a spec is relative to the spec's own folder. One that leaves that folder (an absolute
path, a ``..`` that climbs out, or a symlink that points out) is refused unless the user asked
for it with ``--allow-outside-paths``: a spec from somebody else must not make rbi read
``/etc/shadow`` or ``/proc/self/environ``. Messages name the path as written in the spec, never
anything read from the file.
"""

from __future__ import annotations

import contextlib
import contextvars
from pathlib import Path

from rbi.errors import InputError

ALLOW_OUTSIDE_FLAG = "--allow-outside-paths"

_outside_allowed: contextvars.ContextVar[bool] = contextvars.ContextVar(
    "rbi_outside_paths_allowed", default=False
)


@contextlib.contextmanager
def outside_paths_allowed(allowed: bool = True):
    """Within this block, spec paths may leave the spec's folder (the CLI's
    ``--allow-outside-paths``)."""
    token = _outside_allowed.set(bool(allowed))
    try:
        yield
    finally:
        _outside_allowed.reset(token)


def outside_paths_are_allowed() -> bool:
    """Whether this block lets spec paths leave the spec's folder (see
    :func:`outside_paths_allowed`)."""
    return _outside_allowed.get()


def outside_paths_setting(allow_outside_paths: bool | None) -> bool:
    """A public function's ``allow_outside_paths``: True or False, or None for what the enclosing
    :func:`outside_paths_allowed` block says; TypeError naming it for anything else (the text
    ``"no"`` is no False that would let a spec read any file)."""
    if allow_outside_paths is None:
        return outside_paths_are_allowed()
    if not isinstance(allow_outside_paths, bool):
        raise TypeError(f"allow_outside_paths: must be True, False or None (got {allow_outside_paths!r:.60})")
    return allow_outside_paths


def spec_relative_file(spec_path: str | Path, file: str, label: str, owner: str = "spec") -> Path:
    """The file named ``file`` in the spec at ``spec_path``, resolved against the spec's folder.

    ``label`` prefixes every message (for instance ``top.yaml: point_cloud: file: c.csv``);
    ``owner`` names the file whose folder it is (``spec``, ``robot file``).
    Raises :class:`InputError` when the path leaves the spec's folder and that was not allowed,
    or when nothing (or not a regular file) is there.
    """
    if "\x00" in file:
        raise InputError(f"{label}: not a usable path (it contains a NUL character)")
    folder = Path(spec_path).parent
    named = Path(file)
    candidate = named if named.is_absolute() else folder / named
    if not _outside_allowed.get():
        if named.is_absolute() or not inside(candidate, folder):
            raise InputError(
                f"{label}: the path leaves the {owner}'s folder (absolute, '..' or a symlink out of it); "
                f"rbi reads only files beside the {owner} unless given {ALLOW_OUTSIDE_FLAG}"
            )
    try:
        is_file = candidate.is_file()
        exists = is_file or candidate.exists()
    except OSError:
        is_file = exists = False
    if not is_file:
        raise InputError(f"{label}: " + ("not a regular file" if exists else "no such file"))
    return candidate


def inside(path: Path, folder: Path) -> bool:
    """Does ``path`` resolve to a place inside ``folder`` (False for a symlink loop, or a path
    the OS cannot resolve)?"""
    try:
        return path.resolve().is_relative_to(folder.resolve())
    except (OSError, RuntimeError):
        return False


def file_key(path: Path) -> tuple:
    """What a cache of files read keys a file by: its resolved path, size (bytes) and
    modification time (ns); ValueError (``cannot read: ...``) when it cannot be looked at."""
    try:
        status = path.stat()
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or type(exc).__name__}") from None
    return (str(path.resolve()), status.st_size, status.st_mtime_ns)
