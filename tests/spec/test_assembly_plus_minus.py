"""A sub-assembly whose file writes numbers with ±: they are inputs of the body, named as
``rbi parts --expand`` names the parts (``parts.ASSEMBLY/PART.field``), and the body's
uncertainty equals that of the same parts written out flat (units converted, turned, moved,
patterned), linear and Monte Carlo alike."""

from __future__ import annotations

import numpy as np
import pytest

import rbi
from rbi.spec.load import load_body
from rbi.spec.uncertain import linear, monte_carlo

INNER = """units: {length: mm, mass: g}
parts:
  - {name: rod, shape: cylinder, density: "0.0078 ± 1%", radius: "2 ± 0.01", start: ["-10 ± 0.1", 0, 0], end: [10, 0, 0]}
"""
SUB = """units: {length: mm, mass: g}
parts:
  - {name: blk, shape: box, size: ["20 ± 0.1", 10, 5], mass: "10 ± 0.1", center: [5, 0, 0]}
  - {name: pin, shape: point, mass: 3, position: ["30 ± 0.5", 0, "4 ± 0.2"]}
  - {name: nest, shape: assembly, file: inner.yaml, position: [0, 0, 10]}
"""
TOP = """parts:
  - {name: base, shape: box, size: [0.1, 0.1, 0.02], mass: "0.5 ± 0.01", center: [0, 0, 0]}
  - {name: arm, shape: assembly, file: sub.yaml, position: [0.05, 0.02, 0.01], rotation: {axis: [0, 0, 1], angle_deg: 90}PATTERN}
"""
FLAT = """parts:
  - {name: base, shape: box, size: [0.1, 0.1, 0.02], mass: "0.5 ± 0.01", center: [0, 0, 0]}
  - {name: blk, shape: box, size: [0.01, "0.02 ± 0.0001", 0.005], mass: "0.01 ± 0.0001", center: [0.05, 0.025, 0.01]PATTERN}
  - {name: pin, shape: point, mass: 0.003, position: [0.05, "0.05 ± 0.0005", "0.014 ± 0.0002"]PATTERN}
  - {name: rod, shape: cylinder, density: "7800 ± 1%", radius: "0.002 ± 0.00001", start: [0.05, "0.01 ± 0.0001", 0.02], end: [0.05, 0.03, 0.02]PATTERN}
"""


@pytest.mark.parametrize("pattern", ["", ", pattern: {count: 3, step: [0, 0, 0.1]}"])
def test_a_sub_assemblys_plus_minus_is_propagated_as_the_same_parts_written_flat(tmp_path, pattern):
    for name, text in (("inner", INNER), ("sub", SUB), ("top", TOP), ("flat", FLAT)):
        (tmp_path / f"{name}.yaml").write_text(text.replace("PATTERN", pattern))
    top, flat = load_body(str(tmp_path / "top.yaml")), load_body(str(tmp_path / "flat.yaml"))
    assert [i.path for i in top.spec._uncertain] == [
        "parts.base.mass",
        "parts.arm/blk.size[0]",
        "parts.arm/blk.mass",
        "parts.arm/pin.position[0]",
        "parts.arm/pin.position[2]",
        "parts.arm/nest/rod.density",
        "parts.arm/nest/rod.radius",
        "parts.arm/nest/rod.start[0]",
    ]
    nested, written = linear(top), linear(flat)
    assert not nested.estimated.any()
    np.testing.assert_allclose(nested.values, written.values, rtol=1e-12, atol=1e-15)
    assert np.all(written.uncertainty[:13] > 0) or pattern  # every number moves (Iyz... of the flat body)
    np.testing.assert_allclose(nested.uncertainty, written.uncertainty, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(
        monte_carlo(top, 500, seed=4), monte_carlo(flat, 500, seed=4), rtol=1e-12, atol=1e-15
    )
    spread = rbi.load(tmp_path / "top.yaml").standard_uncertainty()
    assert spread is not None and spread.mass == pytest.approx(float(written.uncertainty[0]), rel=1e-12)
    assert not [w for w in rbi.load(tmp_path / "top.yaml").warnings if "±" in w]


def test_a_measured_mass_keeps_the_sub_assemblys_mass_fixed(tmp_path):
    (tmp_path / "inner.yaml").write_text(INNER)
    (tmp_path / "sub.yaml").write_text(SUB)
    (tmp_path / "top.yaml").write_text("parts: [{name: arm, shape: assembly, file: sub.yaml, mass: 0.02}]\n")
    (tmp_path / "free.yaml").write_text("parts: [{name: arm, shape: assembly, file: sub.yaml}]\n")
    found, free = (
        linear(load_body(str(tmp_path / "top.yaml"))),
        linear(load_body(str(tmp_path / "free.yaml"))),
    )
    assert found.values[0] == pytest.approx(0.02, rel=1e-15)
    assert found.uncertainty[0] < 1e-15 * 0.02  # the inputs only share the measured total out
    # every part's mass scaled alike: the centre of mass is the sub-assembly's own
    np.testing.assert_allclose(found.uncertainty[1:4], free.uncertainty[1:4], rtol=1e-12, atol=1e-18)
    assert found.uncertainty[1] > 0 and found.uncertainty[3] > 0


@pytest.mark.parametrize("pattern", ["", ", pattern: {count: 3, step: [0, 0, 0.1]}"])
def test_parts_expand_gives_each_part_of_a_sub_assembly_its_uncertainty(tmp_path, pattern):
    """`rbi parts --expand`: each row of a sub-assembly has the uncertainty of the same part
    written flat (each copy of a pattern that of the part: a step moves, not scales)."""
    for name, text in (("inner", INNER), ("sub", SUB), ("top", TOP), ("flat", FLAT)):
        (tmp_path / f"{name}.yaml").write_text(text.replace("PATTERN", pattern.replace("3", "1")))
    flat = rbi.load(tmp_path / "flat.yaml").parts()
    (tmp_path / "top.yaml").write_text(TOP.replace("PATTERN", pattern))
    nested = rbi.load(tmp_path / "top.yaml").parts(expand=True)
    copies = 3 if pattern else 1
    assert [p.name for p in nested] == ["base"] + [
        f"arm{f'[{k}]' if pattern else ''}/{name}"
        for k in range(copies)
        for name in ("blk", "pin", "nest/rod")
    ]
    expected = [flat[0]] + [p for _ in range(copies) for p in flat[1:]]
    for row, alone in zip(nested, expected):
        for key in ("mass", "center_of_mass", "inertia_about_com"):
            np.testing.assert_allclose(
                getattr(row.uncertainty, key), getattr(alone.uncertainty, key), rtol=1e-12, atol=1e-18
            )
    assert nested.to_dict()["parts"][1]["uncertainty"] == nested[1].uncertainty.to_dict()


def test_two_parts_naming_one_file_have_inputs_of_their_own(tmp_path):
    """Each `shape: assembly` part draws its file's numbers on its own: twice the variance."""
    (tmp_path / "inner.yaml").write_text(INNER)
    (tmp_path / "sub.yaml").write_text(SUB)
    (tmp_path / "one.yaml").write_text("parts: [{name: a, shape: assembly, file: sub.yaml}]\n")
    (tmp_path / "two.yaml").write_text(
        "parts: [{name: a, shape: assembly, file: sub.yaml}, {name: b, shape: assembly, file: sub.yaml}]\n"
    )
    one, two = (load_body(str(tmp_path / f"{n}.yaml")) for n in ("one", "two"))
    assert [i.path for i in two.spec._uncertain][7:9] == ["parts.b/blk.size[0]", "parts.b/blk.mass"]
    assert linear(two).uncertainty[0] == pytest.approx(np.sqrt(2) * linear(one).uncertainty[0], rel=1e-14)


@pytest.mark.parametrize(
    "count, pattern",
    [(1001, ""), (100, ", pattern: {count: 10001, step: [0, 1, 0]}")],
)
def test_a_sub_assembly_whose_inputs_would_build_too_many_parts_is_refused_in_one_line(
    tmp_path, count, pattern
):
    """Each ± input of a sub-assembly is stepped through all its parts (and copies): 1,001 inputs
    over 1,001 parts, or 100 over 10,001 copies, are more than a million parts to build (before:
    ~0.5 GB and seconds, growing as their product: 8,000 point masses took 23 GB)."""
    (tmp_path / "sub.yaml").write_text(
        "parts:\n"
        + "".join(
            f"  - {{name: p{i}, shape: point, mass: '1 ± 0.1', position: [{i}, 0, 0]}}\n"
            for i in range(count)
        )
    )
    (tmp_path / "top.yaml").write_text(f"parts:\n  - {{name: s, shape: assembly, file: sub.yaml{pattern}}}\n")
    with pytest.raises(rbi.SpecError) as caught:
        rbi.load(tmp_path / "top.yaml")
    assert str(caught.value) == (
        f"{tmp_path / 'top.yaml'}: parts[0] (s): file: sub.yaml: {count:,} numbers with ± inside, each stepped "
        "through all its parts: more than 1,000,000 parts to build for their uncertainty"
    )
