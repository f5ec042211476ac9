"""Runs of a simulation, below the CLI and the API: :mod:`rbi.runs.run` (settings checked before
any work, body → scene and initial state, the run, its summary and its CSV),
:mod:`rbi.runs.values` (numbers given to the API, checked), :mod:`rbi.runs.animation` (a run
drawn as a page or a GIF). Messages name the API's parameters (:class:`rbi.errors.ArgumentError`).
"""
