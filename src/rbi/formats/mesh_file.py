"""Mesh files a spec names (``shape: mesh``) or a robot file points to: read, welded, checked,
and handed to the core as plain arrays.

STL (binary and ASCII), OBJ and Collada (:mod:`rbi.formats.collada`) are parsed here, in bounded memory and with the formats' own
rules (OBJ numbers vertices from 1, and a negative number counts back from the last vertex read
before the face); PLY is parsed by trimesh after its header's counts are checked against the
file's size. The volume integration and every check are rbi's own (:mod:`rbi.core.mesh`). The
file is read into memory by rbi (at most :data:`MAX_MESH_BYTES`) and parsed from those bytes, so
a hostile OBJ cannot make a parser open other files (``mtllib``), and no message ever repeats
what the file holds: only its name as written by the caller, counts, line and vertex numbers.

A mesh of more than :data:`MAX_MESH_TRIANGLES` triangles is refused before its triangles are
built: reading, welding and integrating one at that limit peaks near 1 GB.
"""

from __future__ import annotations

import io
import re
from array import array
from collections import OrderedDict
from pathlib import Path

import numpy as np

from rbi.core.mesh import (
    MeshDistribution,
    RepairedMesh,
    arrays_problem,
    convex_hull_mesh,
    mesh_distribution,
    repair_mesh,
    weld_vertices,
)
from rbi.files.safe import open_input_file, read_input_file
from rbi.formats.collada import parse_collada
from rbi.formats.paths import file_key
from rbi.memory import cached

MAX_MESH_BYTES = 256 * 2**20
"""Largest mesh file rbi reads (256 MiB)."""

MAX_MESH_TRIANGLES = 2_000_000
"""Most triangles rbi reads from one mesh (a 95 MiB binary STL; an OBJ polygon counts as the
triangles it splits into). Far above what mass properties need: decimate a finer mesh first."""

MAX_PLY_BYTES = 32 * 2**20
"""Largest PLY file rbi reads (32 MiB: about 1.7 million triangles binary, 0.6 million ASCII).
PLY is parsed by trimesh, which needs some 25 bytes of memory per byte of file (a binary PLY
of 2 million triangles, 38 MB, peaks at 1 GB): convert a larger mesh to binary STL."""

MESH_FILE_TYPES = {".stl": "stl", ".obj": "obj", ".ply": "ply", ".dae": "dae", ".msh": "msh"}
"""File extensions rbi reads as meshes, and the format of each."""


_CACHE: OrderedDict[tuple, object] = OrderedDict()
"""Meshes already read in this process, keyed by resolved path, size and modification time
(a sweep translates the same spec many times); the last few only, so memory stays bounded."""

_CACHE_ENTRIES = 8


def read_mesh_solid(path: Path, mode: str = "exact", repair: bool = False) -> MeshDistribution:
    """Read, weld, optionally repair, check and integrate the mesh at ``path`` in ``mode``
    (``exact``, ``convex`` or ``shell``; see :mod:`rbi.core.mesh`): where its mass goes per
    unit density (mesh units and axes), the mesh integrated (welded; repaired when asked; the
    hull's in mode ``convex``) and what repair added. Raises ``ValueError`` with a message that
    names what is wrong (never the file's content); the caller adds file and part."""
    key = _file_key(path)

    def make() -> MeshDistribution:
        repaired = RepairedMesh(*read_mesh_arrays(path), 0, 0.0)
        if repair:
            repaired = repair_mesh(repaired.vertices, repaired.faces)
        try:
            distribution = mesh_distribution(repaired.vertices, repaired.faces, mode)
        except ValueError as exc:
            prefix = "after repair, " if repaired.added_faces else ""
            raise ValueError(f"mesh {prefix}{exc}") from None
        return distribution._replace(added_faces=repaired.added_faces, added_area=repaired.added_area)

    return cached(_CACHE, _CACHE_ENTRIES, key + (mode, bool(repair)), make)


def read_mesh_arrays(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """The welded vertices (N, 3) and faces (F, 3) of the mesh file at ``path``, checked to be
    usable arrays (triangles, indices in range, finite coordinates) but not yet for closure."""
    key = _file_key(path)
    file_type = MESH_FILE_TYPES[path.suffix.lower()]

    def make():
        if file_type == "stl":
            _binary_stl_cap(path)
        data = read_input_file(path, MAX_MESH_BYTES, "mesh")  # InputFileRefused is a ValueError
        if not data.strip():
            raise ValueError("file is empty")
        try:
            vertices, faces = _PARSERS[file_type](data)
            del data
            problem = arrays_problem(vertices, faces)
            if problem is not None:
                raise ValueError(f"mesh {problem}")
            return weld_vertices(vertices, faces)
        except MemoryError:  # a large file under a memory limit (ulimit -v): one line, not a traceback
            raise ValueError(
                "not enough memory to read this mesh (decimate it, or allow more memory)"
            ) from None

    return cached(_CACHE, _CACHE_ENTRIES, key, make)


def _file_key(path: Path) -> tuple:
    if path.suffix.lower() not in MESH_FILE_TYPES:
        raise ValueError(
            f"unknown mesh format {path.suffix or '(no extension)'!r}: "
            f"use one of {', '.join(MESH_FILE_TYPES)}"
        )
    return file_key(path)


def _too_many(count: int | None) -> ValueError:
    have = f"more than {MAX_MESH_TRIANGLES}" if count is None else str(count)
    return ValueError(
        f"mesh has {have} triangles; rbi reads at most {MAX_MESH_TRIANGLES} "
        f"(decimate it, e.g. with MeshLab's quadric edge collapse: mass properties need "
        f"far fewer)"
    )


# --- STL --------------------------------------------------------------------------------------


def _binary_stl_cap(path: Path) -> None:
    """Refuse a binary STL beyond the triangle cap from its header alone, before reading it."""
    try:
        with open_input_file(path, "mesh") as stream:  # no size cap: a large one is told its triangles
            head = stream.read(84)
            size = stream.seek(0, io.SEEK_END)  # of the file opened
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or type(exc).__name__}") from None
    if len(head) == 84:
        count = int.from_bytes(head[80:84], "little")
        if size == 84 + 50 * count and count > MAX_MESH_TRIANGLES:
            raise _too_many(count)


_BINARY_STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])


def _parse_stl(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """Binary STL when the size matches the triangle count in its header (80-byte header,
    uint32 count, 50 bytes a triangle), else ASCII STL (``solid`` ... ``endsolid``)."""
    count = int.from_bytes(data[80:84], "little") if len(data) >= 84 else -1
    if count >= 0 and len(data) == 84 + 50 * count:
        if count > MAX_MESH_TRIANGLES:
            raise _too_many(count)
        records = np.frombuffer(data, dtype=_BINARY_STL_RECORD, count=count, offset=84)
        corners = records["corners"].reshape(-1, 3)  # float32, a view into data: welded in float32
        return corners, np.arange(3 * count, dtype=np.int64).reshape(count, 3)
    if data.lstrip()[:5].lower() == b"solid":
        return _parse_ascii_stl(data)
    if count >= 0:
        raise ValueError(
            f"cannot be read as STL (not ASCII, and as binary its header promises {count} "
            f"triangles: {84 + 50 * count} bytes, but the file has {len(data)})"
        )
    raise ValueError("cannot be read as STL (damaged, or not a mesh file)")


_ASCII_VERTEX = re.compile(rb"\bvertex[ \t]+(\S+)[ \t]+(\S+)[ \t]+(\S+)", re.IGNORECASE)
_ASCII_FACET = re.compile(rb"\bendfacet\b", re.IGNORECASE)


def _parse_ascii_stl(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    count = sum(1 for _ in _ASCII_FACET.finditer(data))
    if count > MAX_MESH_TRIANGLES:
        raise _too_many(count)
    batches, batch = [], []
    for match in _ASCII_VERTEX.finditer(data):
        batch.append(match.groups())
        if len(batch) >= 30_000:
            batches.append(_numbers(batch))
            batch = []
    if batch:
        batches.append(_numbers(batch))
    corners = np.concatenate(batches) if batches else np.zeros((0, 3))
    if len(corners) % 3:
        raise ValueError("cannot be read as STL (a facet does not have three vertices)")
    if len(corners) // 3 > MAX_MESH_TRIANGLES:
        raise _too_many(len(corners) // 3)
    return corners, np.arange(len(corners), dtype=np.int64).reshape(-1, 3)


def _numbers(rows: list) -> np.ndarray:
    try:
        return np.array(rows, dtype=bytes).astype(float)
    except ValueError:
        raise ValueError("cannot be read as STL (a vertex coordinate is not a number)") from None


# --- OBJ --------------------------------------------------------------------------------------

_LINES_PER_BLOCK = 1 << 22


def _blocks(data: bytes):
    """The file's lines in blocks of about 4 MiB, so no list of every line is ever built."""
    start = 0
    while start < len(data):
        end = data.find(b"\n", start + _LINES_PER_BLOCK)
        end = len(data) if end < 0 else end + 1
        yield data[start:end].replace(b"\\\r\n", b" ").replace(b"\\\n", b" ").split(b"\n")
        start = end


MAX_OBJ_VERTEX = 2**62
"""Largest vertex number an OBJ face may name (faces are kept as 64-bit integers; no file of
the sizes rbi reads holds a billionth of that many vertices)."""


def _parse_obj(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (``v x y z``) and faces (``f a b c ...``, each corner ``i``, ``i/t``, ``i//n`` or
    ``i/t/n``) of an OBJ file. Vertices are numbered from 1 in the order they appear; a
    negative number counts back from the last vertex read before the face (``-1`` is that
    vertex). A polygon is split into a fan of triangles from its first corner. Everything else
    (normals, texture coordinates, groups, materials, lines) is ignored."""
    coordinates = array("d")
    corners = array("q")
    face_lines = array("q")
    line_number = 0
    for lines in _blocks(data):
        for line in lines:
            line_number += 1
            if line[:2] == b"v " or line[:2] == b"v\t":
                fields = line.split()
                if len(fields) < 4:
                    raise ValueError(
                        f"cannot be read as OBJ (line {line_number}: a vertex needs three coordinates)"
                    )
                try:
                    coordinates.extend((float(fields[1]), float(fields[2]), float(fields[3])))
                except ValueError:
                    raise ValueError(
                        f"cannot be read as OBJ (line {line_number}: a vertex coordinate is not a number)"
                    ) from None
            elif line[:2] == b"f " or line[:2] == b"f\t":
                _add_face(line.split()[1:], len(coordinates) // 3, line_number, corners, face_lines)
                if len(face_lines) > MAX_MESH_TRIANGLES:
                    raise _too_many(None)
    vertices = np.array(coordinates, dtype=float).reshape(-1, 3)  # copied out of the growing buffers
    faces = np.array(corners, dtype=np.int64).reshape(-1, 3)
    if len(faces) and faces.max() >= len(vertices):
        face = int(np.flatnonzero((faces >= len(vertices)).any(axis=1))[0])
        raise ValueError(
            f"mesh face on line {face_lines[face]} names vertex {int(faces[face].max()) + 1}, but the "
            f"file has {len(vertices)} vertices (numbered from 1)"
        )
    return vertices, faces


def _add_face(fields: list, n_vertices: int, line_number: int, corners: array, face_lines: array) -> None:
    """Append the triangles of one face line. A "face" of one or two corners (some exporters
    write edges so) has no area and adds nothing, but its numbers are still checked."""
    indices = []
    for field in fields:
        try:
            number = int(field.split(b"/", 1)[0])
        except ValueError:
            raise ValueError(
                f"cannot be read as OBJ (line {line_number}: a face's vertex number is not a whole number)"
            ) from None
        if number > MAX_OBJ_VERTEX:
            raise ValueError(
                f"mesh face on line {line_number} names vertex {number}, beyond any mesh (OBJ vertex "
                f"numbers up to {MAX_OBJ_VERTEX:,})"
            )
        if number > 0:
            indices.append(number - 1)
        elif number < 0:
            if -number > n_vertices:
                raise ValueError(
                    f"mesh face on line {line_number} counts back {-number} vertices, but only "
                    f"{n_vertices} were read before it (-1 is the last vertex read)"
                )
            indices.append(n_vertices + number)
        else:
            raise ValueError(
                f"mesh face on line {line_number} names vertex 0: OBJ numbers vertices from 1 "
                f"(negative numbers count back from the last vertex read)"
            )
    if not indices:
        raise ValueError(f"cannot be read as OBJ (line {line_number}: a face names no vertex)")
    first = indices[0]
    for second, third in zip(indices[1:-1], indices[2:]):
        corners.extend((first, second, third))
        face_lines.append(line_number)


# --- PLY --------------------------------------------------------------------------------------

_PLY_ELEMENT = re.compile(rb"^element[ \t]+(\w+)[ \t]+(\d+)", re.MULTILINE)


def _parse_ply(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """PLY through trimesh (its parser, without any processing), once the header's element
    counts are known to fit in the file: a hostile header cannot make it allocate more than
    the file could hold."""

    if len(data) > MAX_PLY_BYTES:
        raise ValueError(
            f"PLY file too large ({len(data)} bytes; rbi reads PLY up to {MAX_PLY_BYTES} bytes, "
            f"its parser needing some 25 bytes of memory per byte): convert it to binary STL"
        )
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ValueError("cannot be read as PLY (no `ply` ... `end_header` header)")
    counts = {
        name.decode("ascii", "replace"): int(number) for name, number in _PLY_ELEMENT.findall(data[:end])
    }
    body = len(data) - end
    if counts.get("face", 0) > MAX_MESH_TRIANGLES:
        raise _too_many(counts["face"])
    if counts.get("vertex", 0) * 3 + counts.get("face", 0) * 4 > body:
        raise ValueError(
            f"cannot be read as PLY (the header promises {counts.get('vertex', 0)} vertices and "
            f"{counts.get('face', 0)} faces, more than the file's {body} bytes after it hold)"
        )
    # not at top level: `rbi inertia (mesh part)` would load trimesh too
    import trimesh

    try:
        mesh = trimesh.load(file_obj=io.BytesIO(data), file_type="ply", force="mesh", process=False)
        vertices = np.asarray(mesh.vertices, dtype=float)
        faces = np.asarray(mesh.faces, dtype=np.int64)
    except Exception:  # noqa: BLE001 - any parser failure on untrusted bytes is the same user error
        raise ValueError("cannot be read as PLY (damaged, or not a mesh file)") from None
    if vertices.ndim != 2 or vertices.shape[1:] != (3,) or faces.ndim != 2 or faces.shape[1:] != (3,):
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    if len(faces) > MAX_MESH_TRIANGLES:
        raise _too_many(len(faces))
    return vertices, faces


def _parse_dae(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """Collada: every triangle its scene places, in metres (:mod:`rbi.formats.collada`), at most
    :data:`MAX_MESH_TRIANGLES`."""
    return parse_collada(data, max_triangles=MAX_MESH_TRIANGLES)


# --- MSH --------------------------------------------------------------------------------------


def _parse_msh(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """MuJoCo's binary MSH: four int32 counts (vertices, normals, texture coordinates, faces),
    then as many float32 vertex triples, normal triples and texture pairs, and int32 face
    triples; its size must be exactly what the counts say. With no faces, the convex hull of the
    vertices, as MuJoCo takes it."""
    counts = np.frombuffer(data[:16], dtype="<i4").astype(np.int64) if len(data) >= 16 else None
    if counts is None or counts.min() < 0:
        raise ValueError("cannot be read as MSH (no header of four non-negative counts)")
    n_vertices, n_normals, n_texcoords, n_faces = (int(c) for c in counts)
    faces_at = 16 + 12 * n_vertices + 12 * n_normals + 8 * n_texcoords
    expected = faces_at + 12 * n_faces
    if expected != len(data):
        raise ValueError(
            f"cannot be read as MSH (its header promises {n_vertices} vertices, {n_normals} normals, "
            f"{n_texcoords} texture coordinates and {n_faces} faces: {expected} bytes, but the file "
            f"has {len(data)})"
        )
    if n_faces > MAX_MESH_TRIANGLES:
        raise _too_many(n_faces)
    vertices = np.frombuffer(data, dtype="<f4", count=3 * n_vertices, offset=16).reshape(-1, 3)
    if n_faces == 0:  # bare points: MuJoCo takes their convex hull
        problem = arrays_problem(vertices, np.zeros((1, 3), np.int64))  # the checks of vertices alone
        if problem is not None:
            raise ValueError(f"mesh {problem}")
        return convex_hull_mesh(vertices)
    faces = np.frombuffer(data, dtype="<i4", count=3 * n_faces, offset=faces_at).reshape(-1, 3)
    return vertices.astype(float), faces.astype(np.int64)


_PARSERS = {"stl": _parse_stl, "obj": _parse_obj, "ply": _parse_ply, "dae": _parse_dae, "msh": _parse_msh}
