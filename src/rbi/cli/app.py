"""The entry point that turns input errors into one line and exit status 2, and the table of
commands the typer application (:mod:`rbi.cli.typer_app`) loads on demand.

``rbi --help`` and ``rbi --version`` load no command module (and so no numpy); ``rbi inertia``
loads only its own module, and a plain ``rbi inertia FILE...`` not even typer
(:mod:`rbi.cli.quick`). Each command module imports its heavy dependencies (scipy, the
integrator, matplotlib) inside the command function.
"""

from __future__ import annotations

import os
import sys

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


def __getattr__(name: str):
    """The typer application and its pieces, built on first use (a plain ``rbi inertia FILE``
    never needs them: see :mod:`rbi.cli.quick`)."""
    if name in ("app", "_build_command", "_LazyGroup"):
        from rbi.cli import typer_app

        return getattr(typer_app, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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
    import signal

    from rbi.cli import terminal

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
    import warnings

    from rbi.cli import quick
    from rbi.cli.terminal import Terminated, say
    from rbi.formats.paths import ALLOW_OUTSIDE_FLAG, outside_paths_allowed
    from rbi.spec.errors import InputError

    # numpy's floating-point warnings: non-finite results are refused explicitly (render.emit)
    warnings.simplefilter("ignore", RuntimeWarning)
    args = sys.argv[1:]
    allow_outside = _take_flag(args, ALLOW_OUTSIDE_FLAG)
    if not args:
        args = ["--help"]
    try:
        with outside_paths_allowed(allow_outside):
            status = quick.run(args)  # None: not a plain command line, typer reads it
            if status is None:
                from rbi.cli.completion import enable
                from rbi.cli.typer_app import app

                enable()  # answers the shell's completion script (only when it is the caller)

                status = app(args=args, prog_name="rbi", standalone_mode=False)
    except InputError as exc:
        say(str(exc))
        sys.exit(2)
    except _typer_error("UsageError") as exc:  # (the except expressions run only on an error)
        command = exc.ctx.command_path if exc.ctx is not None else "rbi"
        from rbi.cli.suggest import usage_message

        say(f"{usage_message(exc)} (see `{command} --help`)")
        sys.exit(2)
    except _typer_error("Abort"):
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


def _typer_error(name: str) -> type:
    """typer's ``UsageError`` or ``Abort`` (imported only when an error is being handled)."""
    import typer
    from typer._click import exceptions

    return exceptions.UsageError if name == "UsageError" else typer.Abort
