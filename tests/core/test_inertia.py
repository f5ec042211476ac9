"""Assembly, reference-point shifts, re-expression and principal axes, each checked against
an independent answer: direct sums over point masses, exact rational arithmetic, known
eigen-decompositions built by hand."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from rbi.core.inertia import parallel_axis, parallel_axis_to_com, principal_axes, re_express, symmetric_eigen
from rbi.core.mass import MassProperties, combine
from tests.core import built


def direct_inertia(masses, positions, point):
    """Σ m (|r|² E − r rᵀ) with r measured from ``point``, one mass at a time."""
    total = np.zeros((3, 3))
    for m, p in zip(masses, positions):
        r = np.asarray(p, dtype=float) - np.asarray(point, dtype=float)
        total += m * (np.dot(r, r) * np.eye(3) - np.outer(r, r))
    return total


def point_cloud(seed: int, count: int = 7):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.1, 2.0, size=count), rng.uniform(-1.0, 1.0, size=(count, 3))


def assert_matrix_close(actual, expected, rel):
    np.testing.assert_allclose(actual, expected, rtol=rel, atol=rel * np.max(np.abs(expected)))


# --- assembling parts ------------------------------------------------------------------------


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_point_masses_match_direct_sums(seed):
    masses, positions = point_cloud(seed)
    props = combine(masses, positions)
    com = sum(m * p for m, p in zip(masses, positions)) / sum(masses)
    assert props.mass == pytest.approx(sum(masses), rel=1e-15)
    np.testing.assert_allclose(props.center_of_mass, com, rtol=0, atol=1e-15)
    assert_matrix_close(props.inertia_about_com, direct_inertia(masses, positions, com), rel=1e-13)


@pytest.mark.parametrize("seed", [4, 5])
def test_inertia_about_any_point_matches_direct_sum(seed):
    masses, positions = point_cloud(seed)
    props = combine(masses, positions)
    for point in ([0.0, 0.0, 0.0], [1.5, -2.0, 0.25], props.center_of_mass + 1e-3):
        assert_matrix_close(props.inertia_about(point), direct_inertia(masses, positions, point), rel=1e-13)


def test_inertia_about_the_com_is_the_central_inertia():
    masses, positions = point_cloud(6)
    props = combine(masses, positions)
    assert_matrix_close(props.inertia_about(props.center_of_mass), props.inertia_about_com, rel=1e-15)


def test_parallel_axis_round_trip_and_direction_of_offset():
    masses, positions = point_cloud(7)
    props = combine(masses, positions)
    offset = np.array([0.3, -1.1, 2.0])
    shifted = parallel_axis(props.inertia_about_com, props.mass, offset)
    # Moving away from the CoM adds m(|d|²E − d dᵀ): a positive semi-definite change.
    assert np.linalg.eigvalsh(shifted - props.inertia_about_com).min() >= -1e-14
    assert_matrix_close(parallel_axis(props.inertia_about_com, props.mass, -offset), shifted, rel=1e-15)
    assert_matrix_close(parallel_axis_to_com(shifted, props.mass, offset), props.inertia_about_com, rel=1e-13)


def test_parts_enter_with_their_own_inertia_plus_transport():
    # A cylinder plus a point: the body about its CoM equals each part's own inertia plus
    # m(|d|²E − d dᵀ), worked here from the closed form independently of combine().
    cyl = built.cylinder(2.0, 0.1, [0.0, 0.0, 0.0], [0.0, 0.0, 0.4])
    bolt = built.point(0.5, [0.1, 0.0, 0.4])
    props = MassProperties.sum([cyl, bolt])
    com = (2.0 * np.array([0.0, 0.0, 0.2]) + 0.5 * np.array([0.1, 0.0, 0.4])) / 2.5
    own = np.diag([2.0 * (3 * 0.01 + 0.16) / 12, 2.0 * (3 * 0.01 + 0.16) / 12, 2.0 * 0.01 / 2])
    expected = own + direct_inertia([2.0, 0.5], [[0.0, 0.0, 0.2], [0.1, 0.0, 0.4]], com)
    np.testing.assert_allclose(props.center_of_mass, com, rtol=1e-15, atol=1e-17)
    assert_matrix_close(props.inertia_about_com, expected, rel=1e-14)


def test_combined_inertia_is_exactly_symmetric():
    masses, positions = point_cloud(8)
    props = combine(masses, positions)
    np.testing.assert_array_equal(props.inertia_about_com, props.inertia_about_com.T)


def test_total_mass_must_be_positive():
    with pytest.raises(ValueError):
        combine(np.array([1.0, -1.0]), np.zeros((2, 3)))


# --- accuracy far from the origin ------------------------------------------------------------

# A rotor with dyadic dimensions, so that every coordinate stays exactly representable when
# the whole rotor is moved 1 km or 1000 km away: the input is then the same body, exactly.
ROTOR_POINTS = [
    (Fraction(3, 64), (Fraction(1, 8), Fraction(0), Fraction(1, 32))),
    (Fraction(5, 128), (Fraction(0), Fraction(-1, 8), Fraction(-1, 16))),
    (Fraction(1, 32), (Fraction(-3, 32), Fraction(1, 16), Fraction(0))),
]
DISC = (Fraction(2), Fraction(1, 8), Fraction(-1, 32), Fraction(1, 32))  # mass, radius, z0, z1
HUB = (Fraction(1, 4), Fraction(1, 16), Fraction(1, 32), Fraction(5, 32))  # mass, radius, apex z, base z


def rotor_elements(origin):
    o = np.asarray(origin, dtype=float)
    m, r, z0, z1 = map(float, DISC)
    parts = [built.cylinder(m, r, o + [0.0, 0.0, z0], o + [0.0, 0.0, z1])]
    m, r, za, zb = map(float, HUB)
    parts.append(built.cone(m, r, o + [0.0, 0.0, za], o + [0.0, 0.0, zb]))
    parts += [built.point(float(pm), o + np.array(p, dtype=float)) for pm, p in ROTOR_POINTS]
    return parts


def rotor_exact():
    """Mass, CoM and central inertia of the rotor at the origin, in exact rationals."""
    m_d, r_d, z0, z1 = DISC
    m_h, r_h, za, zb = HUB
    L, h = z1 - z0, zb - za
    items = [
        (m_d, (0, 0, (z0 + z1) / 2), (m_d * (3 * r_d**2 + L**2) / 12, m_d * r_d**2 / 2)),
        (m_h, (0, 0, za + 3 * h / 4), (3 * m_h * (4 * r_h**2 + h**2) / 80, 3 * m_h * r_h**2 / 10)),
    ]
    items += [(pm, p, (0, 0)) for pm, p in ROTOR_POINTS]
    mass = sum(m for m, _, _ in items)
    com = [sum(m * Fraction(p[k]) for m, p, _ in items) / mass for k in range(3)]
    inertia = [[Fraction(0)] * 3 for _ in range(3)]
    for m, p, (transverse, axial) in items:
        d = [Fraction(p[k]) - com[k] for k in range(3)]
        dd = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                inertia[i][j] += m * ((dd if i == j else 0) - d[i] * d[j])
            inertia[i][i] += axial if i == 2 else transverse
    return float(mass), np.array(com, dtype=float), np.array(inertia, dtype=float)


def test_rotor_at_the_origin_matches_exact_rational_answer():
    mass, com, inertia = rotor_exact()
    props = MassProperties.sum(rotor_elements([0.0, 0.0, 0.0]))
    assert props.mass == pytest.approx(mass, rel=1e-15)
    np.testing.assert_allclose(props.center_of_mass, com, rtol=1e-14, atol=1e-17)
    assert_matrix_close(props.inertia_about_com, inertia, rel=1e-13)


@pytest.mark.parametrize(
    "origin", [[1000.0, 0.0, 0.0], [-700.0, 1000.0, 250.0], [1e6, 0.0, 0.0], [1e6, -1e6, 5e5]]
)
def test_rotor_far_from_the_origin_keeps_its_central_inertia(origin):
    mass, com, inertia = rotor_exact()
    far = MassProperties.sum(rotor_elements(origin))
    expected_com = np.asarray(origin) + com  # exact sum: both are short dyadic numbers
    assert far.mass == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(far.center_of_mass, expected_com, rtol=1e-12, atol=0)
    assert_matrix_close(far.inertia_about_com, inertia, rel=1e-9)


# --- re-expression --------------------------------------------------------------------------


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_re_express_is_r_i_rt_and_keeps_eigenvalues(seed):
    masses, positions = point_cloud(seed)
    I = combine(masses, positions).inertia_about_com
    R = Rotation.random(random_state=seed).as_matrix()
    # Rotating every mass by R and summing directly gives the world-axes inertia.
    world_positions = positions @ R.T
    com_world = sum(m * p for m, p in zip(masses, world_positions)) / sum(masses)
    expected = direct_inertia(masses, world_positions, com_world)
    turned = re_express(I, R)
    assert_matrix_close(turned, expected, rel=1e-12)
    np.testing.assert_allclose(np.linalg.eigvalsh(turned), np.linalg.eigvalsh(I), rtol=1e-12)


# --- principal axes -------------------------------------------------------------------------


def assert_right_handed_orthonormal(axes, tol=1e-12):
    np.testing.assert_allclose(axes @ axes.T, np.eye(3), rtol=0, atol=tol)
    assert np.linalg.det(axes) == pytest.approx(1.0, abs=tol)


def assert_reconstructs(moments, axes, matrix, rel=1e-12):
    # axes[i] is the i-th eigenvector, so A = axesᵀ diag(moments) axes.
    assert_matrix_close(axes.T @ np.diag(moments) @ axes, matrix, rel=rel)


def same_up_to_sign(u, v, tol):
    return min(np.max(np.abs(u - v)), np.max(np.abs(u + v))) <= tol


@pytest.mark.parametrize("seed", range(6))
def test_distinct_moments_are_found_with_their_axes(seed):
    Q = Rotation.random(random_state=seed).as_matrix()
    known = np.array([0.7, 1.9, 2.3])
    A = Q @ np.diag(known) @ Q.T
    moments, axes = principal_axes(A)
    np.testing.assert_allclose(moments, known, rtol=1e-13)
    assert_right_handed_orthonormal(axes)
    for i in range(3):
        assert same_up_to_sign(axes[i], Q[:, i], 1e-12)
        # Each axis really is an eigenvector: A a = λ a.
        np.testing.assert_allclose(A @ axes[i], moments[i] * axes[i], atol=1e-13)
    assert_reconstructs(moments, axes, A)


def test_principal_axes_agree_with_lapack():
    rng = np.random.default_rng(3)
    for _ in range(20):
        B = rng.normal(size=(3, 3))
        A = B @ B.T
        moments, axes = principal_axes(A)
        np.testing.assert_allclose(moments, np.linalg.eigvalsh(A), rtol=1e-12, atol=1e-14 * np.abs(A).max())
        assert np.all(np.diff(moments) >= 0)
        assert_right_handed_orthonormal(axes)
        assert_reconstructs(moments, axes, A)


def test_symmetric_eigen_columns_are_eigenvectors():
    rng = np.random.default_rng(9)
    B = rng.normal(size=(3, 3))
    A = B + B.T
    values, vectors = symmetric_eigen(A)
    np.testing.assert_allclose(values, np.linalg.eigvalsh(A), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(A @ vectors, vectors * values, atol=1e-13)


def test_same_answer_twice_and_under_tiny_perturbations():
    Q = Rotation.random(random_state=21).as_matrix()
    A = Q @ np.diag([1.0, 2.0, 3.5]) @ Q.T
    moments, axes = principal_axes(A)
    again = principal_axes(A.copy())
    np.testing.assert_array_equal(again[0], moments)
    np.testing.assert_array_equal(again[1], axes)
    rng = np.random.default_rng(0)
    for _ in range(10):
        E = rng.normal(size=(3, 3)) * 1e-13
        m2, a2 = principal_axes(A + E + E.T)
        # No sign flips and no reordering: the axes move by about the perturbation only.
        np.testing.assert_allclose(a2, axes, atol=1e-11)
        np.testing.assert_allclose(m2, moments, atol=1e-11)


def test_plane_symmetric_body_gets_exact_zeros():
    # The chapter's bolted top: symmetric about the xz plane, so y is exactly a principal axis.
    elements = [
        built.cone(0.4, 0.04, [0, 0, 0], [0, 0, 0.06]),
        built.cylinder(0.1, 0.008, [0, 0, 0.06], [0, 0, 0.10]),
        built.point(0.02, [0.04, 0, 0.06]),
    ]
    moments, axes = principal_axes(MassProperties.sum(elements).inertia_about_com)
    assert_right_handed_orthonormal(axes)
    y_rows = [i for i in range(3) if abs(axes[i, 1]) == 1.0]
    assert len(y_rows) == 1
    assert all(axes[i, 1] == 0.0 for i in range(3) if i != y_rows[0])


@pytest.mark.parametrize("seed", range(5))
def test_coaxial_stack_along_any_axis_gives_a_clean_set(seed):
    Q = Rotation.random(random_state=100 + seed).as_matrix()
    u = Q[:, 2]
    o = np.array([0.3, -0.2, 1.0])
    stack = [
        built.cone(0.4, 0.04, o, o + 0.06 * u),
        built.cylinder(0.1, 0.008, o + 0.06 * u, o + 0.10 * u),
        built.cylinder(0.05, 0.02, o - 0.03 * u, o),
    ]
    I = MassProperties.sum(stack).inertia_about_com
    moments, axes = principal_axes(I)
    assert_right_handed_orthonormal(axes)
    assert_reconstructs(moments, axes, I, rel=1e-12)
    # Which end of the spectrum holds the equal pair depends on the stack's proportions.
    lone = 0 if moments[2] - moments[1] < moments[1] - moments[0] else 2
    assert same_up_to_sign(axes[lone], u, 1e-12)
    # Stable: a second call and a rounding-sized nudge give the same set.
    np.testing.assert_array_equal(principal_axes(I)[1], axes)
    nudged = I * (1 + 1e-15 * np.array([[1, -2, 3], [-2, 1, 2], [3, 2, -1]]))
    np.testing.assert_allclose(principal_axes(nudged)[1], axes, atol=1e-10)


@pytest.mark.parametrize(
    "diagonal, lone", [([1.0, 1.0, 2.0], 2), ([2.0, 5.0, 5.0], 0), ([3.0, 3.0 * (1 + 1e-12), 7.0], 2)]
)
def test_equal_moments_in_body_axes_give_coordinate_axes(diagonal, lone):
    moments, axes = principal_axes(np.diag(diagonal))
    np.testing.assert_allclose(moments, sorted(diagonal), rtol=1e-15)
    assert_right_handed_orthonormal(axes, tol=0)
    assert set(map(tuple, np.abs(axes))) == {(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)}


def test_all_equal_moments_give_the_coordinate_axes():
    Q = Rotation.random(random_state=5).as_matrix()
    A = Q @ (4.0 * np.eye(3)) @ Q.T  # a sphere-like body, with rounding noise off the diagonal
    moments, axes = principal_axes(A)
    np.testing.assert_allclose(moments, [4.0, 4.0, 4.0], rtol=1e-14)
    np.testing.assert_array_equal(axes, np.eye(3))


def test_nearly_equal_moments_still_give_orthonormal_axes():
    Q = Rotation.random(random_state=8).as_matrix()
    for gap in (1e-6, 1e-8, 1e-10, 1e-13):
        A = Q @ np.diag([1.0, 1.0 + gap, 3.0]) @ Q.T
        moments, axes = principal_axes(A)
        assert_right_handed_orthonormal(axes)
        assert same_up_to_sign(axes[2], Q[:, 2], 1e-12)
        # Below DEGENERATE_RTOL (1e-9 of the largest moment) the pair counts as equal and gets
        # canonical axes, so the reconstruction is off by at most the gap itself.
        assert_reconstructs(moments, axes, A, rel=1e-12 if gap > 3e-9 else 1e-9)


def test_zero_and_rank_deficient_inertia():
    moments, axes = principal_axes(np.zeros((3, 3)))
    np.testing.assert_array_equal(moments, [0.0, 0.0, 0.0])
    assert_right_handed_orthonormal(axes, tol=0)
    # Two point masses on a line along (1, 1, 1): zero moment about that line.
    d = np.array([1.0, 1.0, 1.0]) / np.sqrt(3.0)
    props = combine([1.0, 1.0], [d, -d])
    moments, axes = principal_axes(props.inertia_about_com)
    np.testing.assert_allclose(moments, [0.0, 2.0, 2.0], atol=1e-15)
    assert same_up_to_sign(axes[0], d, 1e-15)
    assert_right_handed_orthonormal(axes)


def test_principal_axes_about_a_point_of_a_mass_properties_tuple():
    props = MassProperties(2.0, np.array([0.0, 0.0, 1.0]), np.diag([1.0, 1.0, 0.5]))
    I_origin = props.inertia_about([0.0, 0.0, 0.0])
    np.testing.assert_allclose(I_origin, np.diag([3.0, 3.0, 0.5]), rtol=1e-15)
    moments, axes = principal_axes(I_origin)
    np.testing.assert_allclose(moments, [0.5, 3.0, 3.0], rtol=1e-15)
    assert same_up_to_sign(axes[0], np.array([0.0, 0.0, 1.0]), 0)
