"""The options commands share, as typer declares them (their values are parsed in
:mod:`rbi.cli.option_values`, which needs no typer), and the optional packages some options
need: how --help says so (:func:`needs`) and the refusal, before any work, when one is missing."""

from __future__ import annotations

import functools
import inspect
import logging
from collections.abc import Callable, Mapping
from enum import Enum
from typing import Annotated, Any

import typer
from typer.core import TyperArgument

from rbi import SpecError
from rbi.cli.option_values import parse_about, parse_units

REQUIRED = inspect.Parameter.empty
"""The default of an option the command cannot run without (``rbi export --to``)."""
API: Any = object()
"""The default of an option declared without one: the default of the parameter of that name of
the API function the command calls (:func:`command`), else None."""


def option(kind: Any, *names: str, default: Any = API, name: str | None = None, **settings: Any) -> Any:
    """One option, declared once: its type, flags, default, metavar and help (``settings``:
    typer.Option's), as the parameter :func:`command` gives a command. The parameter is named
    after the first flag (``--mesh-inertia``: ``mesh_inertia``) unless ``name`` names it as the
    API does (``--tilt``: ``tilt_deg``). A ``parser`` (:mod:`rbi.cli.option_values`') is
    called with the text given and the first flag, which its errors name."""
    name = name or names[0].split("/")[0].removeprefix("--").replace("-", "_")
    if "parser" in settings:
        settings["parser"] = functools.partial(settings["parser"], option=names[0])
    annotation = Annotated[kind, typer.Option(*names, **settings)]
    return inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=annotation)


def out_option(metavar: str, help: str, **settings: Any) -> Any:
    """``--out``/``-o``: the file (or folder) a command writes, as :func:`option` declares it
    (``settings``: ``default=REQUIRED`` where writing it is the command's whole job)."""
    return option(str | None, "--out", "-o", metavar=metavar, help=help, **settings)


def plot_option(help: str) -> Any:
    """``--plot FILE``: a picture of the results, ``help`` said of it; the command is refused
    before any work when matplotlib is missing (:func:`require_matplotlib`)."""
    return option(
        str | None,
        "--plot",
        metavar="FILE.png|.svg|.pdf",
        callback=_plot_path,
        help=f"{help} ({needs('matplotlib', 'plot')}).",
    )


def _plot_path(path: str | None) -> str | None:
    if path is not None:
        require_matplotlib()
    return path


def argument(kind: Any, help: str, metavar: str) -> Any:
    """A positional argument as a command's parameter type: ``file: SpecFile``."""
    return Annotated[kind, typer.Argument(help=help, show_default=False, metavar=metavar)]


def command(
    *options: inspect.Parameter, api: Callable[..., Any] | None = None
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A command's decorator: the command takes its own arguments and then ``options``, in the
    order --help lists them, as keywords (those it does not name, in one ``**settings``); an
    option declared without a default defaults as the parameter of that name of ``api``."""
    defaults = {} if api is None else inspect.signature(api).parameters

    def decorate(function: Callable[..., Any]) -> Callable[..., Any]:
        own = inspect.signature(function, eval_str=True).parameters.values()
        arguments = [p for p in own if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD]
        taken = [p.replace(default=_default(p, defaults)) for p in options]
        function.__signature__ = inspect.Signature([*arguments, *taken])  # type: ignore[attr-defined]
        return function

    return decorate


def _default(option: inspect.Parameter, api: Mapping[str, inspect.Parameter]) -> Any:
    if option.default is not API:
        return option.default
    return api[option.name].default if option.name in api else None


class OutputFormat(str, Enum):
    table = "table"
    json = "json"
    csv = "csv"


FORMAT = option(
    OutputFormat,
    "--format",
    "-f",
    default=OutputFormat.table,
    help="table (for people), json (one object) or csv (header + rows).",
)


SpecFile = argument(str, "Body spec (YAML or JSON); - reads it from standard input.", "FILE")
SpecFiles = argument(
    list[str],
    "Body specs (YAML or JSON), one or more (shell globs expand to several); - reads one from standard input.",
    "FILE...",
)
RobotFile = argument(str, "Robot description: .urdf, .sdf or MJCF (.xml).", "ROBOT_FILE")
PACKAGE_PATHS = option(
    list[str] | None,
    "--package-path",
    name="package_paths",
    metavar="NAME=DIR",
    help="Folder of ROS package NAME, for package://NAME/ mesh paths; repeat for several "
    "(ROS_PACKAGE_PATH is searched too).",
)
ABOUT = option(
    str,
    "--about",
    "-a",
    default="com",
    metavar="com|origin|pivot|X,Y,Z",
    parser=parse_about,
    help="Reference point: com, origin, pivot, or X,Y,Z in body coordinates (file units).",
)
UNITS = option(
    str | None,
    "--units",
    "-u",
    metavar="SI|LENGTH,MASS",
    parser=parse_units,
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
    require("matplotlib", "plot", option)


def require(module: str, extra: str, option: str) -> None:
    """Refuse ``option`` with the install command when the optional package ``module`` is missing
    (or cannot be imported), loading it otherwise: it is used next."""
    try:
        __import__(module)  # the import statement's hook (a test's stand-in for a missing package)
    except ImportError:
        raise SpecError(
            f"{option}: needs {module}, which is not installed: pip install '.[{extra}]' from rbi's "
            f"source folder, or pip install {module}"
        ) from None
