"""rbi.memory: the one pause of Python's cyclic garbage collector, and the one bounded cache."""

from __future__ import annotations

import gc
import subprocess
import sys
import sysconfig
import threading
from collections import OrderedDict

import pytest

from rbi import memory
from rbi.memory import cached, collector_paused


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


PAUSE_THEN_CYCLES = """
import gc, weakref
from rbi.memory import collector_paused

class Node:
    pass

def cycle():
    node = Node()
    node.self = node
    return weakref.ref(node)

gc.collect()
with collector_paused():
    inside = cycle()
    churn = [[i] for i in range(50_000)]  # past the young threshold of 3.11-3.14 many times over
    del churn
    assert inside() is not None, "a collection ran inside the pause"
assert gc.isenabled() and gc.get_freeze_count() == 0, "the collector is off or objects stay frozen"
after = [cycle() for _ in range(50_000)]
assert sum(ref() is None for ref in after) > 0, "no collection ran by itself after the pause"
gc.collect()
assert inside() is None, "a full pass left a cycle made inside (frozen?)"
"""


def test_cycles_made_inside_live_through_the_pause_and_are_freed_after_it():
    # In a new interpreter: the suite's process holds threads and settings of other libraries
    # (a collector threshold raised, a thread inside a pause) that decide when collections run.
    done = subprocess.run(
        [sys.executable, "-c", PAUSE_THEN_CYCLES], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr


class _SlowCollectorSwitch:
    """A stand-in for the gc module whose ``disable``, called from a second thread, waits until
    the first thread's pause has ended: the interleaving two sweep threads can meet."""

    def __init__(self) -> None:
        self.on = True
        self.main = threading.get_ident()
        self.second_moved = threading.Event()  # the second thread is disabling, or inside
        self.first_left = threading.Event()

    def isenabled(self) -> bool:
        return self.on

    def disable(self) -> None:
        if threading.get_ident() != self.main:
            self.second_moved.set()
            self.first_left.wait(5.0)
        self.on = False

    def enable(self) -> None:
        self.on = True

    def freeze(self) -> None:
        pass

    def unfreeze(self) -> None:
        pass


def test_pauses_in_two_threads_leave_the_collector_on(monkeypatch):
    switch = _SlowCollectorSwitch()
    monkeypatch.setattr(memory, "gc", switch)

    def second() -> None:
        with collector_paused():
            switch.second_moved.set()

    worker = threading.Thread(target=second)
    with collector_paused():
        worker.start()
        assert switch.second_moved.wait(5.0)
    switch.first_left.set()
    worker.join(10.0)
    # A pause that read the collector as off, and turned it off after the first pause had
    # turned it back on, would leave it off for the rest of the process.
    assert switch.on and not worker.is_alive()


def test_a_pause_left_open_in_another_thread_does_not_keep_the_collector_off(collector_on):
    # A sweep chunk abandoned past its stop keeps its pause in a daemon thread: the pauses
    # counted across threads left the collector off for the rest of the process.
    inside, leave = threading.Event(), threading.Event()

    def abandoned() -> None:
        with collector_paused():
            inside.set()
            leave.wait(10.0)

    worker = threading.Thread(target=abandoned, daemon=True)
    worker.start()
    try:
        assert inside.wait(5.0) and not gc.isenabled()
        with collector_paused():
            assert not gc.isenabled()
        assert gc.isenabled()
    finally:
        leave.set()
        worker.join(10.0)
    assert gc.isenabled() and not worker.is_alive()


FREE_THREADED = bool(sysconfig.get_config_var("Py_GIL_DISABLED"))
"""A free-threaded build keeps no generations (gc.get_objects(generation=0) is not the young)."""


@pytest.mark.skipif(FREE_THREADED, reason="a free-threaded build keeps no young generation")
def test_objects_made_inside_are_left_out_of_the_young_generation(collector_on):
    """So the first young collection after a pause does not walk all it made (they wait for a
    pass over the old objects). Automatic collections are held back meanwhile: what the test sees
    is where the pause left them."""
    saved = gc.get_threshold()
    gc.set_threshold(1_000_000_000)
    try:
        with collector_paused():
            made = [[i] for i in range(10_000)]
        young = {id(o) for o in gc.get_objects(generation=0)}
    finally:
        gc.set_threshold(*saved)
    assert id(made[0]) not in young and id(made[-1]) not in young


def test_the_cache_makes_each_value_once_and_keeps_those_used_last():
    cache: OrderedDict = OrderedDict()
    made: list[int] = []

    def get(k: int) -> int:
        return cached(cache, 3, (k,), lambda: made.append(k) or k * k)

    assert [get(k) for k in (1, 2, 3, 1, 4)] == [1, 4, 9, 1, 16]
    assert made == [1, 2, 3, 4]  # 1 was asked for again and not made again
    assert list(cache) == [(3,), (1,), (4,)]  # 2, the least recently used, went
    assert get(2) == 4 and made[-1] == 2


class _EvictedBeforeRead(OrderedDict):
    """A cache whose entries another thread evicts between a lookup finding one and its read."""

    def __getitem__(self, key):
        self.pop(key, None)
        raise KeyError(key)


def test_an_entry_evicted_between_lookup_and_read_is_made_again():
    # The interleaving two threads of a sweep can meet, made certain: a cache that checks
    # `key in cache` and then reads cache[key] raises KeyError here.
    cache = _EvictedBeforeRead({(1,): "stale"})
    assert cached(cache, 4, (1,), lambda: "made") == "made"


def test_the_cache_shared_by_threads_stays_bounded_and_right():
    cache: OrderedDict = OrderedDict()
    wrong: list = []

    def work(offset: int) -> None:
        try:
            for i in range(20_000):
                k = (i * 7 + offset) % 50
                if cached(cache, 8, (k,), lambda k=k: k + 1000) != k + 1000:
                    wrong.append((k, offset))
        except Exception as exc:  # an exception in a thread would otherwise pass unseen
            wrong.append(repr(exc))

    threads = [threading.Thread(target=work, args=(n,)) for n in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert wrong == []
    assert len(cache) <= 8
