"""The compiled integrator: :mod:`rbi.sim._dop853`, a Cython extension built with the package.

Nothing is compiled, cached or loaded from anywhere but the installed package at run time: no
C compiler, no writable folder and no just-in-time compiler are needed to simulate. The
module's source, ``_dop853.pyx``, documents the equations and the integrator.

:func:`integrator` returns ``Loaded(integrate, integrate_batch, how, load_seconds)``.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

STATUS_DONE = 0
STATUS_MORE = 1  # max_steps reached: call again to continue
STATUS_STEP_TOO_SMALL = 2
STATUS_NOT_FINITE = 3

FAILURES = {
    STATUS_STEP_TOO_SMALL: "the step size fell below the time resolution",
    STATUS_NOT_FINITE: "the state stopped being finite (overflow)",
}
"""Why the kernel stopped a run that ended with a status other than done or more to come."""


class KernelMissing(RuntimeError):
    """The package was not built (a source tree used without ``pip install``)."""


class Loaded(NamedTuple):
    integrate: Callable
    integrate_batch: Callable
    how: str
    load_seconds: float


_LOADED: Loaded | None = None


def integrator() -> Loaded:
    """The compiled integrator, imported once per process."""
    global _LOADED
    if _LOADED is None:
        start = time.perf_counter()
        try:
            from rbi.sim import _dop853  # heavy: the compiled kernel, loaded once and timed
        except ImportError as exc:
            raise KernelMissing(
                "the compiled simulation kernel is missing (rbi.sim._dop853): install rbi with "
                "`pip install .` (or `pip install -e .`) from its source folder, which builds it"
            ) from exc
        how = "Cython, OpenMP" if _dop853.openmp_enabled() else "Cython"
        _LOADED = Loaded(_dop853.integrate, _dop853.integrate_batch, how, time.perf_counter() - start)
    return _LOADED


def available_cores() -> int:
    """The cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:
        return max(1, os.cpu_count() or 1)


OUT_BYTES_PER_CHUNK = 64 * 2**20
"""Most memory the sampled states of one call of :func:`integrate_scenes` may take: its
callers run their runs in chunks of at most this (a sweep's chunk, ``rbi simulate --draws``)."""


def runs_per_call(samples: int) -> int:
    """Most runs of ``samples`` sampled states (7 doubles each) whose states one call of
    :func:`integrate_scenes` holds within :data:`OUT_BYTES_PER_CHUNK`; at least one."""
    return max(1, OUT_BYTES_PER_CHUNK // (samples * 7 * 8))


def integrate_scenes(
    scenes: list[Any], starts: np.ndarray, t: np.ndarray, rtol: float, max_steps: int, threads: int = 0
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Runs of ``scenes`` (:class:`~rbi.sim.scene.Scene`, one a run) from ``starts`` ((B, 7):
    quaternion, ω) sampled at ``t``, in one call of the batched kernel spread over ``threads``
    cores (0: every core). Returns ``out`` (B, N, 7), ``counts`` (B, 4) and ``status`` (B,)."""
    B = len(scenes)
    out = np.empty((B, t.size, 7))
    counts = np.zeros((B, 4), dtype=np.int64)
    status = np.full(B, -1, dtype=np.int64)
    with np.errstate(all="ignore"):
        inertia_inv = np.array([s.inertia_inv for s in scenes])
    integrator().integrate_batch(
        starts,
        t,
        np.array([s.inertia for s in scenes]),
        inertia_inv,
        np.array([s.gravity_moment for s in scenes]),
        np.array([max(s.natural_rate, 0.0) for s in scenes]),
        float(rtol),
        int(max_steps),
        out,
        counts,
        status,
        int(threads) or available_cores(),
    )
    return out, counts, status
