"""rbi.runs.run: a run's settings checked, its scene and initial state prepared, its CSV written.

Expected numbers are closed forms: the chapter's top is a solid cone (0.4 kg, radius 0.04 m,
height 0.06 m, apex on the pivot) under a stem cylinder (0.1 kg, radius 0.008 m, from 0.06 m
to 0.10 m on the axis).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rbi.errors import ArgumentError, InputError
from rbi.runs.run import (
    RunSettings,
    check_run_settings,
    prepare_run,
    refuse_non_finite,
    scene_of,
    spin_axis_value,
    trajectory_csv,
)
from rbi.sim.summary import CSV_COLUMNS
from rbi.spec.load import load_body
from rbi.text import csv_cell

BODIES = Path(__file__).resolve().parents[2] / "bodies"

CONE_MASS, CONE_RADIUS, CONE_HEIGHT = 0.4, 0.04, 0.06
STEM_MASS, STEM_RADIUS, STEM_START, STEM_END = 0.1, 0.008, 0.06, 0.10


@pytest.fixture(scope="module")
def top():
    return load_body(BODIES / "top.yaml")


def test_the_top_s_scene_is_a_heavy_top_on_its_tip(top):
    scene = scene_of(top, None)
    com_height = (CONE_MASS * 0.75 * CONE_HEIGHT + STEM_MASS * 0.5 * (STEM_START + STEM_END)) / (
        CONE_MASS + STEM_MASS
    )
    axial = 0.3 * CONE_MASS * CONE_RADIUS**2 + 0.5 * STEM_MASS * STEM_RADIUS**2
    assert scene.pivoted
    assert scene.mass == pytest.approx(0.5, rel=1e-15)
    assert scene.com_from_pivot == pytest.approx([0.0, 0.0, com_height], abs=1e-15)
    assert scene.inertia[2, 2] == pytest.approx(axial, rel=1e-12)
    assert scene.gravity == pytest.approx(9.81, rel=1e-15)
    assert np.abs(scene.spin_axis) == pytest.approx([0.0, 0.0, 1.0], abs=1e-15)


def test_gravity_is_converted_to_the_spec_s_length_unit(tmp_path):
    spec = tmp_path / "mm.yaml"
    spec.write_text(
        "name: mm\nunits: {length: mm}\npivot: [0, 0, 0]\nparts:\n"
        "  - {name: p, shape: point, mass: 1, position: [0, 0, 10]}\n"
        "  - {name: q, shape: point, mass: 1, position: [5, 0, 10]}\n"
        "  - {name: r, shape: point, mass: 1, position: [0, 5, 10]}\n"
    )
    scene = scene_of(load_body(spec), 2.0)
    assert scene.gravity == pytest.approx(2000.0, rel=1e-15)


@pytest.mark.parametrize(
    ("given", "expected"),
    [("-y", [0.0, -1.0, 0.0]), (" Z ", [0.0, 0.0, 1.0]), ([3, 0, 4], [0.6, 0.0, 0.8]), (None, None)],
)
def test_spin_axis_values(given, expected):
    value = spin_axis_value(given)
    assert value == (None if expected is None else pytest.approx(expected, abs=1e-15))


@pytest.mark.parametrize("given", ["w", [0, 0, 0], [1, 2]])
def test_spin_axis_values_refused_name_the_parameter(given):
    with pytest.raises(ArgumentError, match="spin_axis"):
        spin_axis_value(given)


def test_prepared_state_is_the_tilt_turned_identity_with_the_spin_about_the_axis(top):
    run = prepare_run(top, RunSettings(spin=200.0, tilt_deg=30.0, tilt_axis="X", duration=0.5))
    half = math.radians(15.0)
    assert run.q0 == pytest.approx([math.cos(half), math.sin(half), 0.0, 0.0], abs=1e-15)
    assert np.linalg.norm(run.omega0) == pytest.approx(200.0, rel=1e-15)
    assert np.cross(run.omega0, run.scene.spin_axis) == pytest.approx([0.0, 0.0, 0.0], abs=1e-12)
    assert (run.settings.tilt_axis, run.settings.duration, run.settings.tilt_deg) == ("x", 0.5, 30.0)


def test_omega_is_taken_as_given_in_body_axes(top):
    run = prepare_run(top, RunSettings(omega=[1.0, -2.0, 3.0], duration=0.1))
    assert run.omega0 == pytest.approx([1.0, -2.0, 3.0], abs=0.0)
    with pytest.raises(ArgumentError, match="spin.*omega|omega.*spin"):
        prepare_run(top, RunSettings(spin=1.0, omega=[1.0, 0.0, 0.0]))


@pytest.mark.parametrize(
    ("settings", "parameter"),
    [
        ({"duration": -1.0}, "duration"),
        ({"duration": math.inf}, "duration"),
        ({"tilt_axis": "z"}, "tilt_axis"),
        ({"gravity": -9.81}, "gravity"),
        ({"max_steps": 0}, "max_steps"),
        ({"rtol": 1.0}, "rtol"),
    ],
)
def test_settings_out_of_range_are_refused_by_name(settings, parameter):
    values = {"duration": 1.0, "tilt_axis": "y", "gravity": None, "max_steps": None, "rtol": None}
    with pytest.raises(ArgumentError, match=parameter):
        check_run_settings(RunSettings(**(values | settings)))


def test_a_run_beyond_the_step_budget_is_refused_unless_asked(top):
    with pytest.raises(ArgumentError, match="budget"):
        prepare_run(top, RunSettings(spin=200.0, tilt_deg=5.0, duration=10.0, max_steps=10))
    run = prepare_run(
        top, RunSettings(spin=200.0, tilt_deg=5.0, duration=10.0, max_steps=10, check_budget=False)
    )
    assert run.budget == 10


def test_a_free_body_spinning_about_a_principal_axis_keeps_its_spin(tmp_path):
    spec = tmp_path / "free.yaml"
    spec.write_text(
        "name: free\nparts:\n  - {name: c, shape: cylinder, mass: 2, radius: 0.1, "
        "start: [0, 0, 0], end: [0, 0, 0.3]}\n"
    )
    run = prepare_run(
        load_body(spec), RunSettings(spin=5.0, duration=1.0, samples=11, error_estimate=False)
    ).simulate()
    assert not run.summary.scene.startswith("heavy top")
    omega = np.column_stack([run.columns()[f"w{c}"] for c in "xyz"])
    assert np.abs(omega).max(axis=0) == pytest.approx([0.0, 0.0, 5.0], abs=1e-9)


def test_the_csv_round_trips_every_number_and_leaves_nan_empty():
    columns = {name: np.zeros(2) for name in CSV_COLUMNS}
    columns["t"] = np.array([0.1 + 0.2, -0.0])
    columns["precession_deg"] = np.array([math.nan, 1e-300])
    header, *rows = trajectory_csv(columns).splitlines()
    assert header.split(",") == list(CSV_COLUMNS)
    cells = [dict(zip(CSV_COLUMNS, row.split(","), strict=True)) for row in rows]
    assert float(cells[0]["t"]) == 0.1 + 0.2
    assert cells[1]["t"] == "0.0"
    assert cells[0]["precession_deg"] == ""
    assert float(cells[1]["precession_deg"]) == 1e-300


def test_the_csv_cells_are_the_one_csv_cell_rule():
    """rbi.text.csv_cell writes every number (-0.0 made 0.0 first, as the CLI's CSV does)."""
    values = np.array([1 / 3, -2.5e-310, 1e300, 7.0, -0.0, math.nan, 0.1 + 0.2, -1e-5])
    columns = {name: np.roll(values, i) for i, name in enumerate(CSV_COLUMNS)}
    rows = [line.split(",") for line in trajectory_csv(columns).splitlines()[1:]]
    table = np.column_stack([columns[name] for name in CSV_COLUMNS])
    assert rows == [[csv_cell(v + 0.0) for v in row] for row in table.tolist()]


def test_a_trajectory_that_overflowed_is_refused_naming_the_column():
    with pytest.raises(InputError, match=r"top\.yaml.*wx.*not finite"):
        refuse_non_finite("top.yaml", {"wx": np.array([1.0, math.inf])})
    refuse_non_finite("top.yaml", {"precession_deg": np.array([math.nan])})
