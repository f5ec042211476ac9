"""The error every layer raises for bad input.

:class:`SpecError` (public as ``rbi.SpecError``; ``InputError`` is the same class, the name
the layers below the API use) is bad input from the user: a spec file, a
robot file, a mesh, or a command-line value. ``str(error)`` is one line,
``file: part: field: what is wrong``, which the CLI prints before exiting with status 2.
It lives here, below every other layer, so that file readers (:mod:`rbi.formats`), the spec
layer and the API all raise the same type.
"""

from __future__ import annotations

import math
import re
import reprlib
from collections.abc import Callable, Iterable
from typing import Any


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


class ArgumentError(SpecError, ValueError):
    """A bad argument of a public function (``rbi.simulate(body, duration=-1)``):
    a :class:`ValueError` (and a :class:`SpecError`, so the CLI prints it on one line, exit 2).

    ``parameters`` names the argument(s) as the Python API spells them (``duration``,
    ``spin_axis``; none: the message does not start with a name); ``item`` a key inside one (a
    varied spec path); ``detail`` says what is wrong and may name parameters as ``{name}`` (or
    ``{name=VALUE}``); ``file``, when given, starts the message. ``str(error)`` speaks the API's names
    (``duration: must be ...``); :meth:`named` spells them as a caller's own (the CLI's options).
    """

    def __init__(
        self,
        parameters: str | tuple[str, ...],
        detail: str,
        *,
        item: str | None = None,
        file: str | None = None,
    ) -> None:
        self.parameters = (parameters,) if isinstance(parameters, str) else tuple(parameters)
        self.detail = detail
        self.item = item
        super().__init__(
            self.named(api_name), file=file, field=self.parameters[0] if self.parameters else None
        )
        self.where = file

    def __str__(self) -> str:
        return self.named(api_name)

    def named(self, name: Callable[[str], str]) -> str:
        """The message with each parameter spelled ``name(parameter)``; an ``item`` follows its
        parameter as ``name(parameter + "[]")`` formats it (``{}`` stands for the item)."""
        detail = _PLACEHOLDER.sub(lambda m: name(m[1]) if m[1] else m[0][0], self.detail)
        where = f"{self.where}: " if getattr(self, "where", None) else ""
        if not self.parameters:
            return where + detail
        if self.item is None:
            head = " and ".join(name(p) for p in self.parameters)
        else:
            head = name(self.parameters[0] + "[]").format(self.item)
        return f"{where}{head}: {detail}"


_PLACEHOLDER = re.compile(r"\{\{|\}\}|\{([A-Za-z_]\w*(?:=[^{}]*)?)\}")
"""In an :class:`ArgumentError` detail: ``{{`` and ``}}`` (a brace as written) or ``{name}`` /
``{name=VALUE}`` (a parameter); any other brace is text (a value that was not passed through
:func:`literal`, such as ``{0}`` or a dict's repr, prints as it is instead of breaking the message)."""


def shown(value: Any, width: int = 40) -> str:
    """``value`` for a message in at most ``width`` characters, built without walking all of a
    large list or mapping (a value shared through YAML aliases may stand for millions), on one
    line; an integer no double holds is told by its number of digits."""

    if isinstance(value, int) and value.bit_length() > 64:  # too long to print (or to convert)
        return f"an integer of {int(value.bit_length() * math.log10(2)) + 1} digits"
    shorter = reprlib.Repr()
    shorter.maxlevel, shorter.maxlist, shorter.maxdict = 3, 4, 4
    shorter.maxstring = shorter.maxother = max(width, 12)
    text = re.sub(r"\s*\n\s*", " ", shorter.repr(value))  # one line (a numpy array's repr has several)
    return text if len(text) <= width else text[: width - 3] + "..."


def literal(value: object, quoted: bool = True) -> str:
    """:func:`shown` ``value`` (up to 200 characters; ``str(value)`` when not ``quoted``) for an
    :class:`ArgumentError` detail, its braces doubled so they print as written (single braces
    name parameters)."""
    text = shown(value, 200) if quoted else str(value)
    return text.replace("{", "{{").replace("}", "}}")


def one_of(parameter: str, value: object, choices: Iterable[str]) -> None:
    """ArgumentError naming ``parameter`` unless ``value`` is one of the strings ``choices``
    (a list or a dict given instead is refused, not looked up: it is no key of a dict)."""
    if not (isinstance(value, str) and value in choices):
        raise ArgumentError(parameter, f"expected one of {', '.join(choices)}, got {literal(value)}")


def api_name(parameter: str) -> str:
    """How the Python API spells a parameter in messages (an item as ``vary['PATH']``)."""
    return parameter[:-2] + "[{!r}]" if parameter.endswith("[]") else parameter
