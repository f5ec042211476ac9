"""What reaches the terminal and spreadsheets: names from a spec cannot drive the terminal
(escape sequences, bells, bidi overrides are shown escaped), CSV cells from names cannot run as
formulas, terminals that cannot encode rbi's symbols get ASCII, Ctrl-C says so."""

from __future__ import annotations

import csv
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import rbi.cli.terminal  # noqa: F401  (registers the "rbi-ascii" codec error handler)
from tests.conftest import BODIES, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

RBI_SCRIPT = Path(sys.executable).with_name("rbi")

# Each would act on a terminal if printed raw: set the window title (OSC 0), write the
# clipboard (OSC 52), clear the screen (CSI 2J), ring the bell, a C1 CSI, reverse the text.
HOSTILE = {
    "OSC title": "\x1b]0;pwned\x07",
    "OSC 52 clipboard": "\x1b]52;c;cm0gLXJmIH4=\x07",
    "CSI clear": "\x1b[2J",
    "C1 CSI": "\x9b31m",
    "carriage return": "ok\rfake",
    "bidi override": "\u202eevil",
    "bidi isolate": "\u2066x\u2069",
}
RAW_CONTROLS = (
    [chr(c) for c in range(32) if chr(c) != "\n"]
    + [chr(c) for c in range(127, 160)]
    + ["\u202e", "\u2066", "\u2069", "\u200f"]
)


def _spec(tmp_path, body_name: str, part_name: str, mass: str = "1") -> Path:
    path = tmp_path / "hostile.yaml"
    path.write_text(
        json.dumps(
            {
                "name": body_name,
                "pivot": [0, 0, 0],
                "parts": [
                    {
                        "name": part_name,
                        "shape": "cylinder",
                        "mass": float(mass),
                        "radius": 0.02,
                        "start": [0, 0, 0],
                        "end": [0, 0, 0.1],
                    }
                ],
                "expect": {"mass": {"value": 1.0, "tol": "1%"}},
            }
        )
    )
    return path


def _assert_no_raw_controls(text: str) -> None:
    found = sorted({f"U+{ord(c):04X}" for c in text if c in RAW_CONTROLS})
    assert not found, (found, text)


@pytest.mark.parametrize("kind", sorted(HOSTILE))
@pytest.mark.parametrize("command", ["inertia", "principal", "parts", "momentum", "check"])
def test_names_reach_tables_and_titles_escaped(tmp_path, kind, command):
    payload = HOSTILE[kind]
    spec = _spec(tmp_path, f"body{payload}", f"part{payload}")
    extra = {"momentum": ["--omega", "0,0,10"]}.get(command, [])
    proc = rbi(command, spec, *extra)
    _assert_no_raw_controls(proc.stdout)
    _assert_no_raw_controls(proc.stderr)
    assert proc.returncode == 0, proc.stderr
    escapes = ("\\x", "\\u20", "\\r", "\\n", "\\t")
    assert any(e in proc.stdout for e in escapes), proc.stdout  # the payload, visibly escaped


@pytest.mark.parametrize("kind", sorted(HOSTILE))
def test_names_reach_input_errors_escaped(tmp_path, kind):
    spec = _spec(tmp_path, "body", f"part{HOSTILE[kind]}", mass="-1")
    proc = rbi("inertia", spec)
    one_line_exit_2(proc, "parts[0]", "mass")
    _assert_no_raw_controls(proc.stderr)


def test_usage_errors_and_file_names_are_escaped(tmp_path):
    proc = rbi("inertia", BODIES / "top.yaml", "--bogus\x1b]0;t\x07")
    one_line_exit_2(proc, "--bogus\\x1b]0;t\\x07")
    proc = rbi("inertia", tmp_path / "x\x1b[2J\u202e.yaml")
    one_line_exit_2(proc, "x\\x1b[2J\\u202e.yaml")
    proc = rbi("simulate", BODIES / "top.yaml", "--spin", "200", "--out", tmp_path / "o\x1b[2J.json")
    one_line_exit_2(proc, "\\x1b[2J")


def test_escaping_keeps_columns_aligned(tmp_path):
    """The escape is applied before the table is laid out: every row of the parts table has
    the same width."""
    spec = _spec(tmp_path, "b", "p\x1b[2Jq")
    lines = [line for line in rbi("parts", spec).stdout.splitlines()[1:] if line.strip()]
    assert len({len(line.rstrip()) for line in lines[:1]}) == 1
    assert any("p\\x1b[2Jq" in line for line in lines)


@pytest.mark.parametrize("name", ['=HYPERLINK("http://x","y")', "+cmd", "-2+3", "@SUM(A1)", "\tx", "\rx"])
def test_csv_cells_from_names_cannot_run_as_formulas(tmp_path, name):
    spec = _spec(tmp_path, name, name)
    proc = rbi("parts", spec, "--format", "csv")
    assert proc.returncode == 0, proc.stderr
    rows = list(csv.DictReader(io.StringIO(proc.stdout)))
    cell = rows[0]["name"]
    assert cell.startswith("'"), cell
    assert cell[1:2] in ("=", "+", "-", "@", "\\")
    # numbers are never touched, negative ones included
    assert float(rows[0]["mass"]) == 1.0 and rows[0]["center_of_mass_z"] == "0.05"


def test_csv_numbers_and_plain_names_are_untouched(tmp_path):
    from rbi.reprs import csv_text as to_csv

    text = to_csv([{"name": "wheel", "label": "-0.5", "x": -1.5, "note": "a-b"}])
    assert text.splitlines()[1] == "wheel,-0.5,-1.5,a-b"


# --- terminals that cannot encode rbi's symbols ------------------------------------------------


def _run_script(*args, env_extra=None):
    env = dict(os.environ, **(env_extra or {}))
    return subprocess.run([str(RBI_SCRIPT), *map(str, args)], capture_output=True, env=env, timeout=120)


@pytest.mark.parametrize("encoding", ["cp1252", "latin-1", "ascii"])
def test_a_terminal_without_utf8_gets_ascii_spellings(encoding, tmp_path):
    env = {"PYTHONIOENCODING": encoding}
    table = _run_script("principal", BODIES / "top_bolted.yaml", env_extra=env)
    assert table.returncode == 0, table.stderr
    text = table.stdout.decode(encoding)
    assert "kg*m^2" in text and "x10^-4" in text
    simulate = _run_script(
        "simulate", BODIES / "top.yaml", "--spin", "200", "--tilt", "5", "--duration", "0.1", env_extra=env
    )
    assert simulate.returncode == 0, simulate.stderr
    assert "deg" in simulate.stdout.decode(encoding) and "omega" in simulate.stdout.decode(encoding)
    spec = _spec(tmp_path, "body", "ω² — part", mass="-1")
    error = _run_script("inertia", spec, env_extra=env)
    assert error.returncode == 2 and len(error.stderr.splitlines()) == 1
    line = error.stderr.decode(encoding)
    assert "UnicodeEncodeError" not in line and "mass: must be greater than 0" in line
    # a character the encoding has is kept, one it lacks is spelled in ASCII
    expected = "ω² — part".encode(encoding, errors="rbi-ascii").decode(encoding)
    assert f"({expected})" in line and "omega" in expected
    if encoding == "ascii":
        assert expected == "omega^2 - part"
    ok = _run_script("principal", BODIES / "top_bolted.yaml", "--format", "json", env_extra=env)
    assert json.loads(ok.stdout.decode("ascii"))["mass"] == pytest.approx(0.52)


def test_c_locale_is_fine():
    proc = _run_script("principal", BODIES / "top.yaml", env_extra={"LANG": "C", "LC_ALL": "C"})
    assert proc.returncode == 0 and not proc.stderr, proc.stderr


# --- Ctrl-C ------------------------------------------------------------------------------------


@pytest.mark.skipif(not RBI_SCRIPT.is_file(), reason="needs the installed rbi script")
def test_ctrl_c_says_interrupted_exits_130_and_writes_nothing(tmp_path):
    out = tmp_path / "long.csv"
    proc = subprocess.Popen(
        [
            str(RBI_SCRIPT),
            "simulate",
            str(BODIES / "top.yaml"),
            "--spin",
            "200",
            "--tilt",
            "5",
            "--duration",
            "1000000",
            "--yes",
            "--max-steps",
            "1000000000000",
            "--out",
            str(out),
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=tmp_path,
    )
    try:
        _wait_until_running(proc)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 130
    assert err.strip().splitlines() == ["rbi: interrupted"]
    assert list(tmp_path.iterdir()) == []


def _wait_until_running(proc) -> None:
    """Give the process time to get into its integration (the start-up imports are done once
    it has used a little CPU time); never longer than a minute."""
    deadline = time.monotonic() + 60
    stat = Path(f"/proc/{proc.pid}/stat")
    while time.monotonic() < deadline and proc.poll() is None:
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
            if int(fields[11]) + int(fields[12]) > 150:  # utime + stime, in clock ticks (1.5 s)
                return
        except (OSError, IndexError, ValueError):
            pass
        time.sleep(0.1)
    assert proc.poll() is None, proc.communicate()


def test_warnings_name_parts_escaped(tmp_path):
    """rbi parts warns about an implausible density naming the part: escaped like errors."""
    path = tmp_path / "light.yaml"
    path.write_text(
        json.dumps(
            {
                "parts": [
                    {
                        "name": "ball\x1b]0;t\x07",
                        "shape": "sphere",
                        "mass": 1e-6,
                        "radius": 1,
                        "center": [0, 0, 0],
                    }
                ]
            }
        )
    )
    proc = rbi("parts", path)
    assert proc.returncode == 0 and "warning" in proc.stderr, proc.stderr
    assert "ball\\x1b]0;t\\x07" in proc.stderr
    _assert_no_raw_controls(proc.stderr)


def test_validate_lists_problems_escaped(tmp_path):
    spec = _spec(tmp_path, "b", "p\x1b[2J", mass="-1")
    proc = rbi("validate", spec)
    assert proc.returncode == 2 and "p\\x1b[2J" in proc.stdout
    _assert_no_raw_controls(proc.stdout)


# --- standard output that cannot be written -------------------------------------------------

UNWRITABLE_STDOUT = {
    # /dev/full: every write fails with ENOSPC, as on a full disk
    "full device": lambda: {"stdout": open("/dev/full", "w")},  # noqa: SIM115
    # `rbi ... >&-`: no file descriptor 1 at all
    "closed": lambda: {"stdout": None, "pass_fds": (), "preexec_fn": lambda: os.close(1)},
}


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("how", sorted(UNWRITABLE_STDOUT))
@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_unwritable_stdout_is_one_line_exit_2(how, form):
    """Results that cannot reach standard output are one line naming it, exit 2: not an
    internal error (exit 1, "AttributeError"/"OSError"), not a Python 'Exception ignored' at exit."""
    streams = UNWRITABLE_STDOUT[how]()
    try:
        done = subprocess.run(
            [str(RBI_SCRIPT), "inertia", str(BODIES / "top.yaml"), "--format", form],
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
            **streams,
        )
    finally:
        if streams.get("stdout") is not None:
            streams["stdout"].close()
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2, done.stderr
    assert len(lines) == 1 and lines[0].startswith("rbi: standard output: cannot write"), done.stderr
    assert "internal error" not in done.stderr and "Exception" not in done.stderr


READER_GONE = {
    "check of several files": ["check", "bracket.yaml", "wheel_pattern.yaml"],
    "inertia of several files": ["inertia", "top.yaml", "tbar.yaml"],
    "one audit": ["audit", "two_link_arm.urdf"],
    "a sweep": ["sweep", "top.yaml", "--spin", "1:100:40", "--duration", "0.01", "--samples", "3"],
    "the trajectory to standard output": ["simulate", "top.yaml", "--spin", "9", "--out", "-"],
}


READER_GONE_RUNS = [
    (case, form)
    for case, args in READER_GONE.items()
    for form in ([None] if "--out" in args else ["table", "json", "csv"])  # --out: the file's own form
]


@pytest.mark.parametrize(("case", "form"), READER_GONE_RUNS)
def test_a_reader_that_left_ends_the_run_quietly_with_status_0(case, form):
    """`rbi check a.yaml b.yaml | head -1`: the reader leaving is not a failed check (exit 1) nor
    an error; a run with nothing failed ends quietly with status 0, as a single-file run whose reader left
    after its first line did. (Click and rich each turned a broken pipe into a silent exit 1.)"""
    args = READER_GONE[case] + (["--format", form] if form else [])
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader is gone before rbi writes anything
    try:
        done = subprocess.run(
            [str(RBI_SCRIPT), *args], cwd=BODIES, stdout=write_end, stderr=subprocess.PIPE, timeout=120
        )
    finally:
        os.close(write_end)
    assert done.returncode == 0, done.stderr
    assert b"Traceback" not in done.stderr and b"Exception" not in done.stderr
    assert all(line.startswith(b"rbi: ") for line in done.stderr.splitlines()), done.stderr


KNOWN_STATUS = {  # (files written into the run's folder, arguments, the status known before any output)
    "a failed check": (["fails.yaml"], ["check", "fails.yaml"], 1),
    "a failed check, then a good file": (["fails.yaml"], ["check", "fails.yaml", BODIES / "top.yaml"], 1),
    "a bad file, then a good one": ([], ["check", "missing.yaml", BODIES / "bracket.yaml"], 2),
    "a flagged link": (["flagged.urdf"], ["audit", "flagged.urdf"], 1),
    "an invalid spec": (["invalid.yaml"], ["validate", "invalid.yaml"], 2),
}
KNOWN_STATUS_FILES = {
    # 1 kg point mass checked against 2 kg: fails
    "fails.yaml": "parts: [{shape: point, mass: 1, position: [0, 0, 0]}]\nexpect: {mass: {value: 2, tol: 1%}}\n",
    # a negative principal moment: unphysical, an error-level flag
    "flagged.urdf": '<robot name="r"><link name="base"><inertial><mass value="1"/>'
    '<inertia ixx="-1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>',
    "invalid.yaml": "parts: [{shape: point}]\n",  # no mass, no position
}


@pytest.mark.parametrize("form", ["table", "json", "csv"])
@pytest.mark.parametrize("case", KNOWN_STATUS)
def test_a_reader_that_left_keeps_the_status_already_known(tmp_path, case, form):
    """`rbi check fails.yaml ok.yaml | head -1`: the failed check (1) or bad file (2) was known
    before the reader left, so the run still ends with it (it ended with 0 on 64c62c3: checked)."""
    names, args, status = KNOWN_STATUS[case]
    for name in names:
        (tmp_path / name).write_text(KNOWN_STATUS_FILES[name])
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader is gone before rbi writes anything
    try:
        done = subprocess.run(
            [str(RBI_SCRIPT), *map(str, args), "--format", form],
            cwd=tmp_path,
            stdout=write_end,
            stderr=subprocess.PIPE,
            timeout=120,
        )
    finally:
        os.close(write_end)
    assert done.returncode == status, done.stderr
    assert b"Traceback" not in done.stderr and b"internal error" not in done.stderr
