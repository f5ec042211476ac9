"""Hard cases for mass properties, run through the whole pipeline (YAML spec -> loader ->
core), each checked against an answer worked out independently of rbi's code: closed forms,
exact rational arithmetic, symbolic integration or geometry."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from rbi.core.inertia import principal_axes, re_express
from rbi.core.rotation import axis_angle_matrix
from rbi.spec.load import load_body
from tests.conftest import run_rbi

EPS = np.finfo(float).eps


def num(x) -> str:
    """A float as YAML 1.1 reads it back exactly (with a dot and a signed exponent)."""
    return f"{float(x):.17e}"


def vec(v) -> str:
    return "[" + ", ".join(num(x) for x in v) + "]"


def principal_of(write_spec, text: str):
    body = load_body(write_spec(text))
    return body, *principal_axes(body.props.inertia_about_com)


def assert_clean_frame(axes, tol=1e-13):
    """Rows orthonormal and right-handed (det +1), to ``tol``."""
    np.testing.assert_allclose(axes @ axes.T, np.eye(3), rtol=0, atol=tol)
    assert abs(np.linalg.det(axes) - 1.0) <= tol
    np.testing.assert_allclose(np.cross(axes[0], axes[1]), axes[2], rtol=0, atol=tol)


def parallel(u, v, tol):
    return np.linalg.norm(np.cross(u, v)) <= tol and abs(np.linalg.norm(u) - 1) <= tol


# --- near-degenerate moments -------------------------------------------------------------


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("relative_bump", [1e-12, -1e-12, 3e-13])
def test_axisymmetric_body_with_a_tiny_perturbation(write_spec, seed, relative_bump):
    # A cylinder along a random axis u, plus a speck of mass on u itself at the centre of mass
    # (it changes nothing) and one just off the axis that splits the two transverse moments by
    # about `relative_bump` of their size.
    m, r, L = 2.0, 0.05, 0.4
    Q = Rotation.random(random_state=seed).as_matrix()
    u, w = Q[:, 0], Q[:, 1]
    start = np.array([0.3, -0.7, 1.1])
    end = start + L * u
    centre = 0.5 * (start + end)
    transverse = m * (3 * r * r + L * L) / 12
    speck = abs(relative_bump) * transverse / (0.1**2)
    off_axis = centre + 0.1 * (w if relative_bump > 0 else Q[:, 2])
    body, moments, axes = principal_of(
        write_spec,
        f"""
parts:
  - {{shape: cylinder, mass: {m}, radius: {r}, start: {vec(start)}, end: {vec(end)}}}
  - {{shape: point, mass: {num(speck)}, position: {vec(off_axis)}}}
""",
    )
    assert_clean_frame(axes)
    assert np.all(np.diff(moments) >= 0)
    axial = m * r * r / 2
    # The speck, 0.1 from the axis, adds speck·0.1² to the moments about u and about the
    # perpendicular it is not on (its pull on the centre of mass is of second order, ~1e-24).
    bump = speck * 0.1**2
    np.testing.assert_allclose(moments, [axial + bump, transverse, transverse + bump], rtol=1e-14)
    # The axis of the distinct (axial) moment is the cylinder's axis, whatever the split.
    assert parallel(axes[0], u, 1e-11)
    # The pair spans the plane perpendicular to u.
    assert abs(axes[1] @ u) <= 1e-11 and abs(axes[2] @ u) <= 1e-11
    # The inertia is rebuilt from the reported set to the size of the perturbation.
    I = body.props.inertia_about_com
    np.testing.assert_allclose(axes.T @ np.diag(moments) @ axes, I, rtol=0, atol=5e-12 * transverse)


# --- bodies whose three central moments are equal ---------------------------------------


def test_cone_and_cylinder_proportions_with_equal_moments_symbolically():
    # Independent of rbi: integrate over the solids with sympy and find the proportions at
    # which the axial and transverse central moments coincide.
    import sympy as sp

    r, h, rho, s, z = sp.symbols("r h rho s z", positive=True)
    # Cylinder: height h, radius r, centre at the origin, unit density.
    mass_cyl = sp.pi * r**2 * h
    axial_cyl = sp.integrate(sp.integrate(rho**2 * 2 * sp.pi * rho, (rho, 0, r)), (z, -h / 2, h / 2))
    # transverse about x through the centre: ∫ (y² + z²) dV, with ∫ y² over a disc = π R⁴ / 4
    transverse_cyl = sp.integrate(sp.pi * r**4 / 4 + z**2 * sp.pi * r**2, (z, -h / 2, h / 2))
    assert sp.simplify(axial_cyl / mass_cyl - r**2 / 2) == 0
    ratio_cyl = sp.solve(sp.Eq(axial_cyl, transverse_cyl), h)
    assert ratio_cyl == [sp.sqrt(3) * r]
    # Cone: apex at z = 0, base at z = h; slice radius R(z) = r z / h.
    R = r * z / h
    mass_cone = sp.integrate(sp.pi * R**2, (z, 0, h))
    z_com = sp.integrate(z * sp.pi * R**2, (z, 0, h)) / mass_cone
    axial_cone = sp.integrate(sp.pi * R**4 / 2, (z, 0, h))
    transverse_cone = sp.integrate(sp.pi * R**4 / 4 + (z - z_com) ** 2 * sp.pi * R**2, (z, 0, h))
    assert sp.simplify(z_com - 3 * h / 4) == 0
    assert sp.simplify(axial_cone / mass_cone - sp.Rational(3, 10) * r**2) == 0
    assert sp.simplify(transverse_cone / mass_cone - sp.Rational(3, 80) * (4 * r**2 + h**2)) == 0
    assert sp.solve(sp.Eq(axial_cone, transverse_cone), h) == [2 * r]


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("shape", ["cylinder", "cone"])
def test_equal_moments_give_a_clean_right_handed_set(write_spec, shape, seed):
    m, r = 1.3, 0.07
    u = Rotation.random(random_state=10 + seed).as_matrix()[:, 2]
    a = np.array([0.2, 0.1, -0.4])
    if shape == "cylinder":
        h = math.sqrt(3.0) * r
        spec = f"parts:\n  - {{shape: cylinder, mass: {m}, radius: {r}, start: {vec(a)}, end: {vec(a + h * u)}}}\n"
        moment = m * r * r / 2
    else:
        h = 2.0 * r
        spec = (
            f"parts:\n  - {{shape: cone, mass: {m}, radius: {r}, apex: {vec(a)}, base: {vec(a + h * u)}}}\n"
        )
        moment = 0.3 * m * r * r
    body, moments, axes = principal_of(write_spec, spec)
    np.testing.assert_allclose(moments, [moment] * 3, rtol=1e-13)
    np.testing.assert_allclose(body.props.inertia_about_com, moment * np.eye(3), rtol=0, atol=1e-13 * moment)
    # Every direction is principal: rbi must still answer with one clean right-handed set,
    # the same one every time (the coordinate axes).
    np.testing.assert_array_equal(axes, np.eye(3))


def test_equal_moments_through_the_command_line(write_spec):
    r = 0.05
    path = write_spec(
        f"parts:\n  - {{shape: cone, mass: 2.0, radius: {r}, apex: [0, 0, 0], base: [0.06, 0.0, 0.08]}}\n"
    )
    out = json.loads(run_rbi("principal", path, "--format", "json", check=True).stdout)
    axes = np.array(out["axes"])
    assert_clean_frame(axes, tol=0)
    np.testing.assert_allclose(out["moments"], [0.3 * 2.0 * r * r] * 3, rtol=1e-13)


# --- thin rod -------------------------------------------------------------------------------


@pytest.mark.parametrize("axis", [0, 1, 2])
@pytest.mark.parametrize("start", [[0.0, 0.0, 0.0], [5.0, -3.0, 2.0]])
def test_thin_rod_along_a_coordinate_axis_keeps_its_tiny_moment(write_spec, axis, start):
    m, L = 2.0, 1.0
    r = 1e-6 * L
    end = np.array(start)
    end[axis] += L
    # A second, heavier part on the same axis, so the tiny moment survives an assembly too.
    tip = np.array(start)
    tip[axis] -= 0.25
    body, moments, axes = principal_of(
        write_spec,
        f"""
parts:
  - {{shape: cylinder, mass: {m}, radius: {num(r)}, start: {vec(start)}, end: {vec(end)}}}
  - {{shape: point, mass: 0.5, position: {vec(tip)}}}
""",
    )
    tiny = m * r * r / 2
    assert abs(moments[0] - tiny) <= 1e-6 * tiny
    assert parallel(axes[0], np.eye(3)[axis], 0.0)
    assert_clean_frame(axes)


@pytest.mark.parametrize("seed", range(3))
def test_thin_rod_along_a_slanted_axis_is_as_accurate_as_a_3x3_matrix_allows(write_spec, seed):
    # Along a slanted axis the tiny moment lives in the 1e-12 of matrix entries of size ~0.1,
    # each rounded to ~1e-17: no method working from the matrix can know it better than about
    # eps·I_max/I_min ≈ 4e-5 of itself. rbi must reach that bound (the 1e-6 holds for
    # rods along coordinate axes, above).
    m, L = 2.0, 1.0
    r = 1e-6 * L
    u = Rotation.random(random_state=seed).as_matrix()[:, 0]
    body, moments, axes = principal_of(
        write_spec,
        f"""
parts:
  - {{shape: cylinder, mass: {m}, radius: {num(r)}, start: [0.1, 0.2, 0.3], end: {vec(np.array([0.1, 0.2, 0.3]) + L * u)}}}
""",
    )
    tiny = m * r * r / 2
    transverse = m * (3 * r * r + L * L) / 12
    assert abs(moments[0] - tiny) <= 4 * EPS * transverse
    assert parallel(axes[0], u, 1e-14)
    np.testing.assert_allclose(moments[1:], [transverse, transverse], rtol=1e-14)
    assert_clean_frame(axes)


# --- small parts far from the origin -------------------------------------------------------


def small_body(origin) -> str:
    # Dyadic sizes and offsets (multiples of 2⁻¹⁰ m ≈ 1 mm): every coordinate is exact in
    # binary even 1e6 m from the origin, so the far body is exactly the near one, moved.
    d = 2.0**-10
    o = np.asarray(origin, dtype=float)
    return f"""
parts:
  - {{shape: cylinder, mass: 0.003, radius: {num(d / 2)}, start: {vec(o)}, end: {vec(o + [d, 0, 0])}}}
  - {{shape: cone, mass: 0.001, radius: {num(d / 4)}, apex: {vec(o + [0, d, 0])}, base: {vec(o + [0, d, d])}}}
  - {{shape: point, mass: 0.0005, position: {vec(o + [-d, -d, 2 * d])}}}
"""


@pytest.mark.parametrize("origin", [[1e6, 0.0, 0.0], [1e6, -1e6, 5e5], [-1e6, 1e6, -1e6]])
def test_millimetre_parts_a_thousand_kilometres_away(write_spec, origin):
    near = load_body(write_spec(small_body([0.0, 0.0, 0.0]), "near.yaml")).props
    far = load_body(write_spec(small_body(origin), "far.yaml")).props
    assert far.mass == near.mass
    # The centre of mass is known to the spacing of doubles at 1e6 m (1.2e-10 m) ...
    np.testing.assert_allclose(far.center_of_mass - origin, near.center_of_mass, rtol=0, atol=2.5e-10)
    # ... and the inertia about it keeps nearly all its digits: an error δ in the reference
    # point changes the inertia only by m δ² (parallel-axis theorem).
    np.testing.assert_allclose(
        far.inertia_about_com,
        near.inertia_about_com,
        rtol=0,
        atol=1e-9 * np.max(np.abs(near.inertia_about_com)),
    )
    moments_far, axes_far = principal_axes(far.inertia_about_com)
    moments_near, axes_near = principal_axes(near.inertia_about_com)
    np.testing.assert_allclose(moments_far, moments_near, rtol=1e-9)
    np.testing.assert_allclose(axes_far, axes_near, rtol=0, atol=1e-7)


# --- a speck on a heavy rotor ----------------------------------------------------------------


def rotor_with_bolt_exact(m_rotor, r, half_length, m_bolt, bolt):
    """Mass, CoM and central inertia in exact rational arithmetic (the cylinder's central
    moments m r²/2 and m (3 r² + L²)/12; parallel-axis shifts written out by hand)."""
    F = Fraction
    mr, rr, hl, mb = F(m_rotor), F(r), F(half_length), F(m_bolt)
    b = [F(x) for x in bolt]
    M = mr + mb
    com = [mb * x / M for x in b]  # the rotor's centre is at the origin
    L = 2 * hl
    I = [[F(0)] * 3 for _ in range(3)]
    I[0][0] = I[1][1] = mr * (3 * rr * rr + L * L) / 12
    I[2][2] = mr * rr * rr / 2
    for mass, p in ((mr, [F(0)] * 3), (mb, b)):
        d = [p[k] - com[k] for k in range(3)]
        dd = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                I[i][j] += mass * ((dd if i == j else 0) - d[i] * d[j])
    return M, com, I


def test_microgram_bolt_on_a_tonne_rotor(write_spec):
    m_rotor, r, half, m_bolt = 1000.0, 0.5, 0.1, 1e-6
    bolt = [0.5, 0.0, 0.1]
    body, moments, axes = principal_of(
        write_spec,
        f"""
parts:
  - {{name: rotor, shape: cylinder, mass: {m_rotor}, radius: {r}, start: [0, 0, {-half}], end: [0, 0, {half}]}}
  - {{name: bolt, shape: point, mass: {num(m_bolt)}, position: {vec(bolt)}}}
""",
    )
    M, com, I = rotor_with_bolt_exact(m_rotor, r, half, m_bolt, bolt)
    props = body.props
    assert props.mass == pytest.approx(float(M), rel=1e-15)
    # The bolt moves the centre of mass by 5e-10 m: rbi must get that shift to 1e-12 of itself.
    np.testing.assert_allclose(props.center_of_mass, [float(x) for x in com], rtol=1e-12, atol=0)
    exact = np.array([[float(x) for x in row] for row in I])
    # The bolt's product of inertia (5e-8 kg·m², 4e-10 of the largest moment) to 1e-9 of itself.
    assert props.inertia_about_com[0, 2] == pytest.approx(exact[0, 2], rel=1e-9)
    np.testing.assert_allclose(props.inertia_about_com, exact, rtol=1e-15, atol=0)
    # The spin axis tilts from z towards x by ½·atan2(2 I_xz, I_zz − I_xx) ≈ −8.5e-10 rad.
    tilt = 0.5 * math.atan2(2 * float(I[0][2]), float(I[2][2] - I[0][0]))
    spin_axis = axes[2]
    measured = math.atan2(spin_axis[0], spin_axis[2])  # from z towards x
    assert measured == pytest.approx(tilt, rel=1e-6)
    assert_clean_frame(axes)


# --- rotations -------------------------------------------------------------------------------


def test_a_chain_of_turns_and_its_reverse_through_the_command_line(bodies):
    there = ["x:37", "z:-120", "y:200", "x:0.001"]
    back = ["x:-0.001", "y:-200", "z:120", "x:-37"]
    args = [a for turn in there + back for a in ("--rotate", turn)]
    plain = json.loads(run_rbi("inertia", bodies / "top_bolted.yaml", "--format", "json", check=True).stdout)
    round_trip = json.loads(
        run_rbi("inertia", bodies / "top_bolted.yaml", "--format", "json", *args, check=True).stdout
    )
    I = np.array(plain["inertia"])
    np.testing.assert_allclose(round_trip["inertia"], I, rtol=0, atol=1e-14 * np.max(np.abs(I)))
    # One way only: the world-axes inertia of scipy's rotation (an independent implementation).
    one_way = json.loads(
        run_rbi(
            "inertia",
            bodies / "top_bolted.yaml",
            "--format",
            "json",
            *[a for t in there for a in ("--rotate", t)],
            check=True,
        ).stdout
    )
    turns = [Rotation.from_euler(t[0], float(t[2:]), degrees=True) for t in there]
    R = (turns[3] * turns[2] * turns[1] * turns[0]).as_matrix()  # p * q applies q first
    np.testing.assert_allclose(one_way["inertia"], R @ I @ R.T, rtol=0, atol=1e-14 * np.max(np.abs(I)))


def test_ten_thousand_small_turns_make_one_full_turn():
    I = np.array([[3.0, 0.4, -0.2], [0.4, 2.0, 0.1], [-0.2, 0.1, 1.5]])
    R = axis_angle_matrix([1.0, -2.0, 0.5], 2 * math.pi / 10_000)
    J = I.copy()
    for _ in range(10_000):
        J = re_express(J, R)
    # Each turn may scale by 1 ± a few eps (R itself is orthogonal only to rounding): after
    # 10⁴ turns the error stays within 10⁴·eps, with no growth beyond that.
    bound = 10_000 * EPS
    np.testing.assert_allclose(J, I, rtol=0, atol=bound * np.max(np.abs(I)))
    np.testing.assert_allclose(np.linalg.eigvalsh(J), np.linalg.eigvalsh(I), rtol=bound)


# --- point masses only -----------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(3))
def test_collinear_point_masses_have_a_zero_moment_along_their_line(write_spec, seed):
    u = Rotation.random(random_state=30 + seed).as_matrix()[:, 1]
    p0 = np.array([1.0, 2.0, -0.5])
    masses, offsets = [1.0, 2.0, 0.5], [-0.3, 0.1, 0.7]
    parts = "\n".join(
        f"  - {{shape: point, mass: {m}, position: {vec(p0 + s * u)}}}" for m, s in zip(masses, offsets)
    )
    body, moments, axes = principal_of(write_spec, "parts:\n" + parts + "\n")
    M = sum(masses)
    s_com = sum(m * s for m, s in zip(masses, offsets)) / M
    expected = sum(m * (s - s_com) ** 2 for m, s in zip(masses, offsets))  # Σ m s² about the CoM
    np.testing.assert_allclose(body.props.center_of_mass, p0 + s_com * u, rtol=0, atol=1e-15 * 4)
    assert abs(moments[0]) <= 10 * EPS * expected  # rank deficient: zero up to rounding
    np.testing.assert_allclose(moments[1:], [expected, expected], rtol=1e-14)
    assert parallel(axes[0], u, 1e-13)
    assert_clean_frame(axes)


def test_a_single_point_mass_has_no_inertia_and_still_a_clean_frame(write_spec):
    body, moments, axes = principal_of(
        write_spec, "parts:\n  - {shape: point, mass: 3.0, position: [1000000.0, -2.5, 7]}\n"
    )
    np.testing.assert_array_equal(body.props.center_of_mass, [1e6, -2.5, 7])
    np.testing.assert_array_equal(body.props.inertia_about_com, np.zeros((3, 3)))
    np.testing.assert_array_equal(moments, np.zeros(3))
    np.testing.assert_array_equal(axes, np.eye(3))


def test_flat_cloud_of_point_masses_obeys_the_perpendicular_axis_theorem(write_spec):
    rng = np.random.default_rng(4)
    Q = Rotation.random(random_state=4).as_matrix()
    normal = Q[:, 2]
    pts = rng.normal(size=(7, 2)) @ Q[:, :2].T + [0.5, 0.5, 0.5]
    parts = "\n".join(
        f"  - {{shape: point, mass: {num(m)}, position: {vec(p)}}}"
        for m, p in zip(rng.uniform(0.5, 2, 7), pts)
    )
    body, moments, axes = principal_of(write_spec, "parts:\n" + parts + "\n")
    # Plane lamina: the moment about the normal is the sum of the two in-plane ones.
    assert moments[2] == pytest.approx(moments[0] + moments[1], rel=1e-13)
    assert parallel(axes[2], normal, 1e-12)
    assert_clean_frame(axes)
