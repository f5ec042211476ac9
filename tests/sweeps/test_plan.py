"""The runs of a sweep: axes as given, the product order, reproducible draws."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.sweeps.plan import Draw, Grid, GridAxis, Normal, Plan, Uniform, axis_of


def test_numbers_sequences_grids_and_draws_make_axes():
    np.testing.assert_array_equal(axis_of("spin", Grid(150.0, 250.0, 3)).values(), [150, 200, 250])
    assert axis_of("spin", 200).values().tolist() == [200.0]
    assert axis_of("spin", [3, 1, 2]).values().tolist() == [3.0, 1.0, 2.0]  # as given, not sorted
    assert axis_of("spin", np.array([1.5, 2.5])).count == 2
    assert axis_of("spin", Grid(1, 1, 1)).values().tolist() == [1.0]
    assert axis_of("x", Normal(0.02, 0.001)) == Draw("x", Normal(0.02, 0.001))
    assert axis_of("x", Uniform(-1e-3, 2e-3)) == Draw("x", Uniform(-1e-3, 2e-3))
    assert list(Grid(0, 1, 5)) == [0.0, 0.25, 0.5, 0.75, 1.0] and len(Grid(0, 1, 5)) == 5


@pytest.mark.parametrize(
    "make",
    [
        lambda: Grid(1, 2, 0),
        lambda: Grid(1, 2, -3),
        lambda: Grid(float("inf"), 1, 2),
        lambda: Grid(1, 2, 10**9),
        lambda: Grid(1, 2, 2.5),
        lambda: Uniform(2, 1),
        lambda: Normal(0, -1),
        lambda: Normal(float("nan"), 1),
        lambda: Uniform(-1e308, 1e308),
        lambda: axis_of("spin", float("nan")),
        lambda: axis_of("spin", []),
        lambda: axis_of("spin", "150:250:3"),
        lambda: axis_of("spin", [1, "a"]),
    ],
)
def test_bad_axes_are_refused(make):
    with pytest.raises((TypeError, ValueError)):
        make()


def test_the_last_axis_changes_fastest_and_every_combination_appears_once():
    plan = Plan((axis_of("spin", Grid(1, 3, 3)), axis_of("tilt_deg", [10, 20])))
    values = plan.values(0, plan.size)
    assert plan.size == 6
    assert values.tolist() == [[1, 10], [1, 20], [2, 10], [2, 20], [3, 10], [3, 20]]


@settings(max_examples=25, deadline=None)
@given(cut=st.integers(0, 40), seed=st.integers(0, 2**31))
def test_a_run_has_the_same_values_in_whatever_chunk_it_is_made(cut, seed):
    plan = Plan(
        (axis_of("spin", Grid(100, 200, 4)), axis_of("m", Normal(1, 0.1)), axis_of("r", Uniform(2, 3))),
        runs=10,
        seed=seed,
    )
    whole = plan.values(0, plan.size)
    np.testing.assert_array_equal(np.vstack((plan.values(0, cut), plan.values(cut, plan.size))), whole)
    assert np.all((whole[:, 2] >= 2) & (whole[:, 2] <= 3))


def test_draws_follow_their_distribution_and_the_seed():
    plan = Plan((axis_of("m", Normal(5, 0.5)),), runs=4000, seed=7)
    draws = plan.values(0, plan.size)[:, 0]
    assert abs(draws.mean() - 5) < 4 * 0.5 / np.sqrt(4000) and abs(draws.std() - 0.5) < 0.03
    other = Plan((axis_of("m", Normal(5, 0.5)),), runs=4000, seed=8).values(0, 10)[:, 0]
    assert not np.array_equal(other, draws[:10])


def test_an_axis_is_a_grid_axis_or_a_draw():
    assert isinstance(axis_of("spin", 1.0), GridAxis) and isinstance(axis_of("m", Normal(1, 0)), Draw)
