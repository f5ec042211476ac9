"""Rotation helpers against matrices written out by hand and against scipy's Rotation."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from rbi.core.rotation import (
    axis_angle_matrix,
    compose_world_rotations,
    elementary_rotation,
    matrix_to_quaternion,
    quaternion_from_axis_angle,
    quaternion_multiply,
    quaternion_to_matrix,
    rotate,
    rotate_into_body,
    skew,
    up_in_body,
    z_axis_in_world,
)


def hand_rotation(axis: str, t: float) -> np.ndarray:
    c, s = math.cos(t), math.sin(t)
    return {
        "x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


def scipy_quaternion(R) -> np.ndarray:
    x, y, z, w = Rotation.from_matrix(R).as_quat()  # scipy's default order is scalar last
    q = np.array([w, x, y, z])
    return q if q[0] >= 0 else -q


@pytest.mark.parametrize("axis", "xyz")
@pytest.mark.parametrize("degrees", [30.0, -75.0, 90.0, 180.0, 271.0])
def test_elementary_rotation_is_the_right_hand_rule(axis, degrees):
    t = math.radians(degrees)
    np.testing.assert_allclose(elementary_rotation(axis, t), hand_rotation(axis, t), rtol=0, atol=1e-15)
    unit = np.eye(3)["xyz".index(axis)]
    np.testing.assert_allclose(axis_angle_matrix(unit, t), hand_rotation(axis, t), rtol=0, atol=1e-15)


def test_elementary_rotation_leaves_its_axis_exactly_alone():
    R = elementary_rotation("y", math.radians(30.0))
    np.testing.assert_array_equal(R[1], [0.0, 1.0, 0.0])
    np.testing.assert_array_equal(R[:, 1], [0.0, 1.0, 0.0])


def test_positive_turn_about_z_takes_x_to_y():
    np.testing.assert_allclose(
        elementary_rotation("z", math.pi / 2) @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-16
    )


def test_axis_angle_matches_scipy_rotvec():
    rng = np.random.default_rng(4)
    for _ in range(10):
        axis = rng.normal(size=3)
        angle = rng.uniform(-4.0, 4.0)
        expected = Rotation.from_rotvec(angle * axis / np.linalg.norm(axis)).as_matrix()
        np.testing.assert_allclose(axis_angle_matrix(3.7 * axis, angle), expected, atol=1e-14)


def test_world_rotations_apply_in_the_order_given():
    quarter = math.pi / 2
    # Body y turned +90° about world x lands on world z; a further +90° about world z keeps it.
    R = compose_world_rotations([("x", quarter), ("z", quarter)])
    np.testing.assert_allclose(R @ [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], atol=1e-15)
    # The other order: y -> -x under z, then -x stays under x.
    R = compose_world_rotations([("z", quarter), ("x", quarter)])
    np.testing.assert_allclose(R @ [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], atol=1e-15)


def test_world_rotations_are_the_product_r_n_to_r_1():
    turns = [("x", 0.3), ("y", -1.1), ("z", 2.0), ("y", 0.4)]
    expected = np.eye(3)
    for axis, t in turns:
        expected = hand_rotation(axis, t) @ expected
    np.testing.assert_allclose(compose_world_rotations(turns), expected, atol=1e-15)
    # Same thing in scipy's words: extrinsic (world-axis) rotations in sequence.
    scipy_R = (Rotation.from_euler("y", 0.4) * Rotation.from_euler("xyz", [0.3, -1.1, 2.0])).as_matrix()
    np.testing.assert_allclose(compose_world_rotations(turns), scipy_R, atol=1e-14)
    np.testing.assert_array_equal(compose_world_rotations([]), np.eye(3))


def test_skew_is_the_cross_product():
    a, b = np.array([0.3, -1.2, 2.0]), np.array([-0.7, 0.1, 0.9])
    np.testing.assert_allclose(skew(a) @ b, np.cross(a, b), rtol=1e-15)
    np.testing.assert_array_equal(skew(a), -skew(a).T)


@pytest.mark.parametrize("seed", range(8))
def test_quaternion_to_matrix_matches_scipy_scalar_first(seed):
    x, y, z, w = Rotation.random(random_state=seed).as_quat()
    q = np.array([w, x, y, z])
    expected = Rotation.from_quat([x, y, z, w]).as_matrix()
    np.testing.assert_allclose(quaternion_to_matrix(q), expected, atol=1e-15)
    np.testing.assert_allclose(quaternion_to_matrix(2.5 * q), expected, atol=1e-15)  # normalised first
    np.testing.assert_allclose(matrix_to_quaternion(expected), q if w >= 0 else -q, atol=1e-15)


@pytest.mark.parametrize("angle", [0.0, 1e-9, 0.5, math.pi / 2, math.pi - 1e-7, math.pi])
@pytest.mark.parametrize("axis", [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, -2.0, 0.5]])
def test_quaternion_matrix_round_trip_including_near_half_turns(angle, axis):
    R = axis_angle_matrix(axis, angle)
    q = matrix_to_quaternion(R)
    assert q[0] >= 0 and np.linalg.norm(q) == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_allclose(quaternion_to_matrix(q), R, atol=2e-15)
    expected = scipy_quaternion(R)
    if abs(expected[0]) < 1e-12:  # a half turn: q and −q are the same rotation
        assert min(np.abs(q - expected).max(), np.abs(q + expected).max()) < 1e-14
    else:
        np.testing.assert_allclose(q, expected, atol=1e-14)


def test_stacks_of_quaternions_rotate_like_scipy():
    rng = np.random.default_rng(7)
    q = rng.normal(size=(2, 25, 4))  # any size: normalised first
    scipy = Rotation.from_quat(q.reshape(-1, 4)[:, [1, 2, 3, 0]])  # scipy wants scalar last
    v = rng.normal(size=3)
    np.testing.assert_allclose(quaternion_to_matrix(q).reshape(-1, 3, 3), scipy.as_matrix(), atol=1e-15)
    np.testing.assert_allclose(rotate(q, v).reshape(-1, 3), scipy.apply(v), atol=1e-14)
    vs = rng.normal(size=(2, 25, 3))
    np.testing.assert_allclose(rotate(q, vs).reshape(-1, 3), scipy.apply(vs.reshape(-1, 3)), atol=1e-14)
    np.testing.assert_allclose(
        rotate_into_body(q, vs).reshape(-1, 3), scipy.inv().apply(vs.reshape(-1, 3)), atol=1e-14
    )
    np.testing.assert_allclose(rotate(q[0, 3], v), scipy[3].apply(v), atol=1e-14)  # one quaternion
    unit = q / np.linalg.norm(q, axis=-1, keepdims=True)  # the z axis's helpers take unit quaternions
    np.testing.assert_allclose(z_axis_in_world(unit).reshape(-1, 3), scipy.apply([0, 0, 1]), atol=1e-15)
    np.testing.assert_allclose(up_in_body(unit).reshape(-1, 3), scipy.inv().apply([0, 0, 1]), atol=1e-15)


def test_quaternion_from_axis_angle_matches_the_matrix():
    axis, angle = np.array([0.2, -0.4, 1.0]), 1.3
    q = quaternion_from_axis_angle(axis, angle)
    np.testing.assert_allclose(quaternion_to_matrix(q), axis_angle_matrix(axis, angle), atol=1e-15)
    np.testing.assert_allclose(q[0], math.cos(0.65), rtol=1e-15)


def test_quaternion_product_composes_like_matrices():
    p = quaternion_from_axis_angle([1.0, 2.0, 3.0], 0.7)
    r = quaternion_from_axis_angle([-1.0, 0.5, 0.0], 2.1)
    np.testing.assert_allclose(
        quaternion_to_matrix(quaternion_multiply(p, r)),
        quaternion_to_matrix(p) @ quaternion_to_matrix(r),
        atol=1e-15,
    )
    # Against scipy, whose quaternion product is the same Hamilton product.
    sp = Rotation.from_quat([*p[1:], p[0]]) * Rotation.from_quat([*r[1:], r[0]])
    x, y, z, w = sp.as_quat()
    pr = quaternion_multiply(p, r)
    assert min(np.abs(pr - [w, x, y, z]).max(), np.abs(pr + [w, x, y, z]).max()) < 1e-15
