"""The chapter's numbers for its spinning top (seed chapter, the values tests/test_seed_numbers.py
checks through the CLI), read through the Python API's public names only."""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES


def printed(value, decimals):
    """``approx`` at the chapter's printed rounding: half a unit in the last printed digit."""
    return pytest.approx(value, rel=0, abs=0.5 * 10.0**-decimals)


@pytest.fixture(scope="module")
def top():
    return rbi.load(BODIES / "top.yaml")


@pytest.fixture(scope="module")
def bolted():
    return rbi.load(BODIES / "top_bolted.yaml")


def test_mass_and_centre_of_mass(top, bolted):
    assert top.mass == printed(0.50, 2)
    assert list(top.center_of_mass) == [printed(0.0, 4), printed(0.0, 4), printed(0.0520, 4)]
    assert list(bolted.center_of_mass) == [printed(0.00153846, 8), printed(0.0, 8), printed(0.05230769, 8)]
    assert bolted.center_of_mass.shape == (3,)
    assert top.units == {"length": "m", "mass": "kg"}


def test_inertia_in_body_and_tilted_axes(top):
    np.testing.assert_allclose(top.inertia() * 1e6, np.diag([262.93, 262.93, 195.2]), rtol=0, atol=0.005)
    tilted = top.inertia(axes=[("y", 30)]) * 1e6
    np.testing.assert_allclose(
        tilted, [[246.0, 0.0, -29.33], [0.0, 262.93, 0.0], [-29.33, 0.0, 212.13]], rtol=0, atol=0.005
    )
    # the same turn given as the body -> world matrix
    c, s = np.cos(np.radians(30)), np.sin(np.radians(30))
    R = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    np.testing.assert_allclose(top.inertia(axes=R) * 1e6, tilted, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.linalg.eigvalsh(tilted), [195.2, 262.9333, 262.9333], rtol=0, atol=5e-5)


def test_inertia_about_the_pivot_and_a_point(top):
    # parallel axis theorem by hand: I_pivot = I_com + m (|d|² 1 - d dᵀ), d = CoM - pivot
    d = top.center_of_mass - top.pivot
    expected = top.inertia() + top.mass * (d @ d * np.eye(3) - np.outer(d, d))
    np.testing.assert_allclose(top.inertia(about="pivot"), expected, rtol=1e-12)
    np.testing.assert_allclose(top.inertia(about=(0.0, 0.0, 0.0)), expected, rtol=1e-12)
    np.testing.assert_allclose(top.inertia(about="origin"), expected, rtol=1e-12)


def test_principal_axes_are_rows_as_in_the_chapter(bolted):
    principal = bolted.principal()
    np.testing.assert_allclose(principal.moments * 1e6, [225.0022, 265.1311, 294.9333], rtol=0, atol=5e-5)
    # The chapter prints the eigenvectors as the COLUMNS of a matrix; rbi gives axes as rows.
    chapter = np.array([[-0.1552, -0.9879, 0.0], [0.0, 0.0, 1.0], [-0.9879, 0.1552, 0.0]])
    for axis, column in zip(principal.axes, chapter.T):
        np.testing.assert_allclose(np.sign(axis @ column) * axis, column, rtol=0, atol=5e-5)
    # each row is an eigenvector of the inertia with its moment, and they form a right-handed frame
    inertia = bolted.inertia()
    for moment, axis in zip(principal.moments, principal.axes):
        np.testing.assert_allclose(inertia @ axis, moment * axis, rtol=0, atol=1e-15)
    assert np.linalg.det(principal.axes) == pytest.approx(1.0)


def test_momentum_and_wobble_angle(top, bolted):
    assert list(top.momentum([0, 0, 100]).angular_momentum) == [
        printed(0.0, 6),
        printed(0.0, 6),
        printed(0.01952, 6),
    ]
    out = bolted.momentum([0, 0, 100])
    assert list(out.angular_momentum) == [printed(-0.000615, 6), printed(0.0, 6), printed(0.022597, 6)]
    assert out.angle_deg == printed(1.5600, 4)
    # kinetic energy ½ ωᵀ I ω about the CoM (turning about a fixed CoM)
    w = np.array([0.0, 0.0, 100.0])
    assert out.kinetic_energy == pytest.approx(0.5 * w @ bolted.inertia() @ w, rel=1e-12)


def test_parts_add_up_to_the_body(bolted):
    parts = bolted.parts()
    assert [p.name for p in parts] == ["cone", "stem", "bolt"]
    assert sum(p.mass for p in parts) == pytest.approx(bolted.mass, rel=1e-12)
    com = sum(p.mass * p.center_of_mass for p in parts) / bolted.mass
    np.testing.assert_allclose(com, bolted.center_of_mass, rtol=1e-12)
    total = sum(
        p.inertia_about_com
        + p.mass
        * (
            (p.center_of_mass - com) @ (p.center_of_mass - com) * np.eye(3)
            - np.outer(p.center_of_mass - com, p.center_of_mass - com)
        )
        for p in parts
    )
    np.testing.assert_allclose(total, bolted.inertia(), rtol=1e-12, atol=1e-18)


def test_pivot_and_warnings(top):
    np.testing.assert_array_equal(top.pivot, [0.0, 0.0, 0.0])
    assert top.warnings == []


@pytest.mark.parametrize("name", ["top", "top_bolted", "tbar", "bracket"])
def test_principal_axes_rebuild_the_inertia_about_any_point(name):
    # I = Aᵀ diag(moments) A with the axes A as rows, about the centre of mass and the origin
    body = rbi.load(BODIES / f"{name}.yaml")
    for about in ("com", "origin", (0.01, -0.02, 0.03)):
        principal = body.principal(about=about)
        rebuilt = principal.axes.T @ np.diag(principal.moments) @ principal.axes
        inertia = body.inertia(about=about)
        np.testing.assert_allclose(rebuilt, inertia, rtol=0, atol=1e-12 * np.max(np.abs(inertia)))
        assert list(principal.moments) == sorted(principal.moments)
        np.testing.assert_allclose(
            principal.radii_of_gyration, np.sqrt(principal.moments / body.mass), rtol=1e-12
        )


def test_turned_inertia_is_r_i_rt_for_chained_turns(bolted):
    def turn(axis, degrees):
        c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
        return {
            "x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
            "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
        }[axis]

    R = turn("z", -45.0) @ turn("x", 20.0)  # x:20 first, then z:-45, both about world axes
    np.testing.assert_allclose(
        bolted.inertia(axes=[("x", 20), ("z", -45)]), R @ bolted.inertia() @ R.T, rtol=1e-12, atol=1e-18
    )


FREE_TOP = (BODIES / "top.yaml").read_text().replace("pivot: [0, 0, 0]\n", "")
"""The chapter's top without its pivot: a free body."""


def test_reference_points_by_name_and_their_refusals():
    free = rbi.loads(FREE_TOP)
    assert free.pivot is None
    np.testing.assert_array_equal(free.point(" COM "), [0.0, 0.0, 0.052])  # names: any case, spaces
    np.testing.assert_array_equal(free.point("origin"), [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(free.point((0.01, 0, 2)), [0.01, 0.0, 2.0])
    free.point("com")[2] = 5.0  # a copy: the body keeps its centre of mass
    assert free.center_of_mass[2] == printed(0.052, 4)
    with pytest.raises(rbi.ArgumentError) as refused:
        free.point("pivot")
    assert isinstance(refused.value, ValueError) and refused.value.parameters == ("about",)
    assert str(refused.value) == "<string>: about: pivot needs a `pivot` in the spec, and there is none"
    for name in ("tip", "{x}"):  # braces print as given
        with pytest.raises(ValueError) as refused:
            free.point(name)
        assert str(refused.value) == (
            f"about: expected com, origin, pivot or a point (x, y, z), got {name!r}"
        )


OVERFLOWING_CALLS = {
    "inertia about a far point": (
        lambda b: b.inertia(about=[1e300, 0, 0]),
        "about: the point is too far from the body: the inertia about it overflows double precision",
    ),
    "principal axes about it": (
        lambda b: b.principal(about=[1e300, 0, 0]),
        "about: the point is too far from the body: the inertia about it overflows double precision",
    ),
    "moment about an axis through it": (
        lambda b: b.moment_about_axis([0, 0, 1], about=[1e300, 0, 0]),
        "about: the point is too far from the body: the inertia about it overflows double precision",
    ),
    "energy of a huge spin": (
        lambda b: b.momentum([1e200, 1e200, 1e200]),
        "result kinetic_energy is not finite: ",
    ),
    "a torque no body can take": (
        lambda b: b.dynamics([0, 0, 1], torque=[1e308, 1e308, 1e308]),
        "results linear_acceleration, angular_acceleration are not finite: ",
    ),
}


@pytest.mark.parametrize("case", OVERFLOWING_CALLS)
def test_a_result_that_overflows_is_a_value_error_not_inf(top, case):
    """Inputs of absurd size give inf/NaN; the API refuses them, naming ``about`` where the
    point is to blame, instead of returning them with numpy's RuntimeWarnings (it returned inf
    and nan before; only the CLI refused them)."""
    call, words = OVERFLOWING_CALLS[case]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no RuntimeWarning on the way
        with pytest.raises(ValueError, match=f"^{re.escape(str(top.path))}: {re.escape(words)}"):
            call(top)


def test_results_in_units_that_overflow_are_refused_naming_the_part():
    """in_units returned a body of inf (1e305 kg·m² is 1e311 kg·mm²), and the radii of gyration
    of a body of 1e-300 kg came back inf: the API refuses both, as the CLI did only for the
    second."""
    huge = {"name": "huge", "shape": "custom", "mass": 1, "center_of_mass": [0, 0, 0]}
    body = rbi.load({"parts": [{**huge, "inertia": {"ixx": 1e305, "iyy": 1e305, "izz": 1e305}}]})
    with pytest.raises(ValueError, match=r"^<dict>: parts\[0\] \(huge\): .*not finite"):
        body.in_units("mm", "kg")
    assert body.in_units("m", "g").mass == 1000.0  # in range: converted
    ghost = rbi.load(
        {"parts": [{**huge, "mass": 1e-300, "inertia": {"ixx": 1e10, "iyy": 1e10, "izz": 1e10}}]}
    )
    with pytest.raises(ValueError, match=r"^<dict>: result radii_of_gyration is not finite"):
        ghost.principal()


def test_a_far_point_still_in_range_gives_the_parallel_axis_answer(top):
    """About (1e150, 0, 0) m the inertia is still a double: I_yy = I_yy,com + m (d² + z_c²)
    and I_zz = I_zz,com + m d², d = 1e150 - x_c (the parallel-axis theorem, to rounding)."""
    d = 1e150
    shifted = top.inertia(about=[d, 0, 0])
    com = top.inertia()
    assert shifted[2, 2] == pytest.approx(com[2, 2] + top.mass * d**2, rel=1e-12)
    assert shifted[1, 1] == pytest.approx(com[1, 1] + top.mass * d**2, rel=1e-12)
    assert np.isfinite(shifted).all()


ROD = {
    "name": "rod",
    "units": {"length": "m", "mass": "kg"},
    "parts": [
        {"name": "a", "shape": "point", "mass": 1, "position": [-1, 0, 0]},
        {"name": "b", "shape": "point", "mass": 1, "position": [1, 0, 0]},
    ],
}


@pytest.mark.parametrize(
    "about, where", [("com", "the com"), ("origin", "the origin"), ((2, 0, 0), "the point [2.0, 0.0, 0.0]")]
)
def test_forward_dynamics_of_a_singular_inertia_is_a_value_error_naming_the_point(about, where):
    """Two point masses on the x axis have no moment about x (I_xx = 0 about any point on the
    axis): no torque gives them a finite angular acceleration. A ValueError (it was a SpecError,
    which is none), naming the point as the caller gave it; the inverse problem still answers."""
    rod = rbi.load(ROD)
    with pytest.raises(ValueError, match=rf"the inertia about {re.escape(where)} is singular"):
        rod.dynamics([0, 0, 0], about=about, torque=[0, 0, 1])
    # inverse: spinning up about z at 1 rad/s² about the centre takes I_zz alpha = 2 kg·m² x 1
    assert rod.dynamics([0, 0, 0], alpha=[0, 0, 1]).torque == pytest.approx([0, 0, 2])
