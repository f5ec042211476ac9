"""The entry point: runs the typer application (:mod:`rbi.cli.typer_app`) and turns input
errors into one line and exit status 2, Ctrl-C and SIGTERM into one line and 130 / 143."""

from __future__ import annotations

import os
import signal
import sys
import warnings

import typer
from typer._click.exceptions import UsageError

from rbi import SpecError, outside_paths_allowed
from rbi.cli import completion, terminal
from rbi.cli.option_values import error_line
from rbi.cli.suggest import usage_message
from rbi.cli.terminal import Terminated, say
from rbi.cli.typer_app import COMMANDS, app

__all__ = ["COMMANDS", "app", "main"]


def _take_flag(argv: list[str], flag: str) -> bool:
    """Remove every ``flag`` before a ``--`` from ``argv``; whether there was one."""
    end = argv.index("--") if "--" in argv else len(argv)
    found = flag in argv[:end]
    if found:
        argv[:end] = [a for a in argv[:end] if a != flag]
    return found


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
    terminal.prepare_streams()
    previous_sigterm = signal.getsignal(signal.SIGTERM)
    terminal.install_signal_handlers()
    try:
        _run()
    finally:
        try:
            signal.signal(
                signal.SIGTERM, previous_sigterm if previous_sigterm is not None else signal.SIG_DFL
            )
        except ValueError:  # not the main thread: nothing was installed
            pass


def _run() -> None:
    # numpy's floating-point warnings: non-finite results are refused explicitly (render.emit)
    warnings.simplefilter("ignore", RuntimeWarning)
    args = sys.argv[1:]
    allow_outside = _take_flag(args, "--allow-outside-paths")
    try:
        with outside_paths_allowed(allow_outside):
            completion.enable()  # answers the shell's completion script (only when it is the caller)
            status = app(args=args or ["--help"], prog_name="rbi", standalone_mode=False)
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
    except BrokenPipeError:  # `rbi ... | head`: the reader left; not an error of ours
        sys.stderr.close()
        sys.exit(0)
    except Exception as exc:  # a bug, not bad input: say so on one line unless debugging
        if os.environ.get("RBI_DEBUG"):
            raise
        say(f"internal error: {type(exc).__name__}: {exc} (RBI_DEBUG=1 shows the traceback)")
        sys.exit(1)
    if status == 130:  # typer turns Ctrl-C (KeyboardInterrupt) into a silent exit status 130
        say("interrupted")
    sys.exit(status if isinstance(status, int) else 0)
