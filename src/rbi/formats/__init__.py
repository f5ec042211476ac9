"""Readers of files from outside rbi: robot descriptions (URDF, SDF, MJCF), meshes and point
clouds, and the rules for which paths a spec may name.

Each reader returns plain data (numpy arrays, dataclasses) and raises
:class:`rbi.errors.InputError` for a file it cannot read; none knows of pydantic models, YAML
specs or the terminal. Data flows one way: formats → spec → core → sim/sweep/viz → api → cli.
"""
