"""rbi.simulate gives the arrays `rbi simulate --out` writes, and the summary its JSON prints."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as run_rbi


def cli_ok(*args):
    """`rbi ARGS` run in this process; its output when it succeeds."""
    proc = run_rbi(*args)
    assert proc.returncode == 0, proc.stderr
    return proc


ARGS = ["--spin", "200", "--tilt", "0.01", "--duration", "0.5", "--samples", "101"]


@pytest.fixture(scope="module")
def run():
    return rbi.simulate(
        rbi.load(BODIES / "top_bolted.yaml"), spin=200.0, tilt_deg=0.01, duration=0.5, samples=101
    )


def test_arrays_equal_the_csv_of_the_cli(run, tmp_path):
    out = tmp_path / "run.csv"
    cli_ok("simulate", BODIES / "top_bolted.yaml", *ARGS, "--out", out)
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    column = {name: np.array([float(r[name]) for r in rows]) for name in rows[0]}
    np.testing.assert_array_equal(run.t, column["t"])
    np.testing.assert_array_equal(run.q, np.column_stack([column[c] for c in ("qw", "qx", "qy", "qz")]))
    np.testing.assert_array_equal(run.omega, np.column_stack([column[c] for c in ("wx", "wy", "wz")]))
    np.testing.assert_array_equal(run.tilt_deg, column["tilt_deg"])
    assert run.to_csv() == out.read_text()
    assert run.q.shape == (101, 4) and run.omega.shape == (101, 3)


def test_summary_is_what_the_cli_prints(run):
    printed = json.loads(cli_ok("simulate", BODIES / "top_bolted.yaml", *ARGS, "--format", "json").stdout)
    summary = json.loads(json.dumps(run.to_dict()))
    assert list(summary) == list(printed)
    for key in ("final", "conserved", "stability", "initial", "steps", "tilt_max_deg", "error_estimate"):
        assert summary[key] == printed[key], key


def test_the_motion_obeys_its_invariants(run):
    # unit quaternions, and the energy of a top on a fixed pivot conserved
    np.testing.assert_allclose(np.linalg.norm(run.q, axis=1), 1.0, rtol=0, atol=1e-12)
    assert np.ptp(run.energy) < 1e-9 * np.max(np.abs(run.energy))
    assert run.t[0] == 0.0 and run.t[-1] == 0.5


@pytest.mark.parametrize(
    "settings, named, cli",
    [
        ({"duration": -1.0}, "duration: ", ["--duration", "-1"]),
        ({"spin": 1.0, "omega": [0, 0, 1]}, "spin and omega: ", ["--spin", "1", "--omega", "0,0,1"]),
        ({"samples": 0}, "samples: ", ["--samples", "0"]),
        ({"tilt_axis": "z"}, "tilt_axis: ", ["--tilt-axis", "z"]),
        ({"method": "euler"}, "method: ", ["--method", "euler"]),
        ({"spin_axis": "w"}, "spin_axis: ", ["--spin-axis", "w"]),
        ({"tilt_deg": float("nan")}, "tilt_deg: ", ["--tilt", "nan"]),
    ],
)
def test_bad_settings_raise_a_value_error_naming_the_parameter(settings, named, cli):
    """The API names its own parameter; the CLI says the same with its option's name."""
    body = rbi.load(BODIES / "top_bolted.yaml")
    with pytest.raises(ValueError) as caught:
        rbi.simulate(body, **settings)
    message = str(caught.value)
    assert message.startswith(named) and "--" not in message
    proc = run_rbi("simulate", BODIES / "top_bolted.yaml", *cli)
    assert proc.returncode == 2
    option = " and ".join(c for c in cli if c.startswith("--"))
    assert proc.stderr.startswith(f"rbi: {option}: ") and proc.stderr.endswith(
        message.split(": ", 1)[1][-20:] + "\n"
    )


def test_text_is_not_a_vector_and_a_body_must_be_a_body():
    body = rbi.load(BODIES / "top_bolted.yaml")
    with pytest.raises(ValueError, match=r"^omega: expected 3 finite numbers"):
        rbi.simulate(body, omega="0,0,1")
    with pytest.raises(TypeError, match=r"^body: expected a Body"):
        rbi.simulate(str(BODIES / "top_bolted.yaml"))


def test_a_run_past_the_budget_names_the_parameters_that_raise_it():
    body = rbi.load(BODIES / "top_bolted.yaml")
    with pytest.raises(ValueError) as caught:
        rbi.simulate(body, spin=200.0, max_steps=100)
    assert "max_steps" in str(caught.value) and "check_budget=False" in str(caught.value)
    assert "--" not in str(caught.value)
