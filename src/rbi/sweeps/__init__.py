"""Many simulations (or mass-property evaluations) of one spec: grids, Monte Carlo draws, the
batched compiled kernel on every core or a Dask cluster, rows streamed to a file. The public
function is :func:`rbi.sweep` (in :mod:`rbi.api`); this package is its engine, from the whole
sweep (:mod:`~rbi.sweeps.study`) down to a chunk of runs (:mod:`~rbi.sweeps.runs`).
"""
