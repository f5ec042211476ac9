"""rbi.sweep's files: rows streamed to ``out`` (CSV), a sweep resumed from it, progress, a spec
given by its path, and the stability map drawn by ``SweepTable.plot``; the bolted top's mass
properties checked against the sum of its parts."""

from __future__ import annotations

import csv

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES

BOLTED = BODIES / "top_bolted.yaml"
BOLT_MASSES = [0.01, 0.02, 0.03]


def rows_of(path) -> list[dict[str, str]]:
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_out_streams_the_mass_properties_of_each_bolt(tmp_path):
    out = tmp_path / "bolts.csv"
    told = []
    table = rbi.sweep(
        BOLTED,
        mass_properties=True,
        vary={"parts.bolt.mass": BOLT_MASSES},
        out=out,
        progress=lambda done, total: told.append((done, total)),
    )
    assert (table.count, table.held, len(table)) == (3, True, 3)
    assert told[0] == (0, 3) and told[-1] == (3, 3)
    rows = rows_of(out)
    m = np.array(BOLT_MASSES)
    # cone 0.4 kg and stem 0.1 kg on the axis; the bolt at x = 0.04 m
    np.testing.assert_allclose([float(r["mass"]) for r in rows], 0.5 + m, rtol=1e-15)
    np.testing.assert_allclose([float(r["com_x"]) for r in rows], m * 0.04 / (0.5 + m), rtol=1e-12)
    np.testing.assert_allclose(table["com_x"], m * 0.04 / (0.5 + m), rtol=1e-12)


def test_an_interrupted_sweep_resumes_where_its_file_stopped(tmp_path):
    out = tmp_path / "bolts.csv"
    masses = {"parts.bolt.mass": rbi.Grid(0.01, 0.03, 600)}
    told = []

    def stop_after_the_first_chunk(done, total):
        told.append((done, total))
        if 0 < done < total:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rbi.sweep(BOLTED, mass_properties=True, vary=masses, out=out, progress=stop_after_the_first_chunk)
    kept = len(rows_of(out))
    assert 0 < kept < 600 and told[-1] == (kept, 600)  # the last word: the runs the file kept
    told.clear()
    table = rbi.sweep(
        BOLTED,
        mass_properties=True,
        vary=masses,
        out=out,
        resume=True,
        progress=lambda done, total: told.append((done, total)),
    )
    assert told[0] == (kept, 600) and told[-1] == (600, 600)
    m = np.linspace(0.01, 0.03, 600)
    np.testing.assert_allclose(table["mass"], 0.5 + m, rtol=1e-15)
    np.testing.assert_allclose([float(r["mass"]) for r in rows_of(out)], 0.5 + m, rtol=1e-15)


def test_a_spec_path_sweeps_as_its_body(tmp_path):
    by_path = rbi.sweep(str(BOLTED), spin=[100.0, 200.0], tilt_deg=0.01, duration=0.2, workers=1)
    by_body = rbi.sweep(rbi.load(BOLTED), spin=[100.0, 200.0], tilt_deg=0.01, duration=0.2, workers=1)
    assert by_path.records() == by_body.records()
    assert by_path.name == "bolted-top" and by_path.count == 2


def test_plot_draws_the_map_of_a_simulated_sweep(tmp_path):
    pytest.importorskip("matplotlib")
    table = rbi.sweep(BOLTED, spin=rbi.Grid(100.0, 300.0, 3), tilt_deg=0.01, duration=0.2, workers=1)
    table.plot(tmp_path / "map.png")
    assert (tmp_path / "map.png").read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_plot_refuses_a_study_of_mass_properties(tmp_path):
    table = rbi.sweep(BOLTED, mass_properties=True, vary={"parts.bolt.mass": BOLT_MASSES})
    with pytest.raises(ValueError, match=r"^plot: a map needs simulated runs \(not mass_properties\)$"):
        table.plot(tmp_path / "map.png")
    assert not (tmp_path / "map.png").exists()
