"""Quaternions in robot files (MJCF ``quat``, SDF ``quat_xyzw`` poses): the rotation is
rbi.core.rotation's, normalised once there, whatever the quaternion's size."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbi.core.rotation import quaternion_to_matrix, without_rounding_noise
from rbi.errors import InputError
from rbi.formats.robot import Where
from tests.conftest import run_rbi_inprocess


def test_a_files_quaternion_is_cores_rotation_bit_for_bit():
    # The reader once scaled and normalised the quaternion itself before core normalised it
    # again: 9,308 of 30,005 matrices came out up to 5 eps apart from core's own.
    rng = np.random.default_rng(3)
    quaternions = np.concatenate(
        (
            rng.normal(size=(2000, 4)),
            rng.normal(size=(500, 4)) * 10.0 ** rng.uniform(-300, 300, size=(500, 1)),
        )
    )
    for q in quaternions:
        expected = without_rounding_noise(quaternion_to_matrix(q))
        assert np.array_equal(Where("m.xml").quaternion_matrix(q, "quat"), expected)


@pytest.mark.parametrize("scale", [1e-300, 1.0, 1e300])
def test_a_quaternion_of_any_size_is_its_turn(scale):
    half = math.radians(15.0)  # a turn of 30 degrees about z, w x y z
    R = Where("m.xml").quaternion_matrix([scale * math.cos(half), 0.0, 0.0, scale * math.sin(half)], "quat")
    c, s = math.cos(math.radians(30.0)), math.sin(math.radians(30.0))
    np.testing.assert_allclose(R, [[c, -s, 0], [s, c, 0], [0, 0, 1]], rtol=0, atol=4e-16)
    with pytest.raises(InputError) as refused:
        Where("m.xml", "body[1] (arm)").quaternion_matrix([0.0, 0.0, 0.0, 0.0], "quat")
    assert str(refused.value) == "m.xml: body[1] (arm): quat: the quaternion must not be zero"


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_body_turned_by_a_zero_quaternion_is_refused_in_one_line(tmp_path, form):
    path = tmp_path / "m.xml"
    path.write_text(
        '<mujoco model="m"><worldbody><body name="arm" quat="0 0 0 0">'
        '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></worldbody></mujoco>'
    )
    proc = run_rbi_inprocess("audit", path, "--format", form)
    assert (proc.returncode, proc.stdout) == (2, "")
    assert proc.stderr == f"rbi: {path}: body[0] (arm): quat: the quaternion must not be zero\n"
