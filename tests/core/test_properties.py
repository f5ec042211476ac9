"""Hypothesis properties over random valid specs (cones, cylinders and point masses placed
anywhere), run through the spec models and the translation into core inputs."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.core.inertia import parallel_axis_to_com, principal_axes, re_express
from rbi.core.mass import MassProperties
from rbi.spec.models import BodySpec
from rbi.spec.translate import body_from_spec

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True)

coordinate = st.floats(-2.0, 2.0, allow_nan=False)
point3 = st.lists(coordinate, min_size=3, max_size=3)
positive = st.floats(0.01, 10.0)
radius = st.floats(0.001, 1.0)
direction = st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.1)
length = st.floats(0.01, 2.0)


@st.composite
def axial_placement(draw):
    start = np.array(draw(point3))
    u = np.array(draw(direction))
    end = start + draw(length) * u / np.linalg.norm(u)
    return start.tolist(), end.tolist()


@st.composite
def part(draw):
    shape = draw(st.sampled_from(["cone", "cylinder", "point"]))
    if shape == "point":
        return {"shape": "point", "mass": draw(positive), "position": draw(point3)}
    a, b = draw(axial_placement())
    fields = {"cone": ("apex", "base"), "cylinder": ("start", "end")}[shape]
    amount = draw(st.sampled_from(["mass", "density"]))
    value = draw(positive) if amount == "mass" else draw(st.floats(100.0, 10000.0))
    return {"shape": shape, amount: value, "radius": draw(radius), fields[0]: a, fields[1]: b}


specs = st.lists(part(), min_size=1, max_size=6).map(lambda parts: {"parts": parts})


def body(spec: dict):
    return body_from_spec(BodySpec.model_validate(spec), "random.yaml")


def tolerance(matrix) -> float:
    return 1e-12 * float(np.max(np.abs(matrix)))


rotations = st.lists(st.floats(-1.0, 1.0), min_size=4, max_size=4).filter(lambda q: np.linalg.norm(q) > 0.1)


def quaternion_matrix(q):
    w, x, y, z = np.asarray(q) / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


@SETTINGS
@given(specs)
def test_central_inertia_is_a_valid_inertia_matrix(spec):
    I = body(spec).props.inertia_about_com
    np.testing.assert_array_equal(I, I.T)
    eig = np.linalg.eigvalsh(I)
    tol = tolerance(I)
    assert eig.min() >= -tol  # positive semi-definite (zero only for a line of point masses)
    for i in range(3):  # triangle inequality, for the principal moments and the diagonal
        assert eig[i] <= eig.sum() - eig[i] + tol
        assert I[i, i] <= np.trace(I) - I[i, i] + tol


@SETTINGS
@given(specs, rotations)
def test_eigenvalues_do_not_change_under_rotation(spec, q):
    I = body(spec).props.inertia_about_com
    turned = re_express(I, quaternion_matrix(q))
    np.testing.assert_allclose(np.linalg.eigvalsh(turned), np.linalg.eigvalsh(I), rtol=0, atol=tolerance(I))
    moments, _ = principal_axes(turned)
    np.testing.assert_allclose(moments, principal_axes(I)[0], rtol=0, atol=tolerance(I))


@SETTINGS
@given(specs, point3)
def test_parallel_axis_shift_round_trips(spec, point):
    props = body(spec).props
    I_point = props.inertia_about(point)
    back = parallel_axis_to_com(I_point, props.mass, np.asarray(point) - props.center_of_mass)
    np.testing.assert_allclose(back, props.inertia_about_com, rtol=0, atol=tolerance(I_point))
    # Every moment about another point is at least the central one (PSD difference).
    assert np.linalg.eigvalsh(I_point - props.inertia_about_com).min() >= -tolerance(I_point)


@SETTINGS
@given(specs, st.randoms(use_true_random=False))
def test_reordering_parts_changes_nothing(spec, random):
    loaded = body(spec)
    elements = list(loaded.elements)
    random.shuffle(elements)
    shuffled = MassProperties.sum(elements)
    assert abs(shuffled.mass - loaded.props.mass) <= 1e-14 * shuffled.mass
    np.testing.assert_allclose(shuffled.center_of_mass, loaded.props.center_of_mass, rtol=0, atol=1e-14 * 2.0)
    np.testing.assert_allclose(
        shuffled.inertia_about_com,
        loaded.props.inertia_about_com,
        rtol=0,
        atol=tolerance(loaded.props.inertia_about_com),
    )


@SETTINGS
@given(specs)
def test_principal_axes_form_a_right_handed_eigenbasis(spec):
    I = body(spec).props.inertia_about_com
    moments, axes = principal_axes(I)
    assert np.all(np.diff(moments) >= 0)
    np.testing.assert_allclose(axes @ axes.T, np.eye(3), rtol=0, atol=1e-12)
    assert abs(np.linalg.det(axes) - 1.0) <= 1e-12
    # Reconstruction to the degeneracy threshold (1e-9 of the largest moment).
    np.testing.assert_allclose(axes.T @ np.diag(moments) @ axes, I, rtol=0, atol=2e-9 * np.max(np.abs(I)))
