"""Robot files audited: the kinematic tree (:mod:`rbi.robot.tree`), each link's declared mass
properties against its geometry with flags (:mod:`rbi.robot.audit`), whole-robot totals, and
the ``--fix`` rewrite plan (:mod:`rbi.robot.fix`). :func:`audit` runs it all."""

from __future__ import annotations

import os
from typing import Any

from rbi.formats.paths import outside_paths_allowed
from rbi.formats.robot_files import read_robot
from rbi.memory import collector_paused
from rbi.robot.audit import AuditReport, AuditSettings, audit_model
from rbi.robot.fix import plan_fix


def audit(
    robot_file: str | os.PathLike, settings: AuditSettings | None = None, **options: Any
) -> AuditReport:
    """Audit a URDF, SDF or MJCF file as ``settings`` say (or the keywords of
    :class:`AuditSettings`, :func:`rbi.audit`'s less ``out``): every link's declared mass
    properties against its geometry, with flags, and the whole robot's totals at a
    configuration (SI units); ``fix`` plans the fixed copy (``report.fix``) without writing it.
    Raises :class:`rbi.SpecError` on bad input.
    """
    settings = AuditSettings(**options) if settings is None else settings
    with outside_paths_allowed(settings.allow_outside_paths), collector_paused():
        model = read_robot(
            os.fspath(robot_file), settings.package_paths, geometry=settings.geometry != "none"
        )
        report = audit_model(model, settings)
    report.fix = plan_fix(report, settings.density) if settings.fix else None
    return report


__all__ = ["AuditReport", "AuditSettings", "audit"]
