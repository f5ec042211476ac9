"""Many simulations (or mass-property evaluations) of one spec: grids, Monte Carlo draws, the
batched compiled kernel on every core or a Dask cluster, rows streamed to a file. The public
function is :func:`rbi.sweep` (in :mod:`rbi.api`); this package is its engine.

Modules: :mod:`~rbi.sweeps.plan` (the runs: axes, draws, run i's values), :mod:`~rbi.sweeps.runs`
(a chunk of runs → rows), :mod:`~rbi.sweeps.store` (CSV/Parquet rows, streamed and resumable),
:mod:`~rbi.sweeps.execute` (chunks on local threads or a Dask cluster),
:mod:`~rbi.sweeps.tolerance` (mass-property spreads), :mod:`~rbi.sweeps.study` (a whole sweep:
settings checked, plan, runs executed and streamed, the result `rbi sweep` prints).
"""
