"""Mass properties of a robot link's geometry (the :class:`~rbi.formats.robot.Geom` pieces
a reader returns), per unit density, in the link's frame.

Primitives are :mod:`rbi.core.shapes`' closed forms (the exact ones, as MuJoCo's: a capsule is a
cylinder and two hemispheres); meshes are integrated by :mod:`rbi.core.mesh` in one of three modes, as MuJoCo
names them: ``exact`` (the solid a closed mesh encloses), ``convex`` (the solid convex hull) and
``shell`` (mass on the surface). A shell's density is mass per area (kg/m²), as MuJoCo reads a
geom's density under ``shellinertia``.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from rbi.core import shapes
from rbi.core.mass import MassProperties
from rbi.core.rotation import quaternion_multiply, quaternion_to_matrix
from rbi.errors import InputError
from rbi.formats.paths import file_key
from rbi.formats.robot import Geom
from rbi.memory import cached

if TYPE_CHECKING:
    from rbi.core.mesh import MeshDistribution

MESH_INERTIA_MODES = ("auto", "exact", "convex", "shell")
"""The audit's ``--mesh-inertia`` choices; an MJCF mesh asset may also say ``legacy``."""
"""``auto``: ``exact`` for a closed mesh; for one that is not (open, inconsistently wound, no
volume), its solid convex hull, with a warning saying so (:class:`MeshFallback`)."""


class MeshFallback(NamedTuple):
    """A mesh that ``auto`` could not integrate exactly: the mesh file's name and why; ``used``
    is ``convex`` (its hull stands in) or None (left out: not even its hull has a volume)."""

    file: str
    label: str
    reason: str
    used: str | None

    def message(self) -> str:
        instead = (
            "its convex hull is used instead"
            if self.used
            else "it is left out (even its convex hull has no volume)"
        )
        return f"{self.label}: mesh {self.file}: {self.reason}; {instead}"


class Distribution(NamedTuple):
    """Where a piece of geometry puts its mass, in the link frame: ``unit`` its mass properties
    at density 1 (frame ``"link"``: the mass is the ``measure``, m³, or m² for a shell; the
    centre of mass its centroid, m; the inertia per unit density, kg·m² per kg/m³, link axes),
    and the axis-aligned ``low``/``high`` corners of its bounds (m)."""

    unit: MassProperties
    low: np.ndarray
    high: np.ndarray
    shell: bool

    @property
    def measure(self) -> float:
        """Volume (m³), or area (m²) for a shell."""
        return self.unit.mass


def geoms_sum(geoms, density, where: str, mode: str, as_mujoco: bool = False) -> MassProperties | None:
    """The mass properties of ``geoms`` in the link frame, each piece of geometry with a volume
    (:func:`distribution` in ``mode``) at the density ``density(geom, measure)`` gives it (kg/m³;
    ``measure`` its volume, m³); None when none has a volume, zero mass when their masses add up
    to nothing or less. ``where``: the file and link, for messages (InputError naming the geom
    when its mass or inertia at that density overflows a double)."""
    pieces = []
    for geom in geoms:
        found = distribution(geom, mode, where, as_mujoco=as_mujoco)
        if found is not None and found.measure > 0:
            with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused just below
                piece = found.unit.scaled(density(geom, found.measure))
            if not (np.isfinite(piece.mass) and np.all(np.isfinite(piece.inertia_about_com))):
                raise InputError(
                    f"{where}{geom.label}: its mass or inertia overflows a double; give masses in kg, "
                    "densities in kg/m³ and sizes in metres"
                )
            pieces.append(piece)
    if not pieces:
        return None
    try:
        return MassProperties.sum(pieces)
    except ValueError:
        return MassProperties.zero("link")


PRIMITIVES = {
    ("sphere", False): (shapes.sphere_volume, lambda volume, r: 3 * (shapes.sphere_moment(volume, r),)),
    ("sphere", True): (shapes.sphere_area, lambda area, r: 3 * (shapes.sphere_shell_moment(area, r),)),
    ("box", False): (lambda *edges: shapes.box_volume(edges), shapes.box_moments),
    ("box", True): (shapes.box_area, shapes.box_shell_moments),
    ("ellipsoid", False): (lambda *semi_axes: shapes.ellipsoid_volume(semi_axes), shapes.ellipsoid_moments),
    ("cylinder", False): (shapes.cylinder_volume, shapes.cylinder_moments),
    ("cylinder", True): (shapes.cylinder_area, shapes.cylinder_shell_moments),
    ("capsule", False): (shapes.capsule_volume, shapes.capsule_moments),
    ("capsule", True): (shapes.capsule_area, shapes.capsule_shell_moments),
}
"""The closed forms of each primitive, solid or shell: its volume (or area) and its principal
moments at that mass, both of the sizes :class:`Geom` gives; moments (axial, transverse) for a
primitive along z."""


def primitive(kind: str, size: tuple[float, ...], shell: bool = False) -> tuple[float, np.ndarray]:
    """Volume (or area, for ``shell``) and the principal moments per unit density of a centred
    primitive in its own axes (cylinder and capsule along z), from :mod:`rbi.core.shapes`'
    closed forms at the mass of a unit density. Sizes as :class:`Geom` gives them."""
    if kind == "ellipsoid" and shell:
        raise ValueError("a shell ellipsoid has no closed form; give it a volume (shellinertia off)")
    measure_of, moments_of = PRIMITIVES[(kind, bool(shell))]
    measure = measure_of(*size)
    moments = moments_of(measure, *size)
    if len(moments) == 2:  # (axial, transverse) of a primitive along z
        moments = (moments[1], moments[1], moments[0])
    return measure, np.array(moments)


def half_extent(kind: str, size) -> np.ndarray:
    """Half the primitive's extent along each of its own axes (m): with ``|R|`` of its pose, the
    half-size of its axis-aligned bounding box."""
    if kind == "sphere":
        return np.full(3, size[0])
    if kind == "box":
        return np.asarray(size, dtype=float) / 2
    if kind == "ellipsoid":
        return np.asarray(size, dtype=float)
    if kind == "cylinder":
        return np.array([size[0], size[0], size[1] / 2])
    return np.array([size[0], size[0], size[1] / 2 + size[0]])  # capsule


def distribution(
    geom: Geom,
    mode: str = "exact",
    where: str = "",
    repair: bool = False,
    notes: list[str] | None = None,
    fallbacks: list[MeshFallback] | None = None,
    as_mujoco: bool = False,
) -> Distribution | None:
    """``geom``'s distribution in the link frame; None for a kind that carries no mass (plane,
    height field). ``mode`` is the mesh inertia mode (MJCF geoms give their own; under ``auto``
    an MJCF ``exact`` mesh that is not closed falls back as any mesh does); ``repair`` closes a
    mesh's small holes first (trimesh's ``fill_holes``), each repair noted in ``notes``; in mode
    ``auto`` a mesh integrated other than exactly is listed in ``fallbacks``. ``as_mujoco``:
    a mesh's mass properties as MuJoCo's compiler gives them (:func:`mujoco_mesh_distribution`)."""
    R, p = geom.pose.rotation, geom.pose.translation
    if geom.kind in ("box", "sphere", "cylinder", "capsule", "ellipsoid"):
        try:
            measure, moments = primitive(geom.kind, geom.size, geom.shell)
        except ValueError as exc:
            raise InputError(f"{where}{geom.label}: {exc}") from None
        inertia = (R * moments) @ R.T
        corners = np.abs(R) @ half_extent(geom.kind, geom.size)
        if not (np.isfinite(measure) and np.all(np.isfinite(inertia))):
            raise InputError(
                f"{where}{geom.label}: size {list(geom.size)}: too large to compute with (its volume or "
                "inertia overflows a double); give sizes in metres"
            )
        unit = MassProperties(measure, p, 0.5 * (inertia + inertia.T), "link")
        return Distribution(unit, p - corners, p + corners, geom.shell)
    if geom.kind == "mesh":
        if not (mode == "auto" and geom.mesh_inertia == "exact" and not as_mujoco):
            mode = geom.mesh_inertia or ("shell" if geom.shell else mode)
        if mode == "auto":
            mode, fallback = _auto_mode(geom, where, repair)
            if fallback is not None and fallbacks is not None:
                fallbacks.append(fallback)
            if mode is None:
                return None
        unit, low, high, added = _mesh(geom, mode, where, repair, as_mujoco)
        if added and notes is not None:
            notes.append(
                f"{where}{geom.label}: {geom.mesh_file.name}: --mesh-repair closed holes with {added[0]} "
                f"triangle(s), {added[1]:.4g} m² in all"
            )
        centre, half = (low + high) / 2, (high - low) / 2  # the mesh's bounds, turned and moved
        middle, extent = R @ centre + p, np.abs(R) @ half
        return Distribution(unit.transformed(R, p, "link"), middle - extent, middle + extent, mode == "shell")
    return None


_MESHES: OrderedDict[tuple, tuple] = OrderedDict()
"""Meshes integrated in this process, by file, scale and mode (an audit of a robot asks for each
mesh of each link, often the same file for several links)."""

_MESH_ENTRIES = 4096
"""How many of :data:`_MESHES` are kept (the last used): each holds a few numbers (about 1.3 kB
with its key, whatever the size of its mesh), so at most about 5 MB however many robots a process
audits."""


def _auto_mode(geom: Geom, where: str, repair: bool) -> tuple[str | None, MeshFallback | None]:
    """``exact`` when the mesh is closed; else ``convex`` (or None when the hull has no volume
    either), with the fallback that says why. A mesh that cannot be read is still refused."""
    try:
        _mesh(geom, "exact", where, repair)
        return "exact", None
    except _NotIntegrable as exc:
        reason = exc.reason
    try:
        _mesh(geom, "convex", where, repair)
        used = "convex"
    except _NotIntegrable:
        used = None
    return used, MeshFallback(geom.mesh_file.name, geom.label, reason, used)


class _NotIntegrable(InputError):
    """A mesh that was read but cannot be integrated in the mode asked (open, flat, ...);
    ``reason`` is what is wrong with it, in a few words."""

    reason = ""


def _mesh(geom: Geom, mode: str, where: str, repair: bool = False, as_mujoco: bool = False):
    """(mass properties per unit density, low, high, (faces added, area added) or None) of the
    scaled mesh in its own frame. ``as_mujoco``: as MuJoCo's compiler computes it, from the
    file's vertices stored in single precision (MuJoCo keeps mesh vertices as ``float``) and,
    in modes ``legacy`` and ``exact``, by :func:`mujoco_mesh_distribution`."""
    path = geom.mesh_file
    scale = geom.mesh_scale if geom.mesh_scale is not None else np.ones(3)
    try:
        key = (*file_key(path), tuple(scale), mode, repair, as_mujoco)
    except ValueError as exc:
        raise InputError(f"{where}{geom.label}: {path.name}: {exc}") from None
    return cached(
        _MESHES, _MESH_ENTRIES, key, lambda: _integrated(geom, path, scale, mode, where, repair, as_mujoco)
    )


def _integrated(geom: Geom, path, scale: np.ndarray, mode: str, where: str, repair: bool, as_mujoco: bool):
    """:func:`_mesh`'s value, computed (InputError naming the geom when it cannot be)."""
    from rbi.formats.mesh_file import read_mesh_arrays  # heavy: scipy (rbi.core.mesh)

    try:
        vertices, faces = read_mesh_arrays(path)
    except ValueError as exc:
        raise InputError(f"{where}{geom.label}: {path.name}: {_hinted(str(exc), mode)}") from None
    if as_mujoco:
        vertices = vertices.astype(np.float32).astype(float)
    vertices = vertices * scale
    if np.prod(np.sign(scale)) < 0:
        faces = faces[:, ::-1]
    if not np.all(scale):
        raise InputError(f"{where}{geom.label}: scale {scale.tolist()}: a zero scale flattens the mesh")
    from rbi.core.mesh import mesh_distribution, repair_mesh  # heavy: scipy, for a link with a mesh only

    added = None
    try:
        if repair:
            repaired = repair_mesh(vertices, faces)
            faces = repaired.faces
            added = (repaired.added_faces, repaired.added_area) if repaired.added_faces else None
        found = (
            mujoco_mesh_distribution(vertices, faces, mode)
            if mode == "legacy" or (as_mujoco and mode == "exact")
            else mesh_distribution(vertices, faces, mode)
        )
    except MemoryError:  # a large mesh under a memory limit (ulimit -v): one line, not a traceback
        raise InputError(
            f"{where}{geom.label}: {path.name}: not enough memory to integrate this mesh (decimate it, "
            "or allow more memory)"
        ) from None
    except ValueError as exc:
        refusal = _NotIntegrable(f"{where}{geom.label}: {path.name}: mesh {_hinted(str(exc), mode)}")
        refusal.reason = str(exc).split("; for such a mesh")[0].split("; audit it with")[0]
        raise refusal from None
    unit = found.unit
    if not (np.isfinite(unit.mass) and np.all(np.isfinite(unit.inertia_about_com))):
        raise InputError(
            f"{where}{geom.label}: {path.name}: scale {scale.tolist()}: too large to compute with "
            "(the mesh's volume or inertia overflows a double)"
        )
    used = found.vertices[np.unique(found.faces)]
    if as_mujoco:  # MuJoCo keeps a mesh's principal moments and axes, found per unit volume
        inertia = unit.mass * mujoco_principal(unit.inertia_about_com / unit.mass)
        unit = MassProperties(unit.mass, unit.center_of_mass, inertia, "mesh")
    return unit, used.min(axis=0), used.max(axis=0), added


def mujoco_mesh_distribution(vertices: np.ndarray, faces: np.ndarray, mode: str) -> MeshDistribution:
    """A mesh's inertia in MuJoCo's mode ``legacy`` (its default for a mesh asset) or ``exact``,
    as its compiler computes it (``mjCMesh::Process``, ``ComputeVolume``, ``ComputeInertia``):
    each triangle with the area-weighted centroid of the faces as apex is a pyramid, whose volume
    counts positive whatever the triangle's winding in ``legacy`` and with its sign in ``exact``;
    that gives the volume-weighted centre of mass. The inertia sums the tetrahedra from the centre
    of mass to each triangle (volumes again positive in ``legacy``), and the volume reported is
    their sum. ``legacy`` is exact for a convex mesh seen from inside, ``exact`` for a closed
    consistently wound one; for other meshes each is what MuJoCo gives the body, which is the
    point. Units: those of the vertices (volume L³, inertia per unit density L⁵). ValueError
    where MuJoCo's compiler refuses: no area, no volume or a negative volume. (MuJoCo also
    refuses, in ``exact``, a mesh two of whose triangles run along an edge the same way; that
    depends on how its decoder welds each file format's vertices, and is not checked here.)"""
    from rbi.core.mesh import SIZED_VOLUME_MOMENTS, MeshDistribution  # heavy: scipy (links with meshes)

    V = np.asarray(vertices, dtype=float)
    D, E, F = V[faces[:, 0]], V[faces[:, 1]], V[faces[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(E - D, F - D), axis=1)
    centre = (D + E + F) / 3
    if not area.sum() >= 1e-15:
        raise ValueError("has no area (MuJoCo: mesh surface area is too small)")
    apex = (area[:, None] * centre).sum(axis=0) / area.sum()
    moments = SIZED_VOLUME_MOMENTS[mode == "legacy"]  # MuJoCo's legacy counts each volume positive
    volume = moments(V[faces] - apex)[0]
    if volume.sum() < 0:
        raise ValueError(
            "encloses a negative volume (MuJoCo: mesh volume is negative: misoriented triangles)"
        )
    if not volume.sum() >= 1e-15:
        raise ValueError("encloses no volume (MuJoCo: mesh volume is too small); try inertia: shell")
    com = (volume[:, None] * (0.75 * centre + 0.25 * apex)).sum(axis=0) / volume.sum()
    volume, _, second = moments(V[faces] - com)
    inertia = np.trace(second) * np.eye(3) - second
    unit = MassProperties(float(volume.sum()), com, 0.5 * (inertia + inertia.T), "mesh")
    return MeshDistribution(mode, unit, V, np.asarray(faces))


MESH_EIG_TOLERANCE = 1e-7
"""The relative tolerance with which MuJoCo's compiler finds a mesh's principal axes: its
Jacobi iteration stops when the largest off-diagonal entry is at most this fraction of the
largest entry (matched on dm_control's dog.xml: its 162 meshes' ``mesh_quat`` to 2e-14; 5e-8
and 2e-7 leave 1e-7)."""


def mujoco_principal(inertia: np.ndarray, tolerance: float = MESH_EIG_TOLERANCE) -> np.ndarray:
    """``inertia`` (3×3, symmetric) as MuJoCo's compiler keeps it: the principal moments on the
    axes its Jacobi iteration finds (``mjuu_eig3``: from the identity, one rotation about a
    coordinate axis a step, accumulated as a quaternion, until the largest off-diagonal entry
    is at most ``tolerance`` × the largest entry), turned back into a matrix. For a mesh it
    differs from ``inertia`` by what that iteration leaves (up to 1e-7 of the largest moment
    for dm_control's dog.xml), which is what MuJoCo simulates with."""
    quat = np.array([1.0, 0.0, 0.0, 0.0])
    limit = float(np.max(np.abs(inertia))) * tolerance
    for _ in range(500):
        R = quaternion_to_matrix(quat)
        D = R.T @ inertia @ R
        a, b, c = abs(D[0, 1]), abs(D[0, 2]), abs(D[1, 2])
        row, col, axis = (0, 1, 2) if a > b and a > c else (0, 2, 1) if b > c else (1, 2, 0)
        if abs(D[row, col]) <= limit:
            break
        tau = (D[col, col] - D[row, row]) / (2 * D[row, col])
        t = 1.0 / (tau + math.sqrt(1 + tau * tau)) if tau >= 0 else -1.0 / (-tau + math.sqrt(1 + tau * tau))
        half = t / (1 + math.sqrt(1 + t * t))  # the tangent of half the rotation's angle
        step = np.zeros(4)
        step[0] = 1 / math.sqrt(1 + half * half)
        step[axis + 1] = (half if axis == 1 else -half) * step[0]
        quat = quaternion_multiply(quat, step)
        quat = quat / np.linalg.norm(quat)
    R = quaternion_to_matrix(quat)
    return (R * np.diagonal(R.T @ inertia @ R)) @ R.T


CLOSED_HINT = (
    "; audit it with --mesh-inertia convex (the solid convex hull), --mesh-inertia shell (mass on "
    "the surface) or --mesh-repair (closes holes of three or four edges)"
)


def _hinted(message: str, mode: str) -> str:
    """A mesh refusal with the audit's options where the core's message names the spec's keys
    (``inertia: convex`` is ``--mesh-inertia convex`` here, ``repair: true`` ``--mesh-repair``)."""
    if mode == "exact" and "closed" in message:
        return message.split("; for such a mesh")[0] + CLOSED_HINT
    for key, option in (
        ("inertia: convex", "--mesh-inertia convex"),
        ("inertia: shell", "--mesh-inertia shell"),
        ("inertia: exact", "--mesh-inertia exact"),
        ("repair: true", "--mesh-repair"),
    ):
        message = message.replace(key, option)
    return message
