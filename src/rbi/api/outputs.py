"""Where results are written: an output path checked by rbi's one checked writer (:mod:`rbi.files.output`)."""

from __future__ import annotations

import difflib
import functools
import inspect
import os
from collections.abc import Callable
from typing import TYPE_CHECKING, ParamSpec, TypeVar

from rbi.errors import ArgumentError, InputError, SpecError, literal
from rbi.files.output import OutputTarget, check_distinct, output_target

if TYPE_CHECKING:  # a Body is known by its files_read: `rbi audit` loads no spec modules
    from rbi.api.body import Body

Destination = str | os.PathLike[str] | OutputTarget
"""Where a picture or a file of rows goes: a path (its extension gives the format), or a target
`output_target` has already checked (a caller's own messages then name it)."""


def checked_output(
    path: Destination,
    formats: tuple[str, ...],
    read: str | os.PathLike[str] | Body,
    name: str = "path",
) -> OutputTarget:
    """``path`` checked as an output of one of ``formats`` (its extension) by rbi's one checked
    writer (:mod:`rbi.files.output`): never the file ``read`` (a spec, a robot file), nor for a
    `Body` any file it was read from (`Body.files_read`: a target checked before the body was
    loaded is checked against them now, its refusal naming its option). ArgumentError naming
    the parameter ``name`` when it may not be written there."""
    is_body = hasattr(read, "files_read")
    reads = read.files_read if is_body else [os.fsdecode(os.fspath(read))]  # type: ignore[union-attr, arg-type]
    if isinstance(path, OutputTarget):
        if is_body and not path.is_stdout:
            output_target(path.given, path.option, (path.format,), inputs=reads)
        return path
    given = path_text(path, name)
    try:
        return output_target(given, name, formats, inputs=reads)
    except ArgumentError:
        raise
    except SpecError as exc:
        raise ArgumentError(name, literal(str(exc).removeprefix(f"{name}: "), quoted=False)) from None


def distinct_out_and_plot(out: OutputTarget | None, plot: OutputTarget | None) -> None:
    """ArgumentError naming ``plot`` when it is the file ``out`` names too (a link to it)."""
    try:
        check_distinct([out, plot])
    except InputError:
        shown = literal(plot.given, quoted=False)  # type: ignore[union-attr]
        raise ArgumentError(
            "plot", f"{shown}: is also the {{out}} output of this run; give each output its own file"
        ) from None


def path_text(value: object, name: str = "robot_file") -> str:
    """``value`` as a str path; TypeError naming the parameter ``name`` for anything but a path."""
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{name}: expected a path (str or os.PathLike), got {type(value).__name__}")
    return os.fsdecode(os.fspath(value))


P = ParamSpec("P")
R = TypeVar("R")


def keywords_checked(function: Callable[P, R]) -> Callable[P, R]:
    """``function`` that answers a misspelt keyword with the parameter it resembles:
    ``rbi.sweep(body, tilt=1)`` is TypeError ``sweep() got an unexpected keyword argument
    'tilt' (did you mean 'tilt_deg'?)`` (Python's own error says only the first half)."""
    known = list(inspect.signature(function).parameters)

    @functools.wraps(function)
    def checked(*args: P.args, **kwargs: P.kwargs) -> R:
        for keyword in kwargs:
            if keyword not in known:
                hint = difflib.get_close_matches(keyword, known, n=1)
                raise TypeError(
                    f"{function.__name__}() got an unexpected keyword argument {keyword!r}"
                    + (f" (did you mean {hint[0]!r}?)" if hint else "")
                )
        return function(*args, **kwargs)

    return checked
