"""The large-spec load benchmark: its generated specs are the bodies they say, and one small
run reports every timing (no speed is asserted: timings are for `rbi bench`)."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import yaml

from rbi.bench.largespec import spec_text, yaml_load_ratio
from rbi.spec.load import load_body


@pytest.mark.parametrize("shape", ["point", "cylinder"])
def test_generated_specs_are_the_bodies_written(tmp_path, shape):
    path = tmp_path / "s.yaml"
    path.write_text(spec_text(300, shape, seed=3))
    parts = yaml.safe_load(path.read_text())["parts"]  # read by PyYAML, independently of rbi
    if shape == "point":
        mass = sum(p["mass"] for p in parts)
    else:  # m = ρ π r² |end − start| for each cylinder
        mass = sum(
            p["density"] * np.pi * p["radius"] ** 2 * np.linalg.norm(np.subtract(p["end"], p["start"]))
            for p in parts
        )
    body = load_body(path)
    assert len(body.elements) == 300
    assert body.props.mass == pytest.approx(mass, rel=1e-12)


def test_importing_the_module_runs_nothing():
    code = (
        "import sys, rbi.bench.largespec; assert 'numpy' not in sys.modules and 'subprocess' in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=60)


def test_a_small_run_reports_every_timing():
    result = yaml_load_ratio(200, "point")
    for key in (
        "bare_s",
        "rbi_load_s",
        "rbi_read_s",
        "rbi_validate_s",
        "rbi_translate_s",
        "rbi_inertia_process_s",
    ):
        assert result[key] > 0, key
    assert result["rbi_load_s"] == pytest.approx(
        result["rbi_read_s"] + result["rbi_validate_s"] + result["rbi_translate_s"]
    )
    assert result["ratio"] == pytest.approx(result["rbi_load_s"] / result["bare_s"])
    with pytest.raises(ValueError, match="shape"):
        spec_text(10, "blob")
