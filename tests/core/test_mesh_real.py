"""Meshes that pybullet ships (convex decompositions, CAD exports), against MuJoCo's compiled
mesh inertia: the same vertex and face arrays (rounded to single precision, as MuJoCo keeps
them) integrated by both."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rbi.formats.mesh_file import read_mesh_arrays
from tests.core.test_mesh_modes import combined
from tests.mesh_builders import mesh_mass_properties

pybullet_data = pytest.importorskip("pybullet_data")
mujoco = pytest.importorskip("mujoco")
ROOT = Path(pybullet_data.getDataPath())


def single_precision(name):
    vertices, faces = read_mesh_arrays(ROOT / name)
    return vertices.astype(np.float32).astype(float), faces


def mujoco_mass_properties(vertices, faces, mode, density=1.0):
    """Mass, centre of mass and full inertia about it that MuJoCo compiles for one mesh geom."""
    v = " ".join(repr(float(c)) for c in np.asarray(vertices).ravel())
    f = " ".join(str(int(i)) for i in np.asarray(faces).ravel())
    xml = (
        f'<mujoco><asset><mesh name="m" inertia="{mode}" vertex="{v}" face="{f}"/></asset>'
        f'<worldbody><body><freejoint/><geom type="mesh" mesh="m" density="{density!r}"/></body>'
        f"</worldbody></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, model.body_iquat[1])
    rotation = rotation.reshape(3, 3)
    inertia = rotation @ np.diag(model.body_inertia[1]) @ rotation.T
    return float(model.body_mass[1]), model.body_ipos[1].copy(), inertia


def pieces_joined_by_ordinary_edges(faces):
    """Face labels: faces connected through edges that exactly two triangles use (so closed
    pieces that touch only along shared edges come apart)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    owner = np.tile(np.arange(len(faces)), 3)
    _, edge, uses = np.unique(edges, axis=0, return_inverse=True, return_counts=True)
    edge = edge.ravel()
    order = np.argsort(edge, kind="stable")
    ordinary = uses[edge[order]] == 2
    a, b = owner[order][ordinary][0::2], owner[order][ordinary][1::2]
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(len(faces), len(faces)))
    return connected_components(graph, directed=False)[1]


@pytest.mark.parametrize("name", ["quadruped/microtaur/xavier.stl", "random_urdfs/099/099.obj"])
def test_a_convex_decomposition_once_refused_is_the_sum_of_its_pieces_in_mujoco(name):
    # MuJoCo refuses the whole ("inconsistent orientation" at the shared edges) but takes each
    # piece; rbi reads the whole and must give the pieces' sum
    vertices, faces = single_precision(name)
    labels = pieces_joined_by_ordinary_edges(faces)
    assert labels.max() >= 1
    pieces = []
    for k in range(labels.max() + 1):
        used, piece_faces = np.unique(faces[labels == k], return_inverse=True)
        pieces.append(mujoco_mass_properties(vertices[used], piece_faces.reshape(-1, 3), "exact"))
    mass, com, inertia = combined(pieces)
    props = mesh_mass_properties(vertices, faces, "exact", density=1.0)
    size = np.ptp(vertices, axis=0).max()
    assert props.properties.mass == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(props.properties.center_of_mass, com, rtol=0, atol=1e-12 * size)
    # the trace does not depend on the axes; MuJoCo's principal axes (body_iquat) are good to
    # about 1e-7 only (per piece: moments agree to 5e-14, the rebuilt tensor to 8e-8)
    assert np.trace(props.properties.inertia_about_com) == pytest.approx(np.trace(inertia), rel=1e-12)
    np.testing.assert_allclose(
        props.properties.inertia_about_com, inertia, rtol=0, atol=1e-6 * np.abs(inertia).max()
    )


@pytest.mark.parametrize(
    "name, modes",
    [
        ("duck_vhacd.obj", ("exact", "shell", "convex")),
        ("random_urdfs/065/065.obj", ("exact", "shell", "convex")),  # overlapping pieces: both sum them
        ("a1/meshes/calf.obj", ("shell", "convex")),
        ("objects/mug_col.obj", ("shell", "convex")),
    ],
)
def test_real_meshes_agree_with_mujoco(name, modes):
    vertices, faces = single_precision(name)
    for mode in modes:
        mass, com, inertia = mujoco_mass_properties(vertices, faces, mode, density=1000.0)
        props = mesh_mass_properties(vertices, faces, mode, density=1000.0)
        size = np.ptp(vertices, axis=0).max()
        assert props.properties.mass == pytest.approx(mass, rel=1e-12), mode
        np.testing.assert_allclose(
            props.properties.center_of_mass, com, rtol=0, atol=1e-12 * size, err_msg=mode
        )
        np.testing.assert_allclose(
            np.linalg.eigvalsh(props.properties.inertia_about_com),
            np.linalg.eigvalsh(inertia),
            rtol=1e-12,
            err_msg=mode,
        )
