"""Closed triangle meshes: the volume they enclose, its centre of mass and inertia, and the
checks that make those numbers meaningful.

A mesh is ``vertices`` (N, 3) floats in any length unit L and ``faces`` (F, 3) vertex indices,
each triangle wound counter-clockwise seen from outside (its normal by the right-hand rule
points out of the solid). By the divergence theorem the enclosed solid is the signed sum of
the tetrahedra joining a reference point to every face; each tetrahedron's volume, first and
second moments are closed forms, so the result is exact up to rounding for the polyhedron the
mesh describes. The reference point is taken inside the mesh's bounding box and the second
moments are summed about the centre of mass itself, so a small part far from the origin keeps
its digits.

Pure numpy, vectorised over faces; reading files is done elsewhere.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


class MeshDefects(NamedTuple):
    """What keeps a triangle mesh from bounding a solid (all zero for a good mesh).

    boundary_edges: edges used by only one triangle (holes in the surface).
    overshared_edges: edges used by more than two triangles (non-manifold).
    misoriented_edges: edges whose two triangles run along them in the same direction (a
    face wound against its neighbours, so that its normal points the wrong way).
    degenerate_faces: triangles that name one vertex twice (no area; ignored in the sums).
    """

    boundary_edges: int
    overshared_edges: int
    misoriented_edges: int
    degenerate_faces: int


class MeshVolumeProperties(NamedTuple):
    """Per unit density: volume (L³), centroid (L, mesh frame), and the second-moment inertia
    ``∫ (|r|² E − r rᵀ) dV`` about the centroid (L⁵, mesh axes). Multiply the inertia by a
    density (or by mass / volume) to get M·L²."""

    volume: float
    centroid: np.ndarray
    inertia_per_density: np.ndarray


WELD_RTOL = 1e-9
"""Vertices closer than about this fraction of the bounding box's diagonal are one vertex."""


def weld_vertices(vertices: np.ndarray, faces: np.ndarray, rtol: float = WELD_RTOL) -> tuple[np.ndarray, np.ndarray]:
    """One vertex per position: faces re-indexed onto vertices that coincide.

    STL files store every triangle with its own three corners, so a mesh read from one shares
    no vertex indices until equal positions are joined. CAD exporters write the same corner
    with rounding noise (``-1.7e-17`` for ``0``), so positions are compared on a grid of
    ``rtol`` times the bounding box's diagonal, far below the spacing of single-precision
    coordinates; each welded vertex keeps the coordinates of its first occurrence.
    """
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    low = vertices.min(axis=0)
    diagonal = float(np.linalg.norm(vertices.max(axis=0) - low))
    if diagonal == 0.0:
        keys = np.zeros((vertices.shape[0], 3), dtype=np.int64)
    else:
        keys = np.round((vertices - low) / (rtol * diagonal)).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    return vertices[first], inverse.reshape(-1)[faces]


def mesh_defects(faces: np.ndarray) -> MeshDefects:
    """Edge counts that tell whether ``faces`` close a consistently wound surface.

    Every edge of a closed, consistently wound surface is used by exactly two triangles, once
    in each direction.
    """
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    degenerate = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (faces[:, 2] == faces[:, 0])
    good = faces[~degenerate]
    directed = np.concatenate([good[:, [0, 1]], good[:, [1, 2]], good[:, [2, 0]]])
    undirected = np.sort(directed, axis=1)
    _, uses = np.unique(undirected, axis=0, return_counts=True)
    _, directed_uses = np.unique(directed, axis=0, return_counts=True)
    return MeshDefects(
        boundary_edges=int(np.count_nonzero(uses == 1)),
        overshared_edges=int(np.count_nonzero(uses > 2)),
        misoriented_edges=int(np.count_nonzero(directed_uses > 1)),
        degenerate_faces=int(np.count_nonzero(degenerate)),
    )


def _tetra_sums(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Signed volumes (F,), first moments (F, 3) and second moments ∫ r rᵀ dV (F, 3, 3) of the
    tetrahedra joining the origin to each triangle ``corners`` (F, 3, 3)."""
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    six_volume = np.einsum("ij,ij->i", a, np.cross(b, c))
    volume = six_volume / 6.0
    total = a + b + c
    first = volume[:, None] * total / 4.0
    # ∫ r rᵀ dV over a tetrahedron with one corner at the origin: V/20 (Σ vᵢvᵢᵀ + s sᵀ), s = Σ vᵢ
    outer = (np.einsum("fi,fj->fij", a, a) + np.einsum("fi,fj->fij", b, b) + np.einsum("fi,fj->fij", c, c)
             + np.einsum("fi,fj->fij", total, total))
    second = volume[:, None, None] * outer / 20.0
    return volume, first, second


def enclosed_volume_properties(vertices: np.ndarray, faces: np.ndarray) -> MeshVolumeProperties:
    """Volume, centroid and inertia per unit density of the solid a closed mesh encloses.

    The sums run twice: once about the centre of the bounding box to find the centroid, then
    about the centroid itself, so no large offset is squared and subtracted. A mesh wound
    inside out gives a negative volume (and is reported by the caller, not fixed here).
    """
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    corners = vertices[faces]
    reference = 0.5 * (corners.reshape(-1, 3).min(axis=0) + corners.reshape(-1, 3).max(axis=0))
    volumes, firsts, _ = _tetra_sums(corners - reference)
    volume = float(volumes.sum())
    centroid = reference + firsts.sum(axis=0) / volume
    volumes, firsts, seconds = _tetra_sums(corners - centroid)
    volume = float(volumes.sum())
    drift = firsts.sum(axis=0) / volume  # what rounding left of the first moment about the centroid
    second = seconds.sum(axis=0) - volume * np.outer(drift, drift)
    centroid = centroid + drift
    second = 0.5 * (second + second.T)
    inertia = np.trace(second) * np.eye(3) - second
    return MeshVolumeProperties(volume, centroid, inertia)


def enclosed_volume(vertices: np.ndarray, faces: np.ndarray) -> float:
    """Signed volume the mesh encloses (L³): positive when wound outward, negative inside out."""
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    corners = vertices[np.asarray(faces, dtype=np.int64).reshape(-1, 3)]
    reference = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    return float(_tetra_sums(corners - reference)[0].sum())


def bounding_box_volume(vertices: np.ndarray) -> float:
    """Volume of the axis-aligned box around the vertices (L³): the scale against which an
    enclosed volume counts as none."""
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    return float(np.prod(vertices.max(axis=0) - vertices.min(axis=0)))


VOLUME_RTOL = 1e-12
"""An enclosed volume below this fraction of the bounding box's counts as none (a flat mesh)."""


def mesh_problem(vertices: np.ndarray, faces: np.ndarray) -> str | None:
    """Why the mesh does not bound a solid rbi can integrate, in plain words, or None."""
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if faces.shape[0] == 0 or vertices.shape[0] == 0:
        return "holds no triangles"
    if faces.min() < 0 or faces.max() >= vertices.shape[0]:
        return "a face names a vertex that does not exist"
    if not np.all(np.isfinite(vertices)):
        bad = int(np.flatnonzero(~np.isfinite(vertices).all(axis=1))[0])
        return f"vertex {bad}: coordinates must be finite numbers"
    defects = mesh_defects(faces)
    if defects.boundary_edges:
        return (f"not closed: {defects.boundary_edges} boundary edge{'s' * (defects.boundary_edges != 1)} "
                f"(edges used by only one triangle)")
    if defects.overshared_edges:
        return (f"not a closed surface: {defects.overshared_edges} edge{'s' * (defects.overshared_edges != 1)} "
                f"shared by more than two triangles")
    if defects.misoriented_edges:
        return (f"not consistently wound: {defects.misoriented_edges} edge{'s' * (defects.misoriented_edges != 1)} "
                f"run the same way in both of their triangles (some faces point inward)")
    volume = enclosed_volume(vertices, faces)
    if not abs(volume) > VOLUME_RTOL * bounding_box_volume(vertices):
        return "encloses no volume (the surface is flat or folds onto itself)"
    if volume < 0:
        return (f"inside out: the enclosed volume is negative ({volume:.6g}); every face is wound "
                f"clockwise seen from outside")
    return None
