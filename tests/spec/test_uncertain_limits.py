"""A ± whose distribution reaches past the least value its field takes (a radius, size, mass or
density at or below 0) is warned about, with the share of the distribution there; and the
uncertainty budget carries the body's warnings as every body's JSON does."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import norm

from rbi.spec.load import body_from_raw
from rbi.spec.uncertain import budget

ROD = {"name": "rod", "shape": "cylinder", "start": [0, 0, 0], "end": [0, 0, 1]}


def warnings_of(parts, **top):
    return body_from_raw(
        {"units": {"length": "m", "mass": "kg"}, "parts": parts, **top}, "spec.yaml"
    ).warnings


def test_a_radius_within_one_u_of_zero_is_warned_with_the_normal_share():
    (line,) = warnings_of([ROD | {"radius": "0.01 ± 0.02", "density": 1000}])
    share = norm.cdf(0, loc=0.01, scale=0.02)  # 0.3085
    assert line.startswith("spec.yaml: parts.rod.radius: ")
    assert (
        f"{100 * share:.2g}% of its normal distribution" in line
        and "lies below 0, where the spec allows no value" in line
    )


def test_a_tolerance_is_a_uniform_share():
    # uniform on [1 - 2, 1 + 2]: a quarter of it below 0
    (line,) = warnings_of([ROD | {"radius": 0.1, "density": "1 ± 2"}], uncertainty="tolerance")
    assert "parts.rod.density: 25% of its uniform distribution" in line


@pytest.mark.parametrize(
    "part",
    [
        {"shape": "box", "center": [0, 0, 0], "size": [1, "0.2 ± 0.1", 1], "mass": 1},  # 2.3%
        {"shape": "point", "position": [0, 0, 0], "mass": "1 ± 0.4"},  # 0.62%
        ROD | {"radius": 0.1, "mass": "2 ± 50%"},  # 2.3%
    ],
)
def test_sizes_masses_and_components_are_checked(part):
    (line,) = warnings_of([part])
    assert "% of its normal distribution" in line


@pytest.mark.parametrize(
    "part",
    [
        {"shape": "point", "position": ["0 ± 5", 0, 0], "mass": 1},  # a coordinate has no limit
        {"shape": "point", "position": [0, 0, 0], "mass": "1 ± 0.3"},  # 3.3 u from 0: 0.04%
        {
            "shape": "box",
            "center": [0, 0, 0],
            "size": [1, 1, 1],
            "mass": 1,
            "rotation": {"axis": [0, 0, 1], "angle_deg": "0 ± 90"},
        },
    ],
)
def test_inputs_far_from_a_limit_or_without_one_are_not_warned(part):
    assert warnings_of([part]) == []


def test_the_warned_share_is_the_share_of_monte_carlo_draws():
    loaded = body_from_raw({"parts": [ROD | {"radius": "0.01 ± 0.02", "density": 1000}]}, "spec.yaml")
    (x,) = loaded.spec._uncertain
    drawn = x.draws(np.random.default_rng(7), 200_000)
    assert np.mean(drawn <= 0) == pytest.approx(x.share_below(0.0), abs=0.005)


def test_the_budget_carries_the_body_warnings(tmp_path):
    # no units, a 100 m rod of 0.2 kg: the density says millimetres
    loaded = body_from_raw(
        {"parts": [ROD | {"end": [0, 0, 100], "radius": "10 ± 0.1", "mass": 0.2}]}, "s.yaml"
    )
    out = budget(loaded, "mass")
    assert len(out["warnings"]) == 1 and "look like millimetres" in out["warnings"][0]
    plain = body_from_raw({"units": {"length": "m"}, "parts": [ROD | {"radius": "1 ± 0.01", "mass": 1}]}, "s")
    assert budget(plain, "mass")["warnings"] == []


PRISM = {
    "name": "plate",
    "shape": "prism",
    "outline": [[0, 0], [1, 0], [0.5, "0.02 ± 0.05"], [0, 1]],  # crosses [0,0]-[1,0] when y <= 0
    "start": [0, 0, 0],
    "end": [0, 0, 0.1],
    "density": 1000,
}


@pytest.mark.parametrize(
    "part, value, u, refused",
    [
        (PRISM | {"name": "tube"}, 0.02, 0.05, lambda y: y <= 0),
        (  # a bore wider than the tube
            {
                "shape": "tube",
                "start": [0, 0, 0],
                "end": [0, 0, 1],
                "outer_radius": 1,
                "inner_radius": "0.9 ± 0.1",
            }
            | {"mass": 1, "name": "tube"},
            0.9,
            0.1,
            lambda r: r > 1,
        ),
    ],
)
def test_monte_carlo_counts_the_draws_the_spec_refuses(part, value, u, refused):
    loaded = body_from_raw({"units": {"length": "m", "mass": "kg"}, "parts": [part]}, "spec.yaml")
    out = budget(loaded, "mass", method="monte-carlo", samples=5000, seed=11)
    # the one input's draws, as the seed gives them (JCGM 101: drawn from its normal distribution)
    expected = int(np.sum(refused(np.random.default_rng(11).normal(value, u, 5000))))
    assert 0 < expected < 5000
    (line,) = out["warnings"]
    assert line.startswith(f"spec.yaml: parts[0] (tube): {expected:,} of 5,000 draws")
    assert "give a part the spec refuses" in line
    assert budget(loaded, "mass")["warnings"] == []  # the linear method draws nothing


def test_draws_of_a_simulation_carry_the_same_warning():
    import rbi

    spec = {"pivot": [0, 0, 0], "parts": [PRISM | {"start": [0, 0, 0.1], "end": [0, 0, 0.2]}]}
    run = rbi.simulate(rbi.load(spec), spin=50, duration=0.05, draws=20, seed=2)
    assert any("draws (" in w and "the spec refuses" in w for w in run.summary.warnings)
    assert "warnings" not in run.summary.input_uncertainty


def test_a_draw_no_body_has_is_one_line_not_an_internal_error():
    import rbi

    custom = {"name": "c", "shape": "custom", "mass": 1, "center_of_mass": [0, 0, 0]}
    custom["inertia"] = [["1 ± 0.5", 0, 0], [0, 1, 0], [0, 0, "1.9 ± 0.2"]]  # I1 + I2 < I3 in some draws
    loaded = body_from_raw({"units": {"length": "m", "mass": "kg"}, "parts": [custom]}, "spec.yaml")
    assert budget(loaded, "mass")["quantities"][0]["u"] == 0  # the linear method needs no draw
    with pytest.raises(rbi.SpecError) as refused:
        budget(loaded, "mass", method="monte-carlo", samples=2000, seed=1)
    line = str(refused.value)
    assert line.startswith(
        "spec.yaml: parts[0] (c): Monte Carlo: a draw gives a part rbi cannot build (inertia: "
    )
    assert "triangle inequality" in line and "\n" not in line


def test_a_sub_assemblys_drawn_parts_are_validated_too(tmp_path):
    import yaml

    (tmp_path / "plate.yaml").write_text(yaml.safe_dump({"parts": [PRISM]}, allow_unicode=True))
    spec = {
        "parts": [{"name": "sub", "shape": "assembly", "file": "plate.yaml", "position": ["0 ± 0.1", 0, 0]}]
    }
    loaded = body_from_raw(spec, str(tmp_path / "top.yaml"))
    out = budget(loaded, "mass", method="monte-carlo", samples=5000, seed=11)
    # the inputs in order: the placement's x, then the sub-assembly's own (the prism's vertex y)
    rng = np.random.default_rng(11)
    rng.normal(0, 0.1, 5000)
    expected = int(np.sum(rng.normal(0.02, 0.05, 5000) <= 0))
    (line,) = out["warnings"]
    assert line.startswith(f"{tmp_path / 'plate.yaml'}: parts[0] (plate): {expected:,} of 5,000 draws")
