"""``rbi bench``: what accuracy costs and how fast rbi is, measured in one run.

Sections (each a module with ``run(quick, progress)`` returning plain data and
``planned_steps(quick)``), in the order they run:

- :mod:`rbi.bench.kernel`: ``simulate`` at its defaults against the seed chapter's set-up (and
  at equal-or-better error) and against a minimal loop with the same DOP853 steps.
- :mod:`rbi.bench.workprecision`: error against work for the simulator's methods and the seed
  chapter's set-up (scipy RK45, Python right-hand side), on the bolted top and a free body.
- :mod:`rbi.bench.throughput`: mass properties of 10³ … 10⁶ point masses and of many solid
  parts, in memory and from files.
- :mod:`rbi.bench.largespec`: the whole load of large YAML specs against a bare
  ``yaml.load``.
- :mod:`rbi.bench.latency`: whole-process time of ``rbi`` commands against
  ``python -c "import numpy"``, and a first ``rbi simulate`` in a fresh HOME against a later one.
- :mod:`rbi.bench.sweep`: ``rbi sweep`` throughput against the single-run rate and a loop of
  processes, and its memory while streaming.

:mod:`rbi.bench.report` turns the results into a report (a targets table first, the tables, Markdown
for docs/performance.md, a log–log plot). Times are wall-clock seconds on a possibly busy
machine: the reports lead with ratios measured in the same run.
"""
