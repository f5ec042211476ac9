"""The spec's identity a sweep records for --resume (its SHA-256) is read through the one capped
reader of input files (rbi.files.safe.read_input_file): a spec that has become a FIFO or a
device since it was loaded is never waited on or read without end; a regular spec is hashed by
its bytes, as before."""

from __future__ import annotations

import hashlib
import json
import os
import threading

import pytest

import rbi
from rbi.sweeps.study import Study, SweepSettings
from tests.conftest import BODIES

BOLTED = BODIES / "top_bolted.yaml"
SETTINGS = SweepSettings(mass_properties=True, vary=(("parts.bolt.mass", [0.01, 0.02]),))
WAIT_SECONDS = 5.0


@pytest.mark.parametrize("kind", ["fifo", "device"])
def test_a_spec_replaced_after_loading_never_stops_a_sweep_with_an_output(tmp_path, kind):
    """rbi.load reads the spec; it is then replaced by a FIFO with no writer (or a link to
    /dev/zero) before rbi.sweep hashes it for the output's settings. The sweep ends at once, its
    identity the parsed spec's, as for a spec given as text."""
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
            rbi.sweep(
                body, mass_properties=True, vary={"parts.bolt.mass": [0.01, 0.02]}, out=tmp_path / "s.csv"
            )
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
    parsed = json.dumps(body._raw, sort_keys=True, default=str).encode()
    hashed = Study(str(spec), body._raw, SETTINGS, rows_printed=False).store_settings()["spec_sha256"]
    assert hashed == hashlib.sha256(parsed).hexdigest()


def test_a_regular_spec_is_hashed_by_its_bytes():
    study = Study(str(BOLTED), rbi.load(BOLTED)._raw, SETTINGS, rows_printed=False)
    assert study.store_settings()["spec_sha256"] == hashlib.sha256(BOLTED.read_bytes()).hexdigest()
