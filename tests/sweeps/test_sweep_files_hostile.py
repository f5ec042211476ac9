"""Hostile input for the files `rbi sweep --out` keeps: sidecars, partial files, locks, resume.

What an attacker sharing the folder plants (links, FIFOs, devices, files of another user at the
names rbi uses beside an output) and what a careless user hands `--resume` (a foreign CSV, a
file with more rows than the grid, values the sweep cannot write, a tampered Parquet chunk).
Every refusal is exit 2 with one line, within a second, and leaves every file byte-identical;
nothing outside the output's folder is ever created or written. See docs/security.md, "Files
rbi keeps beside an output".
"""

from __future__ import annotations

import csv
import errno
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbi.files import safe
from rbi.sweeps import store
from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

BOLTED = BODIES / "top_bolted.yaml"
ARGS = [BOLTED, "--spin", "150:250:24", "--duration", "0.1", "--workers", "1"]
RUNS = 24
MASS_ARGS = [BOLTED, "--mass-properties", "--vary", "parts.bolt.mass=uniform(0.01,0.03)", "--runs", "500"]


def rows_of(path):
    with open(path, newline="") as handle:
        return list(csv.reader(handle))


def snapshot(folder: Path) -> dict[str, bytes | str]:
    """Every name in ``folder`` (recursively, links not followed) with its bytes or link target."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = Path(root) / name
            key = str(path.relative_to(folder))
            if path.is_symlink():
                out[key] = "-> " + os.readlink(path)
            elif path.is_file() and path.stat().st_size > 1 << 20:
                info = path.stat()
                out[key] = f"size {info.st_size}, modified {info.st_mtime_ns}"
            elif path.is_file():
                out[key] = path.read_bytes()
            elif path.is_dir():
                out[key] = "dir"
            else:
                out[key] = "special"
    return out


def interrupt_after(monkeypatch, chunks: int, chunk_size: int = 8):
    """Make the next sweep stop with Ctrl-C after ``chunks`` chunks of ``chunk_size`` runs."""
    from rbi.sweeps import runs

    real, calls = runs.run_chunk, []

    def interrupted(job, a, b, threads=0):
        calls.append(a)
        if len(calls) > chunks:
            raise KeyboardInterrupt
        return real(job, a, b, threads)

    monkeypatch.setattr(runs, "run_chunk", interrupted)
    monkeypatch.setattr("rbi.sweeps.runs.SweepJob.chunk_size", lambda self, threads: chunk_size)
    return lambda: monkeypatch.setattr(runs, "run_chunk", real)


@pytest.fixture
def reference(tmp_path_factory):
    folder = tmp_path_factory.mktemp("reference")
    out = folder / "all.csv"
    assert rbi("sweep", *ARGS, "--out", out).returncode == 0
    return out


@pytest.fixture
def interrupted(tmp_path, monkeypatch):
    """An interrupted CSV sweep: (output, restore) with 16 of 24 runs kept and its sidecar."""
    restore = interrupt_after(monkeypatch, 2)
    out = tmp_path / "part.csv"
    proc = rbi("sweep", *ARGS, "--out", out)
    assert proc.returncode == 130, proc.stderr
    restore()
    assert len(rows_of(out)) == 17 and store.settings_path(out).is_file()
    return out


@pytest.fixture
def interrupted_parquet(tmp_path, monkeypatch):
    pytest.importorskip("pyarrow")
    restore = interrupt_after(monkeypatch, 2)
    out = tmp_path / "part.parquet"
    proc = rbi("sweep", *ARGS, "--out", out)
    assert proc.returncode == 130, proc.stderr
    restore()
    assert sorted(os.listdir(store.rows_folder(out))) == ["000000000000.parquet", "000000000008.parquet"]
    return out


def refused_unchanged(out: Path, *words, resume=True, args=ARGS):
    """`--resume` (or a fresh run) on ``out`` is one line, exit 2, without waiting, and changes no
    file (the whole command, spec loading included, on a shared machine: well under 5 s)."""
    before = snapshot(out.parent)
    started = time.monotonic()
    proc = rbi("sweep", *args, "--out", out, *(["--resume"] if resume else []))
    elapsed = time.monotonic() - started
    one_line_exit_2(proc, *words)
    assert elapsed < 5.0, elapsed  # the checks themselves take microseconds: tests/files/test_safe.py
    assert snapshot(out.parent) == before
    return proc


# --- item 1: sidecars, partial files and locks are never followed, read or planted ----------


def test_a_planted_link_at_the_old_fixed_temporary_names_writes_nothing_outside(tmp_path):
    """rbi 2 wrote its settings through `.X.rbi-sweep.json.tmp` and Parquet rows through
    `.X.rbi-partial`: a link planted there made it create or overwrite a file outside."""
    pytest.importorskip("pyarrow")
    outside = tmp_path / "outside"
    outside.mkdir()
    victim = outside / "victim"
    victim.write_text("precious\n")
    work = tmp_path / "work"
    work.mkdir()
    for name in ("s.csv", "s.parquet"):
        (work / f".{name}.rbi-sweep.json.tmp").symlink_to(victim)
        (work / f".{name}.rbi-partial").symlink_to(outside / f"created-{name}")
        proc = rbi("sweep", *ARGS, "--out", work / name)
        assert proc.returncode == 0, proc.stderr
    assert snapshot(outside) == {"victim": b"precious\n"}


@pytest.mark.parametrize("plant", ["symlink", "dangling", "fifo", "devzero", "folder"])
@pytest.mark.parametrize("resume", [False, True])
def test_something_planted_where_the_sidecar_goes_is_exit_2_in_under_a_second(tmp_path, plant, resume):
    out = tmp_path / "s.csv"
    out.write_text("keep me\n")
    side = store.settings_path(out)
    victim = tmp_path / "victim.json"
    victim.write_text("{}")
    if plant == "symlink":
        side.symlink_to(victim)
    elif plant == "dangling":
        side.symlink_to(tmp_path / "nothing")
    elif plant == "fifo":
        os.mkfifo(side)
    elif plant == "devzero":
        side.symlink_to("/dev/zero")
    else:
        side.mkdir()
    refused_unchanged(out, "rbi-sweep.json", resume=resume)


def test_a_fifo_sidecar_does_not_hang_resume_in_a_real_process(tmp_path):
    out = tmp_path / "s.csv"
    out.write_text("run\n")
    os.mkfifo(store.settings_path(out))
    started = time.monotonic()
    proc = subprocess.run(
        [sys.executable, "-m", "rbi", "sweep", *map(str, ARGS), "--out", str(out), "--resume"],
        capture_output=True,
        text=True,
        timeout=30,
    )
    one_line_exit_2(proc, "FIFO")
    assert time.monotonic() - started < 10


def test_a_huge_sidecar_is_refused_by_its_size_without_reading_it(tmp_path, interrupted):
    side = store.settings_path(interrupted)
    with open(side, "r+b") as handle:
        handle.truncate(8 << 30)  # sparse: 8 GiB that would end in MemoryError if read
    refused_unchanged(interrupted, "larger than")


@pytest.mark.parametrize("where", ["after-the-rows", "whole-file"])
def test_a_rows_file_with_gigabytes_and_no_newline_is_refused_without_reading_it(interrupted, where):
    """A line is read at most 1 MiB at a time: rbi 2 read the whole file into memory."""
    if where == "whole-file":
        interrupted.write_bytes(b"")
    with open(interrupted, "r+b") as handle:
        handle.truncate(interrupted.stat().st_size + (8 << 30))  # sparse zeros, no newline
    refused_unchanged(interrupted, "longer than")


def test_a_sidecar_of_another_user_is_not_used(interrupted):
    if os.geteuid() != 0:
        pytest.skip("needs root to give a file to another user")
    os.chown(store.settings_path(interrupted), 65534, 65534)
    refused_unchanged(interrupted, "another user")


@pytest.mark.parametrize("content", [b"not json", b"[1, 2]", b"\xff\xfe", b'{"spin": "0"}', b"[" * 100000])
def test_a_sidecar_rbi_did_not_write_is_refused(interrupted, content):
    store.settings_path(interrupted).write_bytes(content)
    refused_unchanged(interrupted, "cannot resume")


@pytest.mark.parametrize("plant", ["symlink", "fifo", "other-user"])
def test_something_planted_at_the_lock_file_is_exit_2_and_followed_nowhere(tmp_path, plant):
    out = tmp_path / "s.csv"
    victim = tmp_path / "victim"
    victim.write_text("precious\n")
    lock = safe.beside(out, ".rbi-lock")
    if plant == "symlink":
        lock.symlink_to(victim)
    elif plant == "fifo":
        os.mkfifo(lock)
    else:
        if os.geteuid() != 0:
            pytest.skip("needs root to give a file to another user")
        lock.write_bytes(b"")
        os.chown(lock, 65534, 65534)
    refused_unchanged(out, "rbi-lock", resume=False)


@pytest.mark.parametrize("plant", ["symlink", "file", "other-user"])
def test_something_planted_at_the_rows_folder_is_exit_2_and_nothing_is_written_through_it(tmp_path, plant):
    pytest.importorskip("pyarrow")
    out = tmp_path / "s.parquet"
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    folder = store.rows_folder(out)
    if plant == "symlink":
        folder.symlink_to(elsewhere)
    elif plant == "file":
        folder.write_text("not a folder")
    else:
        if os.geteuid() != 0:
            pytest.skip("needs root to give a folder to another user")
        folder.mkdir()
        os.chown(folder, 65534, 65534)
    refused_unchanged(out, "rbi-rows", resume=False)
    assert list(elsewhere.iterdir()) == []


legal_names = st.text(
    st.characters(blacklist_categories=("Cs",), blacklist_characters="/\0"), min_size=1
).filter(lambda n: n not in (".", "..") and len(n.encode()) <= 255)


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(name=legal_names, other=legal_names)
def test_names_beside_any_legal_output_name_fit_and_stay_apart(name, other):
    for suffix in (store.SETTINGS_SUFFIX, store.ROWS_SUFFIX, ".rbi-lock"):
        path = safe.beside(Path("/some/folder") / name, suffix)
        encoded = os.fsencode(path.name)
        assert len(encoded) <= 255 and path.parent == Path("/some/folder")
        assert path.name.startswith(".") and path.name.endswith(suffix) and "/" not in path.name
        encoded.decode("utf-8")  # never a split character
        if other != name:
            assert safe.beside(Path("/some/folder") / other, suffix) != path


def test_a_sweep_into_a_255_byte_name_keeps_sidecars_and_resumes(tmp_path, monkeypatch, reference):
    """rbi 2's sidecar `.NAME.rbi-sweep.json` passed the 255-byte limit for long NAMEs."""
    out = tmp_path / ("é" * 125 + "x.csv")  # 255 bytes in UTF-8
    assert len(os.fsencode(out.name)) == 255
    restore = interrupt_after(monkeypatch, 1)
    assert rbi("sweep", *ARGS, "--out", out).returncode == 130
    restore()
    assert len(os.fsencode(store.settings_path(out).name)) <= 255 and store.settings_path(out).is_file()
    proc = rbi("sweep", *ARGS, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == reference.read_bytes()
    assert sorted(os.listdir(tmp_path)) == [out.name]


# --- item 2: --resume accepts only this sweep's own rows, and changes nothing otherwise -------


def _edit_row(out: Path, index: int, column: str, value: str) -> None:
    rows = rows_of(out)
    rows[index + 1][rows[0].index(column)] = value
    with open(out, "w", newline="") as handle:
        csv.writer(handle, lineterminator="\n").writerows(rows)


HOSTILE_EDITS = [
    ("max_tilt_deg", "inf"),
    ("max_tilt_deg", "-inf"),
    ("max_tilt_deg", "nan"),
    ("energy_drift", "1e400"),
    ("max_tilt_deg", "1_0.5"),
    ("max_tilt_deg", " 1.5"),
    ("max_tilt_deg", "0x10"),
    ("max_tilt_deg", "500.0"),
    ("max_tilt_deg", ""),
    ("spin", "150.5"),
    ("spin", "inf"),
    ("run", "3"),
    ("run", "-1"),
    ("run", "1.0"),
    ("steps", "-5"),
    ("steps", "3.0"),
    ("steps", "１２"),
    ("status", ""),
    ("status", '=HYPERLINK("x")'),
]


@pytest.mark.parametrize("column,value", HOSTILE_EDITS)
def test_a_row_the_sweep_could_not_have_written_is_refused_and_nothing_changes(interrupted, column, value):
    _edit_row(interrupted, 5, column, value)
    refused_unchanged(interrupted, "cannot resume")


def test_a_foreign_csv_is_refused_byte_identical_without_cutting_its_last_line(interrupted):
    interrupted.write_bytes(b"name,score\nada,1\nbob,2")  # rbi 2 cut "bob,2" off first
    refused_unchanged(interrupted, "columns")


def test_more_rows_than_the_grid_are_refused(interrupted, reference):
    """rbi 2 accepted them and reported "-100 failed"."""
    extra = reference.read_bytes() + reference.read_bytes().splitlines(keepends=True)[-1].replace(
        b"23,", b"24,", 1
    )
    interrupted.write_bytes(extra)
    refused_unchanged(interrupted, "more rows")


@pytest.mark.parametrize("change", ["swap", "drop-cell", "extra-cell", "nul", "latin1", "fragment", "blank"])
def test_a_damaged_rows_file_is_refused(interrupted, change):
    data = interrupted.read_bytes()
    lines = data.splitlines(keepends=True)
    if change == "swap":
        lines[3], lines[4] = lines[4], lines[3]
    elif change == "drop-cell":
        lines[3] = lines[3].replace(b",", b"", 1)
    elif change == "extra-cell":
        lines[3] = lines[3].rstrip(b"\n") + b",1.0\n"
    elif change == "nul":
        lines[3] = lines[3].replace(b"ok", b"o\0k")
    elif change == "latin1":
        lines[3] = lines[3].replace(b"ok", b"\xe9")
    elif change == "fragment":  # a partial last line that is not the next run's
        lines.append(b"99,150.0")
    else:
        lines.insert(3, b"\n")
    interrupted.write_bytes(b"".join(lines))
    refused_unchanged(interrupted, "cannot resume")


@settings(
    max_examples=40,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(text=st.text(st.characters(blacklist_characters='\n\r\0,"'), max_size=12))
def test_any_cell_spelling_the_sweep_never_writes_is_refused(interrupted, text):
    """A float cell is taken back only in the exact spelling rbi writes (shortest repr)."""
    try:
        canonical = repr(float(text)) == text
    except ValueError:
        canonical = False
    original = interrupted.read_bytes()
    _edit_row(interrupted, 7, "final_tilt_deg", text)
    try:
        if canonical or text == "":
            return
        refused_unchanged(interrupted, "cannot resume")
    finally:
        interrupted.write_bytes(original)


def test_a_partial_last_line_of_the_next_run_is_dropped_and_resume_completes_exactly(interrupted, reference):
    with open(interrupted, "ab") as handle:
        handle.write(b"16,184.7826086956")
    proc = rbi("sweep", *ARGS, "--out", interrupted, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert interrupted.read_bytes() == reference.read_bytes()
    assert sorted(os.listdir(interrupted.parent)) == ["part.csv"]


def test_a_resume_while_another_run_writes_the_output_is_exit_2(interrupted):
    from rbi.files.lock import OutputLock

    with OutputLock(interrupted, "test"):
        refused_unchanged(interrupted, "another rbi run")
    proc = rbi("sweep", *ARGS, "--out", interrupted, "--resume")
    assert proc.returncode == 0, proc.stderr


@pytest.mark.parametrize("damage", ["flip", "truncate", "extra-column", "inf", "gap", "foreign-file", "link"])
def test_a_tampered_parquet_chunk_is_refused_byte_identical(interrupted_parquet, damage):
    import pyarrow as pa
    import pyarrow.parquet as pq

    folder = store.rows_folder(interrupted_parquet)
    piece = folder / "000000000008.parquet"
    if damage == "flip":
        data = bytearray(piece.read_bytes())
        data[len(data) // 2] ^= 0xFF
        data[len(data) // 3] ^= 0xFF
        piece.write_bytes(bytes(data))
    elif damage == "truncate":  # footerless: what rbi 2 left after a full disk
        piece.write_bytes(piece.read_bytes()[:-20])
    elif damage in ("extra-column", "inf"):
        table = pq.read_table(piece)
        if damage == "inf":
            column = table.column_names.index("max_tilt_deg")
            table = table.set_column(column, "max_tilt_deg", pa.array([float("inf")] * table.num_rows))
        else:
            table = table.append_column("evil", pa.array([1.0] * table.num_rows))
        pq.write_table(table, piece)
    elif damage == "gap":
        piece.rename(folder / "000000000009.parquet")
    elif damage == "foreign-file":
        (folder / "notes.txt").write_text("hello")
    else:
        target = folder.parent / "elsewhere.parquet"
        piece.rename(target)
        piece.symlink_to(target)
    refused_unchanged(interrupted_parquet, "cannot resume")


def test_an_interrupted_parquet_sweep_resumes_to_the_rows_of_an_uninterrupted_one(
    interrupted_parquet, reference
):
    pq = pytest.importorskip("pyarrow.parquet")
    proc = rbi("sweep", *ARGS, "--out", interrupted_parquet, "--resume")
    assert proc.returncode == 0, proc.stderr
    got = pq.read_table(interrupted_parquet).to_pylist()
    want = rows_of(reference)
    assert len(got) == RUNS and [r["run"] for r in got] == list(range(RUNS))
    for row, line in zip(got, want[1:]):
        assert [
            "" if row[c] is None else repr(row[c]) if isinstance(row[c], float) else str(row[c])
            for c in want[0]
        ] == line
    assert sorted(os.listdir(interrupted_parquet.parent)) == ["part.parquet"]


def test_an_edited_spec_is_not_resumed_into_the_old_rows(tmp_path, monkeypatch):
    spec = tmp_path / "top.yaml"
    spec.write_bytes(BOLTED.read_bytes())
    args = [spec, *ARGS[1:]]
    restore = interrupt_after(monkeypatch, 1)
    out = tmp_path / "s.csv"
    assert rbi("sweep", *args, "--out", out).returncode == 130
    restore()
    spec.write_bytes(BOLTED.read_bytes().replace(b"0.02", b"0.03", 1))
    refused_unchanged(out, "spec_sha256", args=args)


def test_a_csv_killed_before_its_header_resumes(tmp_path, monkeypatch, reference):
    restore = interrupt_after(monkeypatch, 0)
    out = tmp_path / "s.csv"
    assert rbi("sweep", *ARGS, "--out", out).returncode == 130
    restore()
    out.write_bytes(b"")  # what a kill between creating the file and writing its header leaves
    proc = rbi("sweep", *ARGS, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == reference.read_bytes()


def test_an_output_name_with_control_characters_stays_one_escaped_line(tmp_path, monkeypatch):
    restore = interrupt_after(monkeypatch, 1)
    out = tmp_path / "a\nb\x1b[2J.csv"
    proc = rbi("sweep", *ARGS, "--out", out)
    restore()
    assert proc.returncode == 130 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert "\x1b" not in proc.stderr
    store.settings_path(out).write_bytes(b"{}")
    refused_unchanged(out, "other settings")


def test_a_fresh_sweep_replaces_an_existing_output_and_keeps_its_mode(tmp_path, reference):
    out = tmp_path / "s.csv"
    out.write_text("old rows\n")
    out.chmod(0o640)
    proc = rbi("sweep", *ARGS, "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == reference.read_bytes() and (out.stat().st_mode & 0o777) == 0o640


def test_an_existing_parquet_output_stays_until_the_new_sweep_completes(tmp_path, monkeypatch):
    pytest.importorskip("pyarrow")
    out = tmp_path / "s.parquet"
    out.write_bytes(b"yesterday's rows")
    restore = interrupt_after(monkeypatch, 1)
    assert rbi("sweep", *ARGS, "--out", out).returncode == 130
    restore()
    assert out.read_bytes() == b"yesterday's rows"


# --- item 2: a full disk keeps every finished row, for --resume ---------------------------------


def test_a_full_disk_mid_sweep_is_one_line_and_keeps_whole_chunks(tmp_path, monkeypatch, reference):
    """ENOSPC in the middle of a write (fault injection): the chunk being written is cut back,
    the rows before it stay, --resume completes the sweep exactly."""
    real = safe.write_all

    def fills_up(fd, data):
        if data.startswith(b"8,"):  # the disk is full half-way through the second chunk of rows
            os.write(fd, data[: len(data) // 2])
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        real(fd, data)

    monkeypatch.setattr(safe, "write_all", fills_up)
    monkeypatch.setattr("rbi.sweeps.runs.SweepJob.chunk_size", lambda self, threads: 8)
    out = tmp_path / "s.csv"
    proc = rbi("sweep", *ARGS, "--out", out)
    one_line_exit_2(proc, "No space left on device", "8 of 24 runs", "--resume")
    assert rows_of(out) == rows_of(reference)[:9]
    monkeypatch.setattr(safe, "write_all", real)
    proc = rbi("sweep", *ARGS, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == reference.read_bytes()


@pytest.fixture
def small_disk(tmp_path):
    """A 48 KiB tmpfs (root only), grown afterwards with ``grow()``."""
    if os.geteuid() != 0 or shutil.which("mount") is None:
        pytest.skip("needs root to mount a small file system")
    mount = tmp_path / "disk"
    mount.mkdir()
    if (
        subprocess.run(
            ["mount", "-t", "tmpfs", "-o", "size=48k", "tmpfs", str(mount)], capture_output=True
        ).returncode
        != 0
    ):
        pytest.skip("cannot mount a tmpfs here")
    try:
        yield mount, lambda: subprocess.run(["mount", "-o", "remount,size=4m", str(mount)], check=True)
    finally:
        subprocess.run(["umount", "-l", str(mount)], capture_output=True)


@pytest.mark.parametrize("extension", ["csv", "parquet"])
def test_a_really_full_disk_keeps_the_finished_rows_readable_for_resume(small_disk, tmp_path, extension):
    if extension == "parquet":
        pq = pytest.importorskip("pyarrow.parquet")
    mount, grow = small_disk
    out = mount / f"m.{extension}"
    proc = rbi("sweep", *MASS_ARGS, "--out", out)
    one_line_exit_2(proc, "No space left on device", "--resume")
    grow()
    proc = rbi("sweep", *MASS_ARGS, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    reference = tmp_path / f"r.{extension}"
    assert rbi("sweep", *MASS_ARGS, "--out", reference).returncode == 0
    if extension == "csv":
        assert out.read_bytes() == reference.read_bytes()
    else:
        assert pq.read_table(out).to_pylist() == pq.read_table(reference).to_pylist()
    assert sorted(os.listdir(mount)) == [out.name]


# --- items 2 and 8: a second writer, SIGTERM, and a resume that completes exactly -------------

SLOW_SWEEP = """
import sys, time
from rbi.sweeps import runs
real = runs.run_chunk
def slow(job, a, b, threads=0):
    time.sleep(0.3)
    return real(job, a, b, threads)
runs.run_chunk = slow
runs.SweepJob.chunk_size = lambda self, threads: 4
sys.argv = ["rbi", *sys.argv[1:]]
from rbi.cli.app import main
main()
"""


def test_sigterm_exits_143_with_one_line_and_resume_completes_exactly(tmp_path, reference):
    """A real process (chunks slowed down) stopped by SIGTERM: exit 143 and one line (rbi 2: 130);
    while it ran, a second run on the same output was exit 2 and changed nothing; --resume
    then gives byte for byte the rows of an uninterrupted sweep."""
    import signal

    out = tmp_path / "s.csv"
    proc = subprocess.Popen(
        [sys.executable, "-c", SLOW_SWEEP, "sweep", *map(str, ARGS), "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and (not out.exists() or out.read_bytes().count(b"\n") < 5):
            time.sleep(0.02)
        for second in (["--resume"], []):
            before = snapshot(tmp_path)
            one_line_exit_2(rbi("sweep", *ARGS, "--out", out, *second), "another rbi run")
            after = snapshot(tmp_path)
            assert after.pop("s.csv").startswith(before.pop("s.csv")) and after == before  # only A wrote
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 143 and err.startswith("rbi: terminated:") and len(err.splitlines()) == 1, err
    kept = out.read_bytes()
    assert 4 <= kept.count(b"\n") - 1 < RUNS and reference.read_bytes().startswith(kept)
    proc = rbi("sweep", *ARGS, "--out", out, "--resume")
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == reference.read_bytes()
    assert sorted(os.listdir(tmp_path)) == ["s.csv"]
