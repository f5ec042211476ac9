"""Two runs on one output never both write it (contract, "Files rbi creates besides its
outputs"): every command's output is written holding the lock ``rbi sweep`` holds while it
streams rows, so a run on a file another run is writing is exit 2 with one line, before its
work, and leaves the file as it was; a run alone leaves no lock file behind.

rbi 3 checked the lock only in ``rbi sweep``: ``rbi simulate --out rs.csv`` during
``rbi sweep --out rs.csv`` exited 0 and replaced the sweep's rows with its trajectory, and the
sweep then said 'Rows written to rs.csv.'."""

from __future__ import annotations

import csv
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from rbi.files.lock import OutputLock
from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi
from tests.sweeps.test_sweep_files_hostile import SLOW_SWEEP  # chunks of 4 runs, 0.3 s each

TOP = BODIES / "top.yaml"
BUSY = "another rbi run is writing this file now; wait for it to end"

HOLD = """
import sys
from rbi.files.lock import OutputLock
with OutputLock(sys.argv[1], "test"):
    print("held", flush=True)
    sys.stdin.readline()
"""


class Holder:
    """Another run writing ``path``: a process, or another thread of this one (the in-process
    runner runs rbi in this thread), holding its lock until :meth:`release`."""

    def __init__(self, path: Path, where: str) -> None:
        self.where = where
        if where == "process":
            self.proc = subprocess.Popen(
                [sys.executable, "-c", HOLD, str(path)],
                stdin=subprocess.PIPE,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                text=True,
            )
            assert self.proc.stdout.readline().strip() == "held", self.proc.stderr.read()
        else:
            held, self.done = threading.Event(), threading.Event()

            def hold():
                with OutputLock(path, "test"):
                    held.set()
                    self.done.wait(60)

            self.thread = threading.Thread(target=hold, daemon=True)
            self.thread.start()
            assert held.wait(30)

    def release(self) -> None:
        if self.where == "process":
            self.proc.communicate("\n", timeout=30)
            assert self.proc.returncode == 0
        else:
            self.done.set()
            self.thread.join(30)


@pytest.fixture(params=["process", "thread"])
def holder(request):
    made = []

    def hold(path: Path) -> Holder:
        made.append(Holder(path, request.param))
        return made[-1]

    yield hold
    for each in made:
        if each.where == "process":
            each.proc.kill()
            each.proc.wait()
        else:
            each.done.set()


COMMANDS = {
    # the long simulation shows the refusal comes before the work (it takes ~20 s)
    "simulate": ("x.csv", ["simulate", TOP, "--spin", "100", "--tilt", "1", "--duration", "20000"]),
    "show": ("x.png", ["show", TOP]),
    "animate": ("x.html", ["animate", TOP, "--spin", "100", "--duration", "0.5"]),
}


@pytest.mark.parametrize("command", COMMANDS)
def test_a_command_on_an_output_another_run_writes_is_exit_2_before_its_work(tmp_path, holder, command):
    name, args = COMMANDS[command]
    out = tmp_path / name
    out.write_bytes(b"the other run's rows\n")
    held = holder(out)
    started = time.monotonic()
    proc = rbi(*args, "--out", out)
    elapsed = time.monotonic() - started
    one_line_exit_2(proc, BUSY, name)
    assert elapsed < 5.0, elapsed
    assert out.read_bytes() == b"the other run's rows\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == [f".{name}.rbi-lock", name]  # the holder's
    held.release()
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


@pytest.mark.parametrize("command", ["show", "animate"])
def test_after_the_other_run_ends_the_command_writes_and_leaves_no_lock_file(tmp_path, holder, command):
    name, args = COMMANDS[command]
    out = tmp_path / name
    out.write_bytes(b"old\n")
    held = holder(out)
    one_line_exit_2(rbi(*args, "--out", out), BUSY)
    held.release()
    proc = rbi(*args, "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() != b"old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_simulate_alone_leaves_only_its_output(tmp_path):
    out = tmp_path / "x.csv"
    proc = rbi("simulate", TOP, "--spin", "100", "--duration", "1", "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv"]
    assert out.read_text().startswith("t,")


def test_a_lock_file_left_by_a_killed_run_is_no_obstacle_and_is_removed(tmp_path):
    out = tmp_path / "x.csv"
    (tmp_path / ".x.csv.rbi-lock").write_bytes(b"")  # a killed run's: the kernel released its lock
    proc = rbi("simulate", TOP, "--spin", "100", "--duration", "1", "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv"]


def test_a_link_planted_at_the_lock_name_is_refused_and_not_followed(tmp_path):
    out = tmp_path / "x.csv"
    victim = tmp_path / "victim"
    victim.write_text("precious\n")
    (tmp_path / ".x.csv.rbi-lock").symlink_to(victim)
    one_line_exit_2(rbi("simulate", TOP, "--spin", "100", "--duration", "1", "--out", out), "rbi-lock")
    assert victim.read_text() == "precious\n" and not out.exists()


def until(condition, seconds: float = 60.0) -> bool:
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def test_simulate_during_a_sweep_on_its_output_is_exit_2_and_the_sweep_keeps_every_row(tmp_path):
    """The tester's case: `rbi sweep --out rs.csv &` then `rbi simulate --out rs.csv` was exit 0
    and left the trajectory in rs.csv, 40 of the sweep's rows lost."""
    out = tmp_path / "rs.csv"
    args = ["sweep", TOP, "--spin", "150:250:24", "--tilt", "1", "--duration", "0.1", "-j", "1", "--out", out]
    sweep = subprocess.Popen(
        [sys.executable, "-c", SLOW_SWEEP, *map(str, args)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert until(lambda: out.exists() and out.read_bytes().count(b"\n") >= 5), "the sweep wrote no rows"
        assert (tmp_path / ".rs.csv.rbi-lock").exists()  # running: holding its lock
        one_line_exit_2(rbi("simulate", TOP, "--spin", "100", "--duration", "1", "--out", out), BUSY)
        _, err = sweep.communicate(timeout=120)
    finally:
        sweep.kill()
    assert sweep.returncode == 0, err
    with open(out, newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0][0] == "run" and [int(r[0]) for r in rows[1:]] == list(range(24))
    assert sorted(os.listdir(tmp_path)) == ["rs.csv"]
