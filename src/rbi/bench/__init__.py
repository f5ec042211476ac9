"""``rbi bench``: what accuracy costs and how fast rbi is, measured in one run.

Each section is a module with ``run(quick, progress, folder)`` returning plain data (``folder``:
an empty temporary folder for its files, removed after it);
:data:`rbi.bench.suite.SECTIONS` lists them in the order they run (each
module's docstring says what it measures and against which baseline). :mod:`rbi.bench.report`
turns the results into a report (a targets table first, the tables, Markdown for
docs/performance.md, a log–log plot). Times are wall-clock seconds on a possibly busy machine:
the reports lead with ratios measured in the same run.
"""

from collections.abc import Callable

Progress = Callable[[str], None]
"""What every section's ``run`` calls with the name of the measurement it starts."""
