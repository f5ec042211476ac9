"""``rbi bench``: what accuracy costs and how fast rbi is, measured in one run.

Sections (each a module with a ``run(quick, progress)`` returning plain data):

- :mod:`rbi.bench.workprecision`: error against work for the simulator's methods and the seed
  chapter's set-up (scipy RK45, Python right-hand side), on the bolted top and a free body.
- :mod:`rbi.bench.throughput`: mass properties of 10³ … 10⁶ point masses and of many solid
  parts, in memory and from files.
- :mod:`rbi.bench.latency`: whole-process time of ``rbi`` commands against
  ``python -c "import numpy"``.

:mod:`rbi.bench.report` renders the results (rich tables, Markdown for docs/performance.md, a
log–log plot). Times are wall-clock seconds on a possibly busy machine: the reports lead with
ratios measured in the same run.
"""
