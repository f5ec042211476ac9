"""Arguments of the wrong type or shape given to a `Body`'s methods are refused as the
contract says: a ValueError or TypeError naming the parameter in the API's words, not
Python's or numpy's own message ("unhashable type: 'list'", "'float' object is not
iterable")."""

from __future__ import annotations

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES


@pytest.fixture(scope="module")
def top():
    return rbi.load(BODIES / "top.yaml")


@pytest.fixture(scope="module")
def toleranced():
    return rbi.load(BODIES / "top_bolted_toleranced.yaml")


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda b: b.in_units(["mm"], "g"), "length"),
        (lambda b: b.in_units("mm", {"g": 1}), "mass"),
        (lambda b: b.inertia_report(products=["cad"]), "products"),
        (lambda b: b.export(["urdf"]), "to"),
    ],
)
def test_a_choice_given_as_a_list_or_dict_is_refused_naming_it(top, call, parameter):
    """b.in_units(['mm'], 'g') and b.inertia_report(products=['cad']) raised TypeError
    "unhashable type: 'list'" (a dict was asked whether it held the list)."""
    with pytest.raises(ValueError, match=rf"^{parameter}: expected one of .*, got [\[{{]"):
        call(top)


@pytest.mark.parametrize("axes", [1.5, 3, True, object()])
@pytest.mark.parametrize("method", ["inertia", "inertia_report", "standard_uncertainty"])
def test_axes_that_are_no_turns_nor_matrix_are_refused_naming_axes(toleranced, method, axes):
    """b.inertia(axes=1.5) raised TypeError "'float' object is not iterable"."""
    with pytest.raises(ValueError, match=r"^axes: expected a 3x3 rotation matrix or \(axis, degrees\) pairs"):
        getattr(toleranced, method)(axes=axes)


def test_no_turns_are_body_axes(top):
    np.testing.assert_array_equal(top.inertia(axes=[]), top.inertia())
    assert top.inertia_report(axes=[]).to_dict() == top.inertia_report().to_dict()


@pytest.mark.parametrize("axis", [[0, 0], [0, 0, 0], "z", object(), [1, None, 0]])
def test_a_bad_axis_of_the_inertia_report_is_named_axis(top, axis):
    """b.inertia_report(axis=[0, 0]) said 'direction: must be a non-zero finite vector' (the
    parameter of rbi.unit_vector, which it called), and axis=object() leaked float()'s TypeError."""
    with pytest.raises(ValueError, match=r"^axis: must be a non-zero finite vector \(x, y, z\), got "):
        top.inertia_report(axis=axis)


@pytest.mark.parametrize("axis", [object(), [1, None, 0], {"x": 1}])
def test_moment_about_an_axis_that_is_no_numbers_is_named_axis(top, axis):
    """b.moment_about_axis(object()) raised "float() argument must be a string or a real number,
    not 'object'" (the core caught an integer too large but not a value of no number)."""
    with pytest.raises(ValueError, match=r"^axis: must be a non-zero finite direction"):
        top.moment_about_axis(axis)


@pytest.mark.parametrize("of", [1.5, 3, True])
def test_uncertainty_of_a_value_that_is_no_name_is_refused_naming_of(toleranced, of):
    """b.uncertainty(of=1.5) raised TypeError "'float' object is not iterable"."""
    with pytest.raises(ValueError, match=r"^of: must name quantities such as mass"):
        toleranced.uncertainty(of=of)
