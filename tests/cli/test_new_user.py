"""What a new user meets first: rbi bench after a plain install, the docs' own examples, the
install command rbi names, the error estimate's promise, and the principal-axis sign rule."""

from __future__ import annotations

import builtins
import json
import re
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.conftest import BODIES, ROOT, one_line_exit_2
from tests.conftest import run_rbi_inprocess as rbi

DOCS = ROOT / "docs"


# --- rbi bench without a source checkout ---------------------------------------------------------


def test_the_bench_bodies_ship_inside_the_package_and_equal_the_examples():
    from rbi.bench.paths import BENCH_BODIES, bodies_folder

    folder = bodies_folder()
    package = Path(sys.modules["rbi"].__file__).resolve().parent
    assert folder.is_relative_to(package)  # not the checkout's bodies/
    for name in BENCH_BODIES:
        assert (folder / name).read_bytes() == (BODIES / name).read_bytes(), name
    package_data = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"][
        "rbi"
    ]
    assert "data/bodies/*.yaml" in package_data


def test_every_body_the_bench_opens_is_one_it_ships():
    """The bench's cases name only shipped bodies (a new case on another body would break
    `rbi bench` after `pip install .`)."""
    from rbi.bench.paths import BENCH_BODIES

    named = set()
    for source in (ROOT / "src" / "rbi" / "bench").glob("*.py"):
        named |= set(re.findall(r"\"([a-z_]+\.yaml)\"", source.read_text()))
    named -= {"warm.yaml"}  # written by the bench itself
    assert {n for n in named if not n.startswith(("cloud_", "parts"))} <= set(BENCH_BODIES)


# --- docs/check.md --------------------------------------------------------------------------------


def _expect_block() -> str:
    text = (DOCS / "check.md").read_text()
    block = re.search(r"```yaml\n(expect:\n.*?)```", text, re.S)
    assert block, "docs/check.md has no ```yaml expect: block"
    return block.group(1)


def test_the_check_docs_example_holds_on_the_body_it_names(tmp_path):
    text = (DOCS / "check.md").read_text()
    assert "bodies/top_bolted.yaml" in text
    spec = tmp_path / "bolted_budget.yaml"
    spec.write_text((BODIES / "top_bolted.yaml").read_text() + _expect_block())
    proc = rbi("check", spec, "--format", "json")
    assert proc.returncode == 0, proc.stdout
    result = json.loads(proc.stdout)
    assert result["ok"] and result["failed"] == 0 and result["passed"] == 4
    # and it fails on the plain top, as the docs say
    plain = tmp_path / "top_budget.yaml"
    plain.write_text((BODIES / "top.yaml").read_text() + _expect_block())
    assert rbi("check", plain).returncode == 1


def test_the_check_docs_example_values_are_the_bolted_tops_by_hand():
    """Izz about the pivot by hand: cone 3/10 m r², stem 1/2 m r², bolt m r² (all on the z axis
    or at radius 0.04 m): 1.92e-4 + 3.2e-6 + 3.2e-5 = 2.272e-4 kg·m², the docs' figure."""
    izz = 0.3 * 0.4 * 0.04**2 + 0.5 * 0.1 * 0.008**2 + 0.02 * 0.04**2
    assert izz == pytest.approx(2.272e-4, rel=1e-12)
    assert "izz: 2.272e-4" in _expect_block()


# --- the install command rbi names ----------------------------------------------------------------

INSTALL = "pip install '.[plot]'"


def test_plot_help_and_error_name_the_install_command_the_readme_uses(tmp_path, monkeypatch):
    readme = (ROOT / "README.md").read_text()
    assert INSTALL in readme
    for command in ("simulate", "bench"):
        help_text = " ".join(rbi(command, "--help").stdout.split())
        assert INSTALL in help_text, command
        assert "rbi[plot]" not in help_text
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name == "matplotlib" or name.startswith("matplotlib."):
            raise ImportError("No module named 'matplotlib'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    for args in (
        ["simulate", BODIES / "top.yaml", "--spin", "200", "--plot", tmp_path / "x.png"],
        ["bench", "--quick", "--plot", tmp_path / "x.png"],
    ):
        proc = rbi(*args)
        one_line_exit_2(proc, "--plot", "matplotlib", INSTALL)
    assert list(tmp_path.iterdir()) == []


# --- the error estimate ---------------------------------------------------------------------------


@pytest.mark.parametrize("rtol", ["1e-12", "1e-13", "1e-14", "3e-15"])
def test_the_error_estimate_is_strictly_tighter_than_the_run(rtol):
    out = json.loads(
        rbi(
            "simulate",
            BODIES / "top_bolted.yaml",
            "--spin",
            "200",
            "--duration",
            "0.3",
            "--rtol",
            rtol,
            "--format",
            "json",
        ).stdout
    )
    estimate = out["error_estimate"]
    reference = float(re.search(r"rtol ([0-9.e+-]+)", estimate["reference"]).group(1))
    assert reference < float(rtol)
    assert (
        estimate["orientation_deg"] > 0.0 and estimate["omega_rad_s"] > 0.0
    )  # not a run compared with itself


def test_at_the_tightest_tolerance_the_estimate_says_it_cannot_be_given():
    out = json.loads(
        rbi(
            "simulate",
            BODIES / "top_bolted.yaml",
            "--spin",
            "200",
            "--duration",
            "0.3",
            "--rtol",
            "1e-15",
            "--format",
            "json",
        ).stdout
    )
    assert out["error_estimate"]["orientation_deg"] is None
    assert "not available" in out["error_estimate"]["reference"]


def test_the_docs_state_the_real_factor():
    from rbi.sim.summary import REFERENCE_RTOL_FACTOR, REFERENCE_RTOL_FLOOR

    text = " ".join((DOCS / "simulate.md").read_text().split())
    factor = round(1 / REFERENCE_RTOL_FACTOR)
    assert f"{factor}× at the default 1e-12" in text and f"never below {REFERENCE_RTOL_FLOOR:g}" in text
    assert 1e-12 * REFERENCE_RTOL_FACTOR == pytest.approx(1e-15)


# --- principal axis signs (docs/conventions.md) --------------------------------------------------


def test_the_conventions_example_box_gives_the_documented_axes(tmp_path):
    spec = tmp_path / "box.yaml"
    spec.write_text("parts:\n  - {shape: box, mass: 1, size: [2, 3, 1], center: [0, 0, 0]}\n")
    axes = json.loads(rbi("principal", spec, "--format", "json").stdout)["axes"]
    assert axes == [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]
    text = " ".join((DOCS / "conventions.md").read_text().split())
    assert "`[2, 3, 1]` gives `axes = [[0, 1, 0], [1, 0, 0], [0, 0, -1]]`" in text


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(-1, 1, allow_nan=False), min_size=3, max_size=3),
    st.lists(st.floats(0.1, 10), min_size=3, max_size=3, unique=True),
)
def test_the_documented_sign_rule_holds(rotation_vector, moments):
    """For distinct moments: axes[0] and axes[1] have their largest component positive and
    axes[2] is their cross product, whatever its sign."""
    from scipy.spatial.transform import Rotation

    from rbi.core.inertia import principal_axes

    moments = sorted(moments)
    if min(np.diff(moments)) < 1e-3:
        return
    rotation = Rotation.from_rotvec(rotation_vector).as_matrix()
    inertia = rotation @ np.diag(moments) @ rotation.T
    _, axes = principal_axes(inertia)
    for axis in axes[:2]:
        k = int(np.argmax(np.abs(axis)))
        assert axis[k] > 0 or np.isclose(abs(axis).max(), sorted(abs(axis))[-2])
    assert np.allclose(axes[2], np.cross(axes[0], axes[1]), atol=1e-12)
