"""The typer application: registers each command and turns input errors into exit status 2.

Command modules import their heavy dependencies (scipy, numba, matplotlib) inside the
command functions, so ``rbi inertia`` never pays for the integrator.
"""

from __future__ import annotations

import os
import sys

import typer

from rbi import __version__
from rbi.cli import (
    bench_command,
    check_command,
    dynamics_command,
    export_command,
    mass_commands,
    parts_command,
    sweep_command,
    schema_command,
    simulate_command,
)
from rbi.spec.errors import InputError

app = typer.Typer(
    name="rbi",
    help="Rigid-body calculator: mass properties, principal axes, momentum and motion of a body "
         "described in a YAML spec. Every command takes --format table|json|csv.",
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
    version: bool = typer.Option(False, "--version", callback=_version, is_eager=True, help="Print the version and exit."),
) -> None:
    """Rigid-body calculator."""


app.command("inertia")(mass_commands.inertia)
app.command("principal")(mass_commands.principal)
app.command("momentum")(mass_commands.momentum)
app.command("dynamics")(dynamics_command.dynamics)
app.command("simulate")(simulate_command.simulate)
app.command("export")(export_command.export)
app.command("check")(check_command.check)
app.command("validate")(schema_command.validate)
app.command("schema")(schema_command.schema)
app.command("parts")(parts_command.parts)
app.command("sweep")(sweep_command.sweep)
app.command("bench")(bench_command.bench)


def main() -> None:
    """Console entry point: exit 2 with one line on bad input, never a traceback."""
    from typer._click import exceptions as click_errors

    import numpy as np

    np.seterr(all="ignore")  # non-finite results are refused explicitly (render.emit), not warned about
    if len(sys.argv) == 1:
        sys.argv.append("--help")
    try:
        status = app(standalone_mode=False)
    except click_errors.UsageError as exc:
        command = exc.ctx.command_path if exc.ctx is not None else "rbi"
        print(f"rbi: {exc.format_message()} (see `{command} --help`)", file=sys.stderr)
        sys.exit(2)
    except typer.Abort:
        print("rbi: aborted", file=sys.stderr)
        sys.exit(130)
    except InputError as exc:
        print(f"rbi: {exc}", file=sys.stderr)
        sys.exit(2)
    except KeyboardInterrupt:
        print("rbi: interrupted", file=sys.stderr)
        sys.exit(130)
    except BrokenPipeError:  # `rbi ... | head`: the reader left; not an error of ours
        sys.stderr.close()
        sys.exit(0)
    except Exception as exc:  # a bug, not bad input: say so on one line unless debugging
        if os.environ.get("RBI_DEBUG"):
            raise
        print(f"rbi: internal error: {type(exc).__name__}: {exc} (RBI_DEBUG=1 shows the traceback)", file=sys.stderr)
        sys.exit(1)
    sys.exit(status if isinstance(status, int) else 0)
