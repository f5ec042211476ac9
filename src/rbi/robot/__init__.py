"""Robot files audited: the kinematic tree (:mod:`rbi.robot.tree`), each link's declared mass
properties against its geometry with flags (:mod:`rbi.robot.audit`), whole-robot totals, and
the ``--fix`` rewrite plan (:mod:`rbi.robot.fix`). :func:`audit` runs it all."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence

from rbi.formats.paths import outside_paths_allowed
from rbi.formats.robot_files import read_robot
from rbi.formats.robot_paths import parse_package_paths
from rbi.memory import collector_paused
from rbi.robot.audit import AuditReport, audit_model, check_choices, material_density
from rbi.robot.tree import parse_joint_values


def audit(
    robot_file: str | os.PathLike,
    *,
    package_paths: Mapping[str, str] | Sequence[str] | None = None,
    geometry: str = "collision",
    density: float | None = None,
    material: str | None = None,
    mesh_inertia: str = "auto",
    joints: Mapping[str, float] | Sequence[str] | None = None,
    fix: bool = False,
    allow_outside_paths: bool = False,
    mesh_repair: bool = False,
) -> AuditReport:
    """Audit a URDF, SDF or MJCF file: every link's declared mass properties against its
    geometry, with flags, and the whole robot's totals at a configuration (SI units). The
    parameters are :func:`rbi.audit`'s, which this serves, less the writing of the fixed copy
    (``fix`` only plans it: ``report.fix``); ``allow_outside_paths`` is a bool here. Raises
    :class:`rbi.SpecError` on bad input.
    """

    check_choices(geometry, mesh_inertia)
    packages = parse_package_paths(package_paths)
    joint_values = parse_joint_values(joints)
    rho = material_density(material, density)
    with outside_paths_allowed(allow_outside_paths), collector_paused():
        model = read_robot(os.fspath(robot_file), packages, geometry=geometry != "none")
        report = audit_model(
            model,
            geometry=geometry,
            density=rho,
            mesh_inertia=mesh_inertia,
            joints=joint_values,
            mesh_repair=mesh_repair,
        )
    report.fix = None
    if fix:
        # not at top level: `rbi audit` would load rbi.robot.fix too
        from rbi.robot.fix import plan_fix

        report.fix = plan_fix(report, rho)
    return report


__all__ = ["AuditReport", "audit"]
