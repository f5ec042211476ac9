"""The spec's identity a sweep records for --resume (its SHA-256) is of the bytes the loader read
(rbi.spec.load.read_spec), those the rows come from: the file is not read a second time, so a
spec edited, or replaced by a FIFO or a device, after it was loaded changes nothing. A regular
spec is hashed by its file's bytes exactly, as before (sidecars already written still resume); a
spec given as text, a dict or on standard input by its parsed form."""

from __future__ import annotations

import hashlib
import io
import json
import os
import sys
import threading

import pytest

import rbi
from rbi.sweeps import store
from rbi.sweeps.study import Study
from tests.conftest import BODIES
from tests.mesh_builders import box_mesh, write_binary_stl

BOLTED = BODIES / "top_bolted.yaml"
VARY = {"parts.bolt.mass": [0.01, 0.02]}
WAIT_SECONDS = 5.0


class Stop(Exception):
    pass


def stop_before_the_end(done, total):
    if done:
        raise Stop  # the rows are written, the sweep not finished: its settings stay


def recorded_identity(source, out) -> str:
    """spec_sha256 of the settings a sweep of ``source`` writes beside ``out`` (stopped before
    it ends, so they stay)."""
    with pytest.raises(Stop):
        rbi.sweep(source, mass_properties=True, vary=VARY, out=out, progress=stop_before_the_end)
    return json.loads(store.settings_path(out).read_bytes())["spec_sha256"]


def sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def parsed_form(raw) -> bytes:
    return json.dumps(raw, sort_keys=True, default=str).encode()


EDITED = BOLTED.read_bytes().replace(b"mass: 0.4", b"mass: 0.5", 1)


@pytest.mark.parametrize("given", ["path", "body", "body in other units"])
def test_a_spec_edited_after_loading_is_identified_by_the_bytes_loaded(tmp_path, monkeypatch, given):
    """The spec file is edited between the loader's read and the writing of the settings (the
    window rbi sweep FILE --out has): the recorded identity is of the bytes the rows come from,
    so --resume refuses the edited file; it used to hash the edited file and go on."""
    spec = tmp_path / "top.yaml"
    spec.write_bytes(BOLTED.read_bytes())
    assert EDITED != BOLTED.read_bytes()
    source = str(spec) if given == "path" else rbi.load(spec)
    if given == "body in other units":
        source = source.in_units("mm", "g")
    real = Study.store_settings

    def edited_first(self):
        spec.write_bytes(EDITED)
        return real(self)

    monkeypatch.setattr(Study, "store_settings", edited_first)
    out = tmp_path / "s.csv"
    assert recorded_identity(source, out) == sha(BOLTED.read_bytes())
    monkeypatch.setattr(Study, "store_settings", real)
    with pytest.raises(rbi.SpecError, match="cannot resume: .*spec_sha256"):
        rbi.sweep(spec, mass_properties=True, vary=VARY, out=out, resume=True)
    spec.write_bytes(BOLTED.read_bytes())
    assert len(rbi.sweep(spec, mass_properties=True, vary=VARY, out=out, resume=True)) == 2


@pytest.mark.parametrize("kind", ["fifo", "device"])
def test_a_spec_replaced_after_loading_never_stops_a_sweep_with_an_output(tmp_path, kind):
    """rbi.load reads the spec; it is then replaced by a FIFO with no writer (or a link to
    /dev/zero) before rbi.sweep writes the output's settings. The sweep ends at once, its
    identity the bytes loaded."""
    spec = tmp_path / "top.yaml"
    spec.write_bytes(BOLTED.read_bytes())
    body = rbi.load(spec)
    spec.unlink()
    if kind == "fifo":
        os.mkfifo(spec)
    else:
        spec.symlink_to("/dev/zero")
    result: list = []
    call = threading.Thread(
        target=lambda: result.append(
            rbi.sweep(body, mass_properties=True, vary=VARY, out=tmp_path / "s.csv")
        ),
        daemon=True,
    )
    call.start()
    call.join(WAIT_SECONDS)
    if call.is_alive():
        if kind == "fifo":  # let the blocked open() go, so the test ends
            os.close(os.open(spec, os.O_WRONLY | os.O_NONBLOCK))
        pytest.fail(f"the sweep waited on (or read without end) the {kind} its spec became")
    assert len(result[0]) == 2 and result[0].failed == 0
    assert recorded_identity(body, tmp_path / "again.csv") == sha(BOLTED.read_bytes())


@pytest.mark.parametrize("given", ["path", "body"])
def test_a_regular_spec_is_hashed_by_its_bytes_exactly(tmp_path, given):
    """The file's bytes as they are (a byte-order mark and CRLF line ends included, which the
    parsed text drops): the identity sidecars written before this change hold."""
    spec = tmp_path / "top.yaml"
    spec.write_bytes(b"\xef\xbb\xbf" + BOLTED.read_bytes().replace(b"\n", b"\r\n"))
    source = str(spec) if given == "path" else rbi.load(spec)
    assert recorded_identity(source, tmp_path / "s.csv") == sha(spec.read_bytes())
    assert recorded_identity(BOLTED, tmp_path / "b.csv") == sha(BOLTED.read_bytes())


@pytest.mark.parametrize("given", ["text", "dict", "stdin"])
def test_a_spec_given_as_text_a_dict_or_on_stdin_is_hashed_by_its_parsed_form(tmp_path, monkeypatch, given):
    text = BOLTED.read_text()
    raw = rbi.load(BOLTED)._raw
    monkeypatch.chdir(tmp_path)
    if given == "text":
        source = rbi.loads(text)
    elif given == "dict":
        source = rbi.load(raw)
    else:
        monkeypatch.setattr(sys, "stdin", io.StringIO(text))
        source = "-"
    assert recorded_identity(source, tmp_path / "s.csv") == sha(parsed_form(raw))


@pytest.mark.parametrize("changed", ["sub-assembly", "mesh"])
def test_resume_refuses_a_changed_file_the_spec_reads(tmp_path, changed):
    """rbi 5: the identity held the spec's bytes only, so --resume went on after a sub-assembly
    or a mesh the spec reads had changed, mixing rows of two bodies. Now the bytes of each file
    it reads are recorded too (``files_sha256``); the same files resume."""
    write_binary_stl(tmp_path / "block.stl", *box_mesh((0.1, 0.2, 0.3)))
    (tmp_path / "sub.yaml").write_text(
        "parts:\n  - {name: bolt, shape: sphere, radius: 0.01, center: [0, 0, 0], mass: 0.02}\n"
    )
    spec = tmp_path / "top.yaml"
    spec.write_text(
        "pivot: [0, 0, 0]\nparts:\n  - {name: block, shape: mesh, file: block.stl, mass: 1}\n"
        "  - {name: s, shape: assembly, file: sub.yaml, position: [0.05, 0, 0.1]}\n"
    )
    out = tmp_path / "s.csv"
    vary = {"parts.block.mass": [1.0, 2.0]}
    with pytest.raises(Stop):
        rbi.sweep(spec, mass_properties=True, vary=vary, out=out, progress=stop_before_the_end)
    recorded = json.loads(store.settings_path(out).read_bytes())
    edited = tmp_path / ("sub.yaml" if changed == "sub-assembly" else "block.stl")
    before = edited.read_bytes()
    assert recorded["files_sha256"] == [sha((tmp_path / n).read_bytes()) for n in ("block.stl", "sub.yaml")]
    if changed == "sub-assembly":
        edited.write_text(before.decode().replace("0.02", "0.03"))
    else:
        write_binary_stl(edited, *box_mesh((0.1, 0.2, 0.4)))
    with pytest.raises(rbi.SpecError, match="cannot resume: .*files_sha256"):
        rbi.sweep(spec, mass_properties=True, vary=vary, out=out, resume=True)
    edited.write_bytes(before)
    assert len(rbi.sweep(spec, mass_properties=True, vary=vary, out=out, resume=True)) == 2
