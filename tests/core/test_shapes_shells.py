"""Thin shells (mass spread evenly over the surface, MuJoCo's shellinertia) in rbi.core.shapes,
against independent answers: the surface integrals of rbi.core.mesh on a box mesh (exact: the
faces are flat) and on fine tessellations of the sphere and the closed cylinder, the textbook
2/3 m r² of a spherical shell, and the limits where a shape becomes another."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.core import shapes
from tests.mesh_builders import box_mesh, cylinder_mesh, mesh_mass_properties, sphere_mesh


def _principal_about_centroid(vertices, faces, mass):
    found = mesh_mass_properties(vertices, faces, "shell", mass=mass)
    return found.area, found.properties.inertia_about_com


@pytest.mark.parametrize("size", [(1.0, 1.0, 1.0), (0.3, 2.0, 0.7), (5.0, 0.01, 0.2)])
def test_box_shell_equals_the_integral_over_its_faces(size):
    a, b, c = size
    area, inertia = _principal_about_centroid(*box_mesh(size), mass=2.5)
    assert shapes.box_area(a, b, c) == pytest.approx(area, rel=1e-14)
    np.testing.assert_allclose(shapes.box_shell_moments(2.5, a, b, c), np.diag(inertia), rtol=1e-13)


def test_sphere_shell_is_two_thirds_m_r_squared_and_the_mesh_agrees():
    m, r = 3.0, 0.4
    assert shapes.sphere_shell_moment(m, r) == pytest.approx(2.0 / 3.0 * m * r * r, rel=1e-15)
    assert shapes.sphere_area(r) == pytest.approx(4.0 * math.pi * r * r, rel=1e-15)
    area, inertia = _principal_about_centroid(*sphere_mesh(r, 400, 800), mass=m)
    assert area == pytest.approx(shapes.sphere_area(r), rel=1e-4)
    np.testing.assert_allclose(np.diag(inertia), [shapes.sphere_shell_moment(m, r)] * 3, rtol=1e-4)


@pytest.mark.parametrize("radius,length", [(0.5, 2.0), (1.0, 0.1), (0.05, 1.0)])
def test_closed_cylinder_shell_equals_the_integral_over_its_side_and_discs(radius, length):
    m = 1.7
    area, inertia = _principal_about_centroid(*cylinder_mesh(radius, length, 4000), mass=m)
    assert shapes.cylinder_area(radius, length) == pytest.approx(area, rel=1e-5)
    axial, transverse = shapes.cylinder_shell_moments(m, radius, length)
    np.testing.assert_allclose([transverse, transverse, axial], np.diag(inertia), rtol=1e-5)


def test_cylinder_shell_limits():
    m, r = 2.0, 0.3
    # length 0: two coincident discs, m r²/2 axial and m r²/4 about a diameter
    assert shapes.cylinder_shell_moments(m, r, 0.0) == pytest.approx(
        (m * r * r / 2, m * r * r / 4), rel=1e-15
    )
    # very long: the side carries it all, a thin tube: m r² axial, m L²/12 dominating across
    L = 1e6
    axial, transverse = shapes.cylinder_shell_moments(m, r, L)
    assert axial == pytest.approx(m * r * r, rel=1e-6)
    assert transverse == pytest.approx(m * L * L / 12, rel=1e-6)


def test_capsule_shell_limits_and_its_parts():
    m, r = 2.0, 0.3
    # no cylinder: a whole spherical shell
    assert shapes.capsule_area(r, 0.0) == pytest.approx(shapes.sphere_area(r), rel=1e-15)
    axial, transverse = shapes.capsule_shell_moments(m, r, 0.0)
    assert axial == pytest.approx(shapes.sphere_shell_moment(m, r), rel=1e-15)
    assert transverse == pytest.approx(shapes.sphere_shell_moment(m, r), rel=1e-15)
    # a capsule's surface is a closed cylinder's without its discs plus a sphere's: the sums of
    # mass-weighted moments match (each part taken from its own closed form)
    L = 1.1
    side_area, sphere_area = 2 * math.pi * r * L, shapes.sphere_area(r)
    sigma = m / (side_area + sphere_area)
    cylinder = shapes.cylinder_area(r, L)
    c_axial, c_transverse = shapes.cylinder_shell_moments(sigma * cylinder, r, L)
    discs = sigma * 2 * math.pi * r * r  # both end discs at the cylinder's density
    side_axial = c_axial - discs * r * r / 2
    side_transverse = c_transverse - discs * (r * r / 4 + L * L / 4)
    caps = sigma * sphere_area
    # two hemispherical shells L/2 from the centre: centroid r/2 beyond each rim, ∫z² dA = A r²/3
    caps_transverse = caps * r * r / 3 + caps * (r * r / 3 + r * L / 2 + L * L / 4)
    axial, transverse = shapes.capsule_shell_moments(m, r, L)
    assert axial == pytest.approx(side_axial + caps * 2 * r * r / 3, rel=1e-14)
    assert transverse == pytest.approx(side_transverse + caps_transverse, rel=1e-14)


def test_solid_capsule_and_ellipsoid_moments_match_their_shapes():
    m, r, L = 1.5, 0.2, 0.9
    whole = shapes.capsule(m, r, [0, 0, -L / 2], [0, 0, L / 2])
    axial, transverse = shapes.capsule_moments(m, r, L)
    np.testing.assert_allclose(np.diag(whole.inertia_about_com), [transverse, transverse, axial], rtol=1e-15)
    # an ellipsoid of equal semi-axes is a sphere: 2/5 m r²
    assert shapes.ellipsoid_moments(m, r, r, r) == pytest.approx((0.4 * m * r * r,) * 3, rel=1e-15)
