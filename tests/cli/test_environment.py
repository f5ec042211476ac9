"""Odd environments: no writable HOME, a read-only current folder, and a folder (or cache) full
of planted code. The installed console script runs none of it; `python -m rbi` differs (Python
itself puts the current folder first on sys.path), which docs/security.md states."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

import pytest

from tests.conftest import BODIES
from tests.users import as_ordinary_user

PLANTED = (
    "numpy",
    "rbi",
    "typer",
    "rich",
    "yaml",
    "pydantic",
    "scipy",
    "sitecustomize",
    "usercustomize",
    "Cython",
    "numba",
)


def _console_script() -> Path:
    script = Path(sysconfig.get_path("scripts")) / "rbi"
    if not script.is_file():
        script = Path(sys.executable).with_name("rbi")
    if not script.is_file():
        pytest.skip("the rbi console script is not installed")
    return script


def _plant(folder: Path, marker: Path) -> None:
    for name in PLANTED:
        (folder / f"{name}.py").write_text(f"open({str(marker)!r}, 'a').write({name!r} + ' ran\\n')\n")
    (folder / "rbi").mkdir()  # a package named rbi in the current folder, too
    (folder / "rbi" / "__init__.py").write_text(f"open({str(marker)!r}, 'a').write('rbi package ran\\n')\n")


def test_the_console_script_runs_no_code_from_a_read_only_current_folder_without_home():
    script = _console_script()
    prefix = as_ordinary_user()
    base = Path(tempfile.mkdtemp(prefix="rbi-env-"))
    try:
        os.chmod(base, 0o777)  # the marker may be written there by whatever runs as nobody
        work = base / "work"
        work.mkdir()
        marker = base / "marker"
        _plant(work, marker)
        os.chmod(work, 0o555)  # read-only current folder
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "XDG_"))}
        env.update(HOME="/nonexistent", PATH=os.environ.get("PATH", "/usr/bin:/bin"))
        for args in (
            [
                "simulate",
                str(BODIES / "top.yaml"),
                "--spin",
                "200",
                "--tilt",
                "5",
                "--duration",
                "0.2",
                "--format",
                "json",
            ],
            ["principal", str(BODIES / "top_bolted.yaml"), "--format", "json"],
        ):
            proc = subprocess.run(
                [*prefix, str(script), *args], cwd=work, env=env, capture_output=True, text=True, timeout=120
            )
            assert proc.returncode == 0, proc.stderr
            assert json.loads(proc.stdout)["name"]
            assert not marker.exists(), marker.read_text()
        simulated = json.loads(
            subprocess.run(
                [
                    *prefix,
                    str(script),
                    "simulate",
                    str(BODIES / "top.yaml"),
                    "--spin",
                    "200",
                    "--duration",
                    "0.2",
                    "--format",
                    "json",
                ],
                cwd=work,
                env=env,
                capture_output=True,
                text=True,
                timeout=120,
            ).stdout
        )
        assert simulated["final"]["t"] == 0.2
    finally:
        os.chmod(base / "work", 0o755)
        shutil.rmtree(base)


def test_a_library_planted_in_the_cache_is_never_loaded(tmp_path):
    """A corrupt or hostile shared object where a build cache would be (~/.cache/rbi, the
    XDG cache) is not loaded: the kernel comes only from the installed package."""
    script = _console_script()
    home = tmp_path / "home"
    for cache in (home / ".cache" / "rbi", home / "xdg" / "rbi"):
        cache.mkdir(parents=True)
        for name in ("_dop853.so", "_dop853.cpython-311-x86_64-linux-gnu.so", "rbi_kernels.so", "kernel.so"):
            (cache / name).write_bytes(b"\x7fELF" + os.urandom(256))  # would crash if loaded
    env = dict(os.environ, HOME=str(home), XDG_CACHE_HOME=str(home / "xdg"))
    proc = subprocess.run(
        [
            str(script),
            "simulate",
            str(BODIES / "top_bolted.yaml"),
            "--spin",
            "200",
            "--duration",
            "0.2",
            "--format",
            "json",
        ],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["final"]["t"] == 0.2


def test_python_dash_m_puts_the_current_folder_first_as_documented(tmp_path):
    """The difference docs/security.md warns about: `python -m rbi` imports a planted rbi.py
    from the current folder (Python's own rule), the console script does not."""
    marker = tmp_path / "marker"
    (tmp_path / "rbi.py").write_text(f"open({str(marker)!r}, 'w').write('ran')\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    subprocess.run(
        [sys.executable, "-m", "rbi", "--version"], cwd=tmp_path, env=env, capture_output=True, timeout=60
    )
    assert marker.exists()
    marker.unlink()
    proc = subprocess.run(
        [str(_console_script()), "--version"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode == 0 and proc.stdout.startswith("rbi ")
    assert not marker.exists()
    security = (Path(__file__).resolve().parents[2] / "docs" / "security.md").read_text()
    assert "python -m rbi" in security


@pytest.mark.parametrize(
    "args",
    [
        ["show", "top.yaml", "--out", "{tmp}/top.png"],
        ["simulate", "top.yaml", "--spin", "5", "--duration", "0.1", "--plot", "{tmp}/path.svg"],
    ],
)
def test_an_unwritable_cache_folder_prints_nothing_but_the_result(tmp_path, args):
    """With XDG_CACHE_HOME (or MPLCONFIGDIR) naming a folder that cannot be made, `rbi show`
    printed matplotlib's two log lines ('mkdir -p failed for path /proc/x/matplotlib ...',
    'Matplotlib created a temporary cache directory ...') around its result. The picture is
    still drawn; stderr stays empty."""
    pytest.importorskip("matplotlib")
    env = {k: v for k, v in os.environ.items() if k not in ("MPLCONFIGDIR", "XDG_CACHE_HOME")}
    for unwritable in ({"XDG_CACHE_HOME": "/proc/rbi-no-such"}, {"MPLCONFIGDIR": "/proc/rbi-no-such"}):
        done = subprocess.run(
            [str(Path(sys.executable).with_name("rbi")), *[a.format(tmp=tmp_path) for a in args]],
            cwd=BODIES,
            env=env | unwritable,
            capture_output=True,
            text=True,
            timeout=300,
        )
        assert done.returncode == 0, done.stderr
        assert done.stderr == "", done.stderr
        assert (tmp_path / Path(args[-1]).name).stat().st_size > 1000
