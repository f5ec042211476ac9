"""The program's manners: data on stdout, diagnostics on stderr, NO_COLOR, plain JSON numbers,
the installed console script."""

from __future__ import annotations

import json
import os
import pty
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import run_rbi, run_rbi_inprocess


def test_data_goes_to_stdout_and_nothing_to_stderr(bodies):
    proc = run_rbi("inertia", bodies / "top.yaml", check=True)
    assert proc.stderr == ""
    assert "spinning-top" in proc.stdout and "kg·m²" in proc.stdout


def test_errors_go_to_stderr_and_nothing_to_stdout(tmp_path):
    proc = run_rbi("inertia", tmp_path / "absent.yaml", "--format", "json")
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert "absent.yaml" in proc.stderr


def run_in_terminal(args, env_extra):
    """Run ``python -m rbi`` with stdout on a pseudo-terminal, so rich sees a real terminal."""
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR", "TERM")}
    env.update({"TERM": "xterm-256color", "COLUMNS": "100"}, **env_extra)
    master, slave = pty.openpty()
    proc = subprocess.Popen(
        [sys.executable, "-m", "rbi", *map(str, args)], stdout=slave, stderr=subprocess.PIPE, env=env
    )
    os.close(slave)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    assert proc.wait(timeout=60) == 0, proc.stderr.read()
    return b"".join(chunks).decode()


def test_a_terminal_gets_styles_unless_no_color_is_set(bodies):
    styled = run_in_terminal(["principal", bodies / "top.yaml"], {})
    assert "\x1b[" in styled  # the check below can fail: styles do appear on a terminal
    plain = run_in_terminal(["principal", bodies / "top.yaml"], {"NO_COLOR": "1"})
    assert "\x1b" not in plain
    assert "2.629333" in plain


def test_no_color_wins_over_force_color(bodies):
    env = {**os.environ, "NO_COLOR": "1", "FORCE_COLOR": "1"}
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", "momentum", str(bodies / "top.yaml"), "--omega", "0,0,100"],
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )
    assert proc.returncode == 0
    assert "\x1b" not in proc.stdout and "\x1b" not in proc.stderr


def test_json_numbers_are_plain_shortest_repr(bodies):
    proc = run_rbi_inprocess("inertia", bodies / "top.yaml", "--rotate", "z:90", "--format", "json")
    assert proc.returncode == 0
    assert '"mass": 0.5,' in proc.stdout
    assert "float64" not in proc.stdout and "NaN" not in proc.stdout and "-0.0," not in proc.stdout
    out = json.loads(proc.stdout)
    assert all(type(x) is float for row in out["inertia"] for x in row)


@pytest.mark.parametrize("command", ["inertia", "principal", "momentum"])
def test_help_lists_the_format_option(command):
    proc = run_rbi_inprocess(command, "--help")
    assert proc.returncode == 0
    assert "--format" in proc.stdout and "--about" in proc.stdout


def test_version():
    proc = run_rbi_inprocess("--version")
    assert proc.returncode == 0 and proc.stdout.startswith("rbi ")


def test_installed_console_script_matches_python_m(bodies):
    script = Path(sys.executable).parent / "rbi"
    if not script.exists():
        script = shutil.which("rbi")
    if script is None:
        pytest.skip("rbi console script not installed next to this Python")
    args = ["principal", str(bodies / "top_bolted.yaml"), "--format", "json"]
    installed = subprocess.run([str(script), *args], capture_output=True, text=True, timeout=60)
    assert installed.returncode == 0 and installed.stderr == ""
    assert installed.stdout == run_rbi(*args, check=True).stdout


@pytest.mark.parametrize("args", [["inertia"], ["principal"], ["momentum", "--omega", "0,0,1"]])
def test_names_are_printed_as_text_not_read_as_markup(write_spec, bodies, args):
    text = (bodies / "top.yaml").read_text().replace("name: spinning-top", 'name: "[bold]top [/] v2"')
    proc = run_rbi_inprocess(args[0], write_spec(text, name="[red]top.yaml"), *args[1:])
    assert proc.returncode == 0, proc.stderr
    assert "[bold]top [/] v2" in proc.stdout
