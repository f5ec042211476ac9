"""Write bodies/bracket.stl: an L-shaped angle bracket as a closed binary STL, in millimetres.

The bracket is the L cross-section below (x across, z up), 40 mm deep along y:
a 60 × 5 mm foot and a 5 × 50 mm upright standing on its left end.

    z
    55 +--+
       |  |
     5 |  +------------+
     0 +---------------+ x
       0  5            60

Run from the project root: .venv/bin/python docs/scripts/make_bracket_stl.py
The file is written with the standard binary STL layout (80-byte header, triangle count,
then per triangle a normal, three corners as float32 and a two-byte attribute), every
triangle wound counter-clockwise seen from outside.
"""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np

OUTLINE_XZ_MM = np.array([[0, 0], [60, 0], [60, 5], [5, 5], [5, 55], [0, 55]], dtype=float)
DEPTH_MM = 40.0
REFLEX_CORNER = 3  # the inner corner of the L: every cap triangle fans out from it


def bracket_triangles() -> np.ndarray:
    """(F, 3, 3) triangles of the extruded L, outward normals."""
    n = len(OUTLINE_XZ_MM)
    front = np.column_stack([OUTLINE_XZ_MM[:, 0], np.zeros(n), OUTLINE_XZ_MM[:, 1]])  # y = 0
    back = np.column_stack([OUTLINE_XZ_MM[:, 0], np.full(n, DEPTH_MM), OUTLINE_XZ_MM[:, 1]])  # y = depth
    triangles = []
    # Seen from -y (the front cap's outside) x points right and z up, so the outline runs
    # counter-clockwise there: the front cap keeps its order, the back cap reverses it, and
    # each side wall runs along the outline edge on the front and back along the rear.
    others = [i for i in range(n) if i != REFLEX_CORNER]
    order = others[others.index((REFLEX_CORNER + 1) % n) :] + others[: others.index((REFLEX_CORNER + 1) % n)]
    for a, b in zip(order[:-1], order[1:]):
        triangles.append([front[REFLEX_CORNER], front[a], front[b]])
        triangles.append([back[REFLEX_CORNER], back[b], back[a]])
    for i in range(n):
        j = (i + 1) % n
        triangles.append([front[i], back[j], front[j]])
        triangles.append([front[i], back[i], back[j]])
    return np.array(triangles)


def signed_volume(triangles: np.ndarray) -> float:
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def write_binary_stl(path: Path, triangles: np.ndarray) -> None:
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    with open(path, "wb") as out:
        out.write(b"L bracket 60 x 40 x 55 mm, 5 mm plate (docs/scripts/make_bracket_stl.py)".ljust(80, b" "))
        out.write(struct.pack("<I", len(triangles)))
        for normal, corners in zip(normals, triangles):
            out.write(struct.pack("<12fH", *normal, *corners.ravel(), 0))


if __name__ == "__main__":
    triangles = bracket_triangles()
    expected = (60 * 5 + 5 * 50) * DEPTH_MM
    assert abs(signed_volume(triangles) - expected) < 1e-9 * expected, "outline wound the wrong way"
    target = Path(__file__).resolve().parents[2] / "bodies" / "bracket.stl"
    write_binary_stl(target, triangles)
    print(f"wrote {target} ({len(triangles)} triangles, {expected:.0f} mm³)")
