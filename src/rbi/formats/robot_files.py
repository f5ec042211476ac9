"""Robot description files (URDF, SDF, MJCF): each link's (body's) inertial element, read with
a hardened XML parser, checked for physical validity and turned into an rbi spec.

All three formats are SI (kg, m, kg·m²). Each link becomes one spec with one ``custom`` part:
the mass, the centre of mass in the link frame, and the inertia about the centre of mass in
the axes of the inertial frame, with the rotation that turns the inertial frame into the link
frame. The off-diagonal entries of all three formats are the inertia matrix's own entries
(``ixy = I[0][1] = −∫xy dm``), the sign rbi's ``inertia`` uses, so they are copied unchanged.

- URDF: ``<robot><link name><inertial><origin xyz rpy/><mass value/>
  <inertia ixx ixy ixz iyy iyz izz/>``; ``rpy`` is roll, pitch, yaw about the fixed x, y, z
  axes (``R = Rz(yaw) Ry(pitch) Rx(roll)``).
- SDF: ``<link name><inertial><pose>x y z roll pitch yaw</pose><mass/><inertia><ixx/>…``;
  the pose's angles follow URDF's; SDF's defaults (mass 1, ``ixx = iyy = izz = 1``) apply to
  missing elements inside ``<inertial>``.
- MJCF: ``<body name><inertial pos quat mass diaginertia|fullinertia/>``; ``quat`` is
  ``w x y z`` (inertial frame to body frame); ``fullinertia`` is ``ixx iyy izz ixy ixz iyz``
  in the body frame.

Hostile files are refused as :class:`InputError` (one line): XML entity declarations and
external references (defusedxml), files over :data:`MAX_FILE_BYTES`, nesting deeper than
:data:`MAX_DEPTH`, and any number that is not a plain finite decimal.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field
from typing import Any, Iterator

import numpy as np

from rbi.core.inertia import re_express
from rbi.core.validity import inertia_problem
from rbi.errors import InputError

MAX_FILE_BYTES = 64 * 1024 * 1024
"""Largest robot file read (64 MiB): far above any real description, whose meshes live in
other files."""

MAX_DEPTH = 500
"""Deepest element nesting read; an MJCF chain of 500 bodies is already far beyond any robot."""

ROBOT_FILE_EXTENSIONS = (".urdf", ".sdf", ".xml", ".mjcf")
FORMAT_BY_ROOT = {"robot": "urdf", "sdf": "sdf", "mujoco": "mjcf"}
LINK_WORD = {"urdf": "link", "sdf": "link", "mjcf": "body"}

_NUMBER = re.compile(r"^[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?$")


@dataclass(frozen=True)
class RobotLink:
    """One link's inertial properties, SI. ``com``: centre of mass in the link frame, m.
    ``inertia``: about the centre of mass in the inertial frame's axes, kg·m².
    ``quaternion``: ``[w, x, y, z]`` turning the inertial frame's axes into the link's, or None
    when they coincide; ``rpy``: the same rotation as URDF/SDF roll, pitch, yaw (radians) when
    the file gave it that way."""

    index: int
    name: str | None
    mass: float
    com: np.ndarray
    inertia: np.ndarray
    quaternion: np.ndarray | None = None
    rpy: tuple[float, float, float] | None = None

    def label(self, word: str) -> str:
        return f"{word}[{self.index}]" + (f" ({self.name})" if self.name is not None else "")

    def spec_rotation(self) -> dict[str, Any] | None:
        """The rotation (inertial frame → link frame) as a spec ``rotation:`` mapping: URDF/SDF
        roll, pitch, yaw as Euler angles about the fixed x, y, z axes, MJCF's quaternion as it
        is; None when the frames coincide."""
        if self.rpy is not None:
            return {"euler_deg": [math.degrees(a) for a in self.rpy], "sequence": "xyz"}
        if self.quaternion is not None:
            return {"quaternion": [float(v) for v in self.quaternion]}
        return None

    def rotation_matrix(self) -> np.ndarray | None:
        """Inertial frame → link frame, exactly as rbi reads the spec's rotation; None for the
        identity."""
        from rbi.core.rotation import euler_matrix, quaternion_to_matrix, without_rounding_noise

        if self.rpy is not None:
            return without_rounding_noise(euler_matrix(np.asarray(self.rpy, dtype=float), "xyz"))
        if self.quaternion is not None:
            return without_rounding_noise(quaternion_to_matrix(np.asarray(self.quaternion, dtype=float)))
        return None

    def inertia_in_link_axes(self) -> np.ndarray:
        """The inertia about the centre of mass in the link frame's axes, kg·m²."""
        R = self.rotation_matrix()
        return self.inertia.copy() if R is None else re_express(self.inertia, R)


@dataclass
class RobotFile:
    """A parsed robot file: ``format`` is ``urdf``, ``sdf`` or ``mjcf``; ``links`` those with
    an inertial element; ``skipped`` (label, reason) for the others."""

    path: str
    format: str
    name: str | None
    links: list[RobotLink] = field(default_factory=list)
    skipped: list[tuple[str, str]] = field(default_factory=list)

    @property
    def link_word(self) -> str:
        return LINK_WORD[self.format]


def is_robot_file(path: str) -> bool:
    """Does ``path`` name a robot description by its extension (``.urdf``, ``.sdf``, ``.xml``,
    ``.mjcf``)?"""
    return os.path.splitext(str(path))[1].lower() in ROBOT_FILE_EXTENSIONS


# --- reading ---------------------------------------------------------------------------------

def read_robot_file(path: str) -> RobotFile:
    """Parse a URDF, SDF or MJCF file (the format from its root element); InputError, one line
    naming the file, the link and the attribute, for anything unreadable or malformed."""
    root = _parse_xml(path)
    tag = _local(root.tag)
    fmt = FORMAT_BY_ROOT.get(tag)
    if fmt is None:
        raise InputError(f"{path}: not a URDF, SDF or MJCF document (the root element is <{_short(tag)}>, "
                         "expected <robot>, <sdf> or <mujoco>)")
    robot = RobotFile(path, fmt, root.get("name") or root.get("model"))
    reader = {"urdf": _urdf_links, "sdf": _sdf_links, "mjcf": _mjcf_links}[fmt]
    for index, element in enumerate(reader(root, path)):
        name = element.get("name")
        label = f"{LINK_WORD[fmt]}[{index}]" + (f" ({_short(name)})" if name is not None else "")
        inertial = _child(element, "inertial")
        if inertial is None:
            robot.skipped.append((label, "no <inertial> element"))
            continue
        read = {"urdf": _urdf_inertial, "sdf": _sdf_inertial, "mjcf": _mjcf_inertial}[fmt]
        where = _Where(path, label)
        robot.links.append(_in_range(where, read(where, index, name, inertial)))
    return robot


MAX_ANGLE_RAD = 1e9
"""Largest inertial-frame angle read (rad): beyond it a double cannot place the angle within a
microradian, so the value cannot be meant (and in degrees it may not even be finite)."""


def _in_range(where: _Where, link: RobotLink) -> RobotLink:
    """``link``, or InputError when its numbers cannot be computed with: an rpy angle beyond
    :data:`MAX_ANGLE_RAD`, or inertia entries whose sum overflows a double."""
    for axis, angle in zip(("roll", "pitch", "yaw"), link.rpy or ()):
        if abs(angle) > MAX_ANGLE_RAD:
            raise where.error(f"inertial rpy: {axis} = {angle:.6g} rad is not an angle a double can hold to a "
                              f"microradian: give it within one turn (between -{math.pi:.5f} and {math.pi:.5f})")
    if not np.isfinite(np.sum(np.abs(link.inertia))):
        raise where.error(f"inertia: numbers too large: the entries (largest {float(np.max(np.abs(link.inertia))):.3g}) "
                          f"add up beyond the largest double, {np.finfo(float).max:.3g}; give the inertia in kg·m²")
    return link


def _parse_xml(path: str):
    from defusedxml import DefusedXmlException
    from defusedxml.ElementTree import iterparse
    from xml.etree.ElementTree import ParseError

    try:
        size = os.path.getsize(path)
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror}") from None
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file")
    if size > MAX_FILE_BYTES:
        raise InputError(f"{path}: {size} bytes: larger than the {MAX_FILE_BYTES // 2**20} MiB rbi reads "
                         "from a robot file")
    depth = 0
    root = None
    try:
        with open(path, "rb") as handle:
            for event, element in iterparse(handle, events=("start", "end"), forbid_dtd=False,
                                            forbid_entities=True, forbid_external=True):
                if event == "start":
                    depth += 1
                    if root is None:
                        root = element
                    if depth > MAX_DEPTH:
                        raise InputError(f"{path}: elements nested deeper than {MAX_DEPTH} levels; "
                                         "refused as not a plausible robot description")
                else:
                    depth -= 1
    except DefusedXmlException as exc:
        raise InputError(f"{path}: refused: the file declares XML entities or external references "
                         f"({type(exc).__name__}); rbi does not expand them") from None
    except ParseError as exc:
        line, column = getattr(exc, "position", (0, 0))
        raise InputError(f"{path}: not well-formed XML (line {line}, column {column})") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror}") from None
    except RecursionError:
        raise InputError(f"{path}: elements nested too deeply") from None
    if root is None:
        raise InputError(f"{path}: empty XML document")
    return root


class _Where:
    """Where a value was read, for error messages: ``file: link[i] (name): what``."""

    def __init__(self, path: str, label: str):
        self.path, self.label = path, label

    def error(self, what: str) -> InputError:
        return InputError(f"{self.path}: {self.label}: {what}")


def _numbers(where: _Where, text: str | None, what: str, count: int | tuple[int, ...]) -> list[float]:
    """Whitespace-separated plain finite decimals (no NaN, inf, hex or underscores)."""
    counts = (count,) if isinstance(count, int) else count
    pieces = (text or "").split()
    expected = " or ".join(str(c) for c in counts)
    if len(pieces) not in counts:
        raise where.error(f"{what}: expected {expected} number(s), got {len(pieces)} ({_short(text)!r})")
    values = []
    for piece in pieces:
        if not _NUMBER.match(piece):
            raise where.error(f"{what}: must be a finite number (got {_short(piece)!r})")
        value = float(piece)
        if not math.isfinite(value):
            raise where.error(f"{what}: must be a finite number (got {_short(piece)!r}, too large)")
        values.append(value)
    return values


def _number(where: _Where, text: str | None, what: str, default: float | None = None) -> float:
    if text is None:
        if default is None:
            raise where.error(f"{what}: missing")
        return default
    return _numbers(where, text, what, 1)[0]


def _from_six(ixx, iyy, izz, ixy, ixz, iyz) -> np.ndarray:
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], dtype=float)


# URDF ----------------------------------------------------------------------------------------

def _urdf_links(root, path: str) -> Iterator:
    return (child for child in root if _local(child.tag) == "link")


def _urdf_inertial(where: _Where, index: int, name: str | None, inertial) -> RobotLink:
    origin = _child(inertial, "origin")
    xyz = _numbers(where, origin.get("xyz", "0 0 0") if origin is not None else "0 0 0", "inertial/origin: xyz", 3)
    rpy = _numbers(where, origin.get("rpy", "0 0 0") if origin is not None else "0 0 0", "inertial/origin: rpy", 3)
    mass_element = _child(inertial, "mass")
    if mass_element is None:
        raise where.error("inertial/mass: missing")
    mass = _number(where, mass_element.get("value"), "inertial/mass: value")
    block = _child(inertial, "inertia")
    if block is None:
        raise where.error("inertial/inertia: missing")
    six = {key: _number(where, block.get(key), f"inertial/inertia: {key}")
           for key in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
    return RobotLink(index, name, mass, np.array(xyz), _from_six(**six), rpy=_rpy_or_none(rpy))


# SDF -----------------------------------------------------------------------------------------

def _sdf_links(root, path: str) -> Iterator:
    return (element for element in root.iter() if _local(element.tag) == "link")


def _sdf_inertial(where: _Where, index: int, name: str | None, inertial) -> RobotLink:
    pose = _child(inertial, "pose")
    xyz, rpy, quaternion = [0.0, 0.0, 0.0], None, None
    if pose is not None:
        relative_to = pose.get("relative_to")
        if relative_to not in (None, "", name):
            raise where.error(f"inertial/pose: relative_to={_short(relative_to)!r}: only poses in the link's own "
                              "frame are read")
        if (pose.get("rotation_format") or "euler_rpy") == "quat_xyzw":
            values = _numbers(where, pose.text, "inertial/pose", 7)
            xyz, (qx, qy, qz, qw) = values[:3], values[3:]
            quaternion = _quaternion_or_none(where, [qw, qx, qy, qz], "inertial/pose")
        else:
            values = _numbers(where, pose.text, "inertial/pose", 6)
            xyz, angles = values[:3], values[3:]
            if (pose.get("degrees") or "").strip().lower() in ("true", "1"):
                angles = [math.radians(a) for a in angles]
            rpy = _rpy_or_none(angles)
    mass_element = _child(inertial, "mass")
    mass = _number(where, None if mass_element is None else mass_element.text, "inertial/mass", default=1.0)
    block = _child(inertial, "inertia")
    six = {}
    for key, default in (("ixx", 1.0), ("iyy", 1.0), ("izz", 1.0), ("ixy", 0.0), ("ixz", 0.0), ("iyz", 0.0)):
        entry = None if block is None else _child(block, key)
        six[key] = _number(where, None if entry is None else entry.text, f"inertial/inertia/{key}", default=default)
    return RobotLink(index, name, mass, np.array(xyz, dtype=float), _from_six(**six), quaternion=quaternion, rpy=rpy)


# MJCF ----------------------------------------------------------------------------------------

def _mjcf_links(root, path: str) -> Iterator:
    for element in root.iter():
        tag = _local(element.tag)
        if tag == "include":
            raise InputError(f"{path}: include: <include> files are not followed; import the file with every body in "
                             "it (MuJoCo's compiler can write one: mj_saveLastXML)")
        if tag == "body":
            yield element


_MJCF_ORIENTATIONS = ("axisangle", "xyaxes", "zaxis", "euler")


def _mjcf_inertial(where: _Where, index: int, name: str | None, inertial) -> RobotLink:
    pos = _numbers(where, inertial.get("pos"), "inertial: pos", 3)
    mass = _number(where, inertial.get("mass"), "inertial: mass")
    for other in _MJCF_ORIENTATIONS:
        if inertial.get(other) is not None:
            raise where.error(f"inertial: {other}: only quat is read for the inertial frame; give its "
                              "orientation as quat=\"w x y z\"")
    full, diagonal = inertial.get("fullinertia"), inertial.get("diaginertia")
    if (full is None) == (diagonal is None):
        raise where.error("inertial: give exactly one of diaginertia and fullinertia")
    quaternion = None
    if inertial.get("quat") is not None:
        if full is not None:
            raise where.error("inertial: quat: not allowed with fullinertia (which is in the body frame)")
        quaternion = _quaternion_or_none(where, _numbers(where, inertial.get("quat"), "inertial: quat", 4),
                                         "inertial: quat")
    if full is not None:
        ixx, iyy, izz, ixy, ixz, iyz = _numbers(where, full, "inertial: fullinertia", 6)
        inertia = _from_six(ixx, iyy, izz, ixy, ixz, iyz)
    else:
        inertia = np.diag(_numbers(where, diagonal, "inertial: diaginertia", 3))
    return RobotLink(index, name, mass, np.array(pos), inertia, quaternion=quaternion)


# shared helpers --------------------------------------------------------------------------------

def _rpy_or_none(rpy) -> tuple[float, float, float] | None:
    return None if not any(rpy) else (float(rpy[0]), float(rpy[1]), float(rpy[2]))


def _quaternion_or_none(where: _Where, wxyz, what: str) -> np.ndarray | None:
    q = np.asarray(wxyz, dtype=float)
    if not np.any(q):
        raise where.error(f"{what}: the quaternion must not be zero")
    if q[0] != 0.0 and not np.any(q[1:]):
        return None
    return q


def _child(element, tag: str):
    for child in element:
        if _local(child.tag) == tag:
            return child
    return None


def _local(tag: Any) -> str:
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def _short(text: Any, limit: int = 40) -> str:
    text = "" if text is None else str(text)
    text = text.encode("unicode_escape").decode("ascii")
    return text if len(text) <= limit else text[: limit - 3] + "..."


# --- validity ----------------------------------------------------------------------------------

def link_problems(robot: RobotFile, link: RobotLink) -> list[str]:
    """Every reason the link's mass properties are not physical, one line each with the margin
    by which the check fails (empty when the link is fine)."""
    where = f"{robot.path}: {link.label(robot.link_word)}"
    problems = []
    if not link.mass > 0.0:
        problems.append(f"{where}: mass: must be greater than 0 (got {link.mass!r} kg)")
    problem = inertia_problem(link.inertia)
    if problem is not None:
        if problem.kind in ("negative moment", "triangle inequality"):
            I1, I2, I3 = (float(m) for m in np.linalg.eigvalsh(link.inertia))
        if problem.kind == "negative moment":
            margin = f"margin {I1:.6g} kg·m² below zero"
        elif problem.kind == "triangle inequality":
            margin = f"margin I1 + I2 − I3 = {I1 + I2 - I3:.6g} kg·m² ({(I1 + I2 - I3) / I3:.3%} of I3)"
        else:
            margin = ""
        problems.append(f"{where}: inertia: {problem.message}" + (f"; {margin}" if margin else ""))
    return problems


def robot_file_problems(path: str) -> list[str]:
    """``rbi validate`` on a robot file: the one line that makes it unreadable, or one line per
    problem of every link."""
    try:
        robot = read_robot_file(path)
    except InputError as exc:
        return [str(exc)]
    return [line for link in robot.links for line in link_problems(robot, link)]


# --- specs ---------------------------------------------------------------------------------------

def link_spec(robot: RobotFile, link: RobotLink) -> dict[str, Any]:
    """The rbi spec (plain dict, SI) of one link: one custom part with the link's mass, centre
    of mass, inertia about it in the inertial frame's axes, and the rotation into link axes."""
    I = link.inertia
    part: dict[str, Any] = {
        "name": link.name or f"{robot.link_word}{link.index}",
        "shape": "custom",
        "mass": float(link.mass),
        "center_of_mass": [float(v) for v in link.com],
        "inertia": {"ixx": float(I[0, 0]), "iyy": float(I[1, 1]), "izz": float(I[2, 2]),
                    "ixy": float(I[0, 1]), "ixz": float(I[0, 2]), "iyz": float(I[1, 2])},
    }
    rotation = link.spec_rotation()
    if rotation is not None:
        part["rotation"] = rotation
    return {
        "name": part["name"],
        "units": {"length": "m", "mass": "kg"},
        "parts": [part],
    }
