"""Stacked translation of the plain parts of the common shapes (rbi.spec.translate.stacked_parts,
a stack per shape: the one path of every spec) gives each part the element the one-part path
(part_element) gives it, to the bit, and errors still name the part."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbi.core.mass import MassProperties
from rbi.spec.errors import InputError
from rbi.spec.load import spec_from_raw
from rbi.spec.translate import body_from_spec, part_element, stacked_parts

MIN_PARTS = 64
"""Parts in a generated spec (the stacked path once started at 64 parts; now it builds any spec)."""

coordinate = st.floats(-5.0, 5.0, allow_nan=False)
vector = st.lists(coordinate, min_size=3, max_size=3)
positive = st.floats(1e-3, 3.0)
amount = st.one_of(
    st.builds(lambda m: {"mass": m}, positive),
    st.builds(lambda d: {"density": d}, st.floats(1.0, 2e4)),
    st.sampled_from([{"density": "steel"}, {"density": "aluminium"}, {"density": "water"}]),
)
hole = st.sampled_from([{}, {}, {}, {"subtract": True}])


def _apart(a, b) -> bool:
    return float(np.linalg.norm(np.subtract(a, b))) > 1e-2


point = st.builds(lambda m, p: {"shape": "point", "mass": m, "position": p}, positive, vector)
cylinder = st.builds(
    lambda a, h, r, s, e: {"shape": "cylinder", "radius": r, "start": s, "end": e, **a, **h},
    amount,
    hole,
    positive,
    vector,
    vector,
).filter(lambda p: _apart(p["start"], p["end"]))
cone = st.builds(
    lambda a, h, r, s, e: {"shape": "cone", "radius": r, "apex": s, "base": e, **a, **h},
    amount,
    hole,
    positive,
    vector,
    vector,
).filter(lambda p: _apart(p["apex"], p["base"]))
sphere = st.builds(
    lambda a, h, r, c: {"shape": "sphere", "radius": r, "center": c, **a, **h}, amount, hole, positive, vector
)
box = st.builds(
    lambda a, h, s, c: {"shape": "box", "size": s, "center": c, **a, **h},
    amount,
    hole,
    st.lists(positive, min_size=3, max_size=3),
    vector,
)
turned_box = st.builds(
    lambda a, s, c, ang: {
        "shape": "box",
        "size": s,
        "center": c,
        "rotation": {"axis": [0, 0, 1], "angle_deg": ang},
        **a,
    },
    amount,
    st.lists(positive, min_size=3, max_size=3),
    vector,
    st.floats(1.0, 89.0),
)
patterned = st.builds(lambda p: {**p, "pattern": {"count": 3, "step": [0.1, 0.0, 0.0]}}, cylinder)
any_part = st.one_of(point, cylinder, cone, sphere, box, turned_box, patterned)


def _spec(parts):
    named = [{**p, "name": f"p{i}"} for i, p in enumerate(parts)]
    return spec_from_raw("batch.yaml", {"name": "batch", "parts": named})


def _per_part(spec):
    out = []
    for part in spec.parts:
        element = part_element(part, spec.units, "batch.yaml")
        out.append(element.scaled(-1.0) if getattr(part, "subtract", False) else element)
    return out


def _close(a, b, scale):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) <= 4e-15 * scale


@settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large]
)
@given(st.lists(any_part, min_size=MIN_PARTS, max_size=MIN_PARTS + 40))
def test_batched_elements_equal_the_per_part_path(parts):
    spec = _spec(parts)
    stacked, holes = stacked_parts(spec, "batch.yaml")
    assert holes == [i for i, p in enumerate(parts) if p.get("subtract")]
    for i, element in enumerate(stacked):  # every part, plain or not, to the bit; holes negated
        want = part_element(spec.parts[i], spec.units, "batch.yaml")
        sign = -1.0 if i in holes else 1.0
        assert element.mass == sign * want.mass
        assert np.array_equal(element.center_of_mass, want.center_of_mass)
        assert np.array_equal(element.inertia_about_com, sign * want.inertia_about_com)
    # the whole body, holes left out (they must lie inside a solid, which random parts do not)
    solid = _spec([{k: v for k, v in p.items() if k != "subtract"} for p in parts])
    expected = _per_part(solid)
    body = body_from_spec(solid, "batch.yaml")
    assert len(body.elements) == len(expected)
    for got, want in zip(body.elements, expected):
        assert got.mass == pytest.approx(want.mass, rel=1e-15, abs=0)
        assert _close(
            got.inertia_about_com,
            want.inertia_about_com,
            float(np.max(np.abs(want.inertia_about_com))) or 1e-300,
        )
    props = MassProperties.sum(expected)
    assert body.props.mass == pytest.approx(props.mass, rel=1e-14)
    assert np.allclose(body.props.center_of_mass, props.center_of_mass, rtol=1e-13, atol=1e-13)
    assert np.allclose(
        body.props.inertia_about_com,
        props.inertia_about_com,
        rtol=1e-12,
        atol=1e-12 * np.max(np.abs(props.inertia_about_com)),
    )


def _one_shape(shape: str, rng: np.random.Generator) -> dict:
    """A part of ``shape`` with random sizes and place, by mass or by density (a number or a
    material); a cylinder or cone along a coordinate axis, either way."""
    amount = [{"mass": float(rng.uniform(0.01, 100.0))}, {"density": float(rng.uniform(100.0, 2e4))}]
    amount.append({"density": str(rng.choice(["steel", "aluminium", "water"]))})
    part = {"shape": shape, **amount[rng.integers(3)]}
    at, size = [float(x) for x in rng.uniform(-5.0, 5.0, 3)], float(rng.uniform(0.01, 3.0))
    along = list(at)
    along[rng.integers(3)] += float(rng.choice([-1.0, 1.0]) * rng.uniform(0.01, 3.0))
    if shape == "cylinder":
        part.update(radius=size, start=at, end=along)
    elif shape == "cone":
        part.update(radius=size, apex=at, base=along)
    elif shape == "sphere":  # numpy's r**3 of an array may round apart from Python's of one float
        part.update(radius=size if "mass" in part else float(rng.integers(1, 200)) / 64.0, center=at)
    else:
        part.update(size=[float(x) for x in rng.uniform(0.01, 3.0, 3)], center=at)
    return part


@pytest.mark.parametrize("shape", ["cylinder", "cone", "sphere", "box"])
def test_each_shape_batched_is_the_one_part_path_to_the_bit(shape):
    """Both paths take each formula from core.shapes (volume, centre of mass, moments, inertia
    matrix) and the same arithmetic for the axis and length (unit_vector's, numpy's norm for the
    volume, Python's r**3 for a sphere's): the same bits, shape by shape (slanting axes: the
    randomised test above)."""
    rng = np.random.default_rng(24)
    spec = _spec([_one_shape(shape, rng) for _ in range(2 * MIN_PARTS)])
    batched, _ = stacked_parts(spec, "batch.yaml")
    assert len(batched) == len(spec.parts)
    for i, element in enumerate(batched):
        want = part_element(spec.parts[i], spec.units, "batch.yaml")
        assert element.mass == want.mass
        assert np.array_equal(element.center_of_mass, want.center_of_mass)
        assert np.array_equal(element.inertia_about_com, want.inertia_about_com)


def test_a_hole_through_the_batch():
    """A spec of many parts with a hole: the hole is negated as in the per-part path."""
    parts = [{"shape": "cylinder", "density": 1000.0, "radius": 0.5, "start": [0, 0, 0], "end": [0, 0, 1]}]
    parts += [{"shape": "point", "mass": 0.001, "position": [0.1, 0.0, 0.5]}] * 80
    parts.append(
        {
            "shape": "cylinder",
            "density": 1000.0,
            "radius": 0.1,
            "start": [0, 0, 0],
            "end": [0, 0, 1],
            "subtract": True,
        }
    )
    body = body_from_spec(_spec(parts), "batch.yaml")
    full, hole = 1000.0 * np.pi * 0.25, 1000.0 * np.pi * 0.01
    assert body.props.mass == pytest.approx(full - hole + 0.08, rel=1e-14)
    assert body.elements[-1].mass == pytest.approx(-hole, rel=1e-15)
    assert body.props.inertia_about_com[2, 2] == pytest.approx(
        0.5 * full * 0.25 - 0.5 * hole * 0.01 + 80 * 0.001 * 0.01 - (0.08**2 * 0.01) / body.props.mass,
        rel=1e-12,
    )


def test_cylinder_closed_form_through_the_batch():
    """An independent check: 100 equal steel cylinders along z, by density, give n times the
    textbook cylinder (m = ρπr²L, I_zz = ½ m r², I_xx = m (3r² + L²)/12)."""
    parts = [
        {"shape": "cylinder", "density": 7850.0, "radius": 0.1, "start": [0, 0, 0], "end": [0, 0, 2.0]}
    ] * 100
    body = body_from_spec(_spec(parts), "batch.yaml")
    m = 7850.0 * np.pi * 0.01 * 2.0
    assert body.props.mass == pytest.approx(100 * m, rel=1e-14)
    assert body.props.inertia_about_com[2, 2] == pytest.approx(100 * 0.5 * m * 0.01, rel=1e-13)
    assert body.props.inertia_about_com[0, 0] == pytest.approx(100 * m * (3 * 0.01 + 4.0) / 12, rel=1e-13)


def test_errors_still_name_the_part():
    parts = [{"shape": "point", "mass": 1.0, "position": [i, 0, 0]} for i in range(100)]
    parts[57] = {"shape": "cylinder", "mass": 1e300, "radius": 1e200, "start": [0, 0, 0], "end": [0, 0, 1]}
    with pytest.raises(InputError, match=r"parts\[57\] \(p57\)"):
        body_from_spec(_spec(parts), "batch.yaml")
