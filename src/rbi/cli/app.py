"""The command line: the table of commands, a group that imports a command's module only when
that command runs, the root options (``--version``, ``--allow-outside-paths``, completion), and
the entry point, which turns input errors into one line and exit status 2, Ctrl-C and SIGTERM
into one line and 130 / 143.

``rbi --help`` and ``rbi --version`` load no command module (and so no numpy); ``rbi inertia``
loads only its own module. Each command module imports its heavy dependencies (scipy, the
integrator, matplotlib) inside the command function.
"""

from __future__ import annotations

import atexit
import difflib
import gc
import importlib
import os
import sys
import warnings
from collections.abc import Iterable

import typer
from typer.core import TyperGroup
from typer.main import get_command_from_info
from typer.models import CommandInfo

from rbi import SpecError, __version__, outside_paths_allowed
from rbi.cli import completion, terminal
from rbi.cli.option_values import error_line
from rbi.cli.options import command, option, plain_argument_help
from rbi.cli.terminal import ReaderLeft, StdoutUnwritable, Terminated, say

try:  # typer 0.26 and later vendor click, and export neither exception publicly
    from typer._click.exceptions import NoSuchOption, UsageError
except ImportError:  # typer 0.16 to 0.25 run on click, whose public home these are
    from click.exceptions import NoSuchOption, UsageError

__all__ = ["COMMANDS", "app", "main"]

_TABLE = {
    # name: (module of rbi.cli holding the function of that name, the summary `rbi --help` shows)
    "inertia": ("mass_commands", "Mass, centre of mass and inertia about a point, in any frame."),
    "principal": ("mass_commands", "Principal moments (ascending) and right-handed principal axes."),
    "parts": ("parts_command", "Per-part mass, centre of mass, inertia and share of the whole."),
    "momentum": ("mass_commands", "Angular momentum and kinetic energy for a given spin."),
    "dynamics": ("dynamics_command", "Newton–Euler: the load for a motion, or the motion for a load."),
    "simulate": ("simulate_command", "Motion of a top on its pivot or of a free body, with its error."),
    "sweep": ("sweep_command", "Many simulations at once: stability maps and tolerance studies."),
    "animate": ("animate_command", "Animation of the motion: a 3D HTML page or a GIF."),
    "show": ("show_command", "Picture of the body as specified: parts, CoM, principal axes."),
    "export": ("export_command", "The <inertial> element for URDF, MJCF or SDF (SI units)."),
    "import": ("import_command", "Links of a URDF, SDF or MJCF file as rbi specs (custom parts)."),
    "audit": ("audit_command", "A robot file's inertials against its geometry; totals; --fix."),
    "uncertainty": ("uncertainty_command", "Uncertainty budget of the numbers a spec writes with ±."),
    "check": ("check_command", "Compare the spec's expect: block with the computed values."),
    "validate": ("schema_command", "Validate many specs at once, one line per problem."),
    "schema": ("schema_command", "JSON Schema of the spec, for editors."),
    "bench": ("bench_command", "Speed against error, throughput and start-up latency."),
}
COMMANDS: dict[str, tuple[str, str, str]] = {
    name: (f"rbi.cli.{module}", "import_robot" if name == "import" else name, summary)
    for name, (module, summary) in _TABLE.items()
}
"""Each command: its module, its function and its one-line summary (`rbi --help` imports none)."""


class _LazyGroup(TyperGroup):
    """A command group that imports a command's module only when that command runs."""

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS)

    def resolve_command(self, ctx, args):
        """An unknown command is refused naming the nearest one (``did you mean inertia?``)."""
        name = args[0] if args else None
        if name is not None and name not in COMMANDS and not name.startswith("-"):
            ctx.fail(f"no such command {name!r}{did_you_mean(name, COMMANDS)}")
        return super().resolve_command(ctx, args)

    def get_command(self, ctx, cmd_name: str):
        if cmd_name not in COMMANDS:
            return None
        if cmd_name not in self.commands:
            self.commands[cmd_name] = build_command(cmd_name)
        return self.commands[cmd_name]

    def format_commands(self, ctx, formatter) -> None:
        with formatter.section("Commands"):
            formatter.write_dl([(name, summary) for name, (_, _, summary) in COMMANDS.items()])


def build_command(name: str):
    """The click command of ``rbi NAME``, its module imported now."""
    module_name, function_name, summary = COMMANDS[name]
    # numpy and the API's modules are imported by rbi.api with the collector paused
    callback = getattr(importlib.import_module(module_name), function_name)
    command = get_command_from_info(
        CommandInfo(name=name, callback=callback, short_help=summary),
        pretty_exceptions_short=True,
        rich_markup_mode=None,
    )
    plain_argument_help(command)
    return command


app = typer.Typer(
    name="rbi",
    cls=_LazyGroup,
    help="Rigid-body calculator: mass properties, principal axes, momentum and motion of a body "
    "described in a YAML spec. Commands that print results take --format table|json|csv; every command takes --help. "
    "Files a spec names are read only from the spec's folder unless --allow-outside-paths is given.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def _version(value: bool) -> None:
    if value:
        print(f"rbi {__version__}")
        raise typer.Exit()


@app.callback()
@command(
    option(bool, "--version", callback=_version, is_eager=True, help="Print the version and exit."),
    option(
        bool,
        "--install-completion",
        callback=completion.install_option,
        is_eager=True,
        help="Install tab completion of commands, options and files for your shell (bash or zsh, from $SHELL).",
    ),
    option(
        bool,
        "--show-completion",
        callback=completion.show_option,
        is_eager=True,
        help="Print the completion script for your shell, to install it by hand.",
    ),
    option(
        bool,
        "--allow-outside-paths",
        help="Let a spec name files outside its own folder (point clouds, meshes); also accepted after the command.",
    ),
)
def _root(**options: bool) -> None:
    """Rigid-body calculator."""


def did_you_mean(name: str, valid: Iterable[str]) -> str:
    """`` (did you mean 'cylinder'?)`` for the valid name nearest ``name`` (difflib's ratio of
    at least 0.6), or nothing."""
    found = difflib.get_close_matches(name, list(valid), n=1, cutoff=0.6)
    return f" (did you mean {found[0]}?)" if found else ""


def usage_message(error) -> str:
    """The one-line message for a click usage error: an unknown option names the nearest of the
    command's own options, as click found it (``no such option: --abuot (did you mean --about?)``)."""

    if isinstance(error, NoSuchOption):
        near = f" (did you mean {error.possibilities[0]}?)" if error.possibilities else ""
        return f"no such option: {error.option_name}{near}"
    # click lays a list of choices out one per line ("Choose from:\n\turdf,\n\tmjcf"): one line here
    return error.format_message().replace(":\n\t", ": ").replace(",\n\t", ", ")


def _take_flag(argv: list[str], flag: str) -> bool:
    """Remove every ``flag`` before a ``--`` from ``argv``; whether there was one."""
    end = argv.index("--") if "--" in argv else len(argv)
    found = flag in argv[:end]
    if found:
        argv[:end] = [a for a in argv[:end] if a != flag]
    return found


def _joints_spread(argv: list[str]) -> list[str]:
    """``--joints a=1 b=2`` (the synopsis's ``[--joints NAME=VALUE ...]``) as ``--joints a=1
    --joints b=2``: each NAME=VALUE word with a number for VALUE that follows a --joints value
    gets its own option (a file name has no such ``=``); nothing after ``--``."""
    spread: list[str] = []
    taking = False
    for at, arg in enumerate(argv):
        if arg == "--":
            return spread + argv[at:]
        if taking and _joint_word(arg):
            spread.append("--joints")
        else:
            taking = arg.startswith("--joints=") or (bool(spread) and spread[-1] == "--joints")
        spread.append(arg)
    return spread


def _joint_word(arg: str) -> bool:
    name, equals, value = arg.partition("=")
    try:
        float(value)
    except ValueError:
        return False
    return bool(equals and name) and not name.startswith("-")


def main() -> None:
    """Console entry point: exit 2 with one line on bad input, never a traceback.

    Every message printed here has control characters escaped (a spec's name or a file name
    cannot drive the terminal) and falls back to ASCII on a terminal that cannot encode it;
    Ctrl-C is ``rbi: interrupted`` (exit 130), SIGTERM unwinds the run so that no temporary
    output file is left behind (exit 143).
    """
    # rbi uses no pydantic plugin: pydantic's documented switch spares the scan of every installed
    # package's entry points when the first model is built (a user's own setting stays)
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "1")
    # at exit, what the run built is handed to the permanent generation: the interpreter's last
    # collections then skip it (~15% of `rbi inertia`'s CPU time went into them); it is all freed
    # with the process, and outputs are closed and stdout flushed before
    atexit.register(gc.freeze)
    terminal.prepare_streams()
    terminal.guard_stdout()
    with terminal.sigterm_unwinds():
        _run()


def _run() -> None:
    # numpy's floating-point warnings: non-finite results are refused explicitly, by the API
    warnings.simplefilter("ignore", RuntimeWarning)
    args = sys.argv[1:]
    allow_outside = _take_flag(args, "--allow-outside-paths")
    args = _joints_spread(args)
    try:
        with outside_paths_allowed(allow_outside):
            completion.enable()  # answers the shell's completion script (only when it is the caller)
            status = app(args=args or ["--help"], prog_name="rbi", standalone_mode=False)
            sys.stdout.flush()  # a full disk is reported here, not by Python at exit
    except SpecError as exc:
        say(error_line(exc))
        sys.exit(2)
    except UsageError as exc:
        command = exc.ctx.command_path if exc.ctx is not None else "rbi"
        say(f"{usage_message(exc)} (see `{command} --help`)")
        sys.exit(2)
    except typer.Abort:
        say("aborted")
        sys.exit(130)
    except KeyboardInterrupt:
        say("interrupted")
        sys.exit(130)
    except Terminated:
        say("terminated")
        raise
    except StdoutUnwritable as exc:  # the results cannot reach the user: the run did not succeed
        terminal.discard_stdout()
        say(f"standard output: cannot write the results: {exc}")
        sys.exit(2)
    except (ReaderLeft, BrokenPipeError) as exc:  # `rbi ... | head`: the reader left; no error of ours
        terminal.discard_stdout()  # what is still buffered is dropped, not flushed again at exit
        sys.exit(exc.status if isinstance(exc, ReaderLeft) else 0)  # a failed check stays failed
    except Exception as exc:  # a bug, not bad input: say so on one line unless debugging
        if os.environ.get("RBI_DEBUG"):
            raise
        say(f"internal error: {type(exc).__name__}: {exc} (RBI_DEBUG=1 shows the traceback)")
        sys.exit(1)
    if status == 130:  # typer turns Ctrl-C (KeyboardInterrupt) into a silent exit status 130
        say("interrupted")
    sys.exit(status if isinstance(status, int) else 0)
