"""A subnormal number (non-zero, below 2.2e-308, the smallest double with all its digits) as a
mass, size or density is refused with one line, exit 2: computed with, its moments lose their
digits (a 5e-320 kg ball of radius 0.1 m printed I = 2.03e-322 where 2/5 m r² = 2.00e-322, and
a radius of gyration 0.0637 m where it is 0.0632) or vanish to 0 (the audit then said
"declared moments ... are -, -, - ×"). The smallest normal mass still computes exactly."""

from __future__ import annotations

import math

import pytest

import rbi
from tests.conftest import one_line_exit_2, run_rbi_inprocess

BALL = {"name": "ball", "shape": "sphere", "radius": 0.1, "center": [0, 0, 0]}


def _write(tmp_path, text, name="body.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "fields, bad",
    [
        ("radius: 0.1, mass: 5e-320", "mass"),
        ("radius: 0.1, density: 5e-320", "density"),
        ("radius: 4e-310, mass: 1", "radius"),
    ],
)
@pytest.mark.parametrize("command", ["inertia", "principal", "check"])
@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_subnormal_number_in_a_spec_is_one_line_exit_2(tmp_path, fields, bad, command, form):
    part = "{name: ball, shape: sphere, center: [0, 0, 0], " + fields + "}"
    expect = "\nexpect:\n  mass: {value: 1, tol: 1%}\n" if command == "check" else "\n"
    path = _write(tmp_path, f"parts:\n  - {part}{expect}")
    proc = run_rbi_inprocess(command, str(path), "--format", form)
    one_line_exit_2(proc, "body.yaml", "parts[0] (ball)", f"{bad}: ", "is subnormal")
    assert proc.stdout == ""


def test_the_api_refuses_a_subnormal_mass_as_a_spec_error():
    with pytest.raises(rbi.SpecError, match=r"parts\[0\] \(ball\): mass: 5e-320 is subnormal"):
        rbi.load({"parts": [{**BALL, "mass": 5e-320}]})


def test_the_smallest_normal_mass_computes_the_closed_form():
    mass = 2.2250738585072014e-308
    body = rbi.load({"parts": [{**BALL, "mass": mass}]})
    assert body.mass == mass
    moment = 2 / 5 * mass * 0.1**2  # solid sphere about a diameter
    assert body.principal().moments == pytest.approx([moment] * 3, rel=1e-12)
    assert math.sqrt(2 / 5) * 0.1 == pytest.approx(math.sqrt(body.principal().moments[0] / mass), rel=1e-12)


URDF = """<robot name="r">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="arm"><inertial><mass value="5e-320"/>
    <inertia ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.001 0.001 0.001"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_subnormal_mass_in_a_robot_file_is_one_line_exit_2(tmp_path, form):
    path = _write(tmp_path, URDF, "arm.urdf")
    proc = run_rbi_inprocess("audit", str(path), "--format", form)
    one_line_exit_2(proc, "arm.urdf", "link[1] (arm)", "mass", "5e-320 is subnormal")
    assert "-, -, -" not in proc.stdout + proc.stderr
