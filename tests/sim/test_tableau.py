"""The DOP853 tableau rbi compiles is scipy's (Hairer's) to the last bit."""

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as reference

from rbi.sim import dop853_tableau as tableau


def test_every_coefficient_matches_scipy():
    for name in ("A", "B", "C", "D", "E3", "E5"):
        np.testing.assert_array_equal(getattr(tableau, name), getattr(reference, name), err_msg=name)


def test_tableau_consistency_conditions():
    # row sums of A equal the nodes C (a condition every Runge-Kutta tableau satisfies)
    np.testing.assert_allclose(tableau.A[:12, :12].sum(axis=1), tableau.C[:12], atol=1e-15)
    assert abs(tableau.B.sum() - 1.0) < 1e-15
