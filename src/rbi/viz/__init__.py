"""Pictures and animations of a body and its motion, from plain data: drawable part geometry
(:mod:`rbi.spec.geometry`), mass properties and sampled trajectories.

Modules: :mod:`~rbi.viz.motion` (the data an animation plays), :mod:`~rbi.viz.page` (the
self-contained three.js HTML page), :mod:`~rbi.viz.frames` (the same view as GIF frames,
matplotlib), :mod:`~rbi.viz.still` (``rbi show``'s pictures). Nothing here is imported by the
mass-property commands.
"""
