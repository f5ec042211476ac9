"""Runs of a simulation, below the CLI and the API: the checks of run settings, the
preparation of a run from a loaded body, and the run itself with its summary.

Modules: :mod:`rbi.runs.values` (command-line style values such as ``"1,2,3"``),
:mod:`rbi.runs.run` (checks of the settings before any work), :mod:`rbi.runs.run`
(body → scene, initial state, step budget), :mod:`rbi.runs.run` (the run, its summary
and its CSV). Messages name the options the CLI uses (``--duration``, ``--spin`` ...), so the
CLI and the Python API report a bad setting with the same line.
"""
