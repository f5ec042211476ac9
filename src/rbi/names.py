"""The public names of rbi, listed once (no imports: ``import rbi`` reads this and stays cheap).

``rbi.__all__`` is :data:`PUBLIC` and ``__version__``; ``rbi.api.__all__`` is :data:`PUBLIC`.
docs/api.md documents :data:`PUBLIC`; the command line imports nothing else of rbi's.
"""

PUBLIC = (
    "load",
    "loads",
    "Body",
    "Principal",
    "Part",
    "Momentum",
    "simulate",
    "Trajectory",
    "sweep",
    "SweepTable",
    "Grid",
    "Normal",
    "Uniform",
    "audit",
    "AuditReport",
    "show",
    "animate",
    "Animation",
    "import_robot",
    "RobotImport",
    "ImportedLink",
    "SpecError",
    "ArgumentError",
    "outside_paths_allowed",
    "visible",
    "MassProperties",
    "Check",
    "Dynamics",
    "validate",
    "spec_schema",
    "unit_vector",
    "Result",
)
"""What ``import rbi`` offers: the API of docs/python-api.md."""
