"""Where results are written: an output path checked by rbi's one checked writer (:mod:`rbi.files.output`)."""

from __future__ import annotations

import contextlib
import difflib
import functools
import inspect
import os
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, ParamSpec, TypeVar

from rbi.errors import ArgumentError, InputError, SpecError, literal
from rbi.files.output import Destination, OutputTarget, check_distinct, output_target

if TYPE_CHECKING:  # a Body is known by its files_read: `rbi audit` loads no spec modules
    from rbi.api.body import Body


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
    with as_parameter(name):
        return output_target(given, name, formats, inputs=reads)


@contextlib.contextmanager
def as_parameter(name: str) -> Iterator[None]:
    """A refusal of rbi's checked writer, which names an output as `checked_output` named it
    (by parameter: ``plot: ...``), as the `ArgumentError` of ``name`` (a caller then spells it
    as its own: the CLI's ``--plot``); any other error passes as it is."""
    try:
        yield
    except ArgumentError:
        raise
    except SpecError as exc:
        if not str(exc).startswith(f"{name}: "):
            raise
        raise ArgumentError(name, literal(str(exc).removeprefix(f"{name}: "), quoted=False)) from None


PLOT_FORMATS = ("png", "svg", "pdf")
"""The forms of a run's or a sweep's plot (its ``plot``)."""


def out_and_plot(
    out: Destination | None, plot: Destination | None, out_formats: tuple[str, ...], read: str | Body
) -> tuple[OutputTarget | None, OutputTarget | None]:
    """A run's ``out`` (one of ``out_formats``) and ``plot`` (:data:`PLOT_FORMATS`), each
    checked by `checked_output` against ``read`` (None where not asked for), before any work;
    ArgumentError naming ``plot`` when it is the file ``out`` names too (a link to it)."""
    targets = (
        None if out is None else checked_output(out, out_formats, read, "out"),
        None if plot is None else checked_output(plot, PLOT_FORMATS, read, "plot"),
    )
    try:
        check_distinct(targets)
    except InputError:
        shown = literal(targets[1].given, quoted=False)  # type: ignore[union-attr]
        raise ArgumentError(
            "plot", f"{shown}: is also the {{out}} output of this run; give each output its own file"
        ) from None
    return targets


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
