"""Misspelt names are answered with the nearest valid one; `rbi --install-completion` writes
a bash or zsh completion script into HOME (a temporary one here) that completes for real."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

SPEC = "parts:\n  - {name: b, shape: %s, %s: %s, radius: 0.1, start: [0, 0, 0], end: [0, 0, 1]}\n"


@pytest.mark.parametrize(
    "shape, field, value, expected",
    [
        ("cylindr", "mass", "1", "unknown shape 'cylindr' (did you mean 'cylinder'?)"),
        ("cylinder", "density", "steal", "unknown material 'steal' (did you mean 'steel'?)"),
    ],
)
def test_unknown_shape_and_material(tmp_path, shape, field, value, expected):
    spec = tmp_path / "s.yaml"
    spec.write_text(SPEC % (shape, field, value))
    proc = rbi("inertia", spec)
    one_line_exit_2(proc)
    assert expected in proc.stderr


@pytest.mark.parametrize(
    "args, expected",
    [
        (["inertai", "x.yaml"], "no such command 'inertai' (did you mean inertia?)"),
        (["simualte"], "no such command 'simualte' (did you mean simulate?)"),
        (["inertia", "x.yaml", "--abuot", "com"], "no such option: --abuot (did you mean --about?)"),
        (["simulate", "x.yaml", "--spinn", "3"], "no such option: --spinn (did you mean --spin?)"),
        (["frobnicate"], "no such command 'frobnicate' (see `rbi --help`)"),
    ],
)
def test_unknown_command_and_option(args, expected):
    proc = rbi(*args)
    one_line_exit_2(proc)
    assert expected in proc.stderr


def _completion_env(home: Path, shell: str) -> dict:
    return {
        **os.environ,
        "HOME": str(home),
        "SHELL": f"/bin/{shell}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
    }


@pytest.mark.parametrize(
    "shell, script, rc, line",
    [
        ("bash", ".bash_completions/rbi.sh", ".bashrc", "source '{home}/.bash_completions/rbi.sh'"),
        ("zsh", ".zfunc/_rbi", ".zshrc", "fpath+=~/.zfunc; autoload -Uz compinit; compinit"),
    ],
)
def test_install_completion_writes_the_script_and_loads_it_once(tmp_path, shell, script, rc, line):
    env = _completion_env(tmp_path, shell)
    for _ in range(2):  # installing twice adds the start-up line once
        proc = subprocess.run(
            [sys.executable, "-m", "rbi", "--install-completion"],
            env=env,
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert proc.returncode == 0, proc.stderr
    assert f"{shell} completion for rbi written to {tmp_path / script}" in proc.stdout
    assert "_RBI_COMPLETE" in (tmp_path / script).read_text()
    assert (tmp_path / rc).read_text().count(line.format(home=tmp_path)) == 1
    shown = subprocess.run(
        [sys.executable, "-m", "rbi", "--show-completion"],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert shown.stdout == (tmp_path / script).read_text()


def test_the_installed_bash_script_completes_commands_and_options(tmp_path):
    if shutil.which("bash") is None or shutil.which("rbi", path=str(Path(sys.executable).parent)) is None:
        pytest.skip("needs bash and the installed rbi")
    env = _completion_env(tmp_path, "bash")
    subprocess.run(
        [sys.executable, "-m", "rbi", "--install-completion"], env=env, check=True, capture_output=True
    )
    script = tmp_path / ".bash_completions" / "rbi.sh"
    words = {"rbi inert": 1, "rbi inertia --ab": 2}
    for typed, index in words.items():
        shell = (
            f"source '{script}'; COMP_WORDS=({typed}); COMP_CWORD={index}; _rbi_completion rbi; "
            'printf "%s\\n" "${COMPREPLY[@]}"'
        )
        proc = subprocess.run(["bash", "-c", shell], env=env, capture_output=True, text=True, timeout=60)
        assert proc.stdout.split() == [{"rbi inert": "inertia", "rbi inertia --ab": "--about"}[typed]], proc


def test_completion_for_an_unknown_shell_is_one_line_exit_2(tmp_path):
    env = {**_completion_env(tmp_path, "bash"), "SHELL": "/usr/bin/fish"}
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", "--install-completion"],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    one_line_exit_2(proc, "fish", "bash and zsh")
    assert not any(tmp_path.iterdir())
