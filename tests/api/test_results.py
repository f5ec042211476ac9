"""The tables of `rbi.api.results` for a spec with ±: values printed ``value ± u`` (contract,
fifth round: 'Tables print value ± u' for inertia, principal, momentum and parts)."""

from __future__ import annotations

import pytest

import rbi
from tests.conftest import run_rbi_inprocess

SPEC = """
units: {length: mm, mass: g}
parts:
  - {name: c, shape: cone, mass: "400 ± 4", radius: 40, apex: [0, 0, 0], base: [0, 0, 60]}
  - {name: bolt, shape: point, mass: "20 ± 1", position: ["40 ± 0.05", 0, 60]}
"""


def test_parts_table_prints_value_plus_minus_u(tmp_path):
    spec = tmp_path / "cone.yaml"
    spec.write_text(SPEC)
    text = str(rbi.load(spec).parts())
    assert "400 ± 4 " in text and "20 ± 1 " in text  # each part's mass
    assert "420 ± 4.1 " in text  # the total: u = √(4² + 1²) = 4.12
    assert "40 ± 0.05 " in text  # the bolt's x
    # the body's x = 20·40/420 = 1.905; u² = (x_b m_b/M²·u_c)² + (x_b m_c/M²·u_b)² + (m_b/M·u_x)²
    m_c, m_b, x_b, big = 400.0, 20.0, 40.0, 420.0
    u = ((x_b * m_b / big**2 * 4) ** 2 + (x_b * m_c / big**2 * 1) ** 2 + (m_b / big * 0.05) ** 2) ** 0.5
    assert f"1.9 ± {u:.2g} " in text
    proc = run_rbi_inprocess("parts", str(spec))
    assert proc.returncode == 0 and "420 ± 4.1 " in proc.stdout
    assert max(map(len, proc.stdout.splitlines())) <= 80


def test_principal_csv_numbers_the_axes_uncertainty_by_axis(tmp_path):
    # a 0.4 × 0.2 plate turned 30 ± 0.5° about z: its in-plane principal axes are uncertain by
    # 0.5°, the normal (z) not at all; the columns are per principal axis (_1 _2 _3), not x y z
    spec = tmp_path / "plate.yaml"
    spec.write_text(
        "parts: [{name: p, shape: box, size: [0.4, 0.2, 0.01], mass: 3, center: [0, 0, 0],"
        ' rotation: {axis: [0, 0, 1], angle_deg: "30 ± 0.5"}}]\n'
    )
    frame = rbi.load(spec).principal().to_pandas()
    assert [frame[f"uncertainty_axes_deg_{i}"][0] for i in (1, 2, 3)] == pytest.approx(
        [0.5, 0.5, 0.0], abs=1e-9
    )
    assert "uncertainty_axes_deg_x" not in frame
    proc = run_rbi_inprocess("principal", str(spec), "--format", "csv")
    header = proc.stdout.splitlines()[0].split(",")
    assert [c for c in header if "axes_deg" in c] == [f"uncertainty_axes_deg_{i}" for i in (1, 2, 3)]
