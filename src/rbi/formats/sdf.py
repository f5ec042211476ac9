"""SDF: ``<sdf>[<world>]<model name><pose/><link name><pose/><inertial/><collision/><visual/>
</link><joint name type><parent/><child/><pose/><axis><xyz/></axis></joint></model>``.

- A link's ``<pose>`` places it in its model's frame (at every joint's zero); a model's pose
  places it in the world. ``x y z roll pitch yaw`` (radians unless ``degrees="true"``), or
  ``rotation_format="quat_xyzw"``. A ``<pose relative_to="NAME">`` (SDFormat 1.7+) is in the
  frame of that link, joint or ``<frame>`` of the same model (``__model__``: the model's), as
  each stands at the zero configuration (:class:`_Frames`).
- ``<inertial><pose/><mass/><inertia><ixx/>…</inertia>``: SDF's defaults (mass 1,
  ``ixx = iyy = izz = 1``) fill missing elements; a link with no ``<inertial>`` has that default
  inertial at its origin (``source="default"``), as SDFormat, Gazebo and Drake give it;
  ``<inertial auto="true">`` (SDFormat 1.11) is computed from the collision geometry at each
  collision's ``<density>`` (default 1000 kg/m³), scaled to a given ``<mass>``.
- Geometry: ``<box><size/>``, ``<cylinder><radius/><length/>``, ``<sphere><radius/>``,
  ``<capsule><radius/><length/>``, ``<ellipsoid><radii/>``, ``<mesh><uri/><scale/>``.
- A joint's ``<pose>`` is in the child link's frame (unless ``relative_to``); its
  ``<axis><xyz>`` in the joint frame (in the model frame with ``use_parent_model_frame``, in any
  other frame of the model with ``expressed_in``).
- ``<include>`` of another model is not followed: it is listed in :attr:`RobotModel.unchecked`,
  so no check reports the file as fine without having read those links.

Link and joint names are the model's own; when the file holds several models they are written
``model::link`` and ``model::joint``.
"""

from __future__ import annotations

import math

import numpy as np

from rbi.core.mass import MassProperties
from rbi.formats.robot import (
    SHAPES,
    Geom,
    Inertial,
    LinkTable,
    Motion,
    Pose,
    RobotModel,
    Where,
    element_label,
    from_six,
    refuse_shared_keys,
    rpy_matrix,
    short,
)
from rbi.formats.robot_geometry import geoms_sum
from rbi.formats.robot_paths import resolve_mesh

JOINT_KINDS = ("revolute", "prismatic", "fixed", "ball", "universal", "revolute2", "screw", "gearbox")
"""SDF's joint types that are their own motion kind; ``continuous`` is ``revolute``, any other ``other``."""


def read_sdf(document, package_paths=None, geometry: bool = True) -> RobotModel:
    path, root = document.path, document.root
    models = list(_models(root, Pose.identity()))
    world = root.child("world")
    first = root.child("model") or (world.child("model") if world is not None else None)
    name = first.get("name") if first is not None else None
    unchecked = [
        f"{path}: include {short(_text(include, 'uri'), 80)!r}: not followed; "
        "the links of the included model are not checked"
        for include in root.iter("include")
    ]
    prefix = len(models) > 1
    table = LinkTable(path, "link")
    named: set[str] = set()
    for model_element, model_pose in models:
        model_name = model_element.get("name") or ""
        if prefix and model_name in named:  # libsdformat refuses it too (DUPLICATE_NAME)
            raise Where(path, f"model {short(model_name)}").error(
                "another model in this file has the same name, so their links and joints cannot be "
                "told apart (SDFormat: model names must be unique)"
            )
        named.add(model_name)
        links: dict[str, int] = {}
        link_poses: dict[str, Pose] = {}
        frames = _Frames(path, model_element)
        for element in model_element.all("link"):
            own = element.get("name")
            row = table.add(f"{model_name}::{own}" if prefix and own is not None else own, element)
            where = Where(path, table.label(row))
            link_poses[own] = model_pose.then(frames.in_model(own, where))
            table.origins[row] = link_poses[own]
            inertial = element.child("inertial")
            auto = inertial is not None and _true(inertial.get("auto"))
            if geometry or auto:
                table.collisions[row] = _geoms(where, element, "collision", package_paths, frames.within(own))
            if geometry:
                table.visuals[row] = _geoms(where, element, "visual", package_paths, frames.within(own))
            if auto:
                table.inertials[row] = _auto_inertial(where, inertial, table.collisions[row])
            elif inertial is not None:
                table.inertials[row] = _inertial(where, inertial, frames.within(own))
            else:  # SDFormat's default inertial: 1 kg, unit moments, at the link origin
                table.inertials[row] = Inertial.read(1.0, np.zeros(3), np.eye(3), source="default")
            links[own] = row
        refuse_shared_keys(path, "link", table.names)  # across models too: "a" + "b::c" is "a::b" + "c"
        _joints(table, model_element, links, link_poses, frames, f"{model_name}::" if prefix else "")
    return RobotModel(path, "sdf", name, table.columns(), unchecked=unchecked, document=document)


def _models(element, pose: Pose, nested: bool = False):
    """(model element, its pose in the world) for every model, nested ones too (``nested``:
    ``element`` is a model, whose own models are named ``model`` in messages)."""
    for child in element.children:
        if child.tag == "world" and not nested:
            yield from _models(child, pose)
        elif child.tag == "model":
            where = Where("", "model" if nested else f"model {short(child.get('name'))}")
            inner = pose.then(_pose(where, child.child("pose"), "pose"))
            yield child, inner
            yield from _models(child, inner, nested=True)


def _pose(where: Where, element, what: str, within=None) -> Pose:
    """The pose ``element`` writes, in its own element's frame: ``within`` (``_Frames.within``),
    when given, turns a pose written ``relative_to`` another frame of the model into the own
    frame; without it, ``relative_to`` is not read (the caller places the frame it names)."""
    if element is None or not element.text:
        return Pose.identity()
    if within is not None:
        return within(where, element.get("relative_to"), _pose(where, element, what))
    xyz, rpy, quaternion = _written(where, element, what)
    if quaternion is not None:
        return Pose(where.quaternion_matrix(quaternion, what), xyz)
    return Pose(rpy_matrix(rpy) if any(rpy) else np.eye(3), xyz)


def _written(where: Where, element, what: str) -> tuple[np.ndarray, list[float] | None, np.ndarray | None]:
    """A ``<pose>`` as written: its position (m) and its rotation, either roll, pitch, yaw (rad,
    read in degrees with ``degrees="true"``) or a quaternion ``w x y z``
    (``rotation_format="quat_xyzw"``, reordered), the other None."""
    if (element.get("rotation_format") or "euler_rpy") == "quat_xyzw":
        values = where.numbers(element.text, what, 7)
        qx, qy, qz, qw = values[3:]
        return np.array(values[:3], dtype=float), None, np.array([qw, qx, qy, qz], dtype=float)
    values = where.numbers(element.text, what, 6)
    rpy = values[3:]
    if _true(element.get("degrees")):
        rpy = [math.radians(a) for a in rpy]
    where.angles(rpy, what)
    return np.array(values[:3], dtype=float), rpy, None


def _inertial(where: Where, inertial, within) -> Inertial:
    pose_element = inertial.child("pose")
    pose = _pose(where, pose_element, "inertial/pose", within)
    moved = pose_element is not None and pose_element.get("relative_to") not in (None, "")
    rpy, quaternion = None, None
    # written in another frame (moved), the rotation into the link's is not the one written
    if _text(inertial, "pose") and not moved:
        _, written, quaternion = _written(where, pose_element, "inertial/pose")
        rpy = tuple(float(a) for a in written) if written is not None and any(written) else None
    mass_element = inertial.child("mass")
    mass = where.number(None if mass_element is None else mass_element.text, "inertial/mass", default=1.0)
    block = inertial.child("inertia")
    six = {}
    for key, default in (("ixx", 1.0), ("iyy", 1.0), ("izz", 1.0), ("ixy", 0.0), ("ixz", 0.0), ("iyz", 0.0)):
        entry = None if block is None else block.child(key)
        six[key] = where.number(
            None if entry is None else entry.text, f"inertial/inertia/{key}", default=default
        )
    inertia = from_six(**six)
    where.check_inertia_range(inertia)
    turned = rpy is not None or (
        (quaternion is not None or moved) and not np.allclose(pose.rotation, np.eye(3), 0, 0)
    )
    return Inertial.read(
        mass,
        pose.translation,
        inertia,
        rotation=pose.rotation if turned else None,
        rpy=rpy,
        quaternion=quaternion if turned and rpy is None else None,
        element=inertial,
    )


SDF_DENSITY = 1000.0
"""SDFormat's default ``<collision><density>`` (kg/m³), for ``<inertial auto="true">``."""


def _auto_inertial(where: Where, inertial, collisions: list[Geom]) -> Inertial:
    """``<inertial auto="true">`` (SDFormat 1.11): the mass properties of the link's collision
    geometry at each collision's ``<density>`` (default 1000 kg/m³), scaled to the inertial's
    ``<mass>`` when it gives one."""

    props = geoms_sum(
        collisions,
        lambda geom, _: SDF_DENSITY if geom.density is None else geom.density,
        f"{where.path}: {where.label}: ",
        "auto",
    ) or MassProperties.zero("link")
    if not props.mass > 0:
        raise where.error(
            'inertial auto="true": the link has no collision geometry with a volume to compute it from'
        )
    if (written := _text(inertial, "mass")) is not None:
        mass = where.number(written, "inertial/mass")
        where.positive((mass,), "inertial/mass")
        props = props.with_mass(mass)
    return Inertial(props, props.inertia_about_com, element=inertial, source="auto")


def _geoms(where: Where, link_element, tag: str, package_paths, within) -> list[Geom]:
    found = []
    for index, element in enumerate(link_element.all(tag)):
        label = element_label(tag, index, element.get("name") or None)
        pose = _pose(where, element.child("pose"), f"{label}/pose", within)
        holder = element.child("geometry")
        shape = next(iter(holder.children), None) if holder is not None else None
        if shape is None:
            raise where.error(f"{label}/geometry: missing")
        geom = _geom(where, shape, pose, f"{label}/geometry/{shape.tag}", package_paths)
        if (density := _text(element, "density")) is not None:
            geom.density = where.number(density, f"{label}/density")
            where.positive((geom.density,), f"{label}/density")
        found.append(geom)
    return found


def _value(where: Where, shape, tag: str, label: str, count: int = 1) -> list[float]:
    child = shape.child(tag)
    if child is None:
        raise where.error(f"{label}/{tag}: missing")
    return where.numbers(child.text, f"{label}/{tag}", count)


def _geom(where: Where, shape, pose: Pose, label: str, package_paths) -> Geom:
    kind = shape.tag
    fields = SHAPES.get(kind)
    if fields is not None:
        size = [value for tag, count in fields for value in _value(where, shape, tag, label, count)]
        tags = [tag for tag, _ in fields]
        where.positive(
            size, f"{label}/{tags[0]}" if len(tags) == 1 else f"{label}: {' and '.join(tags)}", True
        )
        return Geom(kind, tuple(size), pose, label)
    if kind == "mesh":
        uri = _text(shape, "uri")
        if uri is None:
            raise where.error(f"{label}/uri: missing")
        scale_element = shape.child("scale")
        scale = where.numbers("1 1 1" if scale_element is None else scale_element.text, f"{label}/scale", 3)
        mesh = resolve_mesh(where, uri, label, package_paths)
        return Geom("mesh", (), pose, label, mesh_file=mesh, mesh_scale=np.array(scale, dtype=float))
    return Geom(kind, (), pose, label)


def _joints(table: LinkTable, model_element, links: dict, link_poses: dict, frames, prefix: str) -> None:
    """Each joint of the model onto its child link (a row of ``table``); a joint's name is
    ``prefix`` and its own."""
    path = table.path
    for index, element in enumerate(model_element.all("joint")):
        name = element.get("name")
        joint_name = prefix + name if prefix and name is not None else name
        where = Where(path, element_label("joint", index, name))
        parent_element, child_element = element.child("parent"), element.child("child")
        if parent_element is None or child_element is None:
            raise where.error("needs <parent> and <child>")
        parent_name, child_name = parent_element.text, child_element.text
        if child_name not in links:
            raise where.error(f"child: no link named {short(child_name)!r} in this model")
        child = links[child_name]
        kind = element.get("type") or ""
        kind = "revolute" if kind == "continuous" else kind if kind in JOINT_KINDS else "other"
        if parent_name in ("world", "__world__") or parent_name not in links:
            table.motions[child] = [Motion(joint_name, kind)]
            continue
        if table.parents[child] is not None:
            raise where.error(f"child: link {short(child_name)!r} already has a parent joint")
        table.parents[child] = table.names[links[parent_name]]
        table.origins[child] = link_poses[parent_name].inverse().then(link_poses[child_name])
        joint_pose = frames.in_model(child_name, where).inverse().then(frames.in_model(name, where))
        axis_element = element.child("axis")
        xyz_element = axis_element.child("xyz") if axis_element is not None else None
        axis = where.numbers(xyz_element.text, "axis/xyz", 3) if xyz_element is not None else [0.0, 0.0, 1.0]
        if kind in ("revolute", "prismatic"):
            axis = where.unit(axis, "axis/xyz")
            expressed_in = xyz_element.get("expressed_in") if xyz_element is not None else None
            if _text(axis_element, "use_parent_model_frame") in ("true", "1") or expressed_in == "__model__":
                axis = frames.in_model(child_name, where).rotation.T @ axis
            elif expressed_in not in (None, ""):
                axis = frames.within(child_name)(where, expressed_in, Pose.identity()).rotation @ axis
            else:
                axis = joint_pose.rotation @ axis
        effort = None
        if (written := _text(axis_element, "limit", "effort")) is not None:
            effort = where.number(written, "axis/limit/effort")
            effort = None if effort < 0 else abs(effort)  # SDFormat: a negative effort enforces no limit
        table.motions[child] = [
            Motion(
                joint_name, kind, np.asarray(axis, dtype=float), joint_pose.translation, effort_limit=effort
            )
        ]


class _Frames:
    """The named frames of one SDF model (its links, joints and ``<frame>`` elements) placed in
    the model's frame at the zero configuration, as SDFormat's pose graph places them: a link's
    ``<pose>`` is relative to ``__model__`` by default, a joint's to its child link, a frame's
    to the frame it is ``attached_to``; ``relative_to`` names another. Units: metres, radians."""

    def __init__(self, path: str, model_element) -> None:
        self.path = path
        self.elements: dict[str, tuple] = {}
        for tag in ("link", "joint", "frame"):
            for element in model_element.all(tag):
                name = element.get("name")
                if name is not None:
                    self.elements.setdefault(name, (tag, element))
        self.placed: dict[str, Pose] = {"__model__": Pose.identity()}
        self.open: set[str] = set()

    def in_model(self, name: str | None, where: Where) -> Pose:
        """The frame ``name`` in the model's frame (InputError for an unknown name or a loop)."""
        if name in (None, "", "__model__"):
            return Pose.identity()
        if name in self.placed:
            return self.placed[name]
        if name not in self.elements:
            raise where.error(f"relative_to: no link, joint or frame named {short(name)!r} in this model")
        if name in self.open:
            raise where.error(
                f"pose: the frames' relative_to and attached_to form a loop through {short(name)!r}"
            )
        tag, element = self.elements[name]
        pose_element = element.child("pose")
        default = {"link": None, "joint": _text(element, "child"), "frame": element.get("attached_to")}[tag]
        relative_to = (pose_element.get("relative_to") if pose_element is not None else None) or default
        self.open.add(name)
        local = _pose(where, pose_element, "pose")
        self.placed[name] = self.in_model(relative_to, where).then(local)
        self.open.discard(name)
        return self.placed[name]

    def within(self, own: str):
        """A function (where, relative_to, pose) → that pose in frame ``own`` (a link's frame),
        for the poses of the link's inertial, collisions and visuals."""

        def placed(where: Where, relative_to: str | None, pose: Pose) -> Pose:
            if relative_to in (None, "", own):
                return pose
            return self.in_model(own, where).inverse().then(self.in_model(relative_to, where)).then(pose)

        return placed


def _text(element, *tags: str) -> str | None:
    """The text of ``element``'s child ``tags[0]``, that child's child ``tags[1]``, and so on
    (None when one of them is missing or the text is blank)."""
    for tag in tags:
        element = element.child(tag) if element is not None else None
    return element.text or None if element is not None else None


def _true(value: str | None) -> bool:
    """An SDF boolean attribute (``true`` or ``1``, any case, spaces around) is set."""
    return (value or "").strip().lower() in ("true", "1")
