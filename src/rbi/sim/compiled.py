"""The compiled integrator: :mod:`rbi.sim._dop853`, a Cython extension built with the package.

Nothing is compiled, cached or loaded from anywhere but the installed package at run time: no
C compiler, no writable folder and no just-in-time compiler are needed to simulate. The
module's source, ``_dop853.pyx``, documents the equations and the integrator.

:func:`integrator` returns ``Loaded(integrate, integrate_batch, how, load_seconds)``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import NamedTuple

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
