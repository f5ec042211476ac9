"""Shell completion: ``rbi --install-completion`` and ``rbi --show-completion`` (bash, zsh).

The script is typer's (click's completion protocol: the shell calls ``rbi`` with
``_RBI_COMPLETE=complete_bash`` or ``complete_zsh`` and the words typed so far; see
:func:`enable`), so it completes command names, options and file names.

Where it is installed, in the user's HOME (as typer installs it):

- bash: ``~/.bash_completions/rbi.sh``, and one line ``source '~/.bash_completions/rbi.sh'``
  added to ``~/.bashrc`` if it is not there yet;
- zsh: ``~/.zfunc/_rbi``, and ``fpath+=~/.zfunc; autoload -Uz compinit; compinit`` added to
  ``~/.zshrc`` if it is not there yet.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import typer
from typer.completion import completion_init, get_completion_script

from rbi import SpecError

PROG = "rbi"
COMPLETE_VAR = "_RBI_COMPLETE"
SHELLS = ("bash", "zsh")
ZSH_LINE = "fpath+=~/.zfunc; autoload -Uz compinit; compinit"


def enable() -> None:
    """Let the completion script's calls (``_RBI_COMPLETE`` set) be answered: register typer's
    bash and zsh completion classes. Costs nothing on an ordinary run."""
    if os.environ.get(COMPLETE_VAR):
        completion_init()


def shell_name() -> str:
    """The user's shell from ``$SHELL`` (bash or zsh); anything else is bad input."""

    shell = Path(os.environ.get("SHELL", "")).name
    if shell not in SHELLS:
        raise SpecError(
            f"--install-completion: cannot tell the shell from $SHELL ({shell or 'not set'!r}): "
            f"completion is available for {' and '.join(SHELLS)}; set SHELL=/bin/bash or /bin/zsh"
        )
    return shell


def script(shell: str) -> str:
    """The completion script for ``shell``."""

    return get_completion_script(prog_name=PROG, complete_var=COMPLETE_VAR, shell=shell) + "\n"


def install(shell: str, home: Path | None = None) -> tuple[Path, Path]:
    """Write the completion script for ``shell`` and the line that loads it (once) into the
    shell's start-up file: ``(script path, start-up file)``."""
    home = Path.home() if home is None else home
    if shell == "bash":
        target, rc = home / ".bash_completions" / f"{PROG}.sh", home / ".bashrc"
        line = f"source '{target}'"
    else:
        target, rc = home / ".zfunc" / f"_{PROG}", home / ".zshrc"
        line = ZSH_LINE
    _write(target, script(shell))
    existing = rc.read_text() if rc.is_file() else ""
    if line not in existing:
        with open(rc, "a") as handle:
            handle.write(("" if not existing or existing.endswith("\n") else "\n") + line + "\n")
    return target, rc


def _write(target: Path, text: str) -> None:
    """The script, written whole (a temporary file renamed into place), never through a link."""

    target.parent.mkdir(parents=True, exist_ok=True)
    if target.is_symlink():
        raise SpecError(f"--install-completion: {target}: is a symbolic link; remove it first")
    partial = target.with_name(f".{target.name}.{os.getpid()}.partial")
    try:
        partial.write_text(text)
        os.replace(partial, target)
    finally:
        partial.unlink(missing_ok=True)


def install_option(value: bool) -> None:
    """``rbi --install-completion``: install for ``$SHELL`` and say where."""
    if value:
        shell = shell_name()
        target, rc = install(shell)
        print(
            f"{shell} completion for rbi written to {target} and loaded from {rc}; open a new terminal to use it"
        )
        sys.stdout.flush()
        raise typer.Exit()


def show_option(value: bool) -> None:
    """``rbi --show-completion``: print the script for ``$SHELL`` (to install by hand)."""
    if value:
        sys.stdout.write(script(shell_name()))
        raise typer.Exit()
