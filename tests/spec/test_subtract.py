"""Holes (`subtract: true`): against textbook formulas typed in here, the precision left in
thin walls made by subtraction, and bodies that stop being physical."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.spec.errors import InputError
from rbi.spec.load import load_body

EPS = np.finfo(float).eps


def shaft_minus_bore(write_spec, R: float, r: float, L: float, rho: float = 7.85):
    return load_body(
        write_spec(f"""
units: {{length: cm, mass: g}}
parts:
  - {{name: shaft, shape: cylinder, density: {rho!r}, radius: {R!r}, start: [0, 0, 0], end: [0, 0, {L!r}]}}
  - {{name: bore, shape: cylinder, density: {rho!r}, radius: {r!r}, start: [0, 0, 0], end: [0, 0, {L!r}], subtract: true}}
""")
    )


def hollow_cylinder_textbook(R: float, r: float, L: float, rho: float = 7.85):
    """m = ρ π (R² − r²) L, Izz = m (R² + r²)/2, Ixx = m (3 (R² + r²) + L²)/12 about the CoM."""
    m = rho * math.pi * (R - r) * (R + r) * L
    return m, m * (R * R + r * r) / 2, m * (3 * (R * R + r * r) + L * L) / 12


def test_bored_shaft_is_the_hollow_cylinder(write_spec):
    b = shaft_minus_bore(write_spec, 2.0, 1.5, 10.0)
    m, axial, transverse = hollow_cylinder_textbook(2.0, 1.5, 10.0)
    assert b.props.mass == pytest.approx(m, rel=1e-14)
    np.testing.assert_allclose(b.props.center_of_mass, [0, 0, 5.0], rtol=1e-15)
    np.testing.assert_allclose(
        np.diag(b.props.inertia_about_com), [transverse, transverse, axial], rtol=1e-14
    )


@pytest.mark.parametrize("wall", [1e-1, 1e-3, 1e-6, 1e-9])
def test_thin_wall_by_subtraction_loses_about_eps_times_radius_over_wall(write_spec, wall):
    """Cancellation: both cylinders are ~R/(2t) times heavier than the wall, so the relative
    error of the difference is of order ε·R/t. docs/spec.md quotes the measured values."""
    R, L = 1.0, 2.0
    b = shaft_minus_bore(write_spec, R, R - wall, L)
    m, axial, transverse = hollow_cylinder_textbook(R, R - wall, L)
    bound = 8 * EPS * R / wall
    assert b.props.mass == pytest.approx(m, rel=bound)
    assert b.props.inertia_about_com[2, 2] == pytest.approx(axial, rel=bound)
    assert b.props.inertia_about_com[0, 0] == pytest.approx(transverse, rel=bound)


def test_the_tube_shape_keeps_full_precision_where_subtraction_cannot(write_spec):
    R, wall, L = 1.0, 1e-9, 2.0
    b = load_body(
        write_spec(f"""
parts:
  - {{shape: tube, density: 7.85, outer_radius: {R!r}, inner_radius: {R - wall!r}, start: [0, 0, 0], end: [0, 0, {L!r}]}}
""")
    )
    m, axial, _ = hollow_cylinder_textbook(R, R - wall, L)
    assert b.props.mass == pytest.approx(m, rel=4 * EPS)
    assert b.props.inertia_about_com[2, 2] == pytest.approx(axial, rel=4 * EPS)


def test_wheel_with_four_lightening_holes(write_spec):
    R, t, r, d, rho = 100.0, 10.0, 15.0, 55.0, 0.0027  # mm, g/mm³
    holes = "".join(
        f"""
  - {{name: hole{i}, shape: cylinder, density: {rho}, radius: {r}, start: [{x}, {y}, 0], end: [{x}, {y}, {t}], subtract: true}}"""
        for i, (x, y) in enumerate([(d, 0), (-d, 0), (0, d), (0, -d)])
    )
    b = load_body(
        write_spec(f"""
units: {{length: mm, mass: g}}
parts:
  - {{name: disc, shape: cylinder, density: {rho}, radius: {R}, start: [0, 0, 0], end: [0, 0, {t}]}}{holes}
""")
    )
    M = rho * math.pi * R * R * t
    m = rho * math.pi * r * r * t
    izz = M * R * R / 2 - 4 * (m * r * r / 2 + m * d * d)
    # About x: the holes on the y axis sit d away, those on the x axis on it: 2 m d² in all.
    ixx = M * (3 * R * R + t * t) / 12 - (4 * m * (3 * r * r + t * t) / 12 + 2 * m * d * d)
    assert b.props.mass == pytest.approx(M - 4 * m, rel=1e-14)
    np.testing.assert_allclose(b.props.center_of_mass, [0, 0, t / 2], atol=1e-12)
    np.testing.assert_allclose(
        b.props.inertia_about_com, np.diag([ixx, ixx, izz]), rtol=1e-13, atol=1e-9 * izz
    )


def test_one_hole_moves_the_centre_of_mass_away_from_it(write_spec):
    b = load_body(
        write_spec("""
parts:
  - {shape: box, density: steel, center: [0, 0, 0], size: [0.2, 0.1, 0.01]}
  - {shape: cylinder, density: steel, radius: 0.02, start: [0.05, 0, -0.005], end: [0.05, 0, 0.005], subtract: true}
""")
    )
    M, m = 7850 * 0.2 * 0.1 * 0.01, 7850 * math.pi * 0.02**2 * 0.01
    np.testing.assert_allclose(b.props.center_of_mass, [-m * 0.05 / (M - m), 0, 0], rtol=1e-13, atol=1e-18)


def _error(write_spec, text: str) -> str:
    with pytest.raises(InputError) as info:
        load_body(write_spec(text))
    return str(info.value)


def test_a_hole_bigger_than_the_body_is_refused_naming_it(write_spec):
    message = _error(
        write_spec,
        """
units: {length: mm, mass: g}
parts:
  - {name: shaft, shape: cylinder, density: steel, radius: 5, start: [0, 0, 0], end: [0, 0, 50]}
  - {name: bore, shape: cylinder, density: steel, radius: 6, start: [0, 0, 0], end: [0, 0, 50], subtract: true}
""",
    )
    assert "body.yaml: parts[1] (bore): subtract: no mass left" in message
    assert " g (a hole" in message


def test_an_identical_hole_leaves_nothing(write_spec):
    message = _error(
        write_spec,
        """
parts:
  - {name: a, shape: sphere, density: 1000, radius: 0.1, center: [0, 0, 0]}
  - {name: b, shape: sphere, density: 1000, radius: 0.1, center: [0, 0, 0], subtract: true}
""",
    )
    assert "parts[1] (b): subtract: no mass left" in message


def test_a_hole_outside_the_material_makes_the_inertia_unphysical(write_spec):
    # Half the mass "removed" 1 m away from a small ball: positive mass is left, but no mass
    # distribution has that inertia.
    message = _error(
        write_spec,
        """
parts:
  - {name: ball, shape: sphere, mass: 1, radius: 0.1, center: [0, 0, 0]}
  - {name: fine, shape: sphere, mass: 0.01, radius: 0.01, center: [0, 0, 0.05], subtract: true}
  - {name: stray, shape: sphere, mass: 0.5, radius: 0.05, center: [1, 0, 0], subtract: true}
""",
    )
    assert "parts[2] (stray): subtract: the body's inertia" in message
    assert "not positive definite" in message or "triangle inequality" in message


def test_only_solids_with_volume_can_be_holes(write_spec):
    message = _error(
        write_spec,
        "parts:\n  - {name: w, shape: rod, mass: 1, start: [0, 0, 0], end: [1, 0, 0], subtract: true}\n",
    )
    assert "parts[0] (w): subtract: only solids with a volume" in message
