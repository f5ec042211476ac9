"""rbi.files.output writes holding the output's lock (rbi.files.lock): two writers of one file
never both write it, in two processes or two threads of one (tests/cli/test_output_lock.py has
the commands); a sweep's own thread, which holds the lock for the whole run, still writes its
output through the same writer."""

from __future__ import annotations

import os
import threading

import pytest

from rbi.errors import InputError
from rbi.files.lock import OutputLock
from rbi.files.output import atomic_path, output_target, write_output

BUSY = "another rbi run is writing this file now"


def in_thread(work):
    """Run ``work()`` in another thread; returns (thread, result dict: 'error' or 'done')."""
    result: dict = {}

    def run():
        try:
            work()
            result["done"] = True
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            result["error"] = exc

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread, result


def test_two_threads_writing_one_output_do_not_both_write(tmp_path):
    path = tmp_path / "a.csv"
    target = output_target(str(path), "--out", ("csv",))
    writing, finish = threading.Event(), threading.Event()

    def slow_writer(temp):
        with open(temp, "w") as handle:
            handle.write("first\n")
        writing.set()
        assert finish.wait(30)

    thread, result = in_thread(lambda: write_output(target, writer=slow_writer))
    assert writing.wait(30)
    with pytest.raises(InputError, match=BUSY):
        write_output(target, "second\n")
    with pytest.raises(InputError, match=BUSY):  # and a run starting now is refused up front
        output_target(str(path), "--out", ("csv",))
    finish.set()
    thread.join(30)
    assert result == {"done": True}
    assert path.read_text() == "first\n"
    assert sorted(os.listdir(tmp_path)) == ["a.csv"]


def test_a_lock_taken_after_the_check_still_stops_the_write(tmp_path):
    """The up-front check is a courtesy; the write itself holds the lock."""
    path = tmp_path / "a.csv"
    path.write_text("old\n")
    target = output_target(str(path), "--out", ("csv",))
    held, done = threading.Event(), threading.Event()

    def hold():
        with OutputLock(path, "other"):
            held.set()
            assert done.wait(30)

    thread, _ = in_thread(hold)
    assert held.wait(30)
    with pytest.raises(InputError, match=BUSY):
        write_output(target, "new\n")
    done.set()
    thread.join(30)
    assert path.read_text() == "old\n"
    assert sorted(os.listdir(tmp_path)) == ["a.csv"]
    write_output(target, "new\n")
    assert path.read_text() == "new\n"
    assert sorted(os.listdir(tmp_path)) == ["a.csv"]


def test_the_thread_holding_the_lock_writes_through_the_writer_and_keeps_the_lock(tmp_path):
    """What a Parquet sweep does at its end: holding its output's lock, it renames the combined
    file over the output through atomic_path."""
    path = tmp_path / "s.parquet"
    target = output_target(str(path), "--out", ("parquet",))
    with OutputLock(path, "sweep") as lock:
        assert output_target(str(path), "--out", ("parquet",)) == target
        with atomic_path(target) as temp:
            with open(temp, "wb") as handle:
                handle.write(b"rows")
        assert path.read_bytes() == b"rows"
        assert lock.path.exists()  # still held: the writer did not release the sweep's lock
        thread, result = in_thread(lambda: write_output(target, b"other"))
        thread.join(30)
        assert isinstance(result.get("error"), InputError) and BUSY in str(result["error"])
    assert path.read_bytes() == b"rows"
    assert sorted(os.listdir(tmp_path)) == ["s.parquet"]


def test_checking_an_output_creates_nothing_beside_it(tmp_path):
    output_target(str(tmp_path / "a.csv"), "--out", ("csv",))
    assert os.listdir(tmp_path) == []


def test_a_failed_write_releases_the_lock(tmp_path):
    path = tmp_path / "a.csv"
    target = output_target(str(path), "--out", ("csv",))

    def failing(temp):
        raise InputError("the writer failed")

    with pytest.raises(InputError, match="the writer failed"):
        write_output(target, writer=failing)
    assert os.listdir(tmp_path) == []
    write_output(target, "ok\n")
    assert path.read_text() == "ok\n"
