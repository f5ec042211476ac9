"""rbi.sim.elliptic (plain-Python Carlson integrals) against scipy.special, and the closed-form
facts of a Lagrange top computed without importing scipy."""

from __future__ import annotations

import math
import subprocess
import sys

import pytest
import scipy.special as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.sim import elliptic

positive = st.floats(1e-6, 1e3)


@settings(max_examples=300, deadline=None)
@given(positive, positive, positive, st.booleans())
def test_rf_matches_scipy(x, y, z, zero_x):
    x = 0.0 if zero_x else x
    assert elliptic.carlson_rf(x, y, z) == pytest.approx(float(sp.elliprf(x, y, z)), rel=4e-15)


@settings(max_examples=300, deadline=None)
@given(positive, positive, positive, positive, st.booleans())
def test_rj_matches_scipy(x, y, z, p, zero_x):
    x = 0.0 if zero_x else x
    assert elliptic.carlson_rj(x, y, z, p) == pytest.approx(float(sp.elliprj(x, y, z, p)), rel=4e-15)


@settings(max_examples=300, deadline=None)
@given(st.floats(0.0, 0.9999), st.floats(-20.0, 20.0), st.floats(-50.0, 0.999))
def test_k_f_and_pi_match_scipy(m, phi, n):
    assert elliptic.ellipk(m) == pytest.approx(float(sp.ellipk(m)), rel=4e-15)
    assert elliptic.ellipkinc(phi, m) == pytest.approx(float(sp.ellipkinc(phi, m)), rel=4e-15, abs=1e-300)
    reference = float(sp.elliprf(0, 1 - m, 1) + n / 3 * sp.elliprj(0, 1 - m, 1, 1 - n))
    assert elliptic.ellippi(n, m) == pytest.approx(reference, rel=4e-15)


def test_known_values():
    # K(0) = Π(0|0) = π/2; K(1/2) = Γ(1/4)² / (4 √π); Π(n|0) = π / (2 √(1 − n))
    assert elliptic.ellipk(0.0) == pytest.approx(math.pi / 2, rel=1e-16)
    assert elliptic.ellipk(0.5) == pytest.approx(math.gamma(0.25) ** 2 / (4 * math.sqrt(math.pi)), rel=2e-15)
    assert elliptic.ellippi(0.3, 0.0) == pytest.approx(math.pi / (2 * math.sqrt(0.7)), rel=2e-15)
    assert elliptic.ellippi(-2.0, 0.0) == pytest.approx(math.pi / (2 * math.sqrt(3.0)), rel=2e-15)


def test_bad_arguments_raise():
    with pytest.raises(ValueError):
        elliptic.carlson_rf(0.0, 0.0, 1.0)
    with pytest.raises(ValueError):
        elliptic.carlson_rj(1.0, 1.0, 1.0, 0.0)
    with pytest.raises(ValueError):
        elliptic.ellipk(1.0)


def test_simulating_a_symmetric_top_imports_no_scipy(tmp_path):
    """`rbi simulate` on an axisymmetric top reports its closed-form facts without scipy."""
    from pathlib import Path

    top = Path(__file__).resolve().parents[2] / "bodies" / "top.yaml"
    code = (
        "import sys, json\nfrom rbi.cli.app import main\n"
        "sys.argv = ['rbi', 'simulate', sys.argv[1], '--spin', '200', '--tilt', '10', '--format', 'json']\n"
        "try:\n    main()\nexcept SystemExit:\n    pass\n"
        "print('SCIPY', any(m == 'scipy' or m.startswith('scipy.') for m in sys.modules), file=sys.stderr)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code, str(top)], capture_output=True, text=True)
    assert "SCIPY False" in proc.stderr, proc.stderr
    import json

    facts = json.loads(proc.stdout)
    text = json.dumps(facts)
    assert "nutation_period_s" in text
    # a heavy asymmetric top has no closed form, and finding that out loads no scipy either
    bolted = top.with_name("top_bolted.yaml")
    proc = subprocess.run([sys.executable, "-c", code, str(bolted)], capture_output=True, text=True)
    assert "SCIPY False" in proc.stderr, proc.stderr
    assert json.loads(proc.stdout)["closed_form"] is None
