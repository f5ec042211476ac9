"""MJCF (MuJoCo's XML), read as MuJoCo's compiler reads it: bodies with their pose, joints,
geoms and the mass properties the compiler gives them.

What is honoured:
- ``<include file>`` (relative to the main file's folder, under the spec path rules), nested;
- ``<compiler angle eulerseq meshdir assetdir inertiafromgeom inertiagrouprange settotalmass
  boundmass boundinertia balanceinertia>``;
- ``<default>`` classes (nested, ``class`` and ``childclass``), ``<frame>``;
- orientations ``quat``, ``axisangle``, ``euler``, ``xyaxes``, ``zaxis`` (``angle`` in degrees by
  default, as MuJoCo); ``fromto`` for capsule, cylinder, box and ellipsoid geoms;
- geom size conventions (sphere ``r``; capsule and cylinder ``r, half-length``; box half-edges;
  ellipsoid semi-axes; with ``fromto`` a box or ellipsoid takes ``size[0]`` across both transverse
  axes, as MuJoCo does), geom ``mass`` or ``density`` (default 1000 kg/m³), ``shellinertia``,
  ``group`` against ``inertiagrouprange``; mesh assets with ``file``, ``scale`` and ``inertia``
  (``legacy``, MuJoCo's default, ``exact``, ``convex``, ``shell``), each computed as MuJoCo
  computes it;
- a body's mass properties: the explicit ``<inertial>`` (``diaginertia`` or ``fullinertia``,
  any orientation), or the sum of its geoms when ``inertiafromgeom`` is ``true`` (the explicit
  one is then ignored, as MuJoCo ignores it) or ``auto`` without ``<inertial>``; then the bounds
  and ``settotalmass``, which scales every body.

The world body is not a link; its geoms (floors) are ignored, as MuJoCo does for mass.
"""

from __future__ import annotations

import math
import os
from dataclasses import replace
from pathlib import Path

import numpy as np

from rbi.core.mass import MassProperties
from rbi.core.rotation import axis_angle_matrix, matrix_to_quaternion
from rbi.errors import InputError
from rbi.formats.paths import spec_relative_file
from rbi.formats.robot import (
    Geom,
    Inertial,
    LinkTable,
    Motion,
    Pose,
    RobotModel,
    Where,
    check_unique_joint_names,
    element_label,
    from_six,
    refuse_shared_keys,
    short,
)
from rbi.formats.robot_geometry import geoms_sum
from rbi.formats.robot_xml import read_xml

MAX_INCLUDES = 100
"""Most ``<include>`` elements followed in one model (a loop of includes is refused before)."""

GEOM_KINDS = ("plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh", "sdf")
SIZES = {"sphere": (1,), "capsule": (1, 2), "cylinder": (1, 2), "box": (2, 2, 2), "ellipsoid": (1, 1, 1)}
"""The ``size`` numbers each primitive geom reads, and what turns each into the :class:`Geom` size
(a radius or semi-axis stays, a half-length or half-edge doubles)."""
ORIENTATIONS = ("quat", "axisangle", "xyaxes", "zaxis", "euler")
UNSUPPORTED = ("replicate", "attach", "composite", "flexcomp")


class Compiler:
    """The ``<compiler>`` settings that change mass properties or frames (MuJoCo's defaults
    until :meth:`read` sets them)."""

    angle = "degree"
    eulerseq = "xyz"
    meshdir = ""
    assetdir = ""
    inertiafromgeom = "auto"
    group_range: tuple[float, float] = (0, 5)
    settotalmass = -1.0
    boundmass = 0.0
    boundinertia = 0.0
    balanceinertia = "false"

    def read(self, where: Where, element) -> None:
        self.choose(where, element, "angle", ("degree", "radian"))
        seq = element.get("eulerseq")
        if seq is not None:
            if len(seq) != 3 or any(c not in "xyzXYZ" for c in seq):
                raise where.error(
                    f"compiler: eulerseq: {short(seq)!r}: three of x, y, z (lower case: rotating "
                    "axes; upper case: fixed axes)"
                )
            self.eulerseq = seq
        self.meshdir = element.get("meshdir", self.meshdir)
        self.assetdir = element.get("assetdir", self.assetdir)
        self.choose(where, element, "inertiafromgeom", ("true", "false", "auto"))
        if element.get("inertiagrouprange") is not None:
            low, high = where.numbers(element.get("inertiagrouprange"), "compiler: inertiagrouprange", 2)
            self.group_range = (low, high)
        for key in ("settotalmass", "boundmass", "boundinertia"):
            setattr(self, key, where.number(element.get(key), f"compiler: {key}", getattr(self, key)))
        self.choose(where, element, "balanceinertia", ("true", "false"))
        if element.get("coordinate") == "global":
            raise where.error(
                'compiler: coordinate="global": global coordinates are no longer read by MuJoCo; '
                "load and save the model with MuJoCo 2 to convert it"
            )

    def choose(self, where: Where, element, name: str, choices: tuple[str, ...]) -> None:
        """The setting ``name`` from the ``<compiler>`` attribute of that name when it is written;
        InputError when it is not one of ``choices``."""
        value = element.get(name, getattr(self, name))
        if value not in choices:
            allowed = f"{', '.join(choices[:-1])} or {choices[-1]}"
            raise where.error(f"compiler: {name}: {short(value)!r}: must be {allowed}")
        setattr(self, name, value)

    def radians(self, value: float) -> float:
        """An angle as written (degrees unless ``<compiler angle="radian">``), in radians."""
        return math.radians(value) if self.angle == "degree" else value


def read_mjcf(document, package_paths=None, geometry: bool = True) -> RobotModel:
    """The bodies of an MJCF document, with the mass properties MuJoCo's compiler gives them.
    The geoms are always read (they give the bodies their mass); ``geometry`` is ignored."""
    path = document.path
    root = _expanded(document)
    compiler = Compiler()
    for element in root.iter("compiler"):
        compiler.read(Where(path), element)
    for tag in UNSUPPORTED:
        found = next(root.iter(tag), None)
        if found is not None:
            raise InputError(
                f"{path}: <{tag}> (line {found.line}): not read by rbi; compile the model with "
                "MuJoCo and save it (mj_saveLastXML) to audit it"
            )
    defaults = _defaults(root)
    meshes = _mesh_assets(path, root, defaults, compiler)
    document.includes.extend(os.path.realpath(m["file"]) for m in meshes.values() if "file" in m)
    table = LinkTable(path, "body")
    reader = _Bodies(table, compiler, defaults, meshes)
    for world in root.all("worldbody"):
        reader.children(world, Pose.identity(), None, "main")
    refuse_shared_keys(path, "body", table.names)
    joints = [(table.label(row), m.name) for row, motions in enumerate(table.motions) for m in motions]
    check_unique_joint_names(path, joints, "MuJoCo's compiler")
    _actuator_limits(table, root, defaults)
    options = {"gravity": _gravity(path, root), "boundinertia": compiler.boundinertia}
    notes = _compile_inertia(table, compiler)
    _check_moving_bodies(table)
    return RobotModel(
        path, "mjcf", root.get("model"), table.columns(), notes, document=document, options=options
    )


ACTUATORS = ("general", "motor", "position", "velocity", "intvelocity", "damper", "cylinder", "muscle")


def _actuator_limits(table: LinkTable, root, defaults) -> None:
    """A joint without ``actuatorfrcrange`` takes the force ranges of the actuators that drive
    it, each times its gear (the joint's effort is the actuator's force times the gear)."""
    motions = {m.name: m for each in table.motions for m in each if m.name}
    found: dict[str, float] = {}
    for block in root.all("actuator"):
        for element in block.children:
            if element.tag not in ACTUATORS:
                continue
            attrs = _attributes(element, defaults, "main", table.path)
            joint = attrs.get("joint")
            if (
                joint not in motions
                or attrs.get("forcerange") is None
                or attrs.get("forcelimited") == "false"
            ):
                continue
            where = Where(table.path, f"actuator {short(attrs.get('name') or joint)!r}")
            low, high = where.numbers(attrs["forcerange"], "forcerange", 2)
            gear = where.numbers(attrs.get("gear", "1"), "gear", (1, 2, 3, 4, 5, 6))[0]
            found[joint] = found.get(joint, 0.0) + max(abs(low), abs(high)) * abs(gear)
            if not math.isfinite(found[joint]):
                raise where.error(
                    f"forcerange times gear {gear:g}: the joint's force limit overflows a double"
                )
    for joint, limit in found.items():
        if motions[joint].effort_limit is None and limit > 0:
            motions[joint].effort_limit = limit


def _gravity(path: str, root) -> np.ndarray:
    """``<option gravity>`` (m/s², world frame); MuJoCo's default ``0 0 -9.81``; none with
    ``<option><flag gravity="disable"/>``."""
    gravity = [0.0, 0.0, -9.81]
    for option in root.all("option"):
        if option.get("gravity") is not None:
            gravity = Where(path).numbers(option.get("gravity"), "option: gravity", 3)
        flag = option.child("flag")
        if flag is not None and flag.get("gravity") == "disable":
            gravity = [0.0, 0.0, 0.0]
    return np.array(gravity, dtype=float)


MJ_MINVAL = 1e-15
"""MuJoCo's ``mjMINVAL``: a moving body's mass and principal moments must be at least this."""


def _heavy_enough(table: LinkTable, row: int, welded: dict[str, list[int]]) -> bool:
    """Whether the body of ``row`` can carry a joint, as MuJoCo's compiler decides it: its
    compiled mass and every principal moment are at least :data:`MJ_MINVAL` (kg, kg·m²), or so
    are those of a body welded to it (a child without a joint, or that child's welded children,
    and so on)."""
    inertial = table.inertials[row]
    if (
        inertial is not None
        and inertial.mass >= MJ_MINVAL
        and np.linalg.eigvalsh(inertial.written_inertia).min() >= MJ_MINVAL
    ):
        return True
    return any(_heavy_enough(table, child, welded) for child in welded.get(table.key(row), ()))


def _check_moving_bodies(table: LinkTable) -> None:
    """InputError for a body moved by a joint that cannot carry it (:func:`_heavy_enough`), as
    MuJoCo's compiler refuses it ("mass and inertia of moving bodies must be
    larger than mjMINVAL")."""
    welded: dict[str, list[int]] = {}
    for child, parent in enumerate(table.parents):
        if parent is not None and not table.motions[child]:
            welded.setdefault(parent, []).append(child)
    for row, motions in enumerate(table.motions):
        if not motions or _heavy_enough(table, row, welded):
            continue
        inertial = table.inertials[row]
        mass = inertial.mass if inertial is not None else 0.0
        geoms = inertial is not None and inertial.source == "geoms"
        source = "its geoms give it" if geoms else "its <inertial> has"
        if inertial is None:
            why = "has no <inertial> and no geom with mass"
        elif mass < MJ_MINVAL:
            why = f"{source} mass {mass:.6g} kg"
        else:
            why = f"{source} no inertia" if geoms else f"{source} a zero moment"
        raise InputError(
            f"{table.path}: {table.label(row)}: moved by a joint but {why}; MuJoCo's compiler refuses it "
            "(mass and inertia of moving bodies must be larger than 1e-15): give it an <inertial> or a geom with mass"
        )


# --- includes ---------------------------------------------------------------------------------


def _expanded(document):
    """The root with every ``<include>`` replaced by the children of the included file's root."""

    count = [0]

    def expand(element, chain):
        out = []
        for child in element.children:
            if child.tag != "include":
                expand(child, chain)
                out.append(child)
                continue
            name = child.get("file")
            label = f"{document.path}: include (line {child.line})"
            if not name:
                raise InputError(f"{label}: file: missing")
            count[0] += 1
            if count[0] > MAX_INCLUDES:
                raise InputError(f"{label}: more than {MAX_INCLUDES} includes")
            target = spec_relative_file(document.path, name, f"{label}: {short(name, 1000)}", "robot file")
            key = os.path.realpath(target)
            if key in chain:
                raise InputError(f"{label}: {short(name, 80)}: includes itself (a loop of includes)")
            document.includes.append(key)
            included = read_xml(str(target)).root
            for each in included.iter():
                each.source = str(target)
            expand(included, chain | {key})
            out.extend(included.children)
        element.children = out

    expand(document.root, frozenset({os.path.realpath(document.path)}))
    return document.root


# --- defaults ---------------------------------------------------------------------------------


def _defaults(root) -> dict[str, dict[str, dict[str, str]]]:
    """class name → element tag → attributes, each class holding its parents' values."""
    classes: dict[str, dict[str, dict[str, str]]] = {"main": {}}

    def walk(element, name, inherited):
        own = {tag: dict(attrs) for tag, attrs in inherited.items()}
        for child in element.children:
            if child.tag != "default":
                own.setdefault(child.tag, {}).update(child.attrib)
        classes[name] = own
        for child in element.children:
            if child.tag == "default":
                walk(child, child.get("class", "main"), own)

    for top in root.all("default"):
        walk(top, top.get("class", "main"), classes.get("main", {}))
    return classes


def _attributes(element, defaults, active_class: str, path: str) -> dict[str, str]:
    """The element's attributes over its class's defaults; InputError naming the file (``path``,
    or the included file the element is in), the element and its line for a missing class."""
    name = element.get("class", active_class)
    if name not in defaults:
        where = f"{element.source or path}: <{element.tag}> (line {element.line})"
        raise InputError(f"{where}: class {short(name)!r}: no <default class> of that name")
    merged = dict(defaults[name].get(element.tag, {}))
    merged.update({k: v for k, v in element.attrib.items() if k != "class"})
    return merged


# --- assets -----------------------------------------------------------------------------------


def _mesh_assets(path: str, root, defaults, compiler: Compiler) -> dict[str, dict]:

    meshes = {}
    for asset in root.all("asset"):
        for element in asset.all("mesh"):
            attrs = _attributes(element, defaults, "main", path)
            file = attrs.get("file")
            name = attrs.get("name") or (Path(file).stem if file else None)
            where = Where(path, f"mesh {short(name)!r}")
            if not file:
                meshes[name] = {"error": "no file (meshes given by vertices in the XML are not read)"}
                continue
            folder = compiler.meshdir or compiler.assetdir
            relative = os.path.join(folder, file) if folder and not os.path.isabs(file) else file
            scale = where.numbers(attrs.get("scale", "1 1 1"), "scale", 3)
            mode = attrs.get("inertia", "legacy")
            if mode not in ("legacy", "exact", "convex", "shell"):
                raise where.error(f"inertia: {short(mode)!r}: must be convex, exact, legacy or shell")
            meshes[name] = {
                "file": spec_relative_file(
                    path, relative, f"{path}: mesh {short(name)!r}: {short(relative, 1000)}", "robot file"
                ),
                "scale": np.array(scale, dtype=float),
                "mode": mode,
            }
    return meshes


# --- bodies -------------------------------------------------------------------------------------


class _Bodies:
    def __init__(self, table: LinkTable, compiler: Compiler, defaults, meshes):
        self.table, self.compiler, self.defaults, self.meshes = table, compiler, defaults, meshes
        self.counts: dict[int, int] = {}  # row → the body's geoms read, in its group range or not

    def children(self, element, frame: Pose, link: int | None, active_class: str) -> None:
        """Read the bodies, geoms and joints inside ``element``, whose children are placed by
        ``frame`` in the frame of the body of row ``link`` (None: the world)."""
        for child in element.children:
            if child.tag == "body":
                self.body(child, frame, link, active_class)
            elif child.tag == "frame":
                attrs = _attributes(child, self.defaults, active_class, self.table.path)
                inner = frame.then(self.pose(child, attrs))
                self.children(child, inner, link, child.get("childclass", active_class))
            elif child.tag == "geom" and link is not None:
                self.geom(child, frame, link, active_class)

    def body(self, element, frame: Pose, parent: int | None, active_class: str) -> None:
        attrs, table = dict(element.attrib), self.table
        link = table.add(element.get("name"), element)
        where = Where(table.path, table.label(link))
        table.parents[link] = table.key(parent) if parent is not None else None
        table.origins[link] = frame.then(self.pose(element, attrs, where))
        inner_class = element.get("childclass", active_class)
        if inner_class not in self.defaults:
            raise where.error(f"childclass {short(inner_class)!r}: no <default class> of that name")
        for child in element.children:
            if child.tag == "joint":
                self.joint(where, child, link, inner_class)
            elif child.tag == "freejoint":
                table.motions[link].append(Motion(child.get("name"), "free"))
            elif child.tag == "inertial":
                table.inertials[link] = self.inertial(where, child)
        _check_degrees_of_freedom(where, table.motions[link], parent)
        self.counts[link] = 0
        self.children(element, Pose.identity(), link, inner_class)

    def pose(self, element, attrs, where: Where | None = None) -> Pose:
        if where is None:
            where = Where(self.table.path, f"<{element.tag}> (line {element.line})")
        pos = where.numbers(attrs.get("pos", "0 0 0"), "pos", 3)
        return Pose(self.orientation(where, attrs), np.array(pos, dtype=float))

    def orientation(self, where: Where, attrs) -> np.ndarray:
        given = [key for key in ORIENTATIONS if key in attrs]
        if len(given) > 1:
            raise where.error(f"orientation given twice ({', '.join(given)}); give one")
        if not given:
            return np.eye(3)
        key = given[0]
        value = attrs[key]
        if key == "quat":
            return where.quaternion_matrix(where.numbers(value, "quat", 4), "quat")
        if key == "axisangle":
            x, y, z, a = where.numbers(value, "axisangle", 4)
            axis = where.unit([x, y, z], "axisangle: axis")
            angle = self.compiler.radians(a)
            where.angles([angle], "axisangle")
            return axis_angle_matrix(axis, angle)
        if key == "euler":
            values = [self.compiler.radians(v) for v in where.numbers(value, "euler", 3)]
            where.angles(values, "euler")

            R = np.eye(3)
            for letter, angle in zip(self.compiler.eulerseq, values):
                Ri = axis_angle_matrix(np.eye(3)["xyz".index(letter.lower())], angle)
                R = R @ Ri if letter.islower() else Ri @ R
            return R
        if key == "xyaxes":
            v = where.numbers(value, "xyaxes", 6)
            x = where.unit(v[:3], "xyaxes: x")
            y = np.array(v[3:]) - np.dot(x, v[3:]) * x
            y = where.unit(y, "xyaxes: y (along x)")
            return np.column_stack([x, y, np.cross(x, y)])
        return z_to(where.unit(where.numbers(value, "zaxis", 3), "zaxis"))

    def joint(self, where: Where, element, link: int, active_class: str) -> None:
        attrs = _attributes(element, self.defaults, active_class, self.table.path)
        kind = attrs.get("type", "hinge")
        pos = np.array(where.numbers(attrs.get("pos", "0 0 0"), "joint: pos", 3))
        axis = where.numbers(attrs.get("axis", "0 0 1"), "joint: axis", 3)
        motion = JOINT_MOTIONS.get(kind)
        if motion is None:
            raise where.error(f"joint: type {short(kind)!r}: must be free, ball, slide or hinge")
        ref = where.number(attrs.get("ref"), "joint: ref", 0.0)
        if motion == "revolute":
            ref = self.compiler.radians(ref)
        vector = (
            where.unit(axis, "joint: axis") if motion in ("revolute", "prismatic") else np.array([0, 0, 1.0])
        )
        effort = None
        if attrs.get("actuatorfrcrange") is not None and attrs.get("actuatorfrclimited", "auto") != "false":
            low, high = where.numbers(attrs["actuatorfrcrange"], "joint: actuatorfrcrange", 2)
            effort = max(abs(low), abs(high)) or None
        self.table.motions[link].append(
            Motion(attrs.get("name"), motion, vector, pos, ref, effort_limit=effort)
        )

    def inertial(self, where: Where, element) -> Inertial:
        attrs = element.attrib
        pos = np.array(where.numbers(attrs.get("pos"), "inertial: pos", 3), dtype=float)
        mass = where.number(attrs.get("mass"), "inertial: mass")
        full, diagonal = attrs.get("fullinertia"), attrs.get("diaginertia")
        if (full is None) == (diagonal is None):
            raise where.error("inertial: give exactly one of diaginertia and fullinertia")
        turned = any(key in attrs for key in ORIENTATIONS)
        if turned and full is not None:
            raise where.error(
                "inertial: an orientation is not allowed with fullinertia (which is in the body frame)"
            )
        rotation = self.orientation(where, attrs) if turned else None
        quaternion = np.array(where.numbers(attrs["quat"], "inertial: quat", 4)) if "quat" in attrs else None
        if rotation is not None and np.allclose(rotation, np.eye(3), rtol=0, atol=0):
            rotation, quaternion = None, None
        elif rotation is not None and quaternion is None:
            quaternion = matrix_to_quaternion(rotation)
        if full is not None:
            inertia = from_six(*where.numbers(full, "inertial: fullinertia", 6))
        else:
            inertia = np.diag(where.numbers(diagonal, "inertial: diaginertia", 3))
        where.check_inertia_range(inertia)
        return Inertial.read(mass, pos, inertia, rotation=rotation, quaternion=quaternion, element=element)

    def geom(self, element, frame: Pose, link: int, active_class: str) -> None:
        attrs = _attributes(element, self.defaults, active_class, self.table.path)
        label = element_label("geom", self.counts[link], attrs.get("name") or None)
        where = Where(self.table.path, f"{self.table.label(link)}: {label}")
        kind = attrs.get("type", "sphere")
        if kind not in GEOM_KINDS:
            raise where.error(f"type: {short(kind)!r}: not a MuJoCo geom type ({', '.join(GEOM_KINDS)})")
        group = where.number(attrs.get("group"), "group", 0.0)
        size = where.numbers(attrs.get("size", "0 0 0"), "size", (1, 2, 3)) if "size" in attrs else []
        pose, size = self.geom_frame(where, attrs, kind, size)
        mass = where.number(attrs.get("mass"), "mass") if "mass" in attrs else None
        density = where.number(attrs.get("density"), "density", 1000.0)
        if (mass if mass is not None else density) < 0:
            what = f"mass {mass!r}" if mass is not None else f"density {density!r}"
            raise where.error(f"{what} is negative; MuJoCo's compiler refuses the model")
        shell = (attrs.get("shellinertia") or "false") == "true"
        geom = Geom(kind, (), frame.then(pose), label, mass=mass, density=density, shell=shell)
        factors = SIZES.get(kind)
        if factors is not None:
            geom.size = tuple(f * v for f, v in zip(factors, _size(where, size, len(factors), kind)))
        elif kind == "mesh":
            mesh_name = attrs.get("mesh")
            asset = self.meshes.get(mesh_name)
            if asset is None:
                raise where.error(f"mesh: {short(mesh_name)!r}: no <mesh> asset of that name")
            if "error" in asset:
                raise where.error(f"mesh {short(mesh_name)!r}: {asset['error']}")
            if shell:
                raise where.error(
                    'shellinertia: a mesh geom takes its inertia mode from its <mesh inertia="...">'
                    " asset, not from shellinertia (MuJoCo's compiler refuses the model)"
                )
            geom.mesh_file, geom.mesh_scale, geom.mesh_inertia = asset["file"], asset["scale"], asset["mode"]
        where.positive(geom.size, "size", allow_zero=True)
        in_group = self.compiler.group_range[0] <= group <= self.compiler.group_range[1]
        self.counts[link] += 1
        if in_group:
            self.table.collisions[link].append(geom)

    def geom_frame(self, where: Where, attrs, kind: str, size: list[float]) -> tuple[Pose, list[float]]:
        fromto = attrs.get("fromto")
        if fromto is None or kind not in ("capsule", "cylinder", "box", "ellipsoid"):
            return self.pose(None, attrs, where), size
        values = where.numbers(fromto, "fromto", 6)
        start, end = np.array(values[:3]), np.array(values[3:])
        direction = end - start
        length = float(np.linalg.norm(direction))
        if not length > 0:
            raise where.error("fromto: the two ends coincide")
        half = length / 2
        radius = _size(where, size, 1, kind, fromto=True)[0]
        # MuJoCo's compiler: a box or ellipsoid with fromto is as wide as size[0] across both
        # transverse axes (size[1] is not read), as long as the segment
        size = [radius, half] if kind in ("capsule", "cylinder") else [radius, radius, half]
        return Pose(z_to(direction / length), (start + end) / 2), size


def _size(where: Where, size: list[float], needed: int, kind: str, fromto: bool = False) -> list[float]:
    if len(size) < needed:
        raise where.error(
            f"size: a {kind}{' with fromto' if fromto else ''} needs {needed} number(s), got {len(size)}"
        )
    return list(size[:needed])


def z_to(direction) -> np.ndarray:
    """The rotation MuJoCo uses to turn z onto ``direction`` (a unit vector): about z × direction,
    the shortest turn; about x by half a turn when ``direction`` is −z."""

    d = np.asarray(direction, dtype=float)
    axis = np.cross([0.0, 0.0, 1.0], d)
    s = float(np.linalg.norm(axis))
    return axis_angle_matrix(axis / s if s >= 1e-10 else np.array([1.0, 0.0, 0.0]), math.atan2(s, d[2]))


# --- compiled mass properties ---------------------------------------------------------------


def _compile_inertia(table: LinkTable, compiler: Compiler) -> list[str]:
    """Each body's compiled mass properties into ``table`` (from its geoms in the group range,
    its collisions); the notes on ``<inertial>`` elements MuJoCo ignores."""
    notes = []
    inertials = table.inertials
    for row, explicit in enumerate(inertials):
        use_geoms = compiler.inertiafromgeom == "true" or (
            compiler.inertiafromgeom == "auto" and explicit is None
        )
        if use_geoms:
            props = geoms_sum(
                table.collisions[row],
                lambda geom, measure: geom.density if geom.mass is None else geom.mass / measure,
                f"{table.path}: {table.label(row)}: ",
                "exact",
                as_mujoco=True,
            )
            if props is not None:
                inertials[row] = Inertial(props, props.inertia_about_com, element=None, source="geoms")
                if explicit is not None:
                    notes.append(
                        f'{table.path}: {table.label(row)}: <inertial> ignored: inertiafromgeom="true" '
                        "takes the mass properties from the geoms, as MuJoCo does"
                    )
            elif explicit is not None and compiler.inertiafromgeom == "true":
                inertials[row] = None
        inertial = inertials[row]
        if inertial is not None and (compiler.boundmass > 0 or compiler.boundinertia > 0):
            inertial = inertials[row] = _bound(inertial, compiler)
        if inertial is not None and compiler.balanceinertia == "true":
            inertials[row] = _balance(inertial)
    if compiler.settotalmass > 0:
        total = sum(inertial.mass for inertial in inertials if inertial is not None)
        if total > 0:
            scale = compiler.settotalmass / total
            for row, inertial in enumerate(inertials):
                if inertial is not None:
                    inertials[row] = replace(
                        inertial,
                        properties=inertial.properties.scaled(scale),
                        written_inertia=inertial.written_inertia * scale,
                    )
    return notes


def _balance(inertial: Inertial) -> Inertial:
    """``<compiler balanceinertia="true">``: a body whose principal moments break the triangle
    inequality (one larger than the sum of the other two) gets their mean as all three, as
    MuJoCo's compiler does (kg·m², about the body's centre of mass)."""
    a, b, c = np.linalg.eigvalsh(inertial.properties.inertia_about_com)
    if a + b < c or a + c < b or b + c < a:
        mean = (a + b + c) / 3.0
        com = inertial.properties.center_of_mass
        return Inertial.read(
            inertial.mass, com, mean * np.eye(3), element=inertial.element, source=inertial.source
        )
    return inertial


def _bound(inertial: Inertial, compiler: Compiler) -> Inertial:
    mass = max(inertial.mass, compiler.boundmass)
    com = inertial.properties.center_of_mass
    if compiler.boundinertia > 0:
        moments, axes = np.linalg.eigh(inertial.properties.inertia_about_com)
        moments = np.maximum(moments, compiler.boundinertia)
        inertia = (axes * moments) @ axes.T
        return Inertial.read(mass, com, inertia, element=inertial.element, source=inertial.source)
    properties = MassProperties(mass, com, inertial.properties.inertia_about_com, "link")
    return replace(inertial, properties=properties)


JOINT_MOTIONS = {"hinge": "revolute", "slide": "prismatic", "ball": "ball", "free": "free"}
"""MJCF's joint types and the motion kind (:class:`rbi.formats.robot.Motion`) each one is."""

_JOINT_TYPES = {motion: joint_type for joint_type, motion in JOINT_MOTIONS.items()}

_DEGREES_OF_FREEDOM = {"free": 6, "ball": 3, "revolute": 1, "prismatic": 1}


def _check_degrees_of_freedom(where: Where, motions: list[Motion], parent: int | None) -> None:
    """MuJoCo's compiler refuses a free joint below the top level of <worldbody>, a body with
    more than six degrees of freedom, and a ball joint followed by a hinge or ball in the same
    body; so does rbi, in MuJoCo's terms."""
    kinds = [motion.kind for motion in motions]
    words = [_JOINT_TYPES.get(kind, kind) for kind in kinds]
    if "free" in kinds and parent is not None:
        raise where.error(
            "free joint: only a body directly in <worldbody> can have one (MuJoCo: 'free joint can "
            "only be used on top level'); join it to its parent with hinge, slide or ball joints"
        )
    dofs = sum(_DEGREES_OF_FREEDOM.get(kind, 0) for kind in kinds)
    if dofs > 6:
        raise where.error(
            f"its joints ({', '.join(words)}) give it {dofs} degrees of freedom; a body has at most 6 "
            f"(MuJoCo refuses it: 'more than 6 dofs')"
        )
    if "ball" in kinds and any(kind in ("ball", "revolute") for kind in kinds[kinds.index("ball") + 1 :]):
        raise where.error(
            f"its joints ({', '.join(words)}): a ball joint followed by another rotation (MuJoCo refuses "
            f"it: 'ball followed by rotation'); put the hinge before the ball, or use one ball"
        )
