"""The public names of rbi, listed once (no imports: ``import rbi`` reads this and stays cheap).

``rbi.__all__`` is :data:`PUBLIC` and ``__version__``; ``rbi.api.__all__`` is :data:`PUBLIC` and
:data:`CLI_TOOLS`. docs/api.md documents :data:`PUBLIC`.
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

CLI_TOOLS = (
    "import_step",
    # the checked file writer, the collector's pause
    "output_target",
    "check_distinct",
    "write_output",
    "collector_paused",
    # rbi simulate --draws: the motion's spread from the inputs written with ±
    "input_uncertainty",
)
"""What rbi.api offers the command line besides :data:`PUBLIC` (not names of ``rbi``)."""
