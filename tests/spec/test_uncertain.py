"""Numbers written with ± (rbi.spec.uncertain) and their propagation (rbi.core.uncertainty),
against closed forms, the `uncertainties` package on the same model, and Monte Carlo."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml
from uncertainties import ufloat, umath

from rbi.errors import InputError
from rbi.spec.load import body_from_raw
from rbi.spec.plus_minus import parse_plus_minus
from rbi.spec.uncertain import QUANTITIES, budget, linear, monte_carlo, part_uncertainties

BODIES = Path(__file__).resolve().parents[2] / "bodies"
pytestmark = pytest.mark.filterwarnings("error::numpy.exceptions.ComplexWarning")  # no step dropped


def body(parts, **top):
    return body_from_raw({"parts": parts, **top}, "spec.yaml")


def u_of(loaded, name, point=None):
    return float(linear(loaded, point).uncertainty[QUANTITIES.index(name)])


def test_plus_minus_forms():
    assert parse_plus_minus("0.04 ± 0.001") == (0.04, 0.001, False)
    assert parse_plus_minus("2 +- 0.5") == (2.0, 0.5, False)
    assert parse_plus_minus("7800 ± 1%") == (7800.0, 78.0, True)
    assert parse_plus_minus("-3e-2 ± 0") == (-0.03, 0.0, False)


@pytest.mark.parametrize(
    "text", ["0.04 ± -1", "± 3", "1 ± 2 ± 3", "1 ± nan", "nan ± 1", "1 ± inf", "1 ±", "a ± 1"]
)
def test_bad_plus_minus_is_one_line_naming_part_and_field(text):
    with pytest.raises(InputError) as caught:
        body([{"name": "ball", "shape": "sphere", "mass": 1, "radius": text, "center": [0, 0, 0]}])
    message = str(caught.value)
    assert message.startswith("spec.yaml: parts[0] (ball): radius: ") and "\n" not in message


@pytest.mark.parametrize("field, value", [("name", "ball ± 1"), ("shape", "sphere ± 1")])
def test_plus_minus_on_text_is_refused(field, value):
    part = {"name": "ball", "shape": "sphere", "mass": 1, "radius": 1, "center": [0, 0, 0], field: value}
    with pytest.raises(InputError, match=rf"parts\[0\].*{field}: ± is for a number"):
        body([part])


@pytest.mark.parametrize("kind", [[1], {"a": 1}, None, "gaussian"])
def test_an_uncertainty_that_is_not_standard_or_tolerance_is_one_line(kind):
    with pytest.raises(InputError, match=r"^spec.yaml: uncertainty: must be standard .* or tolerance"):
        body([{"shape": "sphere", "mass": "1 ± 0.1", "radius": 1, "center": [0, 0, 0]}], uncertainty=kind)


@pytest.mark.parametrize(
    "inertia, name",
    [
        ({"ixx": 2, "iyy": 2, "izz": 3, "ixy": "0.1 ± 0.01"}, "parts.c.inertia.ixy"),
        ([[2, "0.1 ± 0.01", 0], [0.1, 2, 0], [0, 0, 3]], "parts.c.inertia[0][1]"),
    ],
)
def test_plus_minus_on_a_custom_inertia_moves_both_places_of_a_product(inertia, name):
    custom = {"name": "c", "shape": "custom", "mass": 1, "center_of_mass": [0, 0, 0], "inertia": inertia}
    loaded = body([custom])
    assert [each.path for each in loaded.spec._uncertain] == [name]
    assert u_of(loaded, "inertia[0][1]") == pytest.approx(0.01, rel=1e-12)  # one number, written once
    assert u_of(loaded, "inertia[1][0]") == pytest.approx(0.01, rel=1e-12)
    assert u_of(loaded, "inertia[0][0]") == 0.0


def test_plus_minus_on_both_places_of_a_product_is_refused():
    """[0][1] and [1][0] of a custom inertia are one number: a ± on each would count it as two
    independent inputs (u √2 too large), so the second is refused in one line naming it."""
    inertia = [[2, "0.1 ± 0.01", 0], ["0.1 ± 0.01", 2, 0], [0, 0, 3]]
    custom = {"name": "c", "shape": "custom", "mass": 1, "center_of_mass": [0, 0, 0], "inertia": inertia}
    with pytest.raises(InputError) as caught:
        body([custom])
    assert str(caught.value) == (
        "spec.yaml: parts[0] (c): inertia[1][0]: ± also on inertia[0][1], the same product of inertia: "
        "write it once"
    )


@pytest.mark.parametrize("u", [1e300, 1e-170])
def test_part_uncertainties_whose_squares_leave_a_double(u):
    loaded = body([{"shape": "box", "mass": f"1 ± {u}", "center": [0, 0, 0], "size": [1, 1, 1]}])
    found = part_uncertainties(loaded)
    assert found.mass[0] == pytest.approx(u, rel=1e-12)
    assert found.inertia_about_com[0, 0, 0] == pytest.approx(u / 6, rel=1e-12)  # (1² + 1²)/12 per kg


def test_a_spec_without_plus_minus_has_no_inputs():
    plain = body([{"shape": "sphere", "mass": 1, "radius": 1, "center": [0, 0, 0]}])
    assert plain.spec._uncertain == ()


def test_sphere_closed_form():
    m, r, um, ur = 2.0, 0.3, 0.02, 0.001
    loaded = body(
        [
            {
                "name": "ball",
                "shape": "sphere",
                "mass": f"{m} ± {um}",
                "radius": f"{r} ± {ur}",
                "center": [0, 0, 0],
            }
        ]
    )
    inertia = 0.4 * m * r * r
    expected = inertia * math.hypot(um / m, 2 * ur / r)
    for k in range(3):
        assert u_of(loaded, f"inertia[{k}][{k}]") == pytest.approx(expected, rel=1e-10)
        assert u_of(loaded, f"moments[{k}]") == pytest.approx(expected, rel=1e-10)
    assert u_of(loaded, "mass") == um  # exactly: the complex step of a linear dependence
    assert [i.path for i in loaded.spec._uncertain] == ["parts.ball.mass", "parts.ball.radius"]


def test_tolerance_is_uniform():
    loaded = body([{"shape": "point", "mass": "2 ± 0.3", "position": [0, 0, 0]}], uncertainty="tolerance")
    (only,) = loaded.spec._uncertain
    assert only.u == pytest.approx(0.3 / math.sqrt(3)) and only.distribution == "uniform"
    assert only.path == "parts.0.mass"


def test_point_masses_products_against_uncertainties():
    xs = [ufloat(0.1, 0.002), ufloat(-0.05, 0.001), ufloat(0.02, 0.003)]
    m1, m2 = ufloat(0.5, 0.01), 0.3
    loaded = body(
        [
            {
                "shape": "point",
                "mass": "0.5 ± 0.01",
                "position": ["0.1 ± 0.002", "-0.05 ± 0.001", "0.02 ± 0.003"],
            },
            {"shape": "point", "mass": 0.3, "position": [-0.1, 0.04, 0.0]},
        ]
    )
    second = [-0.1, 0.04, 0.0]
    total = m1 + m2
    com = [(m1 * xs[i] + m2 * second[i]) / total for i in range(3)]
    for i, j in [(0, 1), (0, 2), (1, 2)]:
        product = -(
            m1 * (xs[i] - com[i]) * (xs[j] - com[j]) + m2 * (second[i] - com[i]) * (second[j] - com[j])
        )
        assert u_of(loaded, f"inertia[{i}][{j}]") == pytest.approx(product.std_dev, rel=1e-9)


def test_cylinder_by_density():
    rho, r, length = ufloat(7800, 78), ufloat(0.02, 0.0001), ufloat(0.1, 0.0005)
    loaded = body(
        [
            {
                "shape": "cylinder",
                "density": "7800 ± 1%",
                "radius": "0.02 ± 0.0001",
                "start": [0, 0, 0],
                "end": [0, 0, "0.1 ± 0.0005"],
            }
        ]
    )
    mass = rho * math.pi * r**2 * length
    assert u_of(loaded, "mass") == pytest.approx(mass.std_dev, rel=1e-9)
    assert u_of(loaded, "inertia[2][2]") == pytest.approx((0.5 * mass * r**2).std_dev, rel=1e-9)
    assert u_of(loaded, "inertia[0][0]") == pytest.approx(
        (mass * (3 * r**2 + length**2) / 12).std_dev, rel=1e-9
    )
    assert u_of(loaded, "center_of_mass[2]") == pytest.approx(0.00025, rel=1e-9)


def _shape(kind, rng):
    """A random part of ``kind`` with ± on every number, and its model in ufloats:
    (spec part, mass, com (3), inertia about com (3x3))."""

    def num(value):
        u = abs(value) * rng.uniform(1e-3, 2e-2) + 1e-4
        return f"{value!r} ± {u!r}", ufloat(value, u)

    def vec(scale=0.2):
        written, model = zip(*(num(float(x)) for x in rng.uniform(-scale, scale, 3)))
        return list(written), list(model)

    mass_w, mass = num(float(rng.uniform(0.1, 2.0)))
    if kind == "point":
        pos_w, pos = vec()
        return {"shape": "point", "mass": mass_w, "position": pos_w}, mass, pos, np.zeros((3, 3)).tolist()
    if kind == "sphere":
        r_w, r = num(float(rng.uniform(0.01, 0.1)))
        pos_w, pos = vec()
        moment = 0.4 * mass * r * r
        inertia = [[moment if i == j else 0.0 for j in range(3)] for i in range(3)]
        return {"shape": "sphere", "mass": mass_w, "radius": r_w, "center": pos_w}, mass, pos, inertia
    if kind == "box":
        size_w, size = zip(*(num(float(x)) for x in rng.uniform(0.05, 0.3, 3)))
        pos_w, pos = vec()
        a, b, c = size
        diagonal = [mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12, mass * (a * a + b * b) / 12]
        inertia = [[diagonal[i] if i == j else 0.0 for j in range(3)] for i in range(3)]
        return {"shape": "box", "mass": mass_w, "size": list(size_w), "center": pos_w}, mass, pos, inertia
    # cylinder or cone: axis from start/apex to end/base, both uncertain
    r_w, r = num(float(rng.uniform(0.01, 0.1)))
    s_w, s = vec()
    e_w, e = vec()
    d = [e[i] - s[i] for i in range(3)]
    length = umath.sqrt(sum(x * x for x in d))
    axis = [x / length for x in d]
    if kind == "cylinder":
        axial, transverse = 0.5 * mass * r * r, mass * (3 * r * r + length * length) / 12
        com = [(s[i] + e[i]) / 2 for i in range(3)]
        part = {"shape": "cylinder", "mass": mass_w, "radius": r_w, "start": s_w, "end": e_w}
    else:
        axial, transverse = 0.3 * mass * r * r, 3 * mass * (4 * r * r + length * length) / 80
        com = [s[i] + 0.75 * d[i] for i in range(3)]
        part = {"shape": "cone", "mass": mass_w, "radius": r_w, "apex": s_w, "base": e_w}
    inertia = [
        [axial * axis[i] * axis[j] + transverse * ((i == j) - axis[i] * axis[j]) for j in range(3)]
        for i in range(3)
    ]
    return part, mass, com, inertia


@pytest.mark.parametrize("seed", range(6))
def test_random_specs_equal_uncertainties(seed):
    rng = np.random.default_rng(seed)
    kinds = rng.choice(["point", "sphere", "box", "cylinder", "cone"], size=4)
    built = [_shape(kind, rng) for kind in kinds]
    loaded = body([b[0] for b in built])
    total = sum(b[1] for b in built)
    com = [sum(b[1] * b[2][i] for b in built) / total for i in range(3)]
    inertia = [[0.0] * 3 for _ in range(3)]
    for _, m, c, own in built:
        r = [c[i] - com[i] for i in range(3)]
        rr = sum(x * x for x in r)
        for i in range(3):
            for j in range(3):
                inertia[i][j] = inertia[i][j] + own[i][j] + m * ((i == j) * rr - r[i] * r[j])
    result = linear(loaded)
    u = dict(zip(QUANTITIES, result.uncertainty))
    assert u["mass"] == pytest.approx(total.std_dev, rel=1e-12)
    for i in range(3):
        assert u[f"center_of_mass[{i}]"] == pytest.approx(com[i].std_dev, rel=1e-12)
        for j in range(3):  # complex step through the closed forms: exact to rounding
            assert u[f"inertia[{i}][{j}]"] == pytest.approx(
                inertia[i][j].std_dev, rel=1e-12, abs=1e-15 * u["inertia[0][0]"]
            )


def test_zero_uncertainty_everywhere_is_exactly_zero():
    loaded = body(
        [
            {
                "shape": "cone",
                "mass": "0.4 ± 0",
                "radius": "0.04 ± 0",
                "apex": [0, 0, 0],
                "base": [0, 0, "0.06 ± 0"],
            },
            {"shape": "point", "mass": 0.02, "position": ["0.04 ± 0", 0, 0.06]},
        ]
    )
    assert np.all(linear(loaded).uncertainty == 0.0)
    result = budget(loaded, method="monte-carlo", samples=1000, seed=1)
    assert all(q["u"] == 0.0 for q in result["quantities"])


def test_symmetric_top_has_no_false_axis_uncertainty():
    raw = yaml.safe_load((BODIES / "top.yaml").read_text())
    raw["parts"][0]["radius"] = "0.04 ± 0.0005"
    raw["parts"][0]["mass"] = "0.4 ± 1%"
    loaded = body_from_raw(raw, "top.yaml")
    result = linear(loaded)
    deg = result.axes_deg()
    lone = int(np.argmax(np.abs(result.axes[:, 2])))  # the symmetry axis, z
    assert deg[lone] == 0.0  # the symmetry axis stays
    assert [d for k, d in enumerate(deg) if k != lone] == [None, None]  # I1 = I2: not determined


def test_monte_carlo_agrees_at_small_and_shows_nonlinearity_at_large():
    def spec(rel):
        return body(
            [
                {
                    "shape": "cone",
                    "mass": 0.4,
                    "radius": f"0.04 ± {rel * 100}%",
                    "apex": [0, 0, 0],
                    "base": [0, 0, 0.06],
                },
                {
                    "shape": "point",
                    "mass": f"0.02 ± {rel * 100}%",
                    "position": [f"0.04 ± {rel * 100}%", 0, 0.06],
                },
            ]
        )

    n = 200_000
    small = spec(1e-3)
    drawn = monte_carlo(small, n, seed=3)
    lin = linear(small).uncertainty
    for q in (0, 4, 6, 13):
        sampling = lin[q] / math.sqrt(2 * (n - 1))
        assert abs(np.std(drawn[:, q], ddof=1) - lin[q]) < 4 * sampling
    large = budget(spec(0.3), of=["inertia[0][0]", "moments[2]"], method="monte-carlo", samples=n, seed=3)
    assert not all(q["linear"]["validated"] for q in large["quantities"])


def test_plus_minus_on_a_hole_and_a_pattern():
    hole = body(
        [
            {"shape": "cylinder", "density": 1000, "radius": 0.1, "start": [0, 0, 0], "end": [0, 0, 0.1]},
            {
                "shape": "cylinder",
                "density": 1000,
                "radius": "0.02 ± 0.001",
                "start": [0, 0, 0],
                "end": [0, 0, 0.1],
                "subtract": True,
            },
        ]
    )
    r = ufloat(0.02, 0.001)
    assert u_of(hole, "mass") == pytest.approx((1000 * math.pi * r**2 * 0.1).std_dev, rel=1e-9)
    assert linear(hole).sensitivities[0, 0] < 0  # a larger hole, less mass
    pattern = body(
        [
            {
                "shape": "sphere",
                "mass": "0.1 ± 0.001",
                "radius": 0.01,
                "center": [0.1, 0, 0],
                "pattern": {"count": 4, "axis": [0, 0, 1]},
            },
        ]
    )
    m = ufloat(0.1, 0.001)
    assert u_of(pattern, "mass") == pytest.approx((4 * m).std_dev, rel=1e-12)
    assert u_of(pattern, "inertia[2][2]") == pytest.approx(
        (4 * m * (0.4 * 0.01**2 + 0.1**2)).std_dev, rel=1e-9
    )


def test_plus_minus_on_a_mesh_scale(tmp_path):
    shutil.copy(BODIES / "bracket.stl", tmp_path / "bracket.stl")
    raw = yaml.safe_load((BODIES / "bracket.yaml").read_text())
    raw["parts"] = raw["parts"][:1]
    plain = body_from_raw(raw, str(tmp_path / "b.yaml"))
    raw["parts"][0]["scale"] = "0.001 ± 0.00001"
    loaded = body_from_raw(raw, str(tmp_path / "b.yaml"))
    m, inertia = plain.props.mass, plain.props.inertia_about_com
    assert u_of(loaded, "mass") == pytest.approx(3 * m * 0.01, rel=1e-9)  # mass ∝ scale³
    assert u_of(loaded, "inertia[0][0]") == pytest.approx(5 * inertia[0, 0] * 0.01, rel=1e-9)  # ∝ scale⁵


def test_tolerance_limits_are_drawn_uniform():
    loaded = body([{"shape": "point", "mass": "2 ± 0.3", "position": [0, 0, 0]}], uncertainty="tolerance")
    result = budget(loaded, of=["mass"], method="monte-carlo", samples=100_000, seed=5)["quantities"][0]
    assert result["u"] == pytest.approx(0.3 / math.sqrt(3), rel=0.01)
    low, high = result["interval"]  # 95 % of a uniform on [1.7, 2.3]: width 0.57, inside the limits
    assert 1.7 <= low and high <= 2.3 and high - low == pytest.approx(0.57, abs=0.005)


def test_a_spec_whose_first_part_writes_a_plus_minus_is_validated_once(monkeypatch):
    """Read out of its ± first (validating it as written would fail on each ±, slowly); a ±
    only in a later part still reads, through the failed first validation."""
    from rbi.spec import load

    calls, model = [], load.BodySpec

    class Counted:
        @staticmethod
        def model_validate(raw):
            calls.append(raw)
            return model.model_validate(raw)

    monkeypatch.setattr(load, "BodySpec", Counted)
    first = [{"shape": "point", "mass": "2 ± 0.1", "position": [0, 0, 0]}]
    first.append({"shape": "point", "mass": 1, "position": [1, 0, 0]})
    for parts, validations in ((first, 1), (first[::-1], 2)):
        calls.clear()
        assert linear(body(parts)).uncertainty[0] == pytest.approx(0.1)
        assert len(calls) == validations
