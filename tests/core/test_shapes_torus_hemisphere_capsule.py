"""Torus, hemisphere and capsule closed forms against numerical quadrature of their solids
(scipy), their limiting shapes, and the capsule against MuJoCo's own inertia."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from rbi.core import shapes
from rbi.core.mass import MassProperties

# quadpack flags the square-root edges of these sections (infinite slope) as roundoff; the
# comparisons below still hold to 1e-9 or better.
pytestmark = pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")


def axisymmetric_quadrature(z_low, z_high, rho_low, rho_high):
    """Volume, centroid height, and the axial and transverse moments about the centroid (unit
    density) of the solid of revolution about z whose section at height z runs from radius
    rho_low(z) to rho_high(z). Transverse: ∫ (ρ²/2 + (z − z̄)²) dV, the φ-average of y² + z²."""
    opts = dict(epsabs=0, epsrel=1e-11)

    def integral(f):
        return integrate.dblquad(
            lambda rho, z: 2 * math.pi * rho * f(rho, z), z_low, z_high, rho_low, rho_high, **opts
        )[0]

    volume = integral(lambda rho, z: 1.0)
    z_bar = integral(lambda rho, z: z) / volume
    axial = integral(lambda rho, z: rho * rho)
    transverse = integral(lambda rho, z: 0.5 * rho * rho + (z - z_bar) ** 2)
    return volume, z_bar, axial, transverse


def axial_and_transverse(element, axis):
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    perpendicular = np.cross(u, [1.0, 0, 0] if abs(u[0]) < 0.9 else [0, 1.0, 0])
    perpendicular /= np.linalg.norm(perpendicular)
    I = element.inertia_about_com
    return u @ I @ u, perpendicular @ I @ perpendicular


@pytest.mark.parametrize("R, a", [(1.0, 0.25), (0.3, 0.3), (2.0, 0.01)])
def test_torus_against_quadrature(R, a):
    volume, z_bar, axial, transverse = axisymmetric_quadrature(
        -a,
        a,
        lambda z: R - math.sqrt(max(a * a - z * z, 0.0)),
        lambda z: R + math.sqrt(max(a * a - z * z, 0.0)),
    )
    assert shapes.torus_volume(R, a) == pytest.approx(volume, rel=1e-10)
    assert z_bar == pytest.approx(0.0, abs=1e-12)
    element = shapes.torus(volume, R, a, [1.0, 2.0, 3.0], [0, 0, 1])
    np.testing.assert_allclose(
        np.diag(element.inertia_about_com), [transverse, transverse, axial], rtol=1e-10
    )
    np.testing.assert_array_equal(element.center_of_mass, [1.0, 2.0, 3.0])


def test_torus_on_a_slanted_axis_keeps_its_moments():
    axis = [1.0, -2.0, 0.5]
    element = shapes.torus(3.0, 1.0, 0.2, [0, 0, 0], axis)
    axial, transverse = axial_and_transverse(element, axis)
    assert axial == pytest.approx(3.0 * (1 + 0.75 * 0.04), rel=1e-14)
    assert transverse == pytest.approx(3.0 * (0.5 + 0.625 * 0.04), rel=1e-14)


def test_thin_torus_is_a_ring():
    # a → 0: all mass at R, axial m R², diameter m R²/2
    element = shapes.torus(2.0, 1.5, 1e-9, [0, 0, 0], [0, 0, 1])
    np.testing.assert_allclose(np.diag(element.inertia_about_com), [2.25, 2.25, 4.5], rtol=1e-15)


@pytest.mark.parametrize("r", [1.0, 0.037])
def test_hemisphere_against_quadrature(r):
    volume, z_bar, axial, transverse = axisymmetric_quadrature(
        0, r, lambda z: 0.0, lambda z: math.sqrt(max(r * r - z * z, 0.0))
    )
    assert shapes.hemisphere_volume(r) == pytest.approx(volume, rel=1e-10)
    element = shapes.hemisphere(volume, r, [0, 0, 0], [0, 0, 5])
    assert element.center_of_mass[2] == pytest.approx(z_bar, rel=1e-10)
    np.testing.assert_allclose(
        np.diag(element.inertia_about_com), [transverse, transverse, axial], rtol=1e-10
    )


def test_two_hemispheres_make_a_sphere():
    m, r = 3.0, 0.4
    up = shapes.hemisphere(m / 2, r, [0, 0, 0], [0, 0, 1])
    down = shapes.hemisphere(m / 2, r, [0, 0, 0], [0, 0, -1])

    whole = MassProperties.sum([up, down])
    np.testing.assert_allclose(whole.center_of_mass, 0, atol=1e-16)
    np.testing.assert_allclose(whole.inertia_about_com, 0.4 * m * r * r * np.eye(3), rtol=1e-14, atol=1e-16)


@pytest.mark.parametrize("r, L", [(0.1, 0.6), (1.0, 0.05), (0.02, 3.0)])
def test_capsule_against_quadrature(r, L):
    half = 0.5 * L

    def outer(z):
        beyond = abs(z) - half
        return r if beyond <= 0 else math.sqrt(max(r * r - beyond * beyond, 0.0))

    volume, z_bar, axial, transverse = axisymmetric_quadrature(-half - r, half + r, lambda z: 0.0, outer)
    assert shapes.capsule_volume(r, L) == pytest.approx(volume, rel=1e-9)
    element = shapes.capsule(volume, r, [0, 0, -half], [0, 0, half])
    assert z_bar == pytest.approx(0.0, abs=1e-10 * (L + r))
    np.testing.assert_allclose(np.diag(element.inertia_about_com), [transverse, transverse, axial], rtol=1e-9)


def test_short_capsule_tends_to_a_sphere():
    element = shapes.capsule(2.0, 0.5, [0, 0, 0], [0, 0, 1e-12])
    np.testing.assert_allclose(element.inertia_about_com, 0.4 * 2.0 * 0.25 * np.eye(3), rtol=1e-11)


@pytest.mark.parametrize("radius, half_length", [(0.1, 0.3), (0.05, 0.01), (0.2, 1.5)])
def test_capsule_matches_mujoco(radius, half_length):
    mujoco = pytest.importorskip("mujoco", reason="MuJoCo is not installed (pip install mujoco)")
    density = 1000.0
    xml = (
        f'<mujoco><worldbody><body><geom type="capsule" size="{radius!r} {half_length!r}" '
        f'density="{density!r}"/></body></worldbody></mujoco>'
    )
    model = mujoco.MjModel.from_xml_string(xml)
    mass = density * shapes.capsule_volume(radius, 2 * half_length)
    assert model.body_mass[1] == pytest.approx(mass, rel=1e-12)
    element = shapes.capsule(mass, radius, [0, 0, -half_length], [0, 0, half_length])
    np.testing.assert_allclose(
        np.sort(np.diag(element.inertia_about_com)), np.sort(model.body_inertia[1]), rtol=1e-12
    )
