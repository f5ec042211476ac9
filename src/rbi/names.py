"""The public names of rbi, listed once (no imports: ``import rbi`` reads this and stays cheap).

``rbi.__all__`` is :data:`PUBLIC` and ``__version__``; ``rbi.api.__all__`` is :data:`PUBLIC`.
docs/api.md documents :data:`PUBLIC`; the command line imports nothing else of rbi's.
"""

PUBLIC = {
    "load": "rbi.api.body",
    "loads": "rbi.api.body",
    "Body": "rbi.api.body",
    "Principal": "rbi.api.results",
    "Part": "rbi.api.results",
    "Momentum": "rbi.api.results",
    "simulate": "rbi.api.runs",
    "Trajectory": "rbi.api.runs",
    "sweep": "rbi.api.sweeps",
    "SweepTable": "rbi.api.sweeps",
    "Grid": "rbi.sweeps.plan",
    "Normal": "rbi.sweeps.plan",
    "Uniform": "rbi.sweeps.plan",
    "audit": "rbi.api.robots",
    "AuditReport": "rbi.robot.audit",
    "show": "rbi.api.pictures",
    "animate": "rbi.api.pictures",
    "Animation": "rbi.api.pictures",
    "import_robot": "rbi.api.robots",
    "RobotImport": "rbi.api.robots",
    "ImportedLink": "rbi.api.robots",
    "SpecError": "rbi.errors",
    "ArgumentError": "rbi.errors",
    "outside_paths_allowed": "rbi.formats.paths",
    "visible": "rbi.text",
    "MassProperties": "rbi.core.mass",
    "Check": "rbi.spec.checks",
    "Dynamics": "rbi.api.results",
    "validate": "rbi.api.body",
    "spec_schema": "rbi.api.body",
    "unit_vector": "rbi.api.body",
    "Result": "rbi.reprs",
}
"""What ``import rbi`` offers (the API of docs/python-api.md), each name with the module that
defines it: :mod:`rbi.api` imports that module when the name is first asked for."""
