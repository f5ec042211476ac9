"""The command line's text turned into the numbers the API takes, and the API's errors spelled
with the CLI's options."""

from __future__ import annotations

import numpy as np
import pytest

import rbi
from rbi.cli.option_values import error_line, option_name, parse_vector, spin_axis_option, sweep_values
from rbi.errors import ArgumentError, InputError
from tests.conftest import BODIES, one_line_exit_2, run_rbi_inprocess


def test_ranges_single_values_and_draws_parse():
    assert sweep_values("150:250:3", "--spin") == rbi.Grid(150.0, 250.0, 3)
    np.testing.assert_array_equal(np.asarray(sweep_values("150:250:3", "--spin")), [150, 200, 250])
    assert sweep_values("200", "--spin") == 200.0
    assert sweep_values("normal(0.02, 0.001)", "--vary x") == rbi.Normal(0.02, 0.001)
    assert sweep_values("uniform(-1e-3,2e-3)", "--vary x") == rbi.Uniform(-1e-3, 2e-3)


@pytest.mark.parametrize(
    "text",
    [
        "1:2",
        "a:b:3",
        "1:2:0",
        "1:2:-3",
        "nan",
        "inf:1:2",
        "normal(1)",
        "uniform(2,1)",
        "normal(0,-1)",
        "1:2:3:4",
        "",
        "1:2:1e9",
        "1:2:1000000000",
    ],
)
def test_bad_axes_are_one_line_naming_the_option(text):
    with pytest.raises(InputError) as caught:
        sweep_values(text, "--spin")
    assert str(caught.value).startswith("--spin: ") and "\n" not in str(caught.value)


def test_vectors_and_spin_axes():
    assert parse_vector("1, 2;3", "--omega") == [1.0, 2.0, 3.0]
    assert spin_axis_option("0,1,0") == [0.0, 1.0, 0.0] and spin_axis_option("-y") == "-y"
    with pytest.raises(InputError, match=r"^--omega: expected 3 finite numbers"):
        parse_vector("1,2", "--omega")


def test_api_errors_are_spelled_with_the_options():
    assert option_name("spin_axis") == "--spin-axis" and option_name("tilt_deg") == "--tilt"
    error = ArgumentError(("spin", "omega"), "give one or the other, not both")
    assert str(error) == "spin and omega: give one or the other, not both"
    assert error_line(error) == "--spin and --omega: give one or the other, not both"
    error = ArgumentError("vary", "no such field (see {mass_properties})", item="parts.x.mass", file="a.yaml")
    assert str(error) == "a.yaml: vary['parts.x.mass']: no such field (see mass_properties)"
    assert error_line(error) == "a.yaml: --vary parts.x.mass: no such field (see --mass-properties)"
    assert isinstance(error, ValueError) and isinstance(error, rbi.SpecError)


@pytest.mark.parametrize(
    "args, shown",
    [
        (["simulate", "top.yaml", "--tilt-axis", "{0}"], "rbi: --tilt-axis: must be x or y (got '{0}')"),
        (["simulate", "top.yaml", "--tilt-axis", "{a}"], "rbi: --tilt-axis: must be x or y (got '{a}')"),
        (
            ["simulate", "top.yaml", "--method", "{0}"],
            "--method: must be one of default, rk45, dop853, exact (got '{0}')",
        ),
        (["sweep", "top.yaml", "--vary", "{0}=1:2:2"], "--vary {0}: {0}: no such field in the spec"),
        (
            ["sweep", "top.yaml", "--vary", "parts.{spin}.mass=1:2:2"],
            "parts has no entry '{spin}' (parts: cone, stem)",
        ),
    ],
)
def test_option_values_with_braces_are_one_line_as_written(args, shown):
    """`rbi simulate top.yaml --tilt-axis '{0}'` printed 'internal error: ValueError: Format string
    contains positional fields' (exit 1) and '{a}' came out as '--a': the value was read as a
    placeholder of the message. Now it is exit 2 with the value as typed."""
    args[1] = str(BODIES / args[1])
    one_line_exit_2(run_rbi_inprocess(*args), shown)
