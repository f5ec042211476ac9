"""The typer application: a group that builds a command (from :data:`rbi.cli.app.COMMANDS`)
only when that command runs, and the root options (``--version``, ``--allow-outside-paths``)."""

from __future__ import annotations

import typer
from typer.core import TyperGroup

from rbi import __version__
from rbi.cli.app import COMMANDS


class _LazyGroup(TyperGroup):
    """A command group that imports a command's module only when that command runs."""

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS)

    def parse_args(self, ctx, args):
        from rbi.cli import fast_params

        fast_params.install(self, ctx)
        return super().parse_args(ctx, args)

    def resolve_command(self, ctx, args):
        """An unknown command is refused naming the nearest one (``did you mean inertia?``)."""
        name = args[0] if args else None
        if name is not None and name not in COMMANDS and not name.startswith("-"):
            from rbi.cli.suggest import did_you_mean

            ctx.fail(f"no such command {name!r}{did_you_mean(name, COMMANDS)}")
        return super().resolve_command(ctx, args)

    def get_command(self, ctx, cmd_name: str):
        if cmd_name not in COMMANDS:
            return None
        if cmd_name not in self.commands:
            from rbi.cli import fast_params

            self.commands[cmd_name] = _build_command(cmd_name)
            fast_params.install(self.commands[cmd_name], ctx)
        return self.commands[cmd_name]

    def format_commands(self, ctx, formatter) -> None:
        with formatter.section("Commands"):
            formatter.write_dl([(name, summary) for name, (_, _, summary) in COMMANDS.items()])


def _build_command(name: str):
    import importlib

    from typer.main import get_command_from_info
    from typer.models import CommandInfo

    from rbi.cli import fast_params

    fast_params.quiet_pydantic_plugins()
    module_name, function_name, summary = COMMANDS[name]
    callback = getattr(importlib.import_module(module_name), function_name)
    command = get_command_from_info(
        CommandInfo(name=name, callback=callback, short_help=summary),
        pretty_exceptions_short=True,
        rich_markup_mode=None,
    )
    from rbi.cli.options import plain_argument_help

    plain_argument_help(command)
    return command


from rbi.cli import completion  # noqa: E402  (standard library only until an option is used)

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
