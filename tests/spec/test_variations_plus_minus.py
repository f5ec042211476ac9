"""`rbi sweep --vary PATH` where the spec writes PATH's number with its uncertainty
(``"400 ± 4"``): the path `rbi uncertainty` names an input by is one a sweep can vary (contract,
fifth round), each run setting the value."""

from __future__ import annotations

import csv
import io

import pytest

from tests.conftest import run_rbi_inprocess

SPEC = """
parts:
  - {name: c, shape: cone, mass: "400 ± 4", radius: 40, apex: [0, 0, 0], base: [0, 0, 60]}
  - {name: bolt, shape: point, mass: 20, position: ["40 ± 0.05", 0, 60]}
"""


def test_a_number_written_with_its_uncertainty_can_be_varied(tmp_path):
    spec = tmp_path / "cone.yaml"
    spec.write_text(SPEC)
    proc = run_rbi_inprocess(
        "sweep", str(spec), "--vary", "parts.c.mass=300:500:3", "--mass-properties", "--format", "csv"
    )
    assert proc.returncode == 0, proc.stderr
    rows = list(csv.DictReader(io.StringIO(proc.stdout)))
    assert [float(r["mass"]) for r in rows] == pytest.approx([320.0, 420.0, 520.0], rel=1e-15)
    # the bolt's 20 kg at x = 40: the body's x = 800 / M
    assert [float(r["com_x"]) for r in rows] == pytest.approx([800 / 320, 800 / 420, 800 / 520], rel=1e-14)
    drawn = run_rbi_inprocess(
        "sweep", str(spec), "--vary", "parts.bolt.position[0]=uniform(30,50)", "--runs", "3", "--seed", "1",
        "--mass-properties", "--format", "csv",
    )  # fmt: skip
    assert drawn.returncode == 0, drawn.stderr
    for row in csv.DictReader(io.StringIO(drawn.stdout)):
        assert 30 <= float(row["parts.bolt.position[0]"]) <= 50
        assert float(row["com_x"]) == pytest.approx(
            20 * float(row["parts.bolt.position[0]"]) / 420, rel=1e-14
        )
