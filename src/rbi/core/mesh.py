"""Triangle meshes: the solid they enclose or the surface they are, its centre of mass and
inertia, and the checks that make those numbers meaningful.

A mesh is ``vertices`` (N, 3) floats in any length unit L and ``faces`` (F, 3) vertex indices,
each triangle wound counter-clockwise seen from outside (its normal by the right-hand rule
points out of the solid). By the divergence theorem the enclosed solid is the signed sum of
the tetrahedra joining a reference point to every face; each tetrahedron's volume, first and
second moments are closed forms, so the result is exact up to rounding for the polyhedron the
mesh describes. The reference point is taken inside the mesh's bounding box and the second
moments are summed about the centre of mass itself, so a small part far from the origin keeps
its digits.

Three ways to put mass on a mesh, named as MuJoCo names them (:data:`MESH_INERTIA_MODES`):

- ``exact``: the solid the mesh encloses. The mesh must be closed: every edge used as often in
  one direction as in the other. That admits what CAD exporters and convex decomposition
  write: several closed pieces in one file, touching at vertices, along edges or on faces
  (such an edge is used by four or more triangles, half each way), and cavities (a piece wound
  inward inside another). A piece wound inside out that is no cavity would count its space
  negatively: refused. Pieces that overlap count their shared space twice (as MuJoCo does):
  accepted with a note.
- ``convex``: the solid convex hull of the vertices (scipy's Qhull), never a silent fallback.
- ``shell``: the mass spread evenly over the surface (MuJoCo's ``shellinertia``); any mesh with
  area, open or closed. A density is then mass per area.

:func:`repair_mesh` (opt-in) closes holes of three or four edges with trimesh's
``fill_holes`` and reports the area it added.

numpy, vectorised over faces in chunks (bounded memory); scipy (sparse graphs, Qhull, k-d
trees) is imported with the module, trimesh only by :func:`repair_mesh`; reading files is done
elsewhere.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import ConvexHull, QhullError, cKDTree

from rbi.core.mass import MassProperties

Moments = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray | float, np.ndarray | float]]
"""Per-triangle measures and summed first and second moments of corners (F, 3, 3) about a point
(0 for moments not wanted)."""

MESH_INERTIA_MODES = ("exact", "convex", "shell")
"""How a mesh carries its mass: the enclosed solid, the convex hull's solid, or the surface."""


class MeshError(ValueError):
    """A mesh that cannot give mass properties in the mode asked; ``str()`` says what is wrong
    and what would be right (without the file's name: the caller adds it)."""


class MeshDefects(NamedTuple):
    """What keeps a triangle mesh from bounding a solid (all but ``shared_edges`` zero for a
    good mesh). Counts of undirected edges, each classed by how its triangles use it.

    boundary_edges: edges used by only one triangle (holes in the surface).
    overshared_edges: edges used by more than two triangles whose uses do not balance (not as
    many running one way as the other): a fin, or pieces glued inconsistently.
    misoriented_edges: edges used by two triangles running along them in the same direction (a
    face wound against its neighbours, so that its normal points the wrong way).
    degenerate_faces: triangles that name one vertex twice (no area; ignored in the sums).
    shared_edges: edges used by four or more triangles, half each way: closed pieces touching
    along an edge. Not a defect.
    """

    boundary_edges: int
    overshared_edges: int
    misoriented_edges: int
    degenerate_faces: int
    shared_edges: int = 0


class MeshDistribution(NamedTuple):
    """Where a mode puts the mass: ``unit`` the mass properties at density 1 (frame ``"mesh"``:
    the mass is the volume, L³, in modes ``exact`` and ``convex``, or the area, L², in
    ``shell``; the centre of mass is its centroid, L; the inertia about it is per unit density,
    L⁵ or L⁴, mesh axes). ``vertices`` and ``faces`` are the mesh integrated (the hull's, for
    ``convex``). ``notes``: what the numbers deserve a word on (overlapping pieces).
    ``added_faces`` and ``added_area`` (L²): what :func:`repair_mesh` added to the mesh before
    (0 when it added nothing, or was not asked)."""

    mode: str
    unit: MassProperties
    vertices: np.ndarray
    faces: np.ndarray
    notes: tuple[str, ...] = ()
    added_faces: int = 0
    added_area: float = 0.0


class RepairedMesh(NamedTuple):
    """A mesh after :func:`repair_mesh`: its vertices and faces (the added triangles last), the
    number of triangles added and their total area (L²)."""

    vertices: np.ndarray
    faces: np.ndarray
    added_faces: int
    added_area: float


WELD_RTOL = 1e-9
"""Vertices closer than about this fraction of the bounding box's diagonal are one vertex."""

FACE_CHUNK = 1 << 16
"""Faces integrated at a time: the temporaries stay near 20 MB whatever the mesh's size."""


def _as_arrays(vertices: ArrayLike, faces: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    return (
        np.asarray(vertices, dtype=float).reshape(-1, 3),
        np.asarray(faces, dtype=np.int64).reshape(-1, 3),
    )


def weld_vertices(
    vertices: np.ndarray, faces: np.ndarray, rtol: float = WELD_RTOL
) -> tuple[np.ndarray, np.ndarray]:
    """One vertex per position: faces re-indexed onto vertices that coincide.

    STL files store every triangle with its own three corners, so a mesh read from one shares
    no vertex indices until equal positions are joined. CAD exporters write the same corner
    with rounding noise (``-1.7e-17`` for ``0``), so positions closer than a tolerance ``rtol``
    times the bounding box's diagonal are joined too: equal positions are found by sorting
    (in the input's precision, float32 or float64), then each remaining position is joined to
    those within the tolerance (a k-d tree's neighbour query; never a rounding grid, which
    splits two copies of a corner one ulp apart on either side of a grid line). Each welded
    vertex keeps the coordinates of the lowest of its copies in lexicographic order; the
    result is float64. The vertices must be finite. Raises :class:`MeshError` when more than
    :data:`NEAR_NEIGHBOURS` distinct positions crowd within the tolerance of one.
    """
    vertices = np.asarray(vertices).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if vertices.shape[0] == 0:
        return vertices.astype(float), faces
    order = np.lexsort((vertices[:, 2], vertices[:, 1], vertices[:, 0]))
    ordered = vertices[order]
    starts = np.empty(len(ordered), dtype=bool)
    starts[0] = True
    np.any(ordered[1:] != ordered[:-1], axis=1, out=starts[1:])  # -0.0 == 0.0: joined
    unique = ordered[starts].astype(float)
    del ordered
    inverse = np.empty(len(order), dtype=np.int64)
    inverse[order] = np.cumsum(starts) - 1
    del order, starts
    labels = _near_groups(unique, rtol)
    if labels is not None:
        _, first = np.unique(labels, return_index=True)
        unique = unique[first]
        inverse = labels[inverse]
    return unique, inverse[faces]


NEAR_NEIGHBOURS = 7
"""Most distinct positions welding joins to one (rounding noise gives a handful); more within
the tolerance is a degenerate mesh, refused rather than searched at any cost."""


def _near_groups(points: np.ndarray, rtol: float) -> np.ndarray | None:
    """Group labels (numbered in the points' order) joining distinct ``points`` closer than
    ``rtol`` times their bounding diagonal, directly or through a chain; None when no two are
    that close."""
    if len(points) < 2:
        return None
    low = points.min(axis=0)
    span = points.max(axis=0) - low
    scale = float(np.max(span))
    if not (np.isfinite(scale) and scale > 0):
        return None
    tol = rtol * scale * float(np.linalg.norm(span / scale))

    tree = cKDTree(points, balanced_tree=False, compact_nodes=False)
    distance, neighbour = tree.query(points, k=NEAR_NEIGHBOURS + 2, distance_upper_bound=tol)
    del tree
    found = np.isfinite(distance) & (neighbour != np.arange(len(points))[:, None])
    del distance
    if not found.any():
        return None
    if found.sum(axis=1).max() > NEAR_NEIGHBOURS:
        raise MeshError(
            f"more than {NEAR_NEIGHBOURS} distinct vertices lie within {tol:.3g} of one vertex "
            f"({rtol:g} of the mesh's size): a degenerate mesh, not rounding noise"
        )

    return _components(np.nonzero(found)[0], neighbour[found], len(points))  # numbered in the points' order


def _components(rows: np.ndarray, cols: np.ndarray, n: int) -> np.ndarray:
    """The connected component of each of ``n`` nodes joined by the edges ``rows``-``cols``,
    numbered in the order of each component's first node."""
    graph = coo_matrix((np.ones(len(rows), dtype=np.int8), (rows, cols)), shape=(n, n))
    return connected_components(graph, directed=False)[1]


def _edge_uses(faces: np.ndarray, n_vertices: int) -> tuple[np.ndarray, np.ndarray]:
    """For each undirected edge of the non-degenerate faces: how many triangles use it, and
    the balance of their directions (uses from the lower to the higher vertex index minus
    uses the other way)."""
    directed_from = faces.reshape(-1)
    directed_to = faces[:, [1, 2, 0]].reshape(-1)
    low = np.minimum(directed_from, directed_to)
    high = np.maximum(directed_from, directed_to)
    key = low * np.int64(max(n_vertices, 1)) + high
    del low, high
    _, edge, uses = np.unique(key, return_inverse=True, return_counts=True)
    del key
    direction = np.where(directed_from < directed_to, 1.0, -1.0)
    balance = np.bincount(edge.reshape(-1), weights=direction, minlength=len(uses))
    return uses, balance


def mesh_defects(faces: np.ndarray) -> MeshDefects:
    """Edge counts that tell whether ``faces`` close a consistently wound surface.

    A set of triangles closes a consistently wound surface (the boundary of a solid, perhaps
    of several pieces) when every edge is used as often in one direction as in the other:
    then the divergence theorem holds and the enclosed volume does not depend on the
    reference point. An ordinary closed mesh uses each edge exactly twice, once each way.
    """
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    degenerate = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (faces[:, 2] == faces[:, 0])
    good = faces[~degenerate]
    if len(good) == 0:
        return MeshDefects(0, 0, 0, int(np.count_nonzero(degenerate)), 0)
    uses, balance = _edge_uses(good, int(good.max()) + 1)
    unbalanced = balance != 0
    return MeshDefects(
        boundary_edges=int(np.count_nonzero(uses == 1)),
        overshared_edges=int(np.count_nonzero(unbalanced & (uses > 2))),
        misoriented_edges=int(np.count_nonzero(unbalanced & (uses == 2))),
        degenerate_faces=int(np.count_nonzero(degenerate)),
        shared_edges=int(np.count_nonzero(~unbalanced & (uses > 2))),
    )


def _signed_volumes(corners: np.ndarray) -> np.ndarray:
    """Signed volumes (F,) of the tetrahedra joining the origin to each triangle ``corners``
    (F, 3, 3)."""
    return np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2])) / 6.0


def _areas(corners: np.ndarray) -> np.ndarray:
    """Areas (F,) of the triangles ``corners`` (F, 3, 3)."""
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def _moments(measure: Callable[[np.ndarray], np.ndarray], first_share: float, second_share: float) -> Moments:
    """Per-triangle measures (``measure`` of the corners (F, 3, 3)), their first moments (3,)
    summed and second moments ∫ r rᵀ (3, 3) summed. Over a tetrahedron with one corner at the
    origin (volume V) ∫ r dV = V s/4 and ∫ r rᵀ dV = V/20 (Σ vᵢvᵢᵀ + s sᵀ), s = Σ vᵢ; over a
    triangle (area A) ∫ r dA = A s/3 and ∫ r rᵀ dA = A/12 (Σ vᵢvᵢᵀ + s sᵀ)."""

    def moments(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
        weight = measure(corners)
        total = a + b + c
        first = (weight[:, None] * total / first_share).sum(axis=0)
        outer = sum(np.einsum("fi,fj->fij", v, v) for v in (a, b, c, total))
        return weight, first, (weight[:, None, None] * outer / second_share).sum(axis=0)

    return moments


_volume_moments = _moments(_signed_volumes, 4.0, 20.0)
_surface_moments = _moments(_areas, 3.0, 12.0)
SIZED_VOLUME_MOMENTS = {
    False: _volume_moments,
    True: _moments(lambda corners: np.abs(_signed_volumes(corners)), 4.0, 20.0),
}
"""The tetrahedra joining the origin to triangles (F, 3, 3): their signed volumes (F,) (by
their sizes, without the sign, under ``True``), their first and second moments summed."""


def _sums(
    vertices: np.ndarray, faces: np.ndarray, reference: np.ndarray, moments: Moments
) -> tuple[float, np.ndarray, np.ndarray]:
    measure, first, second = 0.0, np.zeros(3), np.zeros((3, 3))
    for start in range(0, len(faces), FACE_CHUNK):
        m, f, s = moments(vertices[faces[start : start + FACE_CHUNK]] - reference)
        measure += float(m.sum())
        first += f
        second += s
    return measure, first, second


def _integrate(
    vertices: np.ndarray, faces: np.ndarray, moments: Moments
) -> tuple[float, np.ndarray, np.ndarray]:
    """Measure, centroid and inertia per unit density about the centroid. The sums run twice:
    once about the centre of the bounding box to find the centroid, then about the centroid
    itself, so no large offset is squared and subtracted."""
    used = vertices[np.unique(faces)] if len(faces) else vertices
    reference = 0.5 * (used.min(axis=0) + used.max(axis=0))
    measure, first, _ = _sums(vertices, faces, reference, moments)
    if not (np.isfinite(measure) and measure != 0.0):
        return measure, np.full(3, np.nan), np.full((3, 3), np.nan)  # the callers refuse it
    centroid = reference + first / measure
    measure, first, second = _sums(vertices, faces, centroid, moments)
    drift = first / measure  # what rounding left of the first moment about the centroid
    second = second - measure * np.outer(drift, drift)
    centroid = centroid + drift
    second = 0.5 * (second + second.T)
    return measure, centroid, np.trace(second) * np.eye(3) - second


def enclosed_volume_properties(vertices: np.ndarray, faces: np.ndarray) -> MassProperties:
    """The solid a closed mesh encloses at density 1: its mass is the volume (L³), its centre of
    mass the centroid (L), its inertia per unit density (L⁵), frame ``"mesh"``. A mesh wound
    inside out gives a negative volume (and is reported by the caller, not fixed here)."""
    vertices, faces = _as_arrays(vertices, faces)
    return MassProperties(*_integrate(vertices, faces, _volume_moments), "mesh")


def surface_area(vertices: np.ndarray, faces: np.ndarray) -> float:
    """Total area of the triangles (L²)."""
    vertices, faces = _as_arrays(vertices, faces)
    return _sums(vertices, faces, np.zeros(3), lambda corners: (_areas(corners), 0.0, 0.0))[0]


def enclosed_volume(vertices: np.ndarray, faces: np.ndarray) -> float:
    """Signed volume the mesh encloses (L³): positive when wound outward, negative inside out."""
    vertices, faces = _as_arrays(vertices, faces)
    centre = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    return _sums(vertices, faces, centre, lambda corners: (_signed_volumes(corners), 0.0, 0.0))[0]


VOLUME_RTOL = 1e-12
"""An enclosed volume below this fraction of the bounding box's counts as none (a flat mesh)."""


def _plural(count: int, word: str) -> str:
    return f"{count} {word}{'s' * (count != 1)}"


def arrays_problem(vertices: np.ndarray, faces: np.ndarray) -> str | None:
    """What makes the arrays unusable for any mode (no triangles, an index out of range, a
    coordinate that is not a finite number or too large to square), or None."""
    vertices = np.asarray(vertices)  # float32 or float64 as read: no copy
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if vertices.ndim != 2 or vertices.shape[1] != 3 or faces.shape[0] == 0 or vertices.shape[0] == 0:
        return "holds no triangles"
    if faces.min() < 0 or faces.max() >= vertices.shape[0]:
        bad = int(np.flatnonzero((faces < 0).any(axis=1) | (faces >= vertices.shape[0]).any(axis=1))[0])
        return (
            f"face {bad} names a vertex that does not exist (vertices are numbered 0 to "
            f"{vertices.shape[0] - 1})"
        )
    finite = np.isfinite(vertices).all(axis=1)
    if not finite.all():
        bad = int(np.flatnonzero(~finite)[0])
        return f"vertex {bad}: coordinates must be finite numbers"
    if float(np.abs(vertices).max()) > MAX_COORDINATE:
        bad = int(np.flatnonzero((np.abs(vertices) > MAX_COORDINATE).any(axis=1))[0])
        return (
            f"vertex {bad}: a coordinate beyond ±{MAX_COORDINATE:g} (its fifth power, which the "
            f"inertia needs, would overflow); scale the mesh into a smaller unit"
        )
    return None


MAX_COORDINATE = 1e50
"""Largest coordinate magnitude rbi integrates: moments of inertia hold fifth powers of lengths,
and (1e50)⁵ is far inside the float range while no real part is measured in such numbers."""


def closed_mesh_check(vertices: np.ndarray, faces: np.ndarray) -> tuple[str | None, tuple[str, ...]]:
    """Why the mesh does not bound a solid (or None), and notes on a mesh that does but whose
    numbers deserve a word (pieces that overlap, whose shared space counts twice)."""
    vertices, faces = _as_arrays(vertices, faces)
    problem = arrays_problem(vertices, faces)
    if problem is not None:
        return problem, ()
    defects = mesh_defects(faces)
    if defects.boundary_edges:
        return (
            f"not closed: {_plural(defects.boundary_edges, 'boundary edge')} (edges used by only one triangle)",
            (),
        )
    if defects.overshared_edges:
        return (
            f"not a closed surface: {_plural(defects.overshared_edges, 'edge')} used by more than two "
            f"triangles, not as many each way (closed pieces that touch use an edge equally often "
            f"in each direction)"
        ), ()
    if defects.misoriented_edges:
        return (
            f"not consistently wound: {_plural(defects.misoriented_edges, 'edge')} run the same way in "
            f"both of their triangles (some faces point inward)"
        ), ()
    volume = enclosed_volume(vertices, faces)
    if not abs(volume) > VOLUME_RTOL * float(np.prod(np.ptp(vertices, axis=0))):  # the bounding box's
        return "encloses no volume (the surface is flat or folds onto itself)", ()
    if volume < 0:
        return (
            f"inside out: the enclosed volume is negative ({volume:.6g}); every face is wound "
            f"clockwise seen from outside"
        ), ()
    return _pieces_check(vertices, faces, defects)


WINDING_BUDGET = 1_000_000
"""Solid angles evaluated at most when checking how pieces of a mesh lie (a fraction of a second)."""

OVERLAP_NOTE = (
    "pieces of the mesh overlap: the space inside two of them counts twice (as in MuJoCo, which "
    "sums the pieces too); join them into one surface for the solid's own numbers"
)


def _pieces_check(
    vertices: np.ndarray, faces: np.ndarray, defects: MeshDefects
) -> tuple[str | None, tuple[str, ...]]:
    """For a mesh of several pieces (or pieces touching along edges): a piece wound inside out
    that is no cavity (its space would count negatively: refused), and pieces that overlap
    (space counted twice, as the sum of the pieces: a note). Tested by the winding number just
    in front of and just behind a sample of faces (every face of a small mesh): 0 or 1 for a
    solid."""
    face_piece = _piece_of_face(vertices.shape[0], faces)
    if face_piece.max() == 0 and defects.shared_edges == 0:
        return None, ()
    corners = vertices[faces]
    reference = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    corners = corners - reference
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    double_area = np.linalg.norm(cross, axis=1)
    perimeter = sum(np.linalg.norm(corners[:, (i + 1) % 3] - corners[:, i], axis=1) for i in range(3))
    inradius = np.divide(double_area, perimeter, out=np.zeros(len(faces)), where=perimeter > 0)
    size = float(np.linalg.norm(corners.reshape(-1, 3).max(axis=0) - corners.reshape(-1, 3).min(axis=0)))
    usable = inradius > 1e-7 * size
    samples = _sample_faces(face_piece, double_area, usable, max(1, WINDING_BUDGET // (2 * len(faces))))
    if len(samples) == 0:
        return None, ()
    normal = cross[samples] / double_area[samples, None]
    centre = corners[samples].mean(axis=1)
    step = (1e-3 * inradius[samples])[:, None] * normal
    points = np.vstack([centre + step, centre - step])
    winding = _winding_numbers(corners, points)
    near_integer = np.abs(winding - np.round(winding)) < 1e-3
    counts = np.round(winding[near_integer])
    if (counts < 0).any():
        return (
            "inside out: a piece of the mesh is wound clockwise seen from outside and is no cavity "
            "inside another piece (its space would count negatively); turn its faces around"
        ), ()
    return None, ((OVERLAP_NOTE,) if (counts > 1).any() else ())


def _piece_of_face(n_vertices: int, faces: np.ndarray) -> np.ndarray:
    """For each face, the number of the piece (faces connected through shared vertices) it
    belongs to."""
    rows = np.concatenate([faces[:, 0], faces[:, 1]])
    cols = np.concatenate([faces[:, 1], faces[:, 2]])
    return _components(rows, cols, n_vertices)[faces[:, 0]]


def _sample_faces(face_piece: np.ndarray, weight: np.ndarray, usable: np.ndarray, count: int) -> np.ndarray:
    """Up to about ``count`` usable faces: the largest of every piece, then evenly spread ones."""
    candidates = np.flatnonzero(usable)
    if len(candidates) <= count:
        return candidates
    order = candidates[np.lexsort((-weight[candidates], face_piece[candidates]))]
    _, first = np.unique(face_piece[order], return_index=True)
    largest = order[first][:count]
    spread = candidates[np.linspace(0, len(candidates) - 1, max(count - len(largest), 0)).astype(np.int64)]
    return np.unique(np.concatenate([largest, spread]))


def _winding_numbers(corners: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Generalised winding number of the triangles ``corners`` (F, 3, 3) at each point: the
    sum of their signed solid angles over 4π (Van Oosterom and Strackee's formula)."""
    out = np.empty(len(points))
    per_chunk = max(1, 1_000_000 // max(len(corners), 1))
    for start in range(0, len(points), per_chunk):
        p = points[start : start + per_chunk]
        a = corners[None, :, 0, :] - p[:, None, :]
        b = corners[None, :, 1, :] - p[:, None, :]
        c = corners[None, :, 2, :] - p[:, None, :]
        la, lb, lc = (np.linalg.norm(x, axis=2) for x in (a, b, c))
        numerator = np.einsum("pfi,pfi->pf", a, np.cross(b, c))
        denominator = (
            la * lb * lc
            + np.einsum("pfi,pfi->pf", a, b) * lc
            + np.einsum("pfi,pfi->pf", a, c) * lb
            + np.einsum("pfi,pfi->pf", b, c) * la
        )
        out[start : start + per_chunk] = 2.0 * np.arctan2(numerator, denominator).sum(axis=1) / (4.0 * np.pi)
    return out


def convex_hull_mesh(vertices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The convex hull of the points (scipy's Qhull) as a closed mesh wound outward: its
    corner points and faces. Raises :class:`MeshError` when the points span no volume."""

    points = np.asarray(vertices, dtype=float).reshape(-1, 3)
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    try:
        hull = ConvexHull(points - centre)
    except (QhullError, ValueError):
        raise MeshError(
            "the convex hull is flat: the vertices lie in one plane (or on one line) and span "
            "no volume; use inertia: shell for a flat surface"
        ) from None
    corner_ids, faces = np.unique(hull.simplices, return_inverse=True)  # the corners in input order
    faces = faces.reshape(-1, 3).astype(np.int64)
    hull_points = points[corner_ids]
    c = hull_points[faces] - centre
    outward = np.einsum("ij,ij->i", np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]), hull.equations[:, :3])
    faces[outward < 0] = faces[outward < 0][:, ::-1]
    return hull_points, faces


def repair_mesh(vertices: np.ndarray, faces: np.ndarray) -> RepairedMesh:
    """Close small holes (three or four boundary edges) with trimesh's ``fill_holes``, which
    winds each new triangle to match its neighbours. Larger holes are left open (the caller's
    checks report them). The vertices should be welded first."""
    # not at top level: `rbi inertia (mesh part)` would load trimesh too
    import trimesh

    vertices, faces = _as_arrays(vertices, faces)
    if mesh_defects(faces).boundary_edges == 0:
        return RepairedMesh(vertices, faces, 0, 0.0)
    mesh = trimesh.Trimesh(vertices=vertices, faces=faces, process=False, validate=False)
    trimesh.repair.fill_holes(mesh)
    repaired = np.asarray(mesh.faces, dtype=np.int64)
    if len(repaired) < len(faces) or not np.array_equal(repaired[: len(faces)], faces):
        raise MeshError("repair changed the existing faces")  # trimesh appends: never expected
    added = repaired[len(faces) :]
    return RepairedMesh(vertices, repaired, len(added), surface_area(vertices, added))


EXACT_HINTS = {
    ("not closed", "not a closed surface"): (
        "; for such a mesh choose inertia: convex (the solid convex hull), inertia: shell (mass on "
        "the surface), or repair: true (closes holes of three or four edges)"
    ),
    ("not consistently wound", "inside out"): (
        "; turn those faces around, or choose inertia: convex or inertia: shell (neither depends on the winding)"
    ),
    ("encloses no volume",): "; for a flat part choose inertia: shell (the mass spread over the surface)",
}
"""Added to an ``exact``-mode refusal, by how the refusal starts: the other ways to give the mesh
mass properties (for an open mesh), the modes that read a wrongly wound one as it is, and the
surface for a flat one."""


def mesh_distribution(vertices: np.ndarray, faces: np.ndarray, mode: str = "exact") -> MeshDistribution:
    """Where ``mode`` puts the mass of the mesh, per unit density (see :class:`MeshDistribution`).
    Raises :class:`MeshError` naming what is wrong and, in ``exact`` mode, the other modes."""
    vertices, faces = _as_arrays(vertices, faces)
    if mode not in MESH_INERTIA_MODES:
        raise MeshError(f"unknown mesh inertia mode {mode!r}: use exact, convex or shell")
    problem = arrays_problem(vertices, faces)
    if problem is not None:
        raise MeshError(problem)
    if mode == "convex":
        vertices, faces = convex_hull_mesh(vertices[np.unique(faces)])
    elif mode == "shell":
        area, centroid, inertia = _integrate(vertices, faces, _surface_moments)
        if not area > 0:
            raise MeshError("has no area (every triangle is degenerate)")
        return MeshDistribution(mode, MassProperties(area, centroid, inertia, "mesh"), vertices, faces)
    problem, notes = closed_mesh_check(vertices, faces)
    if problem is not None:
        hints = [hint for starts, hint in EXACT_HINTS.items() if problem.startswith(starts)]
        raise MeshError(problem + (hints[0] if hints and mode == "exact" else ""))
    return MeshDistribution(mode, enclosed_volume_properties(vertices, faces), vertices, faces, notes)
