"""Hypothesis properties of whole specs that tests/core/test_properties.py does not cover:
moving, turning or mirroring the geometry moves the answer as physics says; changing units or
scale changes it by the exact factor; cutting a cylinder in two changes nothing."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbi.spec.models import BodySpec
from rbi.spec.translate import body_from_spec

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)

coordinate = st.floats(-2.0, 2.0, allow_nan=False)
point3 = st.lists(coordinate, min_size=3, max_size=3)
direction = st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.1)
PLACEMENT = {"cone": ("apex", "base"), "cylinder": ("start", "end"), "point": ("position",)}


@st.composite
def part(draw):
    shape = draw(st.sampled_from(["cone", "cylinder", "point"]))
    if shape == "point":
        return {"shape": "point", "mass": draw(st.floats(0.01, 10.0)), "position": draw(point3)}
    a = np.array(draw(point3))
    u = np.array(draw(direction))
    b = a + draw(st.floats(0.01, 2.0)) * u / np.linalg.norm(u)
    first, second = PLACEMENT[shape]
    return {
        "shape": shape,
        "mass": draw(st.floats(0.01, 10.0)),
        "radius": draw(st.floats(0.001, 1.0)),
        first: a.tolist(),
        second: b.tolist(),
    }


specs = st.lists(part(), min_size=1, max_size=5).map(lambda parts: {"parts": parts})


def props(spec: dict):
    return body_from_spec(BodySpec.model_validate(spec), "random.yaml").props


def moved(spec: dict, transform) -> dict:
    """The spec with every placement point mapped by ``transform``."""
    parts = []
    for p in spec["parts"]:
        p = dict(p)
        for key in PLACEMENT[p["shape"]]:
            p[key] = [float(x) for x in transform(np.array(p[key]))]
        parts.append(p)
    return spec | {"parts": parts}


def scale_of(I) -> float:
    return float(np.max(np.abs(I))) or 1.0


@SETTINGS
@given(specs, point3)
def test_translating_the_body_moves_the_centre_and_keeps_the_central_inertia(spec, shift):
    a, b = props(spec), props(moved(spec, lambda p: p + shift))
    assert b.mass == a.mass
    np.testing.assert_allclose(b.center_of_mass, a.center_of_mass + shift, rtol=0, atol=1e-12 * 8)
    np.testing.assert_allclose(
        b.inertia_about_com, a.inertia_about_com, rtol=0, atol=1e-11 * scale_of(a.inertia_about_com)
    )


@SETTINGS
@given(specs, st.integers(0, 2**32 - 1))
def test_turning_the_geometry_turns_the_inertia(spec, seed):
    R = Rotation.random(random_state=seed).as_matrix()
    a, b = props(spec), props(moved(spec, lambda p: R @ p))
    np.testing.assert_allclose(b.center_of_mass, R @ a.center_of_mass, rtol=0, atol=1e-12 * 8)
    np.testing.assert_allclose(
        b.inertia_about_com, R @ a.inertia_about_com @ R.T, rtol=0, atol=1e-11 * scale_of(a.inertia_about_com)
    )
    np.testing.assert_allclose(
        np.linalg.eigvalsh(b.inertia_about_com),
        np.linalg.eigvalsh(a.inertia_about_com),
        rtol=0,
        atol=1e-11 * scale_of(a.inertia_about_com),
    )


@SETTINGS
@given(specs, st.integers(0, 2))
def test_mirroring_the_geometry_mirrors_the_inertia(spec, axis):
    S = np.eye(3)
    S[axis, axis] = -1.0
    a, b = props(spec), props(moved(spec, lambda p: S @ p))
    np.testing.assert_allclose(b.center_of_mass, S @ a.center_of_mass, rtol=0, atol=1e-13 * 8)
    np.testing.assert_allclose(
        b.inertia_about_com, S @ a.inertia_about_com @ S, rtol=0, atol=1e-12 * scale_of(a.inertia_about_com)
    )


@SETTINGS
@given(specs, st.integers(-6, 6), st.integers(-6, 6))
def test_power_of_two_scalings_scale_mass_and_inertia_exactly(spec, length_exp, mass_exp):
    # Multiplying lengths by 2^k and masses by 2^j is exact in binary, so the inertia must
    # come out as exactly 2^(2k + j) times the original (up to the last bit).
    k, j = 2.0**length_exp, 2.0**mass_exp
    scaled = moved(spec, lambda p: k * p)
    for p in scaled["parts"]:
        p["mass"] = p["mass"] * j
        if "radius" in p:
            p["radius"] = p["radius"] * k
    a, b = props(spec), props(scaled)
    assert b.mass == a.mass * j
    np.testing.assert_allclose(b.center_of_mass, k * a.center_of_mass, rtol=0, atol=1e-14 * 8 * k)
    np.testing.assert_allclose(
        b.inertia_about_com,
        k * k * j * a.inertia_about_com,
        rtol=0,
        atol=1e-14 * k * k * j * scale_of(a.inertia_about_com),
    )


@SETTINGS
@given(specs)
def test_a_spec_in_millimetres_and_grams_gives_the_same_body_in_its_own_units(spec):
    # Same body written in mm and g: numbers ×1000 for lengths and masses; the inertia in
    # g·mm² is 10⁹ times the one in kg·m² (to rounding: 1000 is not a power of two).
    in_mm = moved(spec, lambda p: 1000.0 * p)
    for p in in_mm["parts"]:
        p["mass"] = p["mass"] * 1000.0
        if "radius" in p:
            p["radius"] = p["radius"] * 1000.0
    in_mm["units"] = {"length": "mm", "mass": "g"}
    a, b = props(spec), props(in_mm)
    assert b.mass == np.float64(a.mass * 1000.0) or abs(b.mass / (a.mass * 1000.0) - 1) < 1e-15
    np.testing.assert_allclose(b.center_of_mass, 1000.0 * a.center_of_mass, rtol=0, atol=1e-12 * 8 * 1000.0)
    np.testing.assert_allclose(
        b.inertia_about_com,
        1e9 * a.inertia_about_com,
        rtol=0,
        atol=1e-12 * 1e9 * scale_of(a.inertia_about_com),
    )


@SETTINGS
@given(specs, st.floats(0.05, 0.95))
def test_cutting_a_cylinder_in_two_changes_nothing(spec, cut):
    cylinders = [i for i, p in enumerate(spec["parts"]) if p["shape"] == "cylinder"]
    if not cylinders:
        spec = spec | {
            "parts": spec["parts"]
            + [
                {
                    "shape": "cylinder",
                    "mass": 1.0,
                    "radius": 0.1,
                    "start": [0.0, 0.0, 0.0],
                    "end": [0.3, -0.2, 0.5],
                }
            ]
        }
        cylinders = [len(spec["parts"]) - 1]
    i = cylinders[0]
    whole = spec["parts"][i]
    start, end = np.array(whole["start"]), np.array(whole["end"])
    middle = (start + cut * (end - start)).tolist()
    pieces = [
        dict(whole, mass=whole["mass"] * cut, end=middle),
        dict(whole, mass=whole["mass"] * (1 - cut), start=middle),
    ]
    cut_spec = spec | {"parts": spec["parts"][:i] + pieces + spec["parts"][i + 1 :]}
    a, b = props(spec), props(cut_spec)
    assert b.mass == np.float64(a.mass) or abs(b.mass / a.mass - 1) < 1e-14
    np.testing.assert_allclose(b.center_of_mass, a.center_of_mass, rtol=0, atol=1e-13 * 8)
    np.testing.assert_allclose(
        b.inertia_about_com, a.inertia_about_com, rtol=0, atol=1e-12 * scale_of(a.inertia_about_com)
    )
