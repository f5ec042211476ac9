"""URDF: ``<robot><link name><inertial>…</inertial><collision>…<visual>…</link><joint …/>``.

- ``<inertial><origin xyz rpy/><mass value/><inertia ixx ixy ixz iyy iyz izz/>``; ``rpy`` is
  roll, pitch, yaw about the fixed x, y, z axes (``R = Rz(yaw) Ry(pitch) Rx(roll)``); the
  inertia is about the centre of mass in the inertial frame's axes, off-diagonal entries the
  matrix's own (``ixy = −∫xy dm``).
- ``<collision>``/``<visual>``: ``<origin/>`` and ``<geometry>`` holding one of ``<box size>``,
  ``<cylinder radius length>`` (along z), ``<sphere radius>``, ``<capsule radius length>`` (as
  pybullet and ROS 2 read it: ``length`` the cylindrical part) or ``<mesh filename scale>``.
- ``<joint type><origin/><parent link/><child link/><axis xyz/>``: the child link's frame in the
  parent's at zero, and the motion (revolute and continuous turn about the axis, prismatic
  slides along it, in the child's frame).
"""

from __future__ import annotations

import numpy as np

from rbi.errors import InputError
from rbi.formats.robot import (
    Geom,
    Inertial,
    Link,
    Motion,
    Pose,
    RobotModel,
    Where,
    angles,
    check_inertia_range,
    check_unique_joint_names,
    check_unique_names,
    from_six,
    number,
    numbers,
    positive,
    rpy_matrix,
    short,
    unit,
)
from rbi.formats.robot_paths import resolve_mesh

MOVING = {
    "revolute": "revolute",
    "continuous": "revolute",
    "prismatic": "prismatic",
    "floating": "floating",
    "planar": "planar",
    "fixed": "fixed",
    "spherical": "ball",
    "ball": "ball",
}


UNIT_AXIS_KINDS = ("revolute", "prismatic")
"""The motions whose ``<axis xyz>`` is made a unit vector (the others keep it as written)."""


def read_urdf(document, package_paths=None, geometry: bool = True) -> RobotModel:
    path, root = document.path, document.root
    model = RobotModel(path, "urdf", root.get("name"), document=document)
    if not root.all("link"):
        raise InputError(f"{path}: no <link>: a URDF needs at least one (urdfdom and pybullet refuse it)")
    for index, element in enumerate(root.all("link")):
        link = Link(index, element.get("name"), element=element, word="link")
        if not link.name:
            raise InputError(
                f"{path}: link[{index}] (line {element.line}): name: missing; every link needs a name "
                "(urdfdom and pybullet refuse it)"
            )
        where = Where(path, link)
        inertial = element.child("inertial")
        if inertial is not None:
            link.inertial = _inertial(where, inertial)
        if geometry:
            link.collisions = _geoms(where, element, "collision", package_paths)
            link.visuals = _geoms(where, element, "visual", package_paths)
        model.links.append(link)
    check_unique_names(path, model.links, "link")
    _joints(model, root)
    return model


def _origin(where: Where, element, what: str) -> Pose:
    origin = element.child("origin") if element is not None else None
    if origin is None:
        return Pose.identity()
    xyz = numbers(where, origin.get("xyz", "0 0 0"), f"{what}/origin: xyz", 3)
    rpy = angles(
        where, numbers(where, origin.get("rpy", "0 0 0"), f"{what}/origin: rpy", 3), f"{what}/origin: rpy"
    )
    return Pose(rpy_matrix(rpy) if any(rpy) else _IDENTITY.copy(), np.array(xyz, dtype=float))


_IDENTITY = np.eye(3)


def _inertial(where: Where, inertial) -> Inertial:
    origin = inertial.child("origin")
    xyz = numbers(
        where, origin.get("xyz", "0 0 0") if origin is not None else "0 0 0", "inertial/origin: xyz", 3
    )
    rpy = numbers(
        where, origin.get("rpy", "0 0 0") if origin is not None else "0 0 0", "inertial/origin: rpy", 3
    )
    angles(where, rpy, "inertial rpy")
    mass_element = inertial.child("mass")
    if mass_element is None:
        raise where.error("inertial/mass: missing")
    mass = number(where, mass_element.get("value"), "inertial/mass: value")
    block = inertial.child("inertia")
    if block is None:
        raise where.error("inertial/inertia: missing")
    six = {
        key: number(where, block.get(key), f"inertial/inertia: {key}")
        for key in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
    }
    inertia = from_six(**six)
    check_inertia_range(where, inertia)
    has_rpy = any(rpy)
    return Inertial.read(
        mass,
        xyz,
        inertia,
        rotation=rpy_matrix(rpy) if has_rpy else None,
        rpy=tuple(float(a) for a in rpy) if has_rpy else None,
        element=inertial,
    )


def _geoms(where: Where, link_element, tag: str, package_paths) -> list[Geom]:
    found = []
    for number_, element in enumerate(link_element.all(tag)):
        label = f"{tag}[{number_}]"
        pose = _origin(where, element, label)
        holder = element.child("geometry")
        shape = None
        if holder is not None:
            shape = next(iter(holder.children), None)
        if shape is None:
            raise where.error(f"{label}/geometry: missing (give a box, cylinder, sphere, capsule or mesh)")
        found.append(_geom(where, shape, pose, f"{label}/geometry/{shape.tag}", package_paths))
    return found


def _geom(where: Where, shape, pose: Pose, label: str, package_paths) -> Geom:
    kind = shape.tag
    if kind == "box":
        size = numbers(where, shape.get("size"), f"{label}: size", 3)
        positive(where, size, f"{label}: size", allow_zero=True)
        return Geom("box", tuple(size), pose, label)
    if kind in ("cylinder", "capsule"):
        radius = number(where, shape.get("radius"), f"{label}: radius")
        length = number(where, shape.get("length"), f"{label}: length")
        positive(where, (radius, length), f"{label}: radius and length", allow_zero=True)
        return Geom(kind, (radius, length), pose, label)
    if kind == "sphere":
        radius = number(where, shape.get("radius"), f"{label}: radius")
        positive(where, (radius,), f"{label}: radius", allow_zero=True)
        return Geom("sphere", (radius,), pose, label)
    if kind == "mesh":
        filename = shape.get("filename")
        if not filename:
            raise where.error(f"{label}: filename: missing")
        scale = numbers(where, shape.get("scale", "1 1 1"), f"{label}: scale", (1, 3))
        scale = scale * 3 if len(scale) == 1 else scale
        mesh = resolve_mesh(
            where.path,
            filename,
            f"{where.path}: {where.label}: {label}: {short(filename, 1000)}",
            package_paths,
        )
        return Geom("mesh", (), pose, label, mesh_file=mesh, mesh_scale=np.array(scale, dtype=float))
    return Geom(kind, (), pose, label)


def _joints(model: RobotModel, root) -> None:
    path = model.path
    by_name = {link.name: link for link in model.links if link.name is not None}
    for index, element in enumerate(root.all("joint")):
        name = element.get("name")
        where = Where(path, lambda index=index, name=name: _joint_label(index, name))
        if not name:
            raise where.error("name: missing; every joint needs a name (urdfdom refuses it)")
        parent, child = element.child("parent"), element.child("child")
        if parent is None or child is None:
            raise where.error("needs <parent link=…/> and <child link=…/>")
        parent_name, child_name = parent.get("link"), child.get("link")
        for role, link_name in (("parent", parent_name), ("child", child_name)):
            if link_name not in by_name:
                raise where.error(f"{role}: no link named {short(link_name)!r}")
        link = by_name[child_name]
        if link.parent is not None:
            raise where.error(
                f"child: link {short(child_name)!r} is already the child of link {short(link.parent)!r}: "
                "two joints close a loop, and a URDF's links form a tree (model a closed chain in SDF or MJCF)"
            )
        kind = element.get("type") or ""
        if kind not in MOVING:
            raise where.error(
                f"type: {short(kind)!r} is not a URDF joint type (revolute, continuous, prismatic, "
                "fixed, floating, planar)"
            )
        link.parent = parent_name
        link.origin = _origin(where, element, "joint")
        motion_kind = MOVING[kind]
        axis_vector = _axis(where, element.child("axis"), motion_kind in UNIT_AXIS_KINDS)
        limit = element.child("limit")
        effort = None
        if limit is not None and limit.get("effort") is not None:
            effort = abs(number(where, limit.get("effort"), "limit: effort"))
        link.motions = [Motion(name, motion_kind, axis_vector, np.zeros(3), effort_limit=effort)]
    check_unique_joint_names(model, "urdfdom")
    check_tree(model)


_UNIT_AXES: dict[str, np.ndarray] = {}
"""Unit axes already worked out, by the ``xyz`` text as written (a large file repeats a few;
short texts only, at most 1,024 of them)."""


def _axis(where: Where, axis_element, to_unit: bool) -> np.ndarray:
    """A joint's axis (its child link's frame): ``xyz`` as written (default 1 0 0), made a unit
    vector when ``to_unit`` (revolute and prismatic joints); a new array each call."""
    if axis_element is None:
        return unit(where, [1, 0, 0], "axis: xyz") if to_unit else np.array([1, 0, 0], float)
    text = axis_element.get("xyz", "1 0 0")
    axis = numbers(where, text, "axis: xyz", 3)
    if not to_unit:
        return np.array(axis, float)
    known = _UNIT_AXES.get(text)
    if known is None:
        known = unit(where, axis, "axis: xyz")
        if len(text) <= 64 and len(_UNIT_AXES) < 1024:
            _UNIT_AXES[text] = known
    return known.copy()


def _joint_label(index: int, name: str | None) -> str:
    return f"joint[{index}]" + (f" ({short(name)})" if name is not None else "")


def check_tree(model: RobotModel) -> None:
    """InputError for links no joint joins to the one root, or joints that form a loop."""
    by_name = {link.name: link for link in model.links}
    roots = [link for link in model.links if link.parent is None]
    if len(roots) > 1:
        names = ", ".join(repr(short(link.name)) for link in roots[:4]) + (", ..." if len(roots) > 4 else "")
        raise InputError(
            f"{model.path}: {len(roots)} root links ({names}): no joint joins them; a URDF has one root "
            "link that every other hangs from (urdfdom and pybullet refuse it)"
        )
    children: dict[str | None, list[str]] = {}
    for link in model.links:
        children.setdefault(link.parent, []).append(link.name)
    reached, queue = 0, list(children.get(None, []))
    while queue:  # one pass from the root: every link reached means no loop
        reached += 1
        queue.extend(children.get(queue.pop(), []))
    if reached == len(model.links):
        return
    for link in model.links:  # a loop: name the first link whose chain of parents runs into it
        seen = set()
        at = link
        while at.parent is not None:
            if at.name in seen:
                raise InputError(
                    f"{model.path}: {link.label}: the joints form a loop through link "
                    f"{short(at.name)!r}; a URDF's links form a tree"
                )
            seen.add(at.name)
            at = by_name[at.parent]
