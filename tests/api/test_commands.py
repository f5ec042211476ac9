"""What the commands compute, through the public API: `Body.in_units`, `moment_about_axis`,
`dynamics` (rbi dynamics), `check` (rbi check), `inertial_xml` (rbi export), `rbi.validate`,
`rbi.spec_schema` and `rbi.unit_vector`, against closed forms."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES

SPHERE = "parts: [{name: ball, shape: sphere, radius: 0.1, mass: 2, center: [0, 0, 0]}]"
M, R = 2.0, 0.1

ROD = """
name: rod
pivot: [0, 0, 0]
parts:
  - {name: bar, shape: cylinder, mass: 2.0, radius: 0.05, start: [0, 0, 0], end: [0, 0, 0.4]}
"""
ROD_M, ROD_R, ROD_L = 2.0, 0.05, 0.4


def test_in_units_scales_mass_lengths_inertia_and_volumes():
    ball = rbi.loads(SPHERE)
    small = ball.in_units("mm", "g")
    assert small.units == {"length": "mm", "mass": "g"}
    assert small.mass == pytest.approx(2000.0, rel=1e-15)
    # 2/5 m r² = 0.008 kg·m² = 0.008 * 1e3 g * 1e6 mm²/m²
    assert small.inertia()[0, 0] == pytest.approx(0.4 * 2000.0 * 100.0**2, rel=1e-14)
    (part,) = small.parts()
    assert part.volume == pytest.approx(4 / 3 * math.pi * 100.0**3, rel=1e-14)
    assert ball.mass == 2.0  # the original is unchanged
    with pytest.raises(rbi.ArgumentError, match="^length: expected one of"):
        ball.in_units("furlong", "g")


def test_mass_properties_is_the_one_value_type():
    props = rbi.loads(ROD).mass_properties
    assert isinstance(props, rbi.MassProperties)
    assert props.mass == ROD_M and props.center_of_mass.tolist() == [0.0, 0.0, ROD_L / 2]
    across = ROD_M * (3 * ROD_R**2 + ROD_L**2) / 12
    np.testing.assert_allclose(
        np.diag(props.inertia_about_com), [across, across, ROD_M * ROD_R**2 / 2], rtol=1e-14
    )


def test_moment_about_an_axis_through_a_point():
    rod = rbi.loads(ROD)
    end_across = ROD_M * (ROD_R**2 / 4 + ROD_L**2 / 3)
    assert rod.moment_about_axis([1, 0, 0], "pivot") == pytest.approx(end_across, rel=1e-13)
    assert rod.moment_about_axis([0, 0, 5], "pivot") == pytest.approx(ROD_M * ROD_R**2 / 2, rel=1e-13)
    # turned 90° about y, the rod's axis lies along world x
    turned = rod.moment_about_axis([1, 0, 0], "pivot", axes=[("y", 90.0)])
    assert turned == pytest.approx(ROD_M * ROD_R**2 / 2, rel=1e-12)
    with pytest.raises(rbi.ArgumentError, match="^axis: must be a non-zero"):
        rod.moment_about_axis([0, 0, 0])


def test_unit_vector_of_any_size():
    np.testing.assert_allclose(rbi.unit_vector([3.0, 0.0, 4.0]), [0.6, 0.0, 0.8], rtol=1e-15)
    assert rbi.unit_vector([1e-300, 0.0, 0.0]).tolist() == [1.0, 0.0, 0.0]
    assert rbi.unit_vector([1e300, 1e300, 0.0]) == pytest.approx([math.sqrt(0.5), math.sqrt(0.5), 0.0])
    with pytest.raises(ValueError, match="^direction:"):
        rbi.unit_vector([0.0, 0.0, 0.0])


def test_inverse_dynamics_about_the_centre_of_mass():
    ball = rbi.loads(SPHERE)
    found = ball.dynamics([0, 0, 0], alpha=[0, 0, 10.0], point_acceleration=[1.0, 0, 0])
    assert isinstance(found, rbi.Dynamics) and found.mode == "inverse" and not found.held
    np.testing.assert_allclose(found.torque, [0, 0, 0.4 * M * R**2 * 10.0], rtol=1e-14)
    np.testing.assert_allclose(found.force, [M * 1.0, 0, 0], rtol=1e-15)  # F = m a


def test_forward_dynamics_of_a_held_point_finds_the_holding_force():
    rod = rbi.loads(ROD)
    torque = 0.3
    found = rod.dynamics([0, 0, 0], about="pivot", torque=[torque, 0, 0])
    assert found.mode == "forward" and found.held
    alpha = torque / (ROD_M * (ROD_R**2 / 4 + ROD_L**2 / 3))  # τ = I_end α about x
    np.testing.assert_allclose(found.alpha, [alpha, 0, 0], rtol=1e-12, atol=1e-15)
    # the centre of mass at (0, 0, L/2) accelerates at α × r = (0, −α L/2, 0): F = m a_c
    np.testing.assert_allclose(found.force, [0, -ROD_M * alpha * ROD_L / 2, 0], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(found.point_acceleration, [0, 0, 0])


def test_forward_dynamics_about_the_centre_of_mass_and_the_spin_term():
    ball = rbi.loads(SPHERE)
    found = ball.dynamics([0, 0, 3.0], force=[0, 4.0, 0], torque=[0, 0, 0.02])
    np.testing.assert_allclose(found.point_acceleration, [0, 4.0 / M, 0], rtol=1e-15)
    np.testing.assert_allclose(found.alpha, [0, 0, 0.02 / (0.4 * M * R**2)], rtol=1e-13, atol=1e-15)
    with pytest.raises(ValueError, match="give either alpha"):
        ball.dynamics([0, 0, 0])


CHECKED = """
name: checked
units: {length: mm, mass: g}
parts:
  - {shape: sphere, radius: 100, mass: 2000, center: [0, 0, 0]}
expect:
  mass: {value: 2010, tol: 1%}
  center_of_mass: {value: [0, 0, 0.5], tol: 0.1}
  moments: {value: [8.0e6, 8.0e6, 8.0e6], tol: 1}
"""


def test_check_compares_each_expectation_with_its_tolerance():
    checks = rbi.loads(CHECKED).check()
    assert [c.quantity for c in checks] == ["mass", "center_of_mass", "moments"]
    mass, com, moments = checks
    assert isinstance(mass, rbi.Check)
    assert mass.deviation == pytest.approx(10.0) and mass.allowed == pytest.approx(20.1) and mass.passed
    assert com.deviation == pytest.approx(0.5) and com.allowed == 0.1 and not com.passed
    assert moments.about == "com" and moments.unit == "g·mm²"
    np.testing.assert_allclose(moments.actual, [0.4 * 2000 * 100.0**2] * 3, rtol=1e-13)
    assert moments.passed
    # a body in other units is still checked in the spec's own
    assert [c.passed for c in rbi.loads(CHECKED).in_units("m", "kg").check()] == [True, False, True]
    with pytest.raises(rbi.SpecError, match="no `expect:` block"):
        rbi.loads(SPHERE).check()


def test_inertial_xml_is_in_si_whatever_the_spec_units():
    body = rbi.loads(CHECKED)
    text = body.inertial_xml("urdf", document=True)
    comment, xml = text.split("\n", 1)
    assert comment.startswith("<!-- rbi export of <string>: SI units") and "spec units were mm, g" in comment
    robot = ET.fromstring(xml)
    assert robot.tag == "robot" and robot.get("name") == "checked"
    inertial = robot.find("link/inertial")
    assert float(inertial.find("mass").get("value")) == pytest.approx(2.0, rel=1e-15)
    assert float(inertial.find("inertia").get("ixx")) == pytest.approx(0.4 * 2.0 * 0.1**2, rel=1e-13)
    assert float(inertial.find("inertia").get("ixy")) == 0.0
    mjcf = ET.fromstring(body.inertial_xml("mjcf", diagonal=True).split("\n", 1)[1])
    assert [float(v) for v in mjcf.get("diaginertia").split()] == pytest.approx([0.008] * 3, rel=1e-13)
    with pytest.raises(rbi.ArgumentError, match="^diagonal: only for to='mjcf'"):
        body.inertial_xml("urdf", diagonal=True)
    with pytest.raises(rbi.ArgumentError, match="^to: expected one of urdf, mjcf, sdf"):
        body.inertial_xml("step")


def test_validate_lists_each_files_problems(tmp_path):
    good, bad = tmp_path / "good.yaml", tmp_path / "bad.yaml"
    good.write_text(SPHERE)
    bad.write_text(SPHERE.replace("radius: 0.1", "radius: -0.1"))
    assert rbi.validate([good, bad, good]) == [
        [],
        [f"{bad}: parts[0] (ball): radius: must be greater than 0 (got -0.1)"],
        [],
    ]
    assert rbi.validate(str(good)) == [[]]
    with pytest.raises(rbi.SpecError, match="give NAME=DIR"):
        rbi.validate([good], package_paths=["nothing"])


def test_spec_schema_describes_the_spec():
    schema = rbi.spec_schema()
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert schema["title"] == "rbi body spec"
    assert {"parts", "units", "pivot", "expect"} <= set(schema["properties"])


def test_parts_give_their_principal_moments_and_inertia_shares():
    two = rbi.loads(
        "parts: [{name: a, shape: sphere, radius: 0.1, mass: 1, center: [-1, 0, 0]},"
        " {name: b, shape: sphere, radius: 0.1, mass: 3, center: [1, 0, 0]}]"
    )
    a, b = two.parts()
    own = 0.4 * 0.1**2
    np.testing.assert_allclose(a.principal_moments, [own] * 3, rtol=1e-13)
    # CoM at x = 0.5: a lies 1.5 away, b 0.5; trace about the CoM: 3 I_own + 2 m d²
    trace_a, trace_b = 3 * own + 2 * 1 * 1.5**2, 3 * 3 * own + 2 * 3 * 0.5**2
    assert a.inertia_share == pytest.approx(trace_a / (trace_a + trace_b), rel=1e-13)
    assert a.inertia_share + b.inertia_share == pytest.approx(1.0, rel=1e-15)
    assert a.integration_error is None


def test_the_cli_helpers_are_public():
    assert rbi.visible("bolt\u202e\n") == "bolt\\u202e\\n"
    assert issubclass(rbi.ArgumentError, ValueError) and issubclass(rbi.ArgumentError, rbi.SpecError)
    with rbi.outside_paths_allowed():
        assert rbi.loads(SPHERE).mass == 2.0


def test_a_holes_volume_is_negative_as_its_mass():
    # Part.volume was the hole's solid volume (+6107.26 mm³ for each drilling of the wheel)
    # while Part.mass was negative; `rbi parts` now prints both negative in every form, and the
    # API gives what the command prints: the parts' volumes add up to the body's
    wheel = rbi.load(str(BODIES / "wheel_with_holes.yaml"))
    parts = wheel.parts()
    hole = next(p for p in parts if p.name == "hole-1")
    assert hole.volume == pytest.approx(hole.mass / 0.0027, rel=1e-12) and hole.volume < 0  # aluminium, g/mm³
    solids = sum(p.volume for p in parts)
    assert solids == pytest.approx(wheel.mass / 0.0027, rel=1e-12)
