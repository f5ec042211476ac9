"""The options commands share, as typer declares them (their values are parsed in
:mod:`rbi.cli.option_values`, which needs no typer), and the optional packages some options
need: how --help says so (:func:`needs`) and the refusal, before any work, when one is missing."""

from __future__ import annotations

import importlib.util
import logging
from enum import Enum
from typing import Annotated, Any

import typer
from typer.core import TyperArgument

from rbi import SpecError


def option(kind: Any, *names: str, **settings: Any) -> Any:
    """An option as a command's parameter type, ``Annotated[kind, typer.Option(*names,
    **settings)]``: declared once here or in a command's module and used as ``name: Option =
    default`` (typer reads the annotation when the command runs)."""
    return Annotated[kind, typer.Option(*names, **settings)]


def argument(kind: Any, help: str, metavar: str) -> Any:
    """A positional argument as a command's parameter type (see :func:`option`)."""
    return Annotated[kind, typer.Argument(help=help, show_default=False, metavar=metavar)]


class OutputFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


FormatOption = option(
    OutputFormat, "--format", "-f", help="table (for people), json (one object) or csv (header + rows)."
)


class DocumentFormat(str, Enum):
    """The forms of a command that prints one JSON document (`rbi schema`): no CSV."""

    table = "table"
    json = "json"


DocumentFormatOption = option(
    DocumentFormat, "--format", "-f", help="table (indented JSON, for people) or json (on one line)."
)
SpecFile = argument(str, "Body spec (YAML or JSON); - reads it from standard input.", "FILE")
SpecFiles = argument(
    list[str],
    "Body specs (YAML or JSON), one or more (shell globs expand to several); - reads one from standard input.",
    "FILE...",
)
RobotFile = argument(str, "Robot description: .urdf, .sdf or MJCF (.xml).", "ROBOT_FILE")
PackagePathOption = option(
    list[str] | None,
    "--package-path",
    metavar="NAME=DIR",
    help="Folder of ROS package NAME, for package://NAME/ mesh paths; repeat for several "
    "(ROS_PACKAGE_PATH is searched too).",
)
AboutOption = option(
    str,
    "--about",
    "-a",
    metavar="com|origin|pivot|X,Y,Z",
    help="Reference point: com, origin, pivot, or X,Y,Z in body coordinates (file units).",
)
UnitsOption = option(
    str | None,
    "--units",
    "-u",
    metavar="SI|LENGTH,MASS",
    help="Report results in other units: SI (m, kg) or e.g. mm,g. Default: the spec file's "
    "units. Numbers given on the command line (an --about X,Y,Z point) stay in the file's units.",
)


def plain_argument_help(command) -> None:
    """Show ``command``'s positional arguments by their metavar alone: ``rbi inertia
    [OPTIONS] FILE`` rather than ``{FILE}`` in the usage line and ``FILE <str>`` in the list."""

    for param in command.params:
        if isinstance(param, TyperArgument) and param.metavar is not None:
            param.__class__ = _PlainArgument


class _PlainArgument(TyperArgument):
    def _usage_display_name(self) -> str:
        name = self.metavar if self.required else f"[{self.metavar}]"
        return name if self.nargs == 1 or self.metavar.endswith("...") else name + "..."

    def display_type_rich(self, ctx) -> None:
        return None


def needs(package: str, extra: str) -> str:
    """``needs matplotlib: pip install '.[plot]' in rbi's source folder``."""
    return f"needs {package}: pip install '.[{extra}]' in rbi's source folder"


def require_matplotlib(option: str = "--plot") -> None:
    """Refuse ``option`` (the one that asked for a picture) with the install command when
    matplotlib is missing."""
    # matplotlib logs two lines on stderr when XDG_CACHE_HOME or MPLCONFIGDIR cannot be written,
    # and then draws all the same in a temporary cache folder: rbi's stderr keeps its own lines
    logging.getLogger("matplotlib").setLevel(logging.ERROR)
    try:
        import matplotlib  # noqa: F401  (the optional extra `plot`, loaded only when a picture is asked for)
    except ImportError:
        raise SpecError(
            f"{option}: needs matplotlib, which is not installed: pip install '.[plot]' from rbi's source folder, or pip install matplotlib"
        ) from None


def require(module: str, extra: str, option: str) -> None:
    """Refuse ``option`` with the install command when the optional package ``module`` is missing."""
    if importlib.util.find_spec(module) is None:
        raise SpecError(
            f"{option}: needs the optional package {module!r}: pip install '.[{extra}]' from rbi's "
            f"source folder, or pip install {module}"
        )
