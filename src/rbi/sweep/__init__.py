"""Many simulations (or mass-property evaluations) of one spec: grids, Monte Carlo draws, the
batched compiled kernel on every core or a Dask cluster, rows streamed to a file.

Called, ``rbi.sweep(body, spin=..., ...)``, this package is the public :func:`rbi.api.sweep`:
the public name and this package share the name ``sweep`` in ``rbi``'s namespace, where
Python's import system binds the package, so the package itself is made callable.

Modules: :mod:`~rbi.sweep.plan` (the runs: axes, draws, run i's values), :mod:`~rbi.sweep.runs`
(a chunk of runs → rows), :mod:`~rbi.sweep.store` (CSV/Parquet rows, streamed and resumable),
:mod:`~rbi.sweep.execute` (chunks on local threads or a Dask cluster),
:mod:`~rbi.sweep.tolerance` (mass-property spreads), :mod:`~rbi.sweep.study` (a whole sweep:
settings checked, plan, runs executed and streamed, the result `rbi sweep` prints).
"""

import sys as _sys
import types as _types


class _CallablePackage(_types.ModuleType):
    def __call__(self, *args, **kwargs):
        """:func:`rbi.api.sweep`: many simulations of one body; one dict per run."""
        from rbi.api import sweep

        return sweep(*args, **kwargs)


_sys.modules[__name__].__class__ = _CallablePackage
