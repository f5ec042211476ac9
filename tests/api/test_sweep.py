"""rbi.sweep takes numbers (the grid's values) and gives the rows `rbi sweep --format json`
prints for the same sweep, as a table: len(), columns as numpy arrays, .to_pandas()."""

from __future__ import annotations

import inspect
import io
import json
import sys

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


@pytest.fixture(scope="module")
def bolted():
    return rbi.load(BODIES / "top_bolted.yaml")


def cli_runs(*args):
    proc = cli_ok("sweep", BODIES / "top_bolted.yaml", *args, "--format", "json", "--workers", "1")
    return json.loads(proc.stdout)["runs"]


def test_grid_rows_equal_the_cli(bolted):
    table = rbi.sweep(
        bolted, spin=[150.0, 205.0, 260.0], tilt_deg=rbi.Grid(0.01, 1, 2), duration=0.3, workers=1
    )
    assert table.records() == cli_runs("--spin", "150:260:3", "--tilt", "0.01:1:2", "--duration", "0.3")
    assert len(table) == 6 and table.failed == 0
    np.testing.assert_array_equal(table["spin"], [150.0, 150.0, 205.0, 205.0, 260.0, 260.0])
    np.testing.assert_array_equal(table["tilt_deg"], [0.01, 1.0] * 3)
    assert table["max_tilt_deg"].dtype == float and table["run"].tolist() == list(range(6))
    assert list(table["status"]) == ["ok"] * 6
    assert set(dict(table)) == set(table.columns)


def test_a_sweep_row_is_the_single_run(bolted):
    # the same run through rbi.simulate: the largest and final tilt agree
    table = rbi.sweep(bolted, spin=200.0, tilt_deg=0.5, duration=0.3, workers=1)
    run = rbi.simulate(bolted, spin=200.0, tilt_deg=0.5, duration=0.3)
    assert table["max_tilt_deg"][0] == pytest.approx(float(np.max(run.tilt_deg)), rel=1e-9)
    assert table["final_tilt_deg"][0] == pytest.approx(float(run.tilt_deg[-1]), rel=1e-9)


def test_a_sleeping_top_stays_up_and_a_slow_one_falls():
    """The chapter's top (a 0.4 kg cone, r 0.04 m, h 0.06 m, on its apex, and a 0.1 kg stem,
    r 0.008 m, from 0.06 to 0.10 m) sleeps above ω_c = 2√(I₁ m g l)/I₃ (closed forms of the
    moments about the apex): at 2 ω_c a 1° nudge stays near 1°, at ω_c / 2 the top falls over."""
    I3 = 0.3 * 0.4 * 0.04**2 + 0.5 * 0.1 * 0.008**2
    I1 = 0.4 * (0.6 * 0.06**2 + 0.15 * 0.04**2) + 0.1 * (0.008**2 / 4 + 0.04**2 / 12 + 0.08**2)
    m, l = 0.5, (0.4 * 0.045 + 0.1 * 0.08) / 0.5
    critical = 2 * np.sqrt(I1 * m * 9.81 * l) / I3
    top = rbi.load(BODIES / "top.yaml")  # /work/shared/cases/top.yaml
    table = rbi.sweep(top, spin=[critical / 2, 2 * critical], tilt_deg=1.0, duration=2.0, workers=1)
    slow, fast = table["max_tilt_deg"]
    assert fast < 1.5 and slow > 30.0


def test_mass_property_draws_equal_the_cli(bolted):
    table = rbi.sweep(
        bolted, mass_properties=True, vary={"parts.bolt.mass": rbi.Uniform(0.01, 0.03)}, runs=5, seed=3
    )
    assert table.records() == cli_runs(
        "--mass-properties", "--vary", "parts.bolt.mass=uniform(0.01,0.03)", "--runs", "5", "--seed", "3"
    )
    # mass = body without the bolt + the drawn bolt mass
    np.testing.assert_allclose(table["mass"], bolted.mass - 0.02 + table["parts.bolt.mass"], rtol=1e-12)
    assert table.spread["mass"]["p0"] == pytest.approx(float(np.min(table["mass"])), rel=1e-12)


def test_bad_variation_names_the_parameter_and_the_cli_its_option(bolted):
    with pytest.raises(ValueError) as caught:
        rbi.sweep(bolted, vary={"parts.nope.mass": [1.0, 2.0]})
    message = str(caught.value)
    assert "vary['parts.nope.mass']: " in message and "--" not in message
    proc = run_rbi("sweep", BODIES / "top_bolted.yaml", "--vary", "parts.nope.mass=1:2:2")
    assert proc.returncode == 2 and "--vary parts.nope.mass: " in proc.stderr
    assert proc.stderr.endswith(message.split(": ")[-1] + "\n")


@pytest.mark.parametrize(
    "settings, named",
    [
        ({"spin": "150:260:3"}, "spin: "),
        ({"tilt_deg": [1.0, float("nan")]}, "tilt_deg: "),
        ({"runs": 0}, "runs: "),
        ({"runs": 3}, "runs: "),
        ({"samples": 0}, "samples: "),
        ({"vary": ["parts.bolt.mass=1:2:2"]}, "vary: "),
        ({"mass_properties": True, "spin": 200.0}, "mass_properties: "),
    ],
)
def test_bad_settings_name_the_parameter(bolted, settings, named):
    with pytest.raises((TypeError, ValueError)) as caught:
        rbi.sweep(bolted, **settings)
    assert str(caught.value).startswith(named) and "--" not in str(caught.value)


def test_the_signature_is_real_and_the_table_shows_itself(bolted):
    parameters = inspect.signature(rbi.sweep).parameters
    assert {"spin", "tilt_deg", "vary", "runs", "duration"} <= set(parameters)
    assert rbi.sweep.__doc__.startswith("Many simulations of one body")
    table = rbi.sweep(bolted, spin=[150.0, 250.0], duration=0.2, workers=1)
    html = table._repr_html_()
    # the table the CLI prints: each header over its unit, the columns --out keeps for want of room left out
    assert html.startswith("<table>") and "<th>max tilt<br>deg</th>" in html and ">ok<" in html
    assert "precession" not in html and list(table.to_pandas())[6] == "precession_rate_deg_s"
    from rich.console import Console

    console = Console(width=200, record=True, file=io.StringIO())
    console.print(table)
    text = console.export_text()
    assert "max tilt" in text and "250" in text and "bolted-top — sweep" in text


def test_to_pandas_or_a_clear_error(bolted, monkeypatch):
    table = rbi.sweep(bolted, spin=[150.0, 250.0], duration=0.2, workers=1)
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="pip install pandas"):
        table.to_pandas()
    monkeypatch.undo()
    import pandas  # a dependency of rbi: to_pandas is part of the contract's API

    frame = table.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and list(frame.columns) == table.columns
    np.testing.assert_array_equal(frame["max_tilt_deg"].to_numpy(), table["max_tilt_deg"])
    assert frame["spin"].tolist() == [150.0, 250.0] and frame["run"].tolist() == [0, 1]


@pytest.mark.parametrize("tilt", [1e20, [0.0, 1e308], rbi.Grid(0.0, 1e12, 2)])
def test_a_tilt_too_large_to_be_a_turn_is_refused_as_simulate_refuses_it(bolted, tilt):
    """`rbi sweep top.yaml --spin 10 --tilt 1e308` gave a row with status ok and a max tilt of
    145.6° (the turn lost to rounding), where `rbi simulate --tilt 1e308` refuses the run: each
    run is simulated as simulate would, so the sweep is refused before any run, naming the axis."""
    with pytest.raises(ValueError, match=r"^tilt_deg: .*too large to be a turn"):
        rbi.sweep(bolted, spin=10.0, tilt_deg=tilt, duration=0.01)
    text = tilt if isinstance(tilt, float) else f"{np.min(tilt)}:{np.max(tilt)}:2"
    proc = run_rbi(
        "sweep", BODIES / "top_bolted.yaml", "--spin", "10", "--tilt", str(text), "--duration", "0.01"
    )
    assert proc.returncode == 2 and proc.stdout == "", proc.stderr
    assert proc.stderr.startswith("rbi: --tilt: ") and "too large to be a turn" in proc.stderr
    assert len(proc.stderr.splitlines()) == 1


@pytest.mark.parametrize(
    "settings, named, words",
    [
        # the command line's START:STOP:COUNT habit: rbi 4 ran spins 100, 300 and 3
        ({"spin": (100, 300, 3)}, "spin: ", ["START, STOP, COUNT", "Grid(100, 300, 3)", "linspace"]),
        ({"tilt_deg": (0.0, 1.0, 5)}, "tilt_deg: ", ["START, STOP, COUNT", "Grid(0.0, 1.0, 5)"]),
        ({"spin": (150.0, 250.0, 3.0)}, "spin: ", ["rbi.Grid(150.0, 250.0, 3)", "3 values"]),
        (
            {"vary": {"parts.bolt.mass": (0.01, 0.03, 5)}},
            "vary['parts.bolt.mass']: ",
            ["Grid(0.01, 0.03, 5)"],
        ),
        ({"spin": [True]}, "spin: ", ["True"]),  # ran spin 1.0
        ({"spin": np.array([True, False])}, "spin: ", ["bool"]),
        ({"spin": np.array([[150.0, 200.0], [250.0, 300.0]])}, "spin: ", ["shape (2, 2)"]),  # flattened
        ({"spin": 150.0, "resume": True}, "resume: ", ["out"]),  # ignored without out
    ],
)
def test_argument_habits_are_refused_naming_the_parameter(bolted, settings, named, words):
    with pytest.raises((TypeError, ValueError)) as caught:
        rbi.sweep(bolted, duration=0.1, workers=1, **settings)
    message = str(caught.value)
    assert message.startswith(named) and "--" not in message, message
    for word in words:
        assert word in message, message


def test_values_that_are_not_the_habit_still_sweep(bolted):
    """A list of three values, a tuple whose last is not whole, an array and a Grid run as given."""
    for spin, expected in [
        ([100.0, 300.0, 3.0], [100.0, 300.0, 3.0]),
        ((150.0, 250.0, 3.5), [150.0, 250.0, 3.5]),
        (np.array([150.0, 250.0]), [150.0, 250.0]),
        (rbi.Grid(100, 300, 3), [100.0, 200.0, 300.0]),
    ]:
        assert rbi.sweep(bolted, spin=spin, duration=0.1, workers=1)["spin"].tolist() == expected


@pytest.mark.parametrize(
    "function, keyword, meant",
    [("sweep", "tilt", "tilt_deg"), ("sweep", "spinaxis", "spin_axis"), ("simulate", "tilt", "tilt_deg")],
)
def test_a_misspelt_keyword_is_told_the_parameter_it_resembles(bolted, function, keyword, meant):
    with pytest.raises(TypeError, match=rf"'{keyword}'.*did you mean '{meant}'\?"):
        getattr(rbi, function)(bolted, spin=150.0, **{keyword: 1.0})
