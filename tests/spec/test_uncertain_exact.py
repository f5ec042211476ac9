"""Sensitivities exact to rounding on the parts built one by one (rotated, patterned, the other
shapes): the complex step through the part's own builder, against the `uncertainties` package
on the same closed-form model (rbi.spec.uncertain.part_derivatives)."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml
from uncertainties import ufloat, umath

from rbi.spec.load import body_from_raw
from rbi.spec.uncertain import QUANTITIES, budget, linear

BODIES = Path(__file__).resolve().parents[2] / "bodies"

pytestmark = pytest.mark.filterwarnings("error::numpy.exceptions.ComplexWarning")  # no step dropped


def number(value, u):
    return f"{value!r} ± {u!r}", ufloat(value, u)


def axisymmetric(axial, transverse, axis):
    return np.array(
        [
            [axial * axis[i] * axis[j] + transverse * ((i == j) - axis[i] * axis[j]) for j in range(3)]
            for i in range(3)
        ],
        dtype=object,
    )


def direction(start, end):
    d = [end[i] - start[i] for i in range(3)]
    length = umath.sqrt(sum(x * x for x in d))
    return [x / length for x in d], length


def assert_matches(part, mass, com, inertia, rel=1e-14):
    """The body of the one part ``part`` against its model (ufloats): every number's u and
    every sensitivity."""
    loaded = body_from_raw({"parts": [part]}, "spec.yaml")
    result = linear(loaded)
    model = [mass, *com, *np.asarray(inertia, dtype=object).reshape(9)]
    inputs = [i.path for i in result.inputs]
    for q, (name, y) in enumerate(zip(QUANTITIES, model)):
        uncertain = hasattr(y, "std_dev")  # else a plain number: no uncertainty, no sensitivities
        value, u, derivatives = (
            (y.nominal_value, y.std_dev, y.derivatives) if uncertain else (float(y), 0.0, {})
        )
        scale = abs(value) + max(abs(v.nominal_value if hasattr(v, "std_dev") else v) for v in model[4:])
        assert result.uncertainty[q] == pytest.approx(u, rel=rel, abs=1e-15 * scale), name
        by_input = {x.tag: d for x, d in derivatives.items()}
        for k, path in enumerate(inputs):
            assert result.sensitivities[q, k] == pytest.approx(
                by_input.get(path, 0.0), rel=rel, abs=1e-14 * scale / result.u[k]
            ), (name, path)


def tagged(value, u, tag):
    return f"{value!r} ± {u!r}", ufloat(value, u, tag)


def test_rotated_box_angle():
    a_w, a = tagged(0.1, 0.001, "parts.b.size[0]")
    t_w, t = tagged(30.0, 0.5, "parts.b.rotation.angle_deg")
    m_w, m = tagged(2.0, 0.02, "parts.b.mass")
    b, c = 0.2, 0.3
    axis = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    cos, sin = umath.cos(umath.radians(t)), umath.sin(umath.radians(t))
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    R = cos * np.eye(3) + sin * K + (1 - cos) * np.outer(axis, axis)
    own = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    part = {
        "name": "b",
        "shape": "box",
        "mass": m_w,
        "size": [a_w, b, c],
        "center": [0.1, 0.0, 0.2],
        "rotation": {"axis": [1, 2, 3], "angle_deg": t_w},
    }
    assert_matches(part, m, [0.1, 0.0, 0.2], R.dot(own).dot(R.T))


def test_rotated_box_axis_and_angle_as_one_stack():
    """An axis and an angle both toleranced: the turns of all rows at once (part_stack)."""
    y_w, y = tagged(2.0, 0.1, "parts.b.rotation.axis[1]")
    t_w, t = tagged(30.0, 0.5, "parts.b.rotation.angle_deg")
    length = umath.sqrt(1.0 + y * y + 9.0)
    axis = [1.0 / length, y / length, 3.0 / length]
    cos, sin = umath.cos(umath.radians(t)), umath.sin(umath.radians(t))
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]], dtype=object)
    R = cos * np.eye(3) + sin * K + (1 - cos) * np.outer(axis, axis)
    own = np.diag([2.0 * (0.04 + 0.09) / 12, 2.0 * (0.01 + 0.09) / 12, 2.0 * (0.01 + 0.04) / 12])
    part = {"name": "b", "shape": "box", "mass": 2.0, "size": [0.1, 0.2, 0.3], "center": [0.1, 0.0, 0.2]}
    part["rotation"] = {"axis": [1, y_w, 3], "angle_deg": t_w}
    assert_matches(part, 2.0, [0.1, 0.0, 0.2], R.dot(own).dot(R.T))


def test_patterned_cylinder_by_density():
    rho_w, rho = tagged(1000.0, 5.0, "parts.c.density")
    r_w, r = tagged(0.05, 0.001, "parts.c.radius")
    x_w, x = tagged(0.3, 0.01, "parts.c.start[0]")
    start, end = [x, 0.0, 0.0], [0.3, 0.0, 0.2]
    axis, length = direction(start, end)
    m = rho * math.pi * r * r * length
    own = axisymmetric(0.5 * m * r * r, m * (3 * r * r + length * length) / 12, axis)
    mid = [(start[i] + end[i]) / 2 for i in range(3)]
    turns = [
        np.array([[math.cos(q), -math.sin(q), 0], [math.sin(q), math.cos(q), 0], [0, 0, 1]])
        for q in (0, 2 * math.pi / 3, 4 * math.pi / 3)
    ]
    coms = [R.dot(np.array(mid, dtype=object)) for R in turns]
    com = sum(coms) / 3
    inertia = sum(R.dot(own).dot(R.T) for R in turns)
    for c in coms:
        d = c - com
        inertia = inertia + m * (np.eye(3) * d.dot(d) - np.outer(d, d))
    part = {
        "name": "c",
        "shape": "cylinder",
        "density": rho_w,
        "radius": r_w,
        "start": [x_w, 0, 0],
        "end": end,
        "pattern": {"count": 3, "axis": [0, 0, 1]},
    }
    assert_matches(part, 3 * m, list(com), inertia)


def test_tube():
    R_w, R = tagged(0.05, 0.001, "parts.t.outer_radius")
    r_w, r = tagged(0.04, 0.001, "parts.t.inner_radius")
    z_w, z = tagged(0.0, 0.01, "parts.t.start[2]")
    start, end = [0.0, 0.0, z], [0.1, 0.0, 0.3]
    axis, length = direction(start, end)
    m = 1000 * math.pi * (R * R - r * r) * length
    own = axisymmetric(m * (R * R + r * r) / 2, m * (3 * (R * R + r * r) + length * length) / 12, axis)
    part = {"name": "t", "shape": "tube", "density": 1000, "outer_radius": R_w, "inner_radius": r_w}
    part |= {"start": [0, 0, z_w], "end": end}
    assert_matches(part, m, [(start[i] + end[i]) / 2 for i in range(3)], own)


def test_frustum():
    a_w, a = tagged(0.05, 0.001, "parts.f.start_radius")
    b_w, b = tagged(0.03, 0.001, "parts.f.end_radius")
    y_w, y = tagged(0.05, 0.01, "parts.f.end[1]")
    start, end = [0.0, 0.0, 0.0], [0.1, y, 0.3]
    axis, h = direction(start, end)
    S = a * a + a * b + b * b
    m = 1000 * math.pi * h * S / 3
    quartic = a**4 + a**3 * b + a * a * b * b + a * b**3 + b**4
    spread = a**4 + 4 * a**3 * b + 10 * a * a * b * b + 4 * a * b**3 + b**4
    own = axisymmetric(
        0.3 * m * quartic / S, 0.15 * m * quartic / S + 3 * m * h * h * spread / (80 * S * S), axis
    )
    along = h * (a * a + 2 * a * b + 3 * b * b) / (4 * S)
    part = {"name": "f", "shape": "frustum", "density": 1000, "start_radius": a_w, "end_radius": b_w}
    part |= {"start": start, "end": [0.1, y_w, 0.3]}
    assert_matches(part, m, [along * axis[i] for i in range(3)], own)


def test_torus():
    R_w, R = tagged(0.2, 0.01, "parts.o.major_radius")
    r_w, r = tagged(0.03, 0.001, "parts.o.minor_radius")
    y_w, y = tagged(1.0, 0.1, "parts.o.axis[1]")
    axis, _ = direction([0.0, 0.0, 0.0], [0.0, y, 1.0])
    m = 1000 * 2 * math.pi**2 * R * r * r
    own = axisymmetric(m * (R * R + 0.75 * r * r), m * (0.5 * R * R + 0.625 * r * r), axis)
    part = {"name": "o", "shape": "torus", "density": 1000, "major_radius": R_w, "minor_radius": r_w}
    part |= {"center": [0, 0, 0], "axis": [0, y_w, 1]}
    assert_matches(part, m, [0.0, 0.0, 0.0], own)


def test_prism_outline_vertex():
    x_w, x = tagged(0.2, 0.01, "parts.p.outline[1][0]")
    y_w, y = tagged(0.15, 0.01, "parts.p.outline[3][1]")
    L_w, L = tagged(0.05, 0.001, "parts.p.end[2]")
    ring = [(0.0, 0.0), (x, 0.0), (0.2, 0.1), (0.0, y)]
    area = sx = sy = sxx = syy = sxy = 0.0
    for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):  # Green's theorem, edge by edge
        c = x0 * y1 - x1 * y0
        area, sx, sy = area + c / 2, sx + (x0 + x1) * c / 6, sy + (y0 + y1) * c / 6
        sxx, syy = sxx + (x0 * x0 + x0 * x1 + x1 * x1) * c / 12, syy + (y0 * y0 + y0 * y1 + y1 * y1) * c / 12
        sxy = sxy + (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c / 24
    cx, cy = sx / area, sy / area
    jxx, jyy, jxy = sxx - area * cx * cx, syy - area * cy * cy, sxy - area * cx * cy
    m = 1000 * area * L
    inertia = np.array(
        [
            [1000 * L * jyy + m * L * L / 12, -1000 * L * jxy, 0.0],
            [-1000 * L * jxy, 1000 * L * jxx + m * L * L / 12, 0.0],
            [0.0, 0.0, 1000 * L * (jxx + jyy)],
        ],
        dtype=object,
    )
    part = {"name": "p", "shape": "prism", "density": 1000, "start": [0, 0, 0], "end": [0, 0, L_w]}
    part["outline"] = [[0, 0], [x_w, 0], [0.2, 0.1], [0, y_w]]
    assert_matches(part, m, [cx, cy, L / 2], inertia)


def test_a_mesh_scale_is_exact_and_a_fallback_is_said_to_be_estimated(tmp_path, monkeypatch):
    """A mesh's scale: mass ∝ scale³, exactly (complex step through its builder). Where a
    builder could not carry the step (forced here), the sensitivities are finite differences
    and the budget says so (JSON and table); otherwise it does not."""
    from rbi.api import load
    from rbi.spec import uncertain

    shutil.copy(BODIES / "bracket.stl", tmp_path / "bracket.stl")
    raw = yaml.safe_load((BODIES / "bracket.yaml").read_text())
    raw["parts"] = raw["parts"][:1]
    raw["parts"][0]["scale"] = "0.001 ± 0.00001"
    (tmp_path / "b.yaml").write_text(yaml.safe_dump(raw))
    loaded = body_from_raw(raw, str(tmp_path / "b.yaml"))
    found = linear(loaded)
    assert found.sensitivities[0, 0] == pytest.approx(3 * loaded.props.mass / 0.001, rel=1e-13)
    assert "estimated_sensitivities" not in budget(loaded)
    monkeypatch.setattr(uncertain, "_complex_step", lambda *args: None)
    assert budget(loaded)["estimated_sensitivities"] == ["parts.bracket.scale"]
    assert "finite differences (~1e-9) for parts.bracket.scale" in str(
        load(str(tmp_path / "b.yaml")).uncertainty()
    )
