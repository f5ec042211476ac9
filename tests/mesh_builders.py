"""Closed triangle meshes built with numpy for the tests, and writers for the file formats
(binary/ASCII STL, OBJ, PLY) written by hand from their published layouts, so that the tests
check rbi's reading and integration against files no part of rbi produced.

Every mesh is wound counter-clockwise seen from outside (outward normals).
"""

from __future__ import annotations

import struct
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from rbi.core.mesh import mesh_distribution, surface_area


def box_mesh(size=(1.0, 1.0, 1.0), center=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """A box with edges ``size`` along x, y, z, centred on ``center``: 8 vertices, 12 faces."""
    a, b, c = (0.5 * float(s) for s in size)
    corners = np.array([[x, y, z] for x in (-a, a) for y in (-b, b) for z in (-c, c)]) + np.asarray(
        center, float
    )
    # vertex index = 4 i + 2 j + k for the signs (i, j, k) of (x, y, z)
    faces = np.array(
        [
            [0, 1, 3],
            [0, 3, 2],  # x = -a, normal -x
            [4, 6, 7],
            [4, 7, 5],  # x = +a
            [0, 4, 5],
            [0, 5, 1],  # y = -b
            [2, 3, 7],
            [2, 7, 6],  # y = +b
            [0, 2, 6],
            [0, 6, 4],  # z = -c
            [1, 5, 7],
            [1, 7, 3],  # z = +c
        ]
    )
    return corners, faces


def tetrahedron_mesh(corners) -> tuple[np.ndarray, np.ndarray]:
    """The tetrahedron on four corners, wound outward whatever their order."""
    v = np.asarray(corners, dtype=float)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    if np.dot(np.cross(v[1] - v[0], v[2] - v[0]), v[3] - v[0]) < 0:
        faces = faces[:, [0, 2, 1]]
    return v, faces


def cylinder_mesh(radius: float, length: float, facets: int) -> tuple[np.ndarray, np.ndarray]:
    """A prism on a regular ``facets``-gon inscribed in the circle of ``radius``, from z = 0 to
    z = length, closed by a centre vertex on each end."""
    angles = 2.0 * np.pi * np.arange(facets) / facets
    ring = np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
    bottom = np.column_stack([ring, np.zeros(facets)])
    top = np.column_stack([ring, np.full(facets, float(length))])
    vertices = np.vstack([bottom, top, [[0, 0, 0], [0, 0, length]]])
    i = np.arange(facets)
    j = (i + 1) % facets
    low_centre, high_centre = 2 * facets, 2 * facets + 1
    sides = np.vstack([np.column_stack([i, j, facets + j]), np.column_stack([i, facets + j, facets + i])])
    bottom_caps = np.column_stack([np.full(facets, low_centre), j, i])
    top_caps = np.column_stack([np.full(facets, high_centre), facets + i, facets + j])
    return vertices, np.vstack([sides, bottom_caps, top_caps])


def sphere_mesh(radius: float, rings: int, segments: int) -> tuple[np.ndarray, np.ndarray]:
    """A latitude-longitude sphere inscribed in the sphere of ``radius``: two poles,
    ``rings`` − 1 circles of ``segments`` vertices."""
    polar = np.pi * np.arange(1, rings) / rings
    azimuth = 2.0 * np.pi * np.arange(segments) / segments
    P, A = np.meshgrid(polar, azimuth, indexing="ij")
    body = radius * np.column_stack(
        [(np.sin(P) * np.cos(A)).ravel(), (np.sin(P) * np.sin(A)).ravel(), np.cos(P).ravel()]
    )
    vertices = np.vstack([[[0, 0, radius]], body, [[0, 0, -radius]]])
    south = len(vertices) - 1

    def index(ring, seg):
        return 1 + ring * segments + seg % segments

    faces = []
    for s in range(segments):
        faces.append([0, index(0, s), index(0, s + 1)])
        faces.append([south, index(rings - 2, s + 1), index(rings - 2, s)])
        for r in range(rings - 2):
            a, b = index(r, s), index(r, s + 1)
            c, d = index(r + 1, s), index(r + 1, s + 1)
            faces.append([a, c, d])
            faces.append([a, d, b])
    return vertices, np.array(faces)


# --- file writers ------------------------------------------------------------------------------


def _normals(vertices, faces):
    tri = np.asarray(vertices, float)[np.asarray(faces)]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    return n / np.linalg.norm(n, axis=1, keepdims=True), tri


def write_binary_stl(path: Path, vertices, faces, header: bytes = b"solid written by the rbi tests") -> Path:
    """80-byte header, uint32 triangle count, then per triangle 12 float32 (normal, 3 corners)
    and a uint16 attribute. The header starts with ``solid``, as many CAD exporters write it."""
    normals, tri = _normals(vertices, faces)
    with open(path, "wb") as out:
        out.write(header.ljust(80, b" ")[:80])
        out.write(struct.pack("<I", len(tri)))
        for n, t in zip(normals, tri):
            out.write(struct.pack("<12fH", *n, *t.ravel(), 0))
    return path


def write_ascii_stl(path: Path, vertices, faces) -> Path:
    normals, tri = _normals(vertices, faces)
    lines = ["solid test"]
    for n, t in zip(normals.tolist(), tri.tolist()):
        lines.append(f"  facet normal {n[0]!r} {n[1]!r} {n[2]!r}")
        lines.append("    outer loop")
        lines.extend(f"      vertex {p[0]!r} {p[1]!r} {p[2]!r}" for p in t)
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid test")
    Path(path).write_text("\n".join(lines) + "\n")
    return path


def write_obj(path: Path, vertices, faces) -> Path:
    lines = [f"v {p[0]!r} {p[1]!r} {p[2]!r}" for p in np.asarray(vertices, float).tolist()]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in np.asarray(faces).tolist()]
    Path(path).write_text("\n".join(lines) + "\n")
    return path


def write_ply(path: Path, vertices, faces) -> Path:
    vertices = np.asarray(vertices, float)
    faces = np.asarray(faces)
    lines = [
        "ply",
        "format ascii 1.0",
        f"element vertex {len(vertices)}",
        "property double x",
        "property double y",
        "property double z",
        f"element face {len(faces)}",
        "property list uchar int vertex_indices",
        "end_header",
    ]
    lines += [f"{p[0]!r} {p[1]!r} {p[2]!r}" for p in vertices.tolist()]
    lines += [f"3 {a} {b} {c}" for a, b, c in faces.tolist()]
    Path(path).write_text("\n".join(lines) + "\n")
    return path


def write_msh(path: Path, vertices, faces, normals: int = 0, texcoords: int = 0) -> Path:
    """MuJoCo's binary MSH: int32 counts of vertices, normals, texture coordinates and faces, then
    float32 vertices, normals (``normals`` zero triples), texture pairs, and int32 faces."""
    vertices, faces = np.asarray(vertices, "<f4"), np.asarray(faces, "<i4")
    counts = np.array([len(vertices), normals, texcoords, len(faces)], "<i4")
    extra = np.zeros(3 * normals + 2 * texcoords, "<f4")
    Path(path).write_bytes(counts.tobytes() + vertices.tobytes() + extra.tobytes() + faces.tobytes())
    return path


WRITERS = {
    "binary.stl": write_binary_stl,
    "ascii.stl": write_ascii_stl,
    "mesh.obj": write_obj,
    "mesh.ply": write_ply,
    "mesh.msh": write_msh,
}
"""File name (its extension picks the format) -> writer."""


def mesh_mass_properties(vertices, faces, mode: str = "exact", *, mass=None, density=None) -> SimpleNamespace:
    """rbi's integration of a mesh (:func:`rbi.core.mesh.mesh_distribution`) at a ``mass`` or a
    ``density`` (per volume, or per area for ``shell``), as a spec's mesh part scales it:
    ``properties`` (MassProperties, frame "mesh"), ``volume`` (None for a shell), ``area`` of
    what was integrated, ``notes``."""
    distribution = mesh_distribution(vertices, faces, mode)
    unit = distribution.unit
    properties = unit.with_mass(float(density) * unit.mass if mass is None else float(mass))
    shell = mode == "shell"
    return SimpleNamespace(
        properties=properties,
        volume=None if shell else unit.mass,
        area=unit.mass if shell else surface_area(distribution.vertices, distribution.faces),
        notes=distribution.notes,
    )
