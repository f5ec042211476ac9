"""Mesh files a spec names (``shape: mesh``): read with trimesh, checked, handed to the core as
plain arrays.

trimesh is used only to parse the file formats (binary and ASCII STL, OBJ, PLY); the volume
integration and every check are rbi's own (:mod:`rbi.core.mesh`). The file is read into memory
by rbi (at most :data:`MAX_MESH_BYTES`) and parsed from those bytes, so a hostile OBJ cannot
make trimesh open other files (``mtllib``), and no message ever repeats what the file holds:
only its name as written in the spec, counts and vertex numbers.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import NamedTuple

import numpy as np

from rbi.core.mesh import MeshVolumeProperties, enclosed_volume_properties, weld_vertices, mesh_problem

MAX_MESH_BYTES = 256 * 2 ** 20
"""Largest mesh file rbi reads (256 MiB: about 5 million triangles of binary STL)."""

MESH_FILE_TYPES = {".stl": "stl", ".obj": "obj", ".ply": "ply"}
"""File extensions rbi reads as meshes, and trimesh's name for each format."""


class MeshSolid(NamedTuple):
    """A checked mesh file: its merged vertices (mesh units) and faces, and the enclosed
    solid's volume properties per unit density, in mesh units and axes."""

    vertices: np.ndarray
    faces: np.ndarray
    properties: MeshVolumeProperties


_CACHE: dict[tuple, MeshSolid] = {}
"""Meshes already read in this process, keyed by resolved path, size and modification time
(a sweep translates the same spec many times)."""


def read_mesh_solid(path: Path) -> MeshSolid:
    """Read, check and integrate the mesh at ``path``. Raises ``ValueError`` with a message
    that names what is wrong (never the file's content); the caller adds file and part."""
    file_type = MESH_FILE_TYPES.get(path.suffix.lower())
    if file_type is None:
        raise ValueError(f"unknown mesh format {path.suffix or '(no extension)'!r}: "
                         f"use one of {', '.join(MESH_FILE_TYPES)}")
    try:
        status = path.stat()
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or type(exc).__name__}") from None
    key = (str(path.resolve()), status.st_size, status.st_mtime_ns)
    cached = _CACHE.get(key)
    if cached is not None:
        return cached
    if status.st_size > MAX_MESH_BYTES:
        raise ValueError(f"file too large for a mesh ({status.st_size} bytes; at most {MAX_MESH_BYTES})")
    try:
        with open(path, "rb") as stream:
            data = stream.read(MAX_MESH_BYTES + 1)
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or type(exc).__name__}") from None
    if len(data) > MAX_MESH_BYTES:
        raise ValueError(f"file too large for a mesh (more than {MAX_MESH_BYTES} bytes)")
    if not data.strip():
        raise ValueError("file is empty")
    vertices, faces = _parse(data, file_type)
    problem = _shape_problem(vertices, faces)
    if problem is None:
        vertices, faces = weld_vertices(vertices, faces)
        problem = mesh_problem(vertices, faces)
    if problem is not None:
        raise ValueError(f"mesh {problem}")
    solid = MeshSolid(vertices, faces, enclosed_volume_properties(vertices, faces))
    _CACHE[key] = solid
    return solid


def _parse(data: bytes, file_type: str) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of mesh ``data`` as trimesh reads them, without its processing
    (no merging, no repairs: what the file says is what gets checked, after rbi's own
    welding of coincident vertices)."""
    import trimesh

    try:
        # from bytes, without a resolver: trimesh cannot open any other file (an OBJ's mtllib)
        extra = {"skip_materials": True} if file_type == "obj" else {}
        mesh = trimesh.load(file_obj=io.BytesIO(data), file_type=file_type, force="mesh", process=False, **extra)
        vertices = np.asarray(mesh.vertices, dtype=float)
        faces = np.asarray(mesh.faces, dtype=np.int64)
    except Exception:  # noqa: BLE001 - any parser failure on untrusted bytes is the same user error
        raise ValueError(f"cannot be read as {file_type.upper()} (damaged, or not a mesh file)") from None
    return vertices, faces


def _shape_problem(vertices: np.ndarray, faces: np.ndarray) -> str | None:
    """Problems to report before merging vertices (which needs well-formed arrays)."""
    if vertices.ndim != 2 or vertices.shape[1] != 3 or faces.ndim != 2 or faces.shape[1] != 3 or faces.shape[0] == 0:
        return "holds no triangles"
    out_of_range = faces.min() < 0 or faces.max() >= vertices.shape[0]
    if out_of_range or not np.all(np.isfinite(vertices)):
        return mesh_problem(vertices, faces)  # names the bad vertex or index
    return None
