"""rbi.core.uncertainty: the law of propagation's root-sum-square against Python's
``math.hypot``, which neither overflows nor underflows (an independent answer)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from rbi.core.uncertainty import combined

terms = st.lists(
    st.floats(min_value=-1e300, max_value=1e300, allow_nan=False, allow_subnormal=False),
    min_size=1,
    max_size=6,
)


@given(terms)
def test_combined_is_the_root_sum_square_at_any_magnitude(values):
    """Found: squares of 1e217 (a cone 1e110 m across, ± 1%) overflowed, and the inertia's
    uncertainty came out inf (an internal error when written as JSON); squares of 1e-169
    underflowed to a printed ± 0."""
    got = combined(np.array([values]), np.ones(len(values)))[0]
    expected = math.hypot(*values)
    assert np.isfinite(got)
    assert got == expected or abs(got - expected) <= 1e-14 * expected


def test_ordinary_terms_keep_the_plain_formula():
    """Terms of ordinary size are summed as √Σ(∂y/∂x·u)², no rescaling."""
    s, u = np.array([[3.0, 4.0], [1e-3, 2e-3]]), np.array([1.0, 2.0])
    np.testing.assert_array_equal(combined(s, u), np.sqrt(np.sum((s * u) ** 2, axis=-1)))
