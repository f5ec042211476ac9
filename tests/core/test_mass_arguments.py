"""`rbi.MassProperties` given arguments of the wrong type or shape refuses them naming the
field or parameter (a ValueError), not with numpy's message ("cannot reshape array of size 2
into shape (3,)", "could not convert string to float") nor with a NaN result (``None`` read
as a number); complex values (a complex step) and negative masses (holes) stay accepted."""

from __future__ import annotations

import numpy as np
import pytest

from rbi import MassProperties
from rbi.errors import shown


@pytest.mark.parametrize(
    "fields, name",
    [
        ((1.0, [0.0, 0.0], np.eye(3)), "center_of_mass"),
        ((1.0, [0.0, 0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]]), "inertia_about_com"),
        ((1.0, ["a", "b", "c"], np.eye(3)), "center_of_mass"),
        (("heavy", [0.0, 0.0, 0.0], np.eye(3)), "mass"),
        ((None, [0.0, 0.0, 0.0], np.eye(3)), "mass"),
        ((10**400, [0.0, 0.0, 0.0], np.eye(3)), "mass"),
        (([1.0, 2.0], np.zeros((3, 3)), np.zeros((2, 3, 3))), "center_of_mass"),
        (([1.0, 2.0], np.zeros((2, 3)), None), "inertia_about_com"),
    ],
)
def test_fields_that_are_no_numbers_of_their_shape_are_refused_naming_them(fields, name):
    with pytest.raises(
        ValueError, match=rf"^{name}: expected (a number|numbers of shape \(.*\)), got "
    ) as refused:
        MassProperties(*fields)
    assert "\n" not in str(refused.value)


def test_complex_values_and_negative_masses_are_still_accepted():
    hole = MassProperties(-1.0, [0.0, 0.0, 0.0], -np.eye(3))
    assert hole.mass == -1.0
    stepped = MassProperties(1.0 + 1e-20j, [0.0, 0.0, 1j * 1e-20], np.eye(3))
    assert stepped.mass.imag == 1e-20 and stepped.center_of_mass.dtype == complex
    np.testing.assert_array_equal(stepped.scaled(2.0 + 0j).inertia_about_com, 2.0 * np.eye(3))


ONE = MassProperties(2.0, [0.0, 0.0, 1.0], np.eye(3))
STACK = MassProperties([1.0, 2.0, -0.5], np.zeros((3, 3)), np.array([np.eye(3)] * 3))


@pytest.mark.parametrize("props", [ONE, STACK], ids=["one", "stack"])
@pytest.mark.parametrize(
    "call, name",
    [
        (lambda p, v: p.inertia_about(v), "point"),
        (lambda p, v: p.transformed(rotation=v), "rotation"),
        (lambda p, v: p.transformed(translation=v), "translation"),
        (lambda p, v: p.scaled(v), "factor"),
        (lambda p, v: p.with_mass(v), "mass"),
    ],
)
@pytest.mark.parametrize(
    "value", [None, "abc", [0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]], {}, [[1.0], [1.0, 2.0]]]
)
def test_a_method_refuses_an_argument_that_is_no_numbers_of_its_shape_naming_it(props, call, name, value):
    """None is no rotation and no translation: they are accepted (the same axes, the same origin).
    ONE.inertia_about(None) was a matrix of NaN; ONE.transformed(rotation=[0, 0]) numpy's
    'matmul: Input operand 1 has a mismatch in its core dimension'; STACK.scaled([0, 0])
    'operands could not be broadcast together with shapes (3,) (2,)'."""
    if value is None and name in ("rotation", "translation"):
        assert call(props, value).to_dict() == props.to_dict()
        return
    with pytest.raises(ValueError, match=rf"^{name}: expected (a number|numbers of shape)"):
        call(props, value)


def test_a_stack_takes_one_argument_a_body():
    np.testing.assert_array_equal(STACK.scaled([1.0, 2.0, 3.0]).mass, [1.0, 4.0, -1.5])
    assert STACK.inertia_about(np.zeros((3, 3))).shape == (3, 3, 3)
    assert (
        STACK.transformed(np.array([np.eye(3)] * 3), np.ones((3, 3))).center_of_mass.tolist()
        == [[1.0] * 3] * 3
    )
    with pytest.raises(ValueError, match=r"^point: expected numbers of shape \(3,\) or \(3, 3\), got "):
        STACK.inertia_about(np.zeros((2, 3)))


def test_a_point_mass_refuses_a_position_of_no_numbers():
    with pytest.raises(ValueError, match=r"^position: expected numbers of shape \(3,\), got None"):
        MassProperties.point(1.0, None)
    with pytest.raises(ValueError, match=r"^position: expected numbers of shape \(2, 3\), got \[0, 0, 1\]"):
        MassProperties.point([1.0, 2.0], [0, 0, 1])


@pytest.mark.parametrize("mass", [["a", "b", "c"], None, "heavy", 10**400])
def test_a_point_mass_of_no_number_is_refused_naming_mass(mass):
    """MassProperties.point(["a", "b", "c"], [0, 0, 1]) said 'position: expected numbers of shape
    (3, 3)': the masses' shape was read before they were checked."""
    with pytest.raises(ValueError, match=r"^mass: expected "):
        MassProperties.point(mass, [0.0, 0.0, 1.0])


def test_an_array_shown_in_a_message_is_one_line():
    assert shown(np.zeros((3, 3)), 200) == "array([[0., 0., 0.], [0., 0., 0.], [0., 0., 0.]])"


def test_one_body_with_a_complex_mass_is_one_body():
    """MassProperties(1 + 1e-20j, ...) was taken for a stack: its to_dict() raised "'complex'
    object has no attribute 'tolist'", len() "object of type 'complex' has no len()"."""
    stepped = MassProperties(1.0 + 1e-20j, [0.0, 0.0, 1e-20j], np.eye(3))
    assert stepped.single and stepped.to_dict()["mass"] == 1.0 + 1e-20j
    assert stepped.to_dict()["center_of_mass"] == [0.0, 0.0, 1e-20j]
    with pytest.raises(TypeError, match="a single MassProperties has no len"):
        len(stepped)
    np.testing.assert_array_equal(
        stepped.transformed(np.eye(3), [1.0, 0.0, 0.0]).center_of_mass, [1.0, 0.0, 1e-20j]
    )


def test_parts_that_are_no_mass_properties_are_refused_naming_parts():
    """MassProperties.sum(["a"]) raised AttributeError "'str' object has no attribute 'frame'"."""
    for call in (MassProperties.sum, MassProperties.concatenate):
        with pytest.raises(TypeError, match=r"^parts: expected MassProperties, got str 'a'"):
            call([ONE, "a"])
    assert MassProperties.sum([ONE, STACK]).mass == ONE.mass + STACK.sum().mass
