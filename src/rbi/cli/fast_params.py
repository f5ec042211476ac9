"""Cheap coercion of command-line values, so that a command does not build a pydantic
``TypeAdapter`` for each of its options on every run.

typer (0.2x) coerces every parameter of the command that runs, given or not, through a pydantic
``TypeAdapter`` built while parsing; importing typer's adapter module and building the adapters
costs about as much as the command's own work (see docs/performance.md). rbi's options are plain
``str``, ``int``, ``float``, ``bool``, ``list[str]`` and enums: for a value that is plainly one of
those (a ``str``, a decimal number, a choice spelled as listed), :class:`FastParam` returns what
typer's adapter would return; for anything else (an error, an unusual spelling) it builds typer's
own coercion and hands the value to it, so messages and edge cases stay typer's.
``tests/cli/test_fast_params.py`` compares both on many inputs.

If typer's internals change (no ``_runtime_param`` slot), :func:`install` does nothing and typer
coerces as it always did.
"""

from __future__ import annotations

import os
import re
from enum import Enum
from typing import Any

_DECIMAL_INT = re.compile(r"[+-]?(?:0|[1-9][0-9]*)\Z")
_DECIMAL_FLOAT = re.compile(r"[+-]?[0-9]+(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?\Z")


def quiet_pydantic_plugins() -> None:
    """Skip pydantic's plugin discovery (a scan of every installed package's entry points, paid
    when the first model class is built); rbi uses no pydantic plugin. A value the user set
    stays.

    With every plugin disabled, pydantic's plugin loader answers "no plugins" without looking,
    yet importing it imports :mod:`importlib.metadata` (and the ``email`` package), about a
    fifth of ``import numpy``'s time; the loader is then replaced, before its first use, by a
    module whose ``get_plugins`` gives that same answer. A pydantic whose plugin machinery
    differs (no ``pydantic.plugin._loader``) is left alone."""
    import sys

    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "1")
    name = "pydantic.plugin._loader"
    if os.environ["PYDANTIC_DISABLE_PLUGINS"] not in ("__all__", "1", "true") or name in sys.modules:
        return
    import importlib.util

    try:
        found = importlib.util.find_spec(name) is not None
    except ImportError:
        found = False
    if found:
        import types

        loader = types.ModuleType(
            name, "pydantic's plugin loader while every plugin is disabled (rbi.cli.fast_params)"
        )
        loader.get_plugins = lambda: ()
        sys.modules[name] = loader


def _fast(annotation: Any, parameter_info: Any, value: Any, ctx: Any) -> tuple[bool, Any]:
    """``(True, coerced)`` when ``value`` is plainly of the annotation's type, else
    ``(False, None)`` (typer's own coercion decides)."""
    if annotation is str:
        return (True, value) if isinstance(value, str) else (False, None)
    if annotation is float:
        if type(value) is float:
            return True, value
        if type(value) is int:
            return True, float(value)
        if isinstance(value, str) and _DECIMAL_FLOAT.match(value):
            return True, float(value)
        return False, None
    if annotation is int:
        if type(value) is int:
            return True, value
        if isinstance(value, str) and _DECIMAL_INT.match(value):
            return True, int(value)
        return False, None
    if annotation is bool:
        return (True, value) if isinstance(value, bool) else (False, None)
    if isinstance(annotation, type) and issubclass(annotation, Enum):
        if isinstance(value, annotation):
            return True, value
        if isinstance(value, str):
            from typer._param_types import coerce_cli_choice

            try:
                return True, coerce_cli_choice(
                    value, choices=list(annotation), case_sensitive=parameter_info.case_sensitive, ctx=ctx
                )
            except ValueError:
                return False, None
        return False, None
    if annotation == list[str]:
        if isinstance(value, (list, tuple)) and all(isinstance(item, str) for item in value):
            return True, list(value)
        return False, None
    return False, None


def _runtime_param_class():
    from dataclasses import dataclass, field

    from typer._coercion import RuntimeParam, build_runtime_param

    @dataclass(frozen=True)
    class FastParam(RuntimeParam):
        """typer's ``RuntimeParam`` with a fast path; typer's own coercion for the rest."""

        descriptor: Any = None
        fallback: list = field(default_factory=list)  # typer's coercion, built when first needed

        def _coerce_value(self, value, param, ctx):
            if self.parameter_info.parser is None:
                done, coerced = _fast(self.annotation, self.parameter_info, value, ctx)
                if done:
                    return coerced
            if not self.fallback:
                self.fallback.append(build_runtime_param(self.descriptor))
            return self.fallback[0]._coerce_value(value, param=param, ctx=ctx)

    return FastParam


def install(command, ctx=None) -> None:
    """Give every typer parameter of ``command`` (a click command built by typer) the fast
    coercion, its help option included (made now from ``ctx``'s help option names, as the
    command's own context inherits them); parameters with a file type are left to typer."""
    params = list(getattr(command, "params", ()))
    if ctx is not None and hasattr(command, "get_help_option"):
        params.append(command.get_help_option(ctx))
    params = [
        p
        for p in params
        if getattr(p, "_runtime_param", 0) is None and getattr(p, "type_descriptor", None) is not None
    ]
    if not params:
        return
    try:
        fast_param = _runtime_param_class()
    except ImportError:
        return
    for param in params:
        descriptor = param.type_descriptor
        if descriptor.file_annotation is None:
            param._runtime_param = fast_param(
                annotation=descriptor.annotation,
                parameter_info=descriptor.parameter_info,
                descriptor=descriptor,
            )
