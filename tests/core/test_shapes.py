"""Each primitive against sympy integration over its volume (uniform density, own frame),
then placed along arbitrary axes and compared with ``Q I Qᵀ`` for a random rotation Q."""

from __future__ import annotations

import math
from functools import cache

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbi.core import shapes
from tests.core import built

rho, phi, z = sp.symbols("rho phi z", real=True)
a_sym, h_sym = sp.symbols("a h", positive=True)


def _solid_of_revolution(radius_at_z, height):
    """Volume, CoM height and the 3×3 inertia per unit density about the CoM of the solid
    0 ≤ z ≤ height, ρ ≤ radius_at_z, integrated symbolically in cylindrical coordinates."""

    def integrate(f):
        return sp.integrate(f * rho, (rho, 0, radius_at_z), (phi, 0, 2 * sp.pi), (z, 0, height))

    volume = sp.simplify(integrate(sp.Integer(1)))
    z_com = sp.simplify(integrate(z) / volume)
    r = sp.Matrix([rho * sp.cos(phi), rho * sp.sin(phi), z - z_com])
    second = r * r.T
    inertia = sp.Matrix(3, 3, lambda i, j: (r.dot(r) if i == j else 0) - second[i, j])
    inertia = inertia.applyfunc(lambda f: sp.simplify(integrate(sp.expand(f))))
    return volume, z_com, inertia


@cache
def cone_integrals():
    """Apex at the origin, base disc of radius a at z = h."""
    volume, z_com, inertia = _solid_of_revolution(a_sym * z / h_sym, h_sym)
    return sp.lambdify((a_sym, h_sym), [volume, z_com, inertia.tolist()], "math")


@cache
def cylinder_integrals():
    """End faces at z = 0 and z = h, radius a."""
    volume, z_com, inertia = _solid_of_revolution(a_sym, h_sym)
    return sp.lambdify((a_sym, h_sym), [volume, z_com, inertia.tolist()], "math")


def expected_from_integrals(integrals, mass, radius, height):
    volume, z_com, inertia_per_density = integrals(radius, height)
    return volume, z_com, (mass / volume) * np.array(inertia_per_density, dtype=float)


def assert_inertia_close(actual, expected, rel=1e-12):
    scale = np.max(np.abs(expected))
    np.testing.assert_allclose(actual, expected, rtol=rel, atol=rel * scale)


DIMENSIONS = [(0.04, 0.06), (1.0, 1.0), (0.3, 7.0), (5.0, 0.01), (2e-3, 3e-1)]


SOLIDS = {
    # name: (closed-form volume, builder from the two axis end points, sympy integrals)
    "cone": (shapes.cone_volume, built.cone, cone_integrals),
    "cylinder": (shapes.cylinder_volume, built.cylinder, cylinder_integrals),
}


@pytest.mark.parametrize("solid", SOLIDS)
@pytest.mark.parametrize("radius, height", DIMENSIONS)
def test_solid_along_z_matches_the_volume_integral(solid, radius, height):
    volume_of, build, integrals = SOLIDS[solid]
    mass = 0.37
    volume, z_com, inertia = expected_from_integrals(integrals(), mass, radius, height)
    assert volume_of(radius, height) == pytest.approx(volume, rel=1e-14)
    element = build(mass, radius, [0.0, 0.0, 0.0], [0.0, 0.0, height])
    assert element.mass == mass
    np.testing.assert_allclose(element.center_of_mass, [0.0, 0.0, z_com], rtol=1e-14, atol=0)
    assert_inertia_close(element.inertia_about_com, inertia)


def test_cone_integral_sanity_against_textbook_closed_forms():
    # Guards the sympy set-up itself: V = πa²h/3, centroid 3h/4 from the apex, I_axis = 3/10 m a².
    volume, z_com, inertia = expected_from_integrals(cone_integrals(), 1.0, 2.0, 3.0)
    assert volume == pytest.approx(math.pi * 4.0 * 3.0 / 3.0, rel=1e-14)
    assert z_com == pytest.approx(2.25, rel=1e-14)
    assert inertia[2, 2] == pytest.approx(0.3 * 4.0, rel=1e-14)


def random_placements(count: int, seed: int):
    rng = np.random.default_rng(seed)
    rotations = Rotation.random(count, random_state=seed).as_matrix()
    for Q in rotations:
        yield Q, rng.uniform(-3.0, 3.0, size=3)


@pytest.mark.parametrize("solid", SOLIDS)
@pytest.mark.parametrize("Q, origin", list(random_placements(6, seed=11)))
def test_solid_along_any_axis_is_the_rotated_integral(solid, Q, origin):
    _, build, integrals = SOLIDS[solid]
    mass, radius, height = 1.3, 0.2, 0.45
    _, z_com, inertia = expected_from_integrals(integrals(), mass, radius, height)
    element = build(mass, radius, origin, origin + Q @ [0.0, 0.0, height])
    np.testing.assert_allclose(element.center_of_mass, origin + Q @ [0.0, 0.0, z_com], rtol=0, atol=1e-14)
    assert_inertia_close(element.inertia_about_com, Q @ inertia @ Q.T, rel=1e-13)


def test_reversed_cylinder_is_the_same_solid():
    forward = built.cylinder(1.0, 0.1, [1.0, 2.0, 3.0], [1.5, 1.0, 3.2])
    backward = built.cylinder(1.0, 0.1, [1.5, 1.0, 3.2], [1.0, 2.0, 3.0])
    np.testing.assert_allclose(forward.center_of_mass, backward.center_of_mass, rtol=0, atol=1e-15)
    assert_inertia_close(forward.inertia_about_com, backward.inertia_about_com, rel=1e-14)


def test_thin_rod_along_x_keeps_its_tiny_axial_moment():
    # m r²/2 with r = 1e-6 next to transverse moments ~ m L²/12 = 1/12: 11 orders apart.
    element = built.cylinder(1.0, 1e-6, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    assert element.inertia_about_com[0, 0] == pytest.approx(0.5e-12, rel=1e-12)
    assert element.inertia_about_com[1, 1] == pytest.approx((3e-12 + 1.0) / 12.0, rel=1e-14)


def test_point_mass_sits_at_its_position_with_no_own_inertia():
    element = built.point(0.02, [0.04, 0.0, 0.06])
    assert element.mass == 0.02
    np.testing.assert_array_equal(element.center_of_mass, [0.04, 0.0, 0.06])
    np.testing.assert_array_equal(element.inertia_about_com, np.zeros((3, 3)))


DENSITY_SPEC = """
parts:
  - name: cone
    shape: cone
    density: 7800.0
    radius: 0.05
    apex: [0.1, -0.2, 0.3]
    base: [0.1, 0.1, 0.7]
  - name: rod
    shape: cylinder
    density: 2700.0
    radius: 0.01
    start: [0.0, 0.0, 0.0]
    end: [0.3, 0.0, 0.4]
"""


def test_density_gives_mass_equal_to_density_times_integrated_volume(write_spec):
    from rbi.spec.load import load_body

    body = load_body(write_spec(DENSITY_SPEC))
    cone_volume = cone_integrals()(0.05, 0.5)[0]  # height |(0, 0.3, 0.4)| = 0.5
    rod_volume = cylinder_integrals()(0.01, 0.5)[0]
    cone_mass, rod_mass = 7800.0 * cone_volume, 2700.0 * rod_volume
    assert body.elements[0].mass == pytest.approx(cone_mass, rel=1e-13)
    assert body.elements[1].mass == pytest.approx(rod_mass, rel=1e-13)
    assert body.props.mass == pytest.approx(cone_mass + rod_mass, rel=1e-13)


@given(
    st.one_of(
        st.floats(min_value=-1e70, max_value=1e70),  # x⁴ a number
        st.complex_numbers(max_magnitude=1e70, allow_nan=False, allow_infinity=False),
    ),
    st.integers(min_value=1, max_value=4),
)
def test_power_is_pythons_power_wherever_that_is_a_number(x, exponent):
    """The closed forms' powers are Python's, bit for bit, for real and complex-step inputs
    alike (numpy's power may round apart)."""
    got, expected = shapes.power(x, exponent), x**exponent
    assert got == expected and type(got) is type(expected)


@pytest.mark.parametrize("x, exponent", [(1e110, 3), (1e80, 4), (complex(1e110, 1e-20), 3)])
def test_power_that_leaves_a_double_is_inf_as_numpys(x, exponent):
    """Python raises OverflowError for 1e110 ** 3 where numpy's float64 gives inf; the closed
    forms give inf, so callers refuse the part by their one finiteness check."""
    assert shapes.power(x, exponent) == math.inf
    with np.errstate(over="ignore"):
        assert np.isinf(np.power(np.float64(abs(x)), exponent, dtype=float))
    assert shapes.sphere_volume(1e110) == math.inf and shapes.hemisphere_volume(1e110) == math.inf
