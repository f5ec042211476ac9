"""Robot description files (URDF, SDF, MJCF): one reading (:func:`read_robot`, built on the
readers in :mod:`rbi.formats.urdf`, :mod:`~rbi.formats.sdf` and :mod:`~rbi.formats.mjcf`) that
``rbi import``, ``rbi validate`` and ``rbi audit`` share, so they agree on every file; each
link's (body's) mass properties checked for physical validity and turned into an rbi spec.

All three formats are SI (kg, m, kg·m²). Each link becomes one spec with one ``custom`` part:
the mass, the centre of mass in the link frame, and the inertia about the centre of mass in
the axes of the inertial frame, with the rotation that turns the inertial frame into the link
frame. What is read from each format, and the sign of the products (copied unchanged), are
tabled in docs/import.md ("What is read from each format").

Hostile files are refused as :class:`InputError` (one line; :mod:`rbi.formats.robot_xml`):
XML entity declarations and external references, files over
:data:`~rbi.formats.robot_xml.MAX_FILE_BYTES`, nesting deeper than
:data:`~rbi.formats.robot_xml.MAX_DEPTH`, unknown encodings, duplicate link names, and any
number that is not a plain finite decimal.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

from rbi.core.validity import InertiaProblem, declared_inertia_problem
from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.mjcf import read_mjcf
from rbi.formats.paths import _outside_allowed
from rbi.formats.robot import Link, RobotModel
from rbi.formats.robot import short as _short
from rbi.formats.sdf import read_sdf
from rbi.formats.urdf import plain_text, read_urdf
from rbi.formats.xacro_sandbox import expand_xacro

ROBOT_FILE_EXTENSIONS = (".urdf", ".sdf", ".xml", ".mjcf", ".xacro")
READER_BY_ROOT = {"robot": read_urdf, "sdf": read_sdf, "mujoco": read_mjcf}


def is_robot_file(path: str) -> bool:
    """Does ``path`` name a robot description by its extension (``.urdf``, ``.sdf``, ``.xml``,
    ``.mjcf``)?"""
    return os.path.splitext(str(path))[1].lower() in ROBOT_FILE_EXTENSIONS


# --- reading ---------------------------------------------------------------------------------


def read_robot(path: str, package_paths: dict | None = None, geometry: bool = True) -> RobotModel:
    """Parse a URDF, SDF or MJCF file (the format from its root element) into a
    :class:`RobotModel`: links with their inertials, geometry (when ``geometry``; MJCF's geoms
    always) and place in the tree. InputError, one line naming the file, the link and the
    attribute, for anything unreadable, malformed or refused (duplicate link names, a mesh that
    cannot be found)."""

    path = str(path)
    if path.lower().endswith(".xacro"):
        expanded, includes = expand_xacro(path, _outside_allowed.get())
        document = robot_xml.read_xml(path, expanded)
        document.includes.extend(includes)
    else:
        document = robot_xml.decoded(path)
        plain = plain_text(document) if b"<robot" in document.text[:65536] else None
        if plain is not None:  # a URDF read from its plain text, not parsed into a tree
            return read_urdf(document, package_paths, geometry, plain)
        document.root = robot_xml.parse(path, document.text)
    reader = READER_BY_ROOT.get(document.root.tag)
    if reader is None:
        raise InputError(
            f"{path}: not a URDF, SDF or MJCF document (the root element is "
            f"<{_short(document.root.tag)}>, expected <robot>, <sdf> or <mujoco>)"
        )
    return reader(document, package_paths, geometry)


# --- validity ----------------------------------------------------------------------------------


def link_problems(robot: RobotModel, link: Link) -> list[str]:
    """Every reason the link's declared mass properties are not physical, one line each with the
    margin by which the check fails (empty when the link is fine)."""
    where = f"{robot.path}: {link.label}"
    mass, inertia = link.inertial.mass, link.inertial.written_inertia
    problems = []
    if mass == 0.0 and np.any(inertia != 0):
        return [
            f"{where}: inertia: mass 0 with non-zero moments; no body without mass has a moment of inertia"
        ]
    if mass == 0.0 and not link.moves:
        return problems  # a root or fixed link without mass: how simulators mark a static base
    if not mass > 0.0:
        problems.append(f"{where}: mass: must be greater than 0 (got {mass!r} kg)")
    problem = declared_inertia_problem(mass, inertia)
    if problem is not None:
        problems.append(f"{where}: inertia: {inertia_problem_text(problem, inertia)}")
    return problems


def inertia_problem_text(problem: InertiaProblem, inertia: np.ndarray) -> str:
    """``problem`` (of the declared ``inertia``) in words with the margin by which the check
    fails, for a negative moment or a triangle-inequality deficit: the one wording of
    ``rbi validate``, ``rbi import`` and ``rbi audit``'s unphysical flag."""
    if problem.kind not in ("negative moment", "triangle inequality"):
        return problem.message
    I1, I2, I3 = (float(m) for m in np.linalg.eigvalsh(inertia))
    if problem.kind == "negative moment":
        return f"{problem.message}; margin {I1:.6g} kg·m² below zero"
    return (
        f"{problem.message}; margin I1 + I2 − I3 = {I1 + I2 - I3:.6g} kg·m² ({(I1 + I2 - I3) / I3:.3%} of I3)"
    )


def robot_file_problems(path: str, package_paths: dict | None = None) -> list[str]:
    """``rbi validate`` on a robot file: the one line that makes it unreadable, or one line per
    problem of every link."""
    try:
        robot = read_robot(path, package_paths)
    except InputError as exc:
        return [str(exc)]
    return list(robot.unchecked) + [
        line for link in robot.inertial_links for line in link_problems(robot, link)
    ]


# --- specs ---------------------------------------------------------------------------------------


def custom_part(name: str, mass: float, center_of_mass, inertia) -> dict[str, Any]:
    """A spec ``custom`` part (plain dict): ``mass``, ``center_of_mass`` and the six entries of
    ``inertia`` (3, 3), about the centre of mass, in the units and axes the caller gives."""
    I = np.asarray(inertia, dtype=float)
    six = {"ixx": I[0, 0], "iyy": I[1, 1], "izz": I[2, 2], "ixy": I[0, 1], "ixz": I[0, 2], "iyz": I[1, 2]}
    return {
        "name": name,
        "shape": "custom",
        "mass": float(mass),
        "center_of_mass": [float(v) for v in center_of_mass],
        "inertia": {key: float(value) for key, value in six.items()},
    }


def link_spec(robot: RobotModel, link: Link) -> dict[str, Any]:
    """The rbi spec (plain dict, SI) of one link: one custom part with the link's mass, centre
    of mass, inertia about it in the inertial frame's axes, and the rotation into link axes (the
    inertial frame → link frame) as a spec ``rotation:`` mapping: URDF/SDF roll, pitch, yaw as
    Euler angles about the fixed x, y, z axes, a quaternion as the file gave it; none when the
    frames coincide."""
    inertial = link.inertial
    name = link.name or f"{robot.link_word}{link.index}"
    part = custom_part(name, inertial.mass, inertial.properties.center_of_mass, inertial.written_inertia)
    if inertial.rpy is not None:
        part["rotation"] = {"euler_deg": [math.degrees(a) for a in inertial.rpy], "sequence": "xyz"}
    elif inertial.quaternion is not None:
        part["rotation"] = {"quaternion": [float(v) for v in inertial.quaternion]}
    return {
        "name": part["name"],
        "units": {"length": "m", "mass": "kg"},
        "parts": [part],
    }
