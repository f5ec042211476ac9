"""The error every layer raises for bad input.

:class:`SpecError` (public as ``rbi.SpecError``; ``InputError`` is the same class, the name
the layers below the API use) is bad input from the user: a spec file, a
robot file, a mesh, or a command-line value. ``str(error)`` is one line,
``file: part: field: what is wrong``, which the CLI prints before exiting with status 2.
It lives here, below every other layer, so that file readers (:mod:`rbi.formats`), the spec
layer and the API all raise the same type.
"""

from __future__ import annotations


class SpecError(Exception):
    """Bad input from the user. ``str(self)`` is the one-line message the CLI prints (exit 2).

    ``file``, ``part`` and ``field`` name where the problem is, when known (None otherwise).
    """

    def __init__(
        self, message: str = "", *, file: str | None = None, part: str | None = None, field: str | None = None
    ) -> None:
        super().__init__(message)
        self.file = file
        self.part = part
        self.field = field


InputError = SpecError
"""The same class as :class:`SpecError` (a traceback and ``repr`` say ``SpecError``, the name
users of ``rbi`` catch)."""
