"""rbi.memory: the one pause of Python's cyclic garbage collector."""

from __future__ import annotations

import gc

import pytest

from rbi.memory import collector_paused


@pytest.fixture
def collector_on():
    was = gc.isenabled()
    gc.enable()
    yield
    if not was:
        gc.disable()


def test_the_collector_is_off_inside_and_on_again_after(collector_on):
    with collector_paused():
        assert not gc.isenabled()
        with collector_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()  # the inner pause leaves it to the outer one
    assert gc.isenabled()


def test_an_error_inside_turns_it_back_on(collector_on):
    with pytest.raises(KeyError), collector_paused():
        raise KeyError("x")
    assert gc.isenabled()


def test_a_collector_turned_off_by_the_caller_stays_off(collector_on):
    gc.disable()
    with collector_paused():
        pass
    assert not gc.isenabled()


def test_objects_made_inside_are_left_to_the_oldest_generation(collector_on):
    gc.collect()
    with collector_paused():
        made = [[i] for i in range(10_000)]
        assert gc.get_count()[0] >= 10_000
    assert gc.get_count()[0] < 10_000 and gc.get_freeze_count() == 0
    assert any(made[0] is o for o in gc.get_objects(generation=2))
