"""Closed triangle meshes (rbi.core.mesh) against closed forms: boxes and tetrahedra exactly,
polygon prisms exactly and the cylinder and sphere in the limit at the expected rate, a mesh
a million lengths from the origin, and every defect that keeps a mesh from bounding a solid."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.core.mesh import closed_mesh_check, enclosed_volume_properties, mesh_defects, weld_vertices
from tests.mesh_builders import box_mesh, cylinder_mesh, sphere_mesh, tetrahedron_mesh


def central_box_inertia(a, b, c):
    """∫ (|r|² E − r rᵀ) dV of an a×b×c box about its centre (unit density)."""
    volume = a * b * c
    return volume / 12.0 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])


def test_box_mesh_is_exact_to_rounding():
    size, center = (0.3, 1.7, 2.9), (4.0, -5.0, 0.25)
    props = enclosed_volume_properties(*box_mesh(size, center))
    assert props.mass == pytest.approx(0.3 * 1.7 * 2.9, rel=1e-15)
    np.testing.assert_allclose(props.center_of_mass, center, rtol=0, atol=1e-15 * 5)
    np.testing.assert_allclose(props.inertia_about_com, central_box_inertia(*size), rtol=1e-14, atol=1e-15)


def simplex_moments(corners):
    """Volume, centroid and second moment ∫ r rᵀ dV of a tetrahedron from the Dirichlet
    integrals of the unit simplex (∫ u_i dV = 1/24, ∫ u_i u_j dV = (1 + δ_ij)/120), mapped by
    the affine map r = p0 + A u."""
    p0 = np.asarray(corners[0], float)
    A = (np.asarray(corners[1:], float) - p0).T
    det = abs(np.linalg.det(A))
    volume = det / 6.0
    first = det * (p0 / 6.0 + A @ np.full(3, 1.0 / 24.0))
    uu = (np.ones((3, 3)) + np.eye(3)) / 120.0
    second = det * (
        np.outer(p0, p0) / 6.0
        + np.outer(p0, A @ np.full(3, 1 / 24))
        + np.outer(A @ np.full(3, 1 / 24), p0)
        + A @ uu @ A.T
    )
    return volume, first / volume, second


def test_unit_right_tetrahedron_textbook_values():
    # volume 1/6, centroid (1/4, 1/4, 1/4), ∫x² dV = 1/60, ∫xy dV = 1/120
    props = enclosed_volume_properties(*tetrahedron_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]))
    assert props.mass == pytest.approx(1 / 6, rel=1e-15)
    np.testing.assert_allclose(props.center_of_mass, [0.25] * 3, rtol=1e-15)
    second_about_origin = (1 / 120) * (np.ones((3, 3)) + np.eye(3))
    second_central = second_about_origin - (1 / 6) * np.full((3, 3), 1 / 16)
    expected = np.trace(second_central) * np.eye(3) - second_central
    np.testing.assert_allclose(props.inertia_about_com, expected, rtol=1e-13, atol=1e-17)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-3, 3, allow_nan=False), min_size=12, max_size=12))
def test_any_tetrahedron_matches_the_dirichlet_integrals(coordinates):
    corners = np.reshape(coordinates, (4, 3))
    A = corners[1:] - corners[0]
    scale = max(float(np.max(np.abs(A))), 1e-300)
    if abs(np.linalg.det(A)) <= 1e-3 * scale**3:  # nearly flat: ill-conditioned for any method
        return
    volume, centroid, second = simplex_moments(corners)
    central = second - volume * np.outer(centroid, centroid)
    expected = np.trace(central) * np.eye(3) - central
    props = enclosed_volume_properties(*tetrahedron_mesh(corners))
    assert props.mass == pytest.approx(volume, rel=1e-12)
    np.testing.assert_allclose(props.center_of_mass, centroid, rtol=0, atol=1e-12 * max(scale, 1.0) * 10)
    np.testing.assert_allclose(
        props.inertia_about_com, expected, rtol=0, atol=1e-9 * float(np.max(np.abs(expected))) + 1e-300
    )


def test_polygon_prism_is_exact_and_converges_to_the_cylinder_at_second_order():
    r, L = 0.5, 2.0
    errors = []
    for n in (32, 64, 128, 256):
        props = enclosed_volume_properties(*cylinder_mesh(r, L, n))
        polygon_area = 0.5 * n * r * r * math.sin(2 * math.pi / n)
        assert props.mass == pytest.approx(polygon_area * L, rel=1e-13)  # the prism, exactly
        cylinder_volume = math.pi * r * r * L
        axial = props.inertia_about_com[2, 2] / props.mass
        errors.append((abs(props.mass / cylinder_volume - 1), abs(axial / (0.5 * r * r) - 1)))
        np.testing.assert_allclose(props.center_of_mass, [0, 0, L / 2], atol=1e-14)
    errors = np.array(errors)
    ratios = errors[:-1] / errors[1:]
    assert np.all((ratios > 3.9) & (ratios < 4.1)), ratios  # halving the facet size quarters the error
    assert errors[-1, 0] < 1.1e-4  # 256 facets: volume within 0.01 %


def test_latitude_longitude_sphere_converges_to_two_fifths_m_r_squared():
    r = 1.3
    errors = []
    for n in (16, 32, 64, 128):
        props = enclosed_volume_properties(*sphere_mesh(r, n, 2 * n))
        moments = np.diag(props.inertia_about_com) / props.mass
        errors.append(
            max(abs(props.mass / (4 / 3 * math.pi * r**3) - 1), np.max(np.abs(moments / (0.4 * r * r) - 1)))
        )
        np.testing.assert_allclose(props.center_of_mass, 0, atol=1e-14)
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.5) & (ratios < 4.5)), ratios
    assert errors[-1] < 1e-3


def test_a_mesh_a_million_lengths_away_keeps_its_central_inertia():
    size = (0.3, 0.5, 0.7)
    offset = np.array([1e6, -2e6, 3e6])
    vertices, faces = box_mesh(size)
    near = enclosed_volume_properties(vertices, faces)
    far = enclosed_volume_properties(vertices + offset, faces)
    expected = central_box_inertia(*size)
    np.testing.assert_allclose(far.inertia_about_com, expected, rtol=1e-9, atol=1e-9 * expected.max())
    assert far.mass == pytest.approx(near.mass, rel=1e-9)
    np.testing.assert_allclose(far.center_of_mass - offset, 0, atol=1e-9)
    sphere_v, sphere_f = sphere_mesh(0.2, 24, 48)
    sphere_near = enclosed_volume_properties(sphere_v, sphere_f).inertia_about_com
    sphere_far = enclosed_volume_properties(sphere_v + offset, sphere_f).inertia_about_com
    np.testing.assert_allclose(sphere_far, sphere_near, rtol=0, atol=1e-9 * sphere_near.max())


def triangle_soup(vertices, faces, noise=0.0, seed=0):
    """Every triangle with its own three corners, as an STL file stores them, optionally with
    rounding noise of size ``noise`` added to coordinates that are zero."""
    corners = np.asarray(vertices, float)[faces].reshape(-1, 3).copy()
    if noise:
        zero = corners == 0
        corners[zero] = np.random.default_rng(seed).uniform(-noise, noise, size=zero.sum())
    return corners, np.arange(len(corners)).reshape(-1, 3)


def test_welding_joins_stl_corners_with_cad_rounding_noise():
    soup_v, soup_f = triangle_soup(*box_mesh((2, 2, 2), (1, 1, 1)), noise=1e-17)
    assert mesh_defects(soup_f).boundary_edges == 36  # unshared corners: every edge is a boundary
    vertices, faces = weld_vertices(soup_v, soup_f)
    assert len(vertices) == 8
    assert closed_mesh_check(vertices, faces)[0] is None
    assert enclosed_volume_properties(vertices, faces).mass == pytest.approx(8.0, rel=1e-15)


def test_welding_keeps_distinct_vertices_apart():
    vertices, faces = sphere_mesh(1.0, 200, 400)  # neighbours about 0.008 apart
    welded, _ = weld_vertices(vertices, faces)
    assert len(welded) == len(vertices)


def test_good_meshes_have_no_defects():
    for vertices, faces in (box_mesh(), cylinder_mesh(1, 1, 7), sphere_mesh(1, 5, 9)):
        assert mesh_defects(faces) == (0, 0, 0, 0, 0)
        assert closed_mesh_check(vertices, faces)[0] is None


def test_a_missing_triangle_leaves_three_boundary_edges():
    vertices, faces = box_mesh()
    assert mesh_defects(faces[1:]).boundary_edges == 3
    assert (
        closed_mesh_check(vertices, faces[1:])[0]
        == "not closed: 3 boundary edges (edges used by only one triangle)"
    )
    assert mesh_defects(faces[2:]).boundary_edges == 4  # a whole side gone: its square outline


def test_a_flipped_face_is_inconsistent_winding():
    vertices, faces = box_mesh()
    faces = faces.copy()
    faces[5] = faces[5, ::-1]
    assert mesh_defects(faces).misoriented_edges == 3
    assert closed_mesh_check(vertices, faces)[0].startswith("not consistently wound: 3 edges")


def test_an_inside_out_mesh_has_negative_volume():
    vertices, faces = box_mesh((1, 2, 3))
    inverted = faces[:, ::-1]
    assert enclosed_volume_properties(vertices, inverted).mass == pytest.approx(-6.0)
    assert closed_mesh_check(vertices, inverted)[0].startswith(
        "inside out: the enclosed volume is negative (-6)"
    )


def test_a_flat_double_sided_sheet_encloses_nothing():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    faces = np.array([[0, 1, 2], [0, 2, 1]])
    assert mesh_defects(faces) == (0, 0, 0, 0, 0)
    assert closed_mesh_check(vertices, faces)[0].startswith("encloses no volume")


def test_an_edge_shared_by_four_triangles_half_each_way_joins_two_solids():
    # two tetrahedra touching along one edge, as a convex decomposition writes them
    v1, f1 = tetrahedron_mesh([[0, 0, 0], [0, 0, 1], [1, 0, 0], [0, 1, 0]])
    v2, f2 = tetrahedron_mesh([[0, 0, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0]])
    vertices = np.vstack([v1, v2[2:]])
    remap = np.array([0, 1, 4, 5])
    faces = np.vstack([f1, remap[f2]])
    defects = mesh_defects(faces)
    assert defects.overshared_edges == 0 and defects.boundary_edges == 0 and defects.shared_edges == 1
    assert closed_mesh_check(vertices, faces)[0] is None
    assert enclosed_volume_properties(vertices, faces).mass == pytest.approx(2 / 6, rel=1e-15)


def test_empty_and_broken_arrays_are_named():
    assert closed_mesh_check(np.zeros((0, 3)), np.zeros((0, 3), int))[0] == "holds no triangles"
    vertices, faces = box_mesh()
    assert closed_mesh_check(vertices, np.vstack([faces, [[0, 1, 99]]]))[0] == (
        "face 12 names a vertex that does not exist (vertices are numbered 0 to 7)"
    )
    vertices = vertices.copy()
    vertices[6, 1] = np.nan
    assert closed_mesh_check(vertices, faces)[0] == "vertex 6: coordinates must be finite numbers"


def test_degenerate_faces_are_counted_and_add_nothing():
    vertices, faces = box_mesh((1, 2, 3))
    with_sliver = np.vstack([faces, [[0, 0, 1]]])
    assert mesh_defects(with_sliver).degenerate_faces == 1
    assert closed_mesh_check(vertices, with_sliver)[0] is None
    assert enclosed_volume_properties(vertices, with_sliver).mass == pytest.approx(6.0, rel=1e-15)
