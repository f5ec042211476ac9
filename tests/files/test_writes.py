"""Output paths the existing tests (tests/cli/test_output.py, tests/cli/test_simulate_hardening.py)
do not reach: SIGTERM mid-write, standard output under its device names and as a non-root user,
a full disk, and paths the file system refuses, all as the CLI sees them."""

from __future__ import annotations

import errno
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import pytest

from rbi.files.output import output_target
from rbi.spec.errors import InputError
from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi
from tests.users import as_ordinary_user

TOP = BODIES / "top.yaml"


def test_sigterm_during_the_write_leaves_no_temporary_file(tmp_path):
    """A process killed by SIGTERM while it is writing an output unwinds: the target keeps its
    old content and no `.rbi-XXXX` file is left beside it; it exits 143 with one line."""
    target = tmp_path / "out.csv"
    target.write_text("old\n")
    script = textwrap.dedent(f"""
        import sys, time
        from rbi.cli import app
        from rbi.files.output import open_output, output_target

        def slow_command():
            target = output_target({str(target)!r}, "--out", ("csv",))
            with open_output(target) as handle:
                handle.write("t,x\\n" * 1000)
                handle.flush()
                print("writing", flush=True)
                time.sleep(60)
                handle.write("never\\n")

        app.app.command("slow")(slow_command)
        app.COMMANDS["slow"] = ("time", "sleep", "test only")
        sys.argv = ["rbi", "slow"]
        app.main()
    """)
    proc = subprocess.Popen(
        [sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    assert proc.stdout.readline().strip() == "writing", proc.stderr.read()
    assert any(p.name.startswith(".rbi-") for p in tmp_path.iterdir())  # mid-write indeed
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 143, err
    assert err.strip().splitlines() == ["rbi: terminated"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
    assert target.read_text() == "old\n"


@pytest.mark.parametrize("alias", ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"])
def test_standard_output_under_its_device_names_is_a_stream(alias, tmp_path, monkeypatch):
    target = output_target(alias, "--out", ("csv",), stdout_format="csv")
    assert target.is_stdout and target.format == "csv"
    with pytest.raises(InputError, match="standard output"):
        output_target(alias, "--plot", ("png",))
    monkeypatch.chdir(tmp_path)
    proc = rbi("simulate", TOP, "--spin", "200", "--duration", "0.1", "--samples", "3", "--out", alias)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("t,qw,qx,qy,qz,wx,wy,wz") and len(proc.stdout.splitlines()) == 4
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("out", ["-", "/dev/stdout"])
def test_a_non_root_user_streams_to_standard_output(out):
    script = Path(sys.executable).with_name("rbi")
    folder = tempfile.mkdtemp(prefix="rbi-nobody-")
    try:
        os.chmod(folder, 0o555)  # an ordinary user may enter, not write
        proc = subprocess.run(
            [
                *as_ordinary_user(),
                str(script),
                "simulate",
                str(TOP),
                "--spin",
                "200",
                "--duration",
                "0.1",
                "--samples",
                "3",
                "--out",
                out,
            ],
            capture_output=True,
            text=True,
            cwd=folder,
            timeout=120,
        )
        assert proc.returncode == 0, proc.stderr
        assert proc.stdout.startswith("t,qw,qx,qy,qz,wx,wy,wz") and len(proc.stdout.splitlines()) == 4
        assert os.listdir(folder) == []
    finally:
        shutil.rmtree(folder)


def test_a_full_disk_is_one_line_exit_2_and_nothing_is_left(tmp_path, monkeypatch):
    """ENOSPC while writing (as /dev/full would give; rbi refuses devices, so the writer is made
    to fail instead)."""
    import builtins

    import rbi.files.output as output

    real_open = builtins.open

    class FullDisk:
        def __init__(self, handle):
            self.handle = handle

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.handle.close()

        def write(self, text):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    def full_open(path, mode="r", **kwargs):
        handle = real_open(path, mode, **kwargs)
        return FullDisk(handle) if "w" in mode and os.path.basename(str(path)).startswith(".rbi-") else handle

    monkeypatch.setattr(output, "open", full_open, raising=False)
    out = tmp_path / "x.csv"
    proc = rbi("simulate", TOP, "--spin", "200", "--duration", "0.1", "--out", out)
    one_line_exit_2(proc, "--out", "No space left on device")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "path,words",
    [
        ("", ["--out", "empty"]),
        ("y" * 300 + ".csv", ["--out", "longer than 255"]),
        ("/sys/x.csv", ["--out", "/sys/x.csv"]),
        ("/nonexistent-folder/x.csv", ["does not exist"]),
    ],
)
def test_paths_the_file_system_refuses_are_exit_2_before_the_run(path, words):
    # --duration 1e9 would be refused by the step budget: the path is checked before it
    proc = rbi("simulate", TOP, "--spin", "200", "--duration", "100", "--out", path)
    one_line_exit_2(proc, *words)
    assert "budget" not in proc.stderr


def test_bench_write_docs_into_a_folder_is_refused_before_any_measurement(tmp_path):
    proc = rbi("bench", "--quick", "--write-docs", tmp_path)
    one_line_exit_2(proc, "--write-docs", "folder")
    proc = rbi("bench", "--quick", "--write-docs", tmp_path / "perf.html")
    one_line_exit_2(proc, "--write-docs", ".md")
    proc = rbi("bench", "--quick", "--plot", tmp_path / "p.png", "--write-docs", tmp_path / "p.png")
    one_line_exit_2(proc, "--write-docs")
    assert list(tmp_path.iterdir()) == []


def test_a_pdf_plot_is_a_pdf(tmp_path):
    pytest.importorskip("matplotlib")
    pdf = tmp_path / "x.pdf"
    proc = rbi("simulate", TOP, "--spin", "200", "--tilt", "5", "--duration", "0.2", "--plot", pdf)
    assert proc.returncode == 0, proc.stderr
    assert pdf.read_bytes()[:5] == b"%PDF-"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.pdf"]


def test_the_cli_writes_with_the_umask_and_keeps_a_replaced_files_mode(tmp_path):
    import stat

    new, old = tmp_path / "new.csv", tmp_path / "old.csv"
    old.write_text("x\n")
    os.chmod(old, 0o644)
    previous = os.umask(0o022)
    try:
        for out in (new, old):
            proc = rbi("simulate", TOP, "--spin", "200", "--duration", "0.1", "--samples", "3", "--out", out)
            assert proc.returncode == 0, proc.stderr
    finally:
        os.umask(previous)
    assert stat.S_IMODE(os.stat(new).st_mode) == 0o644  # 0666 less the umask, not mkstemp's 0600
    assert stat.S_IMODE(os.stat(old).st_mode) == 0o644
    assert old.read_text().startswith("t,qw")
