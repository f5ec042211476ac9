"""rbi.import_robot and rbi.audit(out=...): what `rbi import` and `rbi audit --fix --out` do, from
Python, checked against the closed forms of the arm's cylinder and box."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES

ARM = BODIES / "two_link_arm.urdf"

PLACEHOLDER_MJCF = """<mujoco model="m">
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/><geom type="box" size="0.1 0.05 0.025"/>
    </body>
  </worldbody>
</mujoco>
"""


def cylinder_along_x(m, r, length):
    """A solid cylinder's inertia about its centre, axis along x."""
    across = m * (3 * r**2 + length**2) / 12
    return np.diag([m * r**2 / 2, across, across])


def box(m, a, b, c):
    """A solid box's inertia about its centre, edges a, b, c along x, y, z."""
    return np.diag([m * (b**2 + c**2), m * (a**2 + c**2), m * (a**2 + b**2)]) / 12


def test_import_robot_gives_each_link_in_link_axes():
    robot = rbi.import_robot(ARM)
    assert (robot.format, robot.name, robot.link_word) == ("urdf", "two_link_arm", "link")
    assert [link.name for link in robot.links] == ["upper_arm", "forearm"]
    assert robot.skipped == [("link[0] (base_link)", "no <inertial> element")]
    upper, fore = robot.links
    assert upper.mass == 1.2 and fore.mass == 0.8
    np.testing.assert_allclose(upper.center_of_mass, [0.15, 0, 0], atol=1e-15)
    np.testing.assert_allclose(upper.inertia, cylinder_along_x(1.2, 0.03, 0.3), atol=1e-6)
    np.testing.assert_allclose(fore.inertia, box(0.8, 0.25, 0.04, 0.04), rtol=1e-12, atol=1e-18)
    # pitch = 90°: a turn of 90° about y
    half = math.sqrt(0.5)
    np.testing.assert_allclose(upper.inertial_quaternion, [half, 0, half, 0], atol=1e-15)
    assert upper.problems == [] and fore.problems == []


def test_each_link_spec_and_the_whole_robot_load_back():
    robot = rbi.import_robot(ARM, links=["forearm"])
    (fore,) = robot.links
    body = rbi.loads(fore.yaml)
    assert body.mass == pytest.approx(0.8)
    np.testing.assert_allclose(body.inertia(), box(0.8, 0.25, 0.04, 0.04), rtol=1e-12, atol=1e-18)
    whole = rbi.loads(robot.robot_yaml())
    assert whole.mass == pytest.approx(2.0)
    # (1.2 kg × 0.15 m + 0.8 kg × (0.3 + 0.125) m) / 2 kg
    assert whole.center_of_mass[0] == pytest.approx((1.2 * 0.15 + 0.8 * 0.425) / 2.0, rel=1e-12)


def test_import_robot_names_its_links_parameter():
    with pytest.raises(ValueError, match=r"^links: .*has no link named 'forarm' .*did you mean 'forearm'"):
        rbi.import_robot(ARM, links=["forarm"])


def test_audit_out_writes_the_fixed_copy_with_the_boxs_inertia(tmp_path):
    robot = tmp_path / "m.xml"
    robot.write_text(PLACEHOLDER_MJCF)
    fixed = tmp_path / "fixed.xml"
    report = rbi.audit(robot, fix=True, out=fixed)
    assert [c.link for c in report.fix.changes] and fixed.read_bytes() == report.fix.content
    (arm,) = rbi.audit(fixed).links
    np.testing.assert_allclose(arm.declared.inertia_about_com, box(2.0, 0.2, 0.1, 0.05), rtol=1e-6)
    assert robot.read_text() == PLACEHOLDER_MJCF  # the original is untouched


def test_audit_out_needs_fix_and_never_replaces_the_robot_file(tmp_path):
    robot = tmp_path / "m.xml"
    robot.write_text(PLACEHOLDER_MJCF)
    with pytest.raises(ValueError, match=r"^out: writes the fixed copy, so it needs fix=True$"):
        rbi.audit(robot, out=tmp_path / "fixed.xml")
    with pytest.raises(rbi.SpecError, match="rbi never overwrites its input"):
        rbi.audit(robot, fix=True, out=robot)
    assert robot.read_text() == PLACEHOLDER_MJCF
