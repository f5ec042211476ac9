"""A stopped sweep keeps every run that finished, and stops soon: chunks of long runs are sized
to end about every second (rbi 2 put a sweep of 40 long runs in one chunk of 40: Ctrl-C waited
for the whole batch, then dropped its rows), the chunks in flight when it is stopped are
written, and `--resume` computes only the rest, giving the rows of an uninterrupted sweep.

Wall-clock bounds here are loose on purpose: the machine is shared."""

from __future__ import annotations

import csv
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

import rbi
from rbi.spec.load import read_spec
from rbi.sweeps import execute
from rbi.sweeps.execute import Chunks
from rbi.sweeps.study import Study, SweepSettings
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as run_rbi

TOP = BODIES / "top.yaml"
BOLTED = BODIES / "top_bolted.yaml"
RUNS = 60
LONG = ["--spin", f"150:250:{RUNS}", "--tilt", "1", "--duration", "200"]
"""60 runs of 200 s (about 0.05 s of one core each): rbi 2 made them one chunk."""


def rows_of(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def whole_rows(path) -> int:
    try:
        return max(0, path.read_bytes().count(b"\n") - 1)
    except FileNotFoundError:
        return 0


def long_sweep(out, **options):
    return rbi.sweep(TOP, spin=rbi.Grid(150, 250, RUNS), tilt_deg=1.0, duration=200.0, out=out, **options)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("reference") / "all.csv"
    long_sweep(out)
    rows = rows_of(out)
    assert len(rows) == RUNS and all(r["status"] == "ok" for r in rows)
    return rows


@pytest.fixture
def computed(monkeypatch):
    """Runs each chunk computed, as (first run, runs) once the chunk has ended."""
    from rbi.sweeps import runs

    real, ended = runs.run_chunk, []

    def counted(job, a, b, threads=0):
        rows = real(job, a, b, threads)
        ended.append((a, b - a))
        return rows

    monkeypatch.setattr(runs, "run_chunk", counted)
    return ended


def resume_computes_only_the_rest(out, kept: int, reference, computed) -> None:
    computed.clear()
    proc = run_rbi("sweep", TOP, *LONG, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert sum(n for _, n in computed) == RUNS - kept and min(a for a, _ in computed) == kept
    assert rows_of(out) == reference


def test_ctrl_c_keeps_the_finished_runs_soon_and_resume_computes_the_rest(tmp_path, reference, computed):
    """`rbi sweep ... --out` of long runs, Ctrl-C as soon as the first rows are in the file:
    exit 130 with the rows kept (rbi 2: no row reached the file until every run had ended,
    then Ctrl-C kept none of them)."""
    out = tmp_path / "rs.csv"
    proc = subprocess.Popen(
        [sys.executable, "-m", "rbi", "sweep", str(TOP), *LONG, "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        deadline = time.monotonic() + 120
        while proc.poll() is None and time.monotonic() < deadline and whole_rows(out) < 1:
            time.sleep(0.01)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=120)
    finally:
        proc.kill()
    kept = rows_of(out)
    assert proc.returncode == 130, err
    assert 1 <= len(kept) < RUNS, err
    assert err.startswith(f"rbi: interrupted: {len(kept)} of {RUNS} runs kept in {out}"), err
    assert kept == reference[: len(kept)]
    resume_computes_only_the_rest(out, len(kept), reference, computed)


def test_a_stop_from_the_progress_callback_keeps_every_finished_run(tmp_path, reference, computed):
    """The progress callback raises KeyboardInterrupt once the first runs are in: the chunks
    that ended are all in the file, no chunk past those in flight was started, and --resume
    computes only the rest (rbi 2: all 60 runs computed in one chunk before the stop)."""
    out = tmp_path / "rs.csv"

    def stop(done, total):
        if done > 0:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        long_sweep(out, progress=stop)
    ended = sum(n for _, n in computed)
    kept = rows_of(out)
    assert 1 <= len(kept) < RUNS and len(computed) <= 2
    assert len(kept) == ended  # every run that finished is in the file
    assert kept == reference[: len(kept)]
    resume_computes_only_the_rest(out, len(kept), reference, computed)


@pytest.mark.parametrize("failure", [RuntimeError, KeyboardInterrupt])
def test_a_progress_callback_failing_at_once_leaves_the_output_unlocked(tmp_path, failure):
    """The first progress call (0 runs done) raises: the output is closed and its lock given up
    (rbi 2 made that call outside the try that closes it: a second sweep on the output in the
    same process was refused, 'another rbi run')."""
    out = tmp_path / "s.csv"

    def fails(done, total):
        raise failure

    with pytest.raises(failure):
        rbi.sweep(BOLTED, spin=[150.0, 250.0], duration=0.1, workers=1, out=out, progress=fails)
    table = rbi.sweep(BOLTED, spin=[150.0, 250.0], duration=0.1, workers=1, out=out, resume=True)
    assert len(table) == 2 and [r["run"] for r in rows_of(out)] == ["0", "1"]


def test_chunks_of_long_runs_are_small_and_of_short_runs_unchanged():
    """The repro's sweep (40 runs of 1000 s) is cut into chunks of a few runs; a sweep of
    4 s runs keeps SweepJob.chunk_size's chunks (its throughput)."""

    def first_chunk(duration):
        settings = SweepSettings(spin=rbi.Grid(150, 250, 40), tilt_deg=1.0, duration=duration, workers=2)
        study = Study(str(TOP), read_spec(TOP)[0], settings)
        return next(iter(study._chunks(0)))

    assert first_chunk(1000.0)[1] <= 8
    assert first_chunk(4.0) == (0, 40)


def test_chunk_sizes_follow_how_long_chunks_took():
    chunks = Chunks(0, 10_000, most=64, least=2, run_seconds=0.25)
    assert chunks.size() == 4  # about a second
    chunks.took(4, 8.0)  # 2 s a run: the fewest that keep the cores busy
    assert chunks.size() == 2
    chunks.took(2, 0.02)  # fast: at most twice the last chunk
    assert chunks.size() == 4
    chunks.took(64, 0.5)
    assert chunks.size() == 64  # never more than most
    assert Chunks(0, 100, most=8).size() == 8  # no estimate: most
    assert list(Chunks(5, 12, most=3)) == [(5, 8), (8, 11), (11, 12)]


def test_ctrl_c_while_rows_are_delivered_lets_the_chunk_finish():
    """A signal that arrives while a chunk's rows are written is handled right after: the
    chunk is written whole, then the sweep stops (keeping the chunk in flight)."""
    delivered = []

    def on_rows(rows):
        if not delivered:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)  # Python would run the handler here
        delivered.extend(rows)

    with pytest.raises(KeyboardInterrupt):
        execute.run_local(lambda a, b, threads: [[k] for k in range(a, b)], Chunks(0, 100, 10), 1, on_rows)
    assert len(delivered) in (10, 20) and delivered == [[k] for k in range(len(delivered))]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_stop_waits_for_a_chunk_in_flight_no_longer_than_stop_seconds(monkeypatch):
    """A chunk that does not end within STOP_SECONDS of the stop is left to its (daemon)
    thread: the sweep stops without it."""
    monkeypatch.setattr(execute, "STOP_SECONDS", 0.2)
    release, delivered = threading.Event(), []

    def compute(a, b, threads):
        if a > 0:
            release.wait(60)
        return [[k] for k in range(a, b)]

    def on_rows(rows):
        delivered.extend(rows)
        raise KeyboardInterrupt

    started = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            execute.run_local(compute, Chunks(0, 30, 10), 1, on_rows)
        waited = time.monotonic() - started
    finally:
        release.set()
    assert delivered == [[k] for k in range(10)] and waited < 30
