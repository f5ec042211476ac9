"""Monte Carlo draws of turned, patterned, mesh and STEP parts built as one stack
(rbi.spec.uncertain.part_stack): each draw equal to the part built alone by its own builder
(rbi.spec.translate.part_element) with the drawn values written in, the builder called once for
all draws (a file's solid: its scalings) or not at all (the closed forms)."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from rbi.spec import uncertain
from rbi.spec.load import body_from_raw
from rbi.spec.translate import part_element

BODIES = Path(__file__).resolve().parents[2] / "bodies"

PARTS = {
    "turned box": (
        {
            "shape": "box",
            "mass": "2 ± 0.02",
            "size": ["0.1 ± 0.001", 0.2, 0.3],
            "center": [0.1, "0 ± 0.01", 0.2],
        }
        | {"rotation": {"axis": [1, "2 ± 0.1", 3], "angle_deg": "30 ± 0.5"}},
        0,
    ),
    "patterned cylinder": (
        {"shape": "cylinder", "density": "1000 ± 5", "radius": "0.05 ± 0.001", "start": ["0.3 ± 0.01", 0, 0]}
        | {"end": [0.3, 0, 0.2], "pattern": {"count": 3, "axis": [0, 0, 1], "through": [0.1, 0, 0]}},
        0,
    ),
    "row of points, its step toleranced": (
        {
            "shape": "point",
            "mass": "1 ± 0.1",
            "position": [0.1, 0, 0],
            "pattern": {"count": 4, "step": ["0.1 ± 0.01", 0, 0]},
        },
        0,
    ),
    "hole": (
        {"shape": "sphere", "density": 1000, "radius": "0.01 ± 0.001", "center": [0, 0, 0], "subtract": True},
        0,
    ),
    "mesh": (
        {"shape": "mesh", "file": "bracket.stl", "scale": "0.001 ± 0.00001", "density": "2700 ± 1%"}
        | {"position": ["0.1 ± 0.001", 0, 0], "rotation": {"axis": [0, 0, 1], "angle_deg": 90}},
        1,
    ),
    "mesh shell by mass": (
        {
            "shape": "mesh",
            "file": "bracket.stl",
            "scale": "0.001 ± 0.00001",
            "mass": "0.2 ± 0.01",
            "inertia": "shell",
        }
        | {"pattern": {"count": 2, "step": [0, 0, 0.1]}},
        1,
    ),
    "STEP": (
        {"shape": "step", "file": "flange.step", "density": "7850 ± 0.5%", "position": [0, 0, "0.01 ± 0.001"]}
        | {"pattern": {"count": 2, "axis": [1, 0, 0]}},
        1,
    ),
}


@pytest.mark.parametrize("name", PARTS)
def test_draws_of_a_part_are_one_stack_equal_to_the_part_built_alone(tmp_path, monkeypatch, name):
    part, builds = PARTS[name]
    if name == "STEP":
        pytest.importorskip("OCP")
    for file in ("bracket.stl", "flange.step"):
        shutil.copy(BODIES / file, tmp_path / file)
    host = {"shape": "sphere", "density": 1000, "radius": 0.05, "center": [0, 0, 0]}
    parts = [host, part] if part.get("subtract") else [part]
    loaded = body_from_raw({"parts": parts}, str(tmp_path / "spec.yaml"))
    index, inputs = len(parts) - 1, list(loaded.spec._uncertain)
    draws = np.stack([x.draws(np.random.default_rng(7), 200) for x in inputs], axis=1)
    calls = []
    monkeypatch.setattr(uncertain, "part_element", lambda *a: calls.append(a) or part_element(*a))
    mass, com, inertia = uncertain.part_stack(loaded, index, inputs, draws)
    assert len(calls) == builds
    sign = -1.0 if part.get("subtract") else 1.0
    for row in (0, 199):
        alone = loaded.spec.parts[index]
        for k, x in enumerate(inputs):
            alone = uncertain._replaced(alone, x.steps, float(draws[row, k]))
        element = part_element(alone, loaded.spec.units, loaded.path)
        scale = abs(element.mass) * float(np.max(np.abs(element.center_of_mass))) ** 2
        assert sign * mass[row] == pytest.approx(element.mass, rel=1e-13)
        np.testing.assert_allclose(com[row], element.center_of_mass, rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(
            sign * inertia[row], element.inertia_about_com, rtol=1e-12, atol=1e-13 * scale
        )


def test_a_body_in_other_units_draws_and_propagates_in_them(tmp_path):
    """`Body.in_units`: the budget's values and u, linear and Monte Carlo, are the file's
    converted (the parts are drawn in the file's units, then converted with the body)."""
    import rbi

    (tmp_path / "spec.yaml").write_text(
        'parts: [{shape: box, mass: "2 ± 0.02", size: ["0.1 ± 0.001", 0.2, 0.3], center: [0.1, 0, 0.2]},'
        ' {shape: point, mass: 1, position: ["0.3 ± 0.01", 0, 0]}]\n'
    )
    body = rbi.load(tmp_path / "spec.yaml")
    factor = {"mass": 1e3, "center_of_mass[0]": 1e3, "inertia[1][1]": 1e9}
    for method in ("linear", "monte-carlo"):
        kg_m, g_mm = (
            b.uncertainty(list(factor), method, 2000, seed=3) for b in (body, body.in_units("mm", "g"))
        )
        for a, b in zip(kg_m.quantities, g_mm.quantities):
            assert b["value"] == pytest.approx(a["value"] * factor[a["quantity"]], rel=1e-12)
            assert b["u"] == pytest.approx(a["u"] * factor[a["quantity"]], rel=1e-9)
