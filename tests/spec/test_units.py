"""Units: a spec written in mm/g (or in/lb) gives its results in mm/g (in/lb), equal to the
same body in m/kg converted by hand with the exact unit definitions."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG, gravity_in, unit_labels
from tests.conftest import run_rbi_inprocess

# The bolted top in SI, and the same body written in other units. Every length is scaled by
# 1/L and every mass by 1/M, where L and M are the unit sizes in metres and kilograms.
SI_PARTS = [
    ("cone", 0.4, 0.04, [0.0, 0.0, 0.0], [0.0, 0.0, 0.06]),
    ("cylinder", 0.1, 0.008, [0.0, 0.0, 0.06], [0.0, 0.0, 0.10]),
]
SI_BOLT = (0.02, [0.04, 0.0, 0.06])
SI_PIVOT = [0.0, 0.0, -0.01]


def spec_text(length_unit: str, mass_unit: str, L: float, M: float) -> str:
    def vec(v):
        return "[" + ", ".join(repr(x / L) for x in v) + "]"

    lines = [f"units: {{length: {length_unit}, mass: {mass_unit}}}", f"pivot: {vec(SI_PIVOT)}", "parts:"]
    for shape, mass, radius, a, b in SI_PARTS:
        ends = ("apex", "base") if shape == "cone" else ("start", "end")
        lines += [
            f"  - shape: {shape}",
            f"    mass: {mass / M!r}",
            f"    radius: {radius / L!r}",
            f"    {ends[0]}: {vec(a)}",
            f"    {ends[1]}: {vec(b)}",
        ]
    lines += ["  - shape: point", f"    mass: {SI_BOLT[0] / M!r}", f"    position: {vec(SI_BOLT[1])}"]
    return "\n".join(lines) + "\n"


def rbi_json(*args):
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


# Exact definitions (NIST): 1 in = 0.0254 m, 1 ft = 0.3048 m, 1 lb = 0.45359237 kg.
UNIT_SETS = [
    ("mm", "g", 1e-3, 1e-3),
    ("cm", "kg", 1e-2, 1.0),
    ("in", "lb", 0.0254, 0.45359237),
    ("ft", "g", 0.3048, 1e-3),
]


@pytest.mark.parametrize("length_unit, mass_unit, L, M", UNIT_SETS)
def test_results_come_back_in_the_files_units(write_spec, length_unit, mass_unit, L, M):
    si = write_spec(spec_text("m", "kg", 1.0, 1.0), name="si.yaml")
    other = write_spec(spec_text(length_unit, mass_unit, L, M), name="other.yaml")
    for about in ("com", "pivot"):
        a, b = rbi_json("inertia", si, "--about", about), rbi_json("inertia", other, "--about", about)
        assert b["units"] == {"length": length_unit, "mass": mass_unit}
        assert b["mass"] == pytest.approx(a["mass"] / M, rel=1e-12)
        np.testing.assert_allclose(
            b["center_of_mass"], np.array(a["center_of_mass"]) / L, rtol=1e-12, atol=1e-12
        )
        np.testing.assert_allclose(b["about"], np.array(a["about"]) / L, rtol=1e-12, atol=1e-12)
        expected = np.array(a["inertia"]) / (M * L * L)
        np.testing.assert_allclose(b["inertia"], expected, rtol=1e-10, atol=1e-12 * np.abs(expected).max())
    w = "0.5,-1.0,30.0"
    a, b = rbi_json("momentum", si, "--omega", w), rbi_json("momentum", other, "--omega", w)
    np.testing.assert_allclose(
        b["angular_momentum"], np.array(a["angular_momentum"]) / (M * L * L), rtol=1e-10
    )
    assert b["kinetic_energy"] == pytest.approx(a["kinetic_energy"] / (M * L * L), rel=1e-10)
    assert b["angle_deg"] == pytest.approx(a["angle_deg"], rel=1e-9)


def test_density_is_mass_per_cubic_length_unit(write_spec):
    # Steel, 7850 kg/m³ = 0.00785 g/mm³: a 20 mm × 100 mm rod weighs 7850 π 0.01² 0.1 kg.
    si = write_spec(
        "parts:\n  - {shape: cylinder, density: 7850.0, radius: 0.01, start: [0, 0, 0], end: [0.1, 0, 0]}\n"
    )
    mm = write_spec(
        "units: {length: mm, mass: g}\n"
        "parts:\n  - {shape: cylinder, density: 0.00785, radius: 10.0, start: [0, 0, 0], end: [100.0, 0, 0]}\n",
        name="mm.yaml",
    )
    kg = 7850.0 * np.pi * 0.01**2 * 0.1
    assert rbi_json("inertia", si)["mass"] == pytest.approx(kg, rel=1e-13)
    assert rbi_json("inertia", mm)["mass"] == pytest.approx(1000.0 * kg, rel=1e-13)


def test_table_headers_carry_the_files_units(write_spec):
    path = write_spec(spec_text("mm", "g", 1e-3, 1e-3))
    for args, labels in (
        (["inertia"], ["g·mm²", "mm", " g "]),
        (["principal"], ["g·mm²"]),
        (["momentum", "--omega", "0,0,100"], ["g·mm²/s", "rad/s", "g·mm²/s²"]),
    ):
        proc = run_rbi_inprocess(args[0], path, *args[1:])
        assert proc.returncode == 0, proc.stderr
        for label in labels:
            assert label in proc.stdout, (args, label, proc.stdout)
        assert "kg" not in proc.stdout


def test_unit_tables_hold_the_exact_definitions():
    assert LENGTH_UNITS_IN_M == {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
    assert MASS_UNITS_IN_KG == {"kg": 1.0, "g": 0.001, "lb": 0.45359237}
    assert gravity_in("mm") == pytest.approx(9810.0, rel=1e-15)
    assert gravity_in("ft") == pytest.approx(9.81 / 0.3048, rel=1e-15)
    labels = unit_labels("in", "lb")
    assert labels["inertia"] == "lb·in²" and labels["angular_momentum"] == "lb·in²/s"
