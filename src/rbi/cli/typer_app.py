"""The typer application: the table of commands, a group that imports a command's module only
when that command runs, and the root options (``--version``, ``--allow-outside-paths``,
completion).

``rbi --help`` and ``rbi --version`` load no command module (and so no numpy); ``rbi inertia``
loads only its own module. Each command module imports its heavy dependencies (scipy, the
integrator, matplotlib) inside the command function.
"""

from __future__ import annotations

import importlib

import typer
from typer.core import TyperGroup
from typer.main import get_command_from_info
from typer.models import CommandInfo

from rbi import __version__
from rbi.cli import completion
from rbi.cli.options import plain_argument_help
from rbi.cli.suggest import did_you_mean

COMMANDS: dict[str, tuple[str, str, str]] = {
    # name: (module, function, the one-line summary `rbi --help` shows)
    "inertia": (
        "rbi.cli.mass_commands",
        "inertia",
        "Mass, centre of mass and inertia about a point, in any frame.",
    ),
    "principal": (
        "rbi.cli.mass_commands",
        "principal",
        "Principal moments (ascending) and right-handed principal axes.",
    ),
    "parts": (
        "rbi.cli.parts_command",
        "parts",
        "Per-part mass, centre of mass, inertia and share of the whole.",
    ),
    "momentum": (
        "rbi.cli.mass_commands",
        "momentum",
        "Angular momentum and kinetic energy for a given spin.",
    ),
    "dynamics": (
        "rbi.cli.dynamics_command",
        "dynamics",
        "Newton–Euler: the load for a motion, or the motion for a load.",
    ),
    "simulate": (
        "rbi.cli.simulate_command",
        "simulate",
        "Motion of a top on its pivot or of a free body, with its error.",
    ),
    "sweep": (
        "rbi.cli.sweep_command",
        "sweep",
        "Many simulations at once: stability maps and tolerance studies.",
    ),
    "animate": ("rbi.cli.animate_command", "animate", "Animation of the motion: a 3D HTML page or a GIF."),
    "show": ("rbi.cli.show_command", "show", "Picture of the body as specified: parts, CoM, principal axes."),
    "export": (
        "rbi.cli.export_command",
        "export",
        "The <inertial> element for URDF, MJCF or SDF (SI units).",
    ),
    "import": (
        "rbi.cli.import_command",
        "import_robot",
        "Links of a URDF, SDF or MJCF file as rbi specs (custom parts).",
    ),
    "audit": (
        "rbi.cli.audit_command",
        "audit",
        "A robot file's inertials against its own geometry; totals; --fix.",
    ),
    "check": ("rbi.cli.check_command", "check", "Compare the spec's expect: block with the computed values."),
    "validate": ("rbi.cli.schema_command", "validate", "Validate many specs at once, one line per problem."),
    "schema": ("rbi.cli.schema_command", "schema", "JSON Schema of the spec, for editors."),
    "bench": ("rbi.cli.bench_command", "bench", "Speed against error, throughput and start-up latency."),
}


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
def _root(
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Print the version and exit."
    ),
    install_completion: bool = typer.Option(
        False,
        "--install-completion",
        callback=completion.install_option,
        is_eager=True,
        help="Install tab completion of commands, options and files for your shell (bash or zsh, from $SHELL).",
    ),
    show_completion: bool = typer.Option(
        False,
        "--show-completion",
        callback=completion.show_option,
        is_eager=True,
        help="Print the completion script for your shell, to install it by hand.",
    ),
    allow_outside_paths: bool = typer.Option(
        False,
        "--allow-outside-paths",
        help="Let a spec name files outside its own folder (point clouds, meshes); also accepted after the command.",
    ),
) -> None:
    """Rigid-body calculator."""
