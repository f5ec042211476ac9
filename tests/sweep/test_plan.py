"""The runs of a sweep: axes as written, the product order, reproducible draws."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.sweep.plan import Draw, GridAxis, Plan, parse_axis


def test_range_single_value_and_draws_parse():
    assert parse_axis("spin", "150:250:3") == GridAxis("spin", 150.0, 250.0, 3)
    np.testing.assert_array_equal(parse_axis("spin", "150:250:3").values(), [150, 200, 250])
    assert parse_axis("spin", "200") == GridAxis("spin", 200.0, 200.0, 1)
    assert parse_axis("spin", "1:1:1").values().tolist() == [1.0]
    assert parse_axis("x", "normal(0.02, 0.001)") == Draw("x", "normal", 0.02, 0.001)
    assert parse_axis("x", "uniform(-1e-3,2e-3)") == Draw("x", "uniform", -1e-3, 2e-3)


@pytest.mark.parametrize(
    "text",
    [
        "1:2",
        "a:b:3",
        "1:2:0",
        "1:2:-3",
        "nan",
        "inf:1:2",
        "normal(1)",
        "uniform(2,1)",
        "normal(0,-1)",
        "1:2:3:4",
        "",
        "1:2:1e9",
    ],
)
def test_bad_axes_are_refused(text):
    with pytest.raises(ValueError):
        parse_axis("spin", text)


def test_the_last_axis_changes_fastest_and_every_combination_appears_once():
    plan = Plan((parse_axis("spin", "1:3:3"), parse_axis("tilt_deg", "10:20:2")))
    values = plan.values(0, plan.size)
    assert plan.size == 6
    assert values.tolist() == [[1, 10], [1, 20], [2, 10], [2, 20], [3, 10], [3, 20]]


@settings(max_examples=25, deadline=None)
@given(cut=st.integers(0, 40), seed=st.integers(0, 2**31))
def test_a_run_has_the_same_values_in_whatever_chunk_it_is_made(cut, seed):
    plan = Plan(
        (parse_axis("spin", "100:200:4"), parse_axis("m", "normal(1,0.1)"), parse_axis("r", "uniform(2,3)")),
        runs=10,
        seed=seed,
    )
    whole = plan.values(0, plan.size)
    np.testing.assert_array_equal(np.vstack((plan.values(0, cut), plan.values(cut, plan.size))), whole)
    assert np.all((whole[:, 2] >= 2) & (whole[:, 2] <= 3))


def test_draws_follow_their_distribution_and_the_seed():
    plan = Plan((parse_axis("m", "normal(5,0.5)"),), runs=4000, seed=7)
    draws = plan.values(0, plan.size)[:, 0]
    assert abs(draws.mean() - 5) < 4 * 0.5 / np.sqrt(4000) and abs(draws.std() - 0.5) < 0.03
    other = Plan((parse_axis("m", "normal(5,0.5)"),), runs=4000, seed=8).values(0, 10)[:, 0]
    assert not np.array_equal(other, draws[:10])
