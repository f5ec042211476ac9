"""Memory that rbi holds on to: Python's cyclic garbage collector, paused while rbi builds large
structures that live on, and caches bounded in entries."""

from __future__ import annotations

import contextlib
import gc
import threading
from collections import OrderedDict
from collections.abc import Callable, Iterator
from typing import Any

_pause_lock = threading.Lock()
_pause_state = {"open": 0, "resume": False}
"""How many threads are inside a pause, and whether the collector was on before the first of
them paused it."""
_thread = threading.local()
"""Each thread's own pauses: ``depth`` (how many are open) and ``resume`` (turn the collector
back on when its last one ends)."""


@contextlib.contextmanager
def collector_paused() -> Iterator[None]:
    """Pause the cyclic garbage collector for the block; when the thread's last open pause ends,
    turn it back on if it was on before the first pause (of any thread) turned it off.

    Reading a spec of 10⁵ parts or a robot file of a million elements, auditing 10⁵ links and
    printing their report each make millions of containers and none of them is garbage: the
    collector's passes over them took 16 of 42 s of an audit's CPU (issue 25). On resuming, every
    tracked object, those made meanwhile among them, is moved to the oldest generation unscanned
    (``gc.freeze`` then ``gc.unfreeze``), so the first young collection does not walk them all
    (0.6-0.9 of 3.4 s of CPU for 20,000 links); cycles among them are collected by the next full
    pass.

    Each thread's pauses end with its own: a pause still open in another thread (a sweep's chunk
    abandoned past its stop, still running in a daemon thread) does not keep the collector off
    after this one (it only costs that thread its pause), and a pause that found the collector
    turned off by another thread's never turns it off again after that one turned it on."""
    with _pause_lock:
        if not getattr(_thread, "depth", 0):
            _thread.depth = 0
            _thread.resume = _pause_state["resume"] if _pause_state["open"] else gc.isenabled()
            _pause_state["resume"] = _thread.resume
            _pause_state["open"] += 1
            if gc.isenabled():
                gc.disable()
        _thread.depth += 1
    try:
        yield
    finally:
        with _pause_lock:
            _thread.depth -= 1
            if _thread.depth == 0:
                _pause_state["open"] -= 1
                if _thread.resume:
                    gc.freeze()
                    gc.unfreeze()
                    gc.enable()


def cached(cache: OrderedDict, entries: int, key: tuple, make: Callable[[], Any]) -> Any:
    """``cache[key]``, made by ``make()`` when it is not there; the cache keeps the ``entries``
    values used last (a sweep reads the same file and builds the same body many times; memory
    stays bounded). Safe to share between threads: an entry another thread evicts meanwhile is
    made again."""
    try:
        cache.move_to_end(key)
        return cache[key]
    except KeyError:
        pass
    value = make()
    cache[key] = value
    while len(cache) > entries:
        try:
            cache.popitem(last=False)
        except KeyError:
            break
    return value
