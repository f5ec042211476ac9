"""The added primitive solids against independent integrals.

Each closed form in rbi.core.shapes is compared with a direct numerical integration of
``∫ (|r|² E − r rᵀ) dm`` over the solid placed in space: tensor-product Gauss–Legendre rules
in the solid's natural coordinates (exact for the polynomial integrands, so agreement is to
rounding) and the trapezoid rule in the azimuth (exact for the trigonometric polynomials
that appear). Orientations come from scipy's Rotation, not from rbi's rotation code.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbi.core import shapes
from tests.core import built

RTOL = 1e-11


def _gauss(n: int, a: float, b: float) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def _azimuth(n: int = 16) -> tuple[np.ndarray, np.ndarray]:
    phi = 2.0 * np.pi * np.arange(n) / n
    return phi, np.full(n, 2.0 * np.pi / n)


def mass_properties(points: np.ndarray, weights: np.ndarray):
    """Mass, centre of mass and inertia about it of point masses ``weights`` at ``points``."""
    m = weights.sum()
    com = weights @ points / m
    r = points - com
    second = (r * weights[:, None]).T @ r
    return m, com, np.trace(second) * np.eye(3) - second


def frame_for(axis: np.ndarray) -> np.ndarray:
    """Columns: two unit vectors perpendicular to ``axis`` and the unit axis (right-handed)."""
    w = axis / np.linalg.norm(axis)
    helper = np.array([1.0, 0, 0]) if abs(w[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(w, helper)
    u /= np.linalg.norm(u)
    return np.column_stack([u, np.cross(w, u), w])


def solid_of_revolution(start, end, radius_at, inner_at=lambda t: 0.0, n=10):
    """Quadrature points and volumes of the solid between radii inner_at(t) and radius_at(t),
    t = distance along the axis from ``start``."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    h = np.linalg.norm(end - start)
    frame = frame_for(end - start)
    pts, vols = [], []
    phi, wphi = _azimuth()
    for t, wt in zip(*_gauss(n, 0.0, h)):
        for rho, wr in zip(*_gauss(n, inner_at(t), radius_at(t))):
            for p, wp in zip(phi, wphi):
                local = np.array([rho * math.cos(p), rho * math.sin(p), t])
                pts.append(start + frame @ local)
                vols.append(wt * wr * wp * rho)
    return np.array(pts), np.array(vols)


def ball(center, radii, rotation, inner=0.0, n=8):
    """Quadrature of the region inner ≤ |u| ≤ 1 of the unit ball mapped by
    ``center + rotation diag(radii) u`` (a sphere, shell or turned ellipsoid)."""
    scale = rotation @ np.diag(radii)
    pts, vols = [], []
    phi, wphi = _azimuth()
    for r, wr in zip(*_gauss(n, inner, 1.0)):
        for c, wc in zip(*_gauss(n, -1.0, 1.0)):  # c = cos θ
            s = math.sqrt(1.0 - c * c)
            for p, wp in zip(phi, wphi):
                u = r * np.array([s * math.cos(p), s * math.sin(p), c])
                pts.append(center + scale @ u)
                vols.append(wr * wc * wp * r * r * abs(np.linalg.det(scale)))
    return np.array(pts), np.array(vols)


def assert_matches(element, points, volumes, density):
    m, com, inertia = mass_properties(points, density * volumes)
    assert element.mass == pytest.approx(m, rel=RTOL)
    np.testing.assert_allclose(element.center_of_mass, com, rtol=RTOL, atol=RTOL * np.abs(points).max())
    np.testing.assert_allclose(
        element.inertia_about_com, inertia, rtol=RTOL, atol=RTOL * np.abs(inertia).max()
    )


ROT = Rotation.from_rotvec([0.3, -0.7, 0.5]).as_matrix()


def test_box_turned_matches_exact_quadrature():
    size, center, density = np.array([0.3, 0.1, 0.05]), np.array([1.0, -2.0, 0.5]), 2700.0
    grid = [_gauss(2, -s / 2, s / 2) for s in size]  # 2-point Gauss: exact to degree 3
    pts = np.array(
        [center + ROT @ np.array([x, y, z]) for x in grid[0][0] for y in grid[1][0] for z in grid[2][0]]
    )
    vols = np.array([wx * wy * wz for wx in grid[0][1] for wy in grid[1][1] for wz in grid[2][1]])
    mass = density * shapes.box_volume(size)
    assert_matches(built.box(mass, size, center, ROT), pts, vols, density)


def test_ellipsoid_turned_matches_quadrature():
    semi, center, density = np.array([0.2, 0.05, 0.12]), np.array([0.1, 0.0, -0.3]), 1000.0
    pts, vols = ball(center, semi, ROT)
    mass = density * shapes.ellipsoid_volume(semi)
    assert_matches(shapes.ellipsoid(mass, semi, center, ROT), pts, vols, density)


def test_sphere_matches_quadrature():
    center, radius, density = np.array([0.0, 0.5, 0.0]), 0.07, 7850.0
    pts, vols = ball(center, [radius] * 3, np.eye(3))
    assert_matches(built.sphere(density * shapes.sphere_volume(radius), radius, center), pts, vols, density)


@pytest.mark.parametrize("inner_fraction", [0.0, 0.5, 0.999])
def test_thick_spherical_shell_matches_quadrature(inner_fraction):
    center, R, density = np.array([1.0, 2.0, 3.0]), 0.1, 8960.0
    pts, vols = ball(center, [R] * 3, np.eye(3), inner=inner_fraction)
    mass = density * shapes.spherical_shell_volume(R, inner_fraction * R)
    assert_matches(shapes.spherical_shell(mass, R, inner_fraction * R, center), pts, vols, density)


def test_thin_shell_limit_is_two_thirds_m_r_squared():
    # Surface integral over the sphere: ∫ (y² + z²) dA / A for a unit sphere is 2/3.
    c, wc = _gauss(8, -1.0, 1.0)
    phi, wphi = _azimuth()
    s = np.sqrt(1 - c[:, None] ** 2)
    x = s * np.cos(phi)[None, :]
    w = wc[:, None] * wphi[None, :]
    mean_x2 = (w * x * x).sum() / w.sum()
    R, m = 0.25, 3.0
    shell = shapes.spherical_shell(m, R, R, np.zeros(3))
    np.testing.assert_allclose(shell.inertia_about_com, 2 * mean_x2 * m * R * R * np.eye(3), rtol=1e-13)
    assert 2 * mean_x2 == pytest.approx(2.0 / 3.0, rel=1e-13)


@pytest.mark.parametrize("inner", [0.0, 0.02, 0.0399])
def test_tube_matches_quadrature(inner):
    start, end, R, density = [0.1, 0.2, 0.3], [0.4, -0.1, 0.8], 0.04, 2700.0
    pts, vols = solid_of_revolution(start, end, lambda t: R, lambda t: inner)
    length = float(np.linalg.norm(np.subtract(end, start)))
    mass = density * shapes.tube_volume(R, inner, length)
    assert_matches(shapes.tube(mass, R, inner, start, end), pts, vols, density)


@pytest.mark.parametrize("a, b", [(0.05, 0.02), (0.02, 0.05), (0.0, 0.03), (0.03, 0.0), (0.04, 0.04)])
def test_frustum_matches_quadrature(a, b):
    start, end, density = np.array([0.0, 0.1, 0.0]), np.array([0.2, 0.3, -0.1]), 1240.0
    h = float(np.linalg.norm(end - start))
    pts, vols = solid_of_revolution(start, end, lambda t: a + (b - a) * t / h)
    mass = density * shapes.frustum_volume(a, b, h)
    assert_matches(shapes.frustum(mass, a, b, start, end), pts, vols, density)


def test_rod_matches_line_quadrature():
    start, end, m = np.array([0.0, 0.0, 1.0]), np.array([0.3, 0.4, 1.0]), 0.2
    t, w = _gauss(3, 0.0, 1.0)
    pts = start + t[:, None] * (end - start)
    mass, com, inertia = mass_properties(pts, m * w)
    rod = shapes.rod(m, start, end)
    np.testing.assert_allclose(rod.center_of_mass, com, rtol=1e-14)
    np.testing.assert_allclose(rod.inertia_about_com, inertia, rtol=1e-12, atol=1e-16)


# --- limits that connect the new shapes with the old ones -------------------------------------

lengths = st.floats(0.01, 10.0)


@settings(max_examples=40, deadline=None)
@given(r=lengths, h=lengths)
def test_frustum_with_equal_radii_is_the_cylinder(r, h):
    a, b = shapes.frustum(2.0, r, r, [0, 0, 0], [0, h, 0]), built.cylinder(2.0, r, [0, 0, 0], [0, h, 0])
    np.testing.assert_allclose(a.center_of_mass, b.center_of_mass, rtol=1e-13)
    np.testing.assert_allclose(a.inertia_about_com, b.inertia_about_com, rtol=1e-13)


@settings(max_examples=40, deadline=None)
@given(r=lengths, h=lengths)
def test_frustum_with_a_point_end_is_the_cone(r, h):
    a, b = shapes.frustum(2.0, 0.0, r, [0, 0, 0], [h, 0, 0]), built.cone(2.0, r, [0, 0, 0], [h, 0, 0])
    np.testing.assert_allclose(a.center_of_mass, b.center_of_mass, rtol=1e-13)
    np.testing.assert_allclose(a.inertia_about_com, b.inertia_about_com, rtol=1e-13)


@settings(max_examples=40, deadline=None)
@given(r=lengths, h=lengths)
def test_tube_without_bore_is_the_cylinder_and_shell_without_hole_the_sphere(r, h):
    np.testing.assert_allclose(
        shapes.tube(1.5, r, 0.0, [0, 0, 0], [0, 0, h]).inertia_about_com,
        built.cylinder(1.5, r, [0, 0, 0], [0, 0, h]).inertia_about_com,
        rtol=1e-13,
    )
    np.testing.assert_allclose(
        shapes.spherical_shell(1.5, r, 0.0, [0, 0, 0]).inertia_about_com,
        built.sphere(1.5, r, [0, 0, 0]).inertia_about_com,
        rtol=1e-13,
    )


def test_box_with_equal_edges_turned_anyhow_stays_isotropic():
    cube = built.box(6.0, [0.2, 0.2, 0.2], [0, 0, 0], ROT)
    np.testing.assert_allclose(cube.inertia_about_com, 6.0 * 0.08 / 12 * np.eye(3), rtol=1e-14, atol=1e-17)
