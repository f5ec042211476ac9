"""A stack of n bodies in one rbi.core.mass.MassProperties (as scipy's Rotation holds many): each
operation on the stack equals the same operation on each body built alone, and the numbers
against closed forms."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbi.core.mass import MassProperties

finite = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)


@st.composite
def bodies(draw, n=None):
    """``(masses (n,), centres (n, 3), inertias (n, 3, 3))``: positive masses, physical
    inertias (a turned diagonal of moments obeying the triangle inequality)."""
    n = draw(st.integers(1, 12)) if n is None else n
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    masses = rng.uniform(0.1, 10.0, n)
    centres = rng.uniform(-5.0, 5.0, (n, 3)) * draw(st.sampled_from([1e-3, 1.0, 1e3]))
    a = rng.uniform(0.1, 3.0, (n, 3))  # a box's half sizes: its moments are physical
    moments = masses[:, None] / 3 * (a[:, [1, 0, 0]] ** 2 + a[:, [2, 2, 1]] ** 2)
    turns = Rotation.random(n, random_state=seed).as_matrix()
    inertias = turns @ (moments[:, :, None] * np.eye(3)) @ np.swapaxes(turns, 1, 2)
    return masses, centres, 0.5 * (inertias + np.swapaxes(inertias, 1, 2))


def _singles(masses, centres, inertias):
    return [MassProperties(float(m), c, i) for m, c, i in zip(masses, centres, inertias)]


@settings(max_examples=60, deadline=None)
@given(bodies())
def test_the_sum_of_a_stack_is_the_sum_of_its_bodies(arrays):
    stack = MassProperties(*arrays)
    alone = MassProperties.sum(_singles(*arrays))
    total = stack.sum()
    assert total.single and total.mass == alone.mass
    np.testing.assert_array_equal(total.center_of_mass, alone.center_of_mass)
    np.testing.assert_array_equal(total.inertia_about_com, alone.inertia_about_com)
    np.testing.assert_array_equal(
        MassProperties.sum([stack[:1], stack[1:]]).inertia_about_com, total.inertia_about_com
    )


@settings(max_examples=60, deadline=None)
@given(bodies(), st.data())
def test_an_element_of_a_stack_is_the_body_built_alone(arrays, data):
    stack = MassProperties(*arrays, frame="link")
    singles = _singles(*arrays)
    i = data.draw(st.integers(-len(stack), len(stack) - 1))
    assert len(stack) == len(singles) and stack[i].single and stack[i].frame == "link"
    assert repr(stack[i]) == repr(MassProperties(*(a[i] for a in arrays), frame="link"))
    assert type(stack[i].mass) is float
    picked = stack[np.arange(len(stack))[::-1]]
    assert [repr(p) for p in picked] == [
        repr(MassProperties(s.mass, s.center_of_mass, s.inertia_about_com, "link")) for s in singles[::-1]
    ]
    assert repr(MassProperties.concatenate([stack[:i], stack[i:]])) == repr(stack)


@settings(max_examples=60, deadline=None)
@given(bodies(), st.tuples(finite, finite, finite))
def test_inertia_about_a_point_of_a_stack_is_each_bodys(arrays, point):
    stack = MassProperties(*arrays)
    about = stack.inertia_about(point)
    assert about.shape == (len(stack), 3, 3)
    for k, body in enumerate(_singles(*arrays)):
        np.testing.assert_array_equal(about[k], body.inertia_about(point))
    each = stack.inertia_about(stack.center_of_mass)  # one point a body
    np.testing.assert_array_equal(each, stack.inertia_about_com)


@settings(max_examples=60, deadline=None)
@given(bodies())
def test_principal_axes_of_a_stack_are_each_bodys(arrays):
    stack = MassProperties(*arrays)
    moments, axes = stack.principal()
    for k, body in enumerate(_singles(*arrays)):
        m, a = body.principal()
        scale = m[-1]
        np.testing.assert_allclose(moments[k], m, rtol=0, atol=1e-12 * scale)
        gaps = np.diff(m) / scale
        if gaps.min() > 1e-6:  # distinct moments: the same axes, same signs
            np.testing.assert_allclose(axes[k], a, rtol=0, atol=1e-9 / gaps.min())
    np.testing.assert_allclose(np.linalg.det(axes), 1.0, rtol=1e-12)  # right-handed
    np.testing.assert_allclose(
        axes @ np.swapaxes(axes, 1, 2), np.broadcast_to(np.eye(3), axes.shape), atol=1e-12
    )


def test_principal_axes_of_coincident_moments_are_the_single_bodys_choice():
    # a rod along (1, 1, 0)/√2 (two equal moments), a sphere (three), a flat disc about z (two)
    u = np.array([1.0, 1.0, 0.0]) / np.sqrt(2)
    rod = 2.0 * np.eye(3) - 1.5 * np.outer(u, u)
    inertias = np.array([rod, np.eye(3) * 4.0, np.diag([1.0, 1.0, 2.0]), np.diag([3.0, 2.0, 1.0])])
    stack = MassProperties(np.ones(4), np.zeros((4, 3)), inertias)
    moments, axes = stack.principal()
    for k in range(4):
        m, a = stack[k].principal()
        np.testing.assert_allclose(moments[k], m, rtol=1e-15)
        np.testing.assert_allclose(axes[k], a, atol=1e-15)
    np.testing.assert_array_equal(axes[1], np.eye(3))
    np.testing.assert_allclose(moments[3], [1.0, 2.0, 3.0])
    np.testing.assert_allclose(np.abs(axes[3]), np.eye(3)[::-1], atol=1e-15)


def test_transformed_stack_turns_each_body():
    # boxes 1 × 2 × 3 m of 12 kg (moments 13, 10, 5) turned 90° about z: x and y moments swap
    box = MassProperties(
        np.full(2, 12.0), [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], [np.diag([13.0, 10.0, 5.0])] * 2
    )
    quarter = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    moved = box.transformed(quarter, [0.0, 0.0, 2.0], "body")
    np.testing.assert_allclose(moved.center_of_mass, [[0.0, 1.0, 2.0], [0.0, 0.0, 3.0]], atol=1e-16)
    np.testing.assert_allclose(moved.inertia_about_com, [np.diag([10.0, 13.0, 5.0])] * 2, atol=1e-15)
    each = box.transformed(np.stack([quarter, np.eye(3)]))  # one rotation a body
    np.testing.assert_allclose(each.inertia_about_com[1], np.diag([13.0, 10.0, 5.0]), atol=0)
    for k in range(2):
        one = box[k].transformed(quarter, [0.0, 0.0, 2.0], "body")
        np.testing.assert_allclose(moved[k].inertia_about_com, one.inertia_about_com, rtol=1e-15)


def test_scaled_and_with_mass_scale_mass_and_inertia_of_each_body():
    stack = MassProperties([1.0, 2.0], [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]], [np.eye(3), 2 * np.eye(3)])
    doubled = stack.scaled(2.0)
    np.testing.assert_array_equal(doubled.mass, [2.0, 4.0])
    np.testing.assert_array_equal(doubled.inertia_about_com, [2 * np.eye(3), 4 * np.eye(3)])
    np.testing.assert_array_equal(doubled.center_of_mass, stack.center_of_mass)
    measured = stack.with_mass([3.0, 3.0])
    np.testing.assert_array_equal(measured.inertia_about_com, [3 * np.eye(3), 3 * np.eye(3)])
    np.testing.assert_array_equal(stack.scaled([1.0, 0.5]).mass, [1.0, 1.0])
    assert stack[0].scaled(3.0).mass == 3.0 and type(stack[0].scaled(3.0).mass) is float


def test_len_and_indexing_of_a_single_body_are_refused_as_scipys_rotation_does():
    one = MassProperties.point(1.0, [0.0, 0.0, 0.0])
    assert one.single and bool(one)
    with pytest.raises(TypeError):
        len(one)
    with pytest.raises(TypeError):
        one[0]
    with pytest.raises(TypeError):
        len(Rotation.identity())  # the model followed
    with pytest.raises(IndexError):
        MassProperties.point([1.0, 2.0], np.zeros((2, 3)))[2]
    with pytest.raises(ValueError, match="1-D"):
        MassProperties(np.ones((2, 2)), np.zeros((4, 3)), np.zeros((4, 3, 3)))
    with pytest.raises(ValueError, match="positive"):
        MassProperties.point(np.zeros(2), np.zeros((2, 3))).sum()


def test_to_dict_is_json_ready_for_one_body_and_a_stack():
    one = MassProperties(2.0, [1.0, 2.0, 3.0], np.diag([1.0, 2.0, 3.0]))
    assert json.loads(json.dumps(one.to_dict())) == {
        "mass": 2.0,
        "center_of_mass": [1.0, 2.0, 3.0],
        "inertia_about_com": [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]],
    }
    stack = MassProperties.concatenate([one, one.scaled(2.0)])
    assert json.loads(json.dumps(stack.to_dict()))["mass"] == [2.0, 4.0]
    assert len(stack.to_dict()["inertia_about_com"]) == 2


def test_rbi_massproperties_is_this_class():
    import rbi

    assert rbi.MassProperties is MassProperties
