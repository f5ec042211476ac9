"""The DOP853 tableau rbi compiles (src/rbi/sim/_dop853_tableau.h) is scipy's (Hairer's) to the
last bit."""

import re
from pathlib import Path

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as reference

from rbi.sim import _dop853

HEADER = Path(_dop853.__file__).with_name("_dop853_tableau.h")


def header_tableau() -> dict[str, np.ndarray]:
    text = HEADER.read_text() if HEADER.exists() else Path("src/rbi/sim/_dop853_tableau.h").read_text()
    tableau = {}
    for name in ("A", "B", "C", "D", "E3", "E5"):
        block = re.search(rf"DOP853_{name}\[[^=]*=\s*\{{(.*?)\}};", text, re.S).group(1)
        numbers = [float(v) for v in re.findall(r"[-+]?\d[\d.e+-]*", block)]
        tableau[name] = np.array(numbers).reshape(getattr(reference, name).shape)
    return tableau


def test_every_coefficient_of_the_header_matches_scipy():
    for name, values in header_tableau().items():
        np.testing.assert_array_equal(values, getattr(reference, name), err_msg=name)


def test_tableau_consistency_conditions():
    tableau = header_tableau()
    # row sums of A equal the nodes C (a condition every Runge-Kutta tableau satisfies)
    np.testing.assert_allclose(tableau["A"][:12, :12].sum(axis=1), tableau["C"][:12], atol=1e-15)
    assert abs(tableau["B"].sum() - 1.0) < 1e-15
