"""Loading the compiled integrator of :mod:`rbi.sim.kernels`.

:func:`integrator` returns the compiled ``integrate`` function and says how it was obtained.
The first call in a process pays for loading (numba's on-disk cache, or compiling on the very
first run); :func:`integrator` does that once and times it.
"""

from __future__ import annotations

import time
from typing import Callable, NamedTuple

import numpy as np


STATUS_DONE = 0
STATUS_MORE = 1  # max_steps reached: call again to continue
STATUS_STEP_TOO_SMALL = 2
STATUS_NOT_FINITE = 3


class Loaded(NamedTuple):
    integrate: Callable
    how: str  # "numba-jit"
    load_seconds: float


_LOADED: Loaded | None = None


def integrator() -> Loaded:
    """The compiled integrator, loaded (and warmed up) once per process."""
    global _LOADED
    if _LOADED is None:
        start = time.perf_counter()
        from rbi.sim import kernels

        _warm_up(kernels.integrate)
        _LOADED = Loaded(kernels.integrate, "numba-jit", time.perf_counter() - start)
    return _LOADED


def _warm_up(integrate: Callable) -> None:
    """One tiny run, so that compiling or loading from the cache happens here, not in a timed
    integration."""
    y = np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
    eye = np.eye(3)
    integrate(y, np.zeros(2), np.array([0.0, 0.1]), np.empty((2, 7)), eye, eye, np.zeros(3),
              np.array([1e-6, 1.0]), np.zeros(4, dtype=np.int64), 100)
