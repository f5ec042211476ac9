"""Many simulations (or mass-property evaluations) of one spec: grids, Monte Carlo draws, the
batched compiled kernel on every core or a Dask cluster, rows streamed to a file.

Modules: :mod:`~rbi.sweep.plan` (the runs: axes, draws, run i's values), :mod:`~rbi.sweep.runs`
(a chunk of runs → rows), :mod:`~rbi.sweep.store` (CSV/Parquet rows, streamed and resumable),
:mod:`~rbi.sweep.execute` (chunks on local threads or a Dask cluster),
:mod:`~rbi.sweep.tolerance` (mass-property spreads).
"""
