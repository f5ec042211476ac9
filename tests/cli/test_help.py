"""Help a newcomer can live in: an example in every command's --help, whole summaries in
`rbi --help` on an 80-column terminal, plain FILE in usage lines."""

from __future__ import annotations

import os

import pytest

from rbi.cli.app import COMMANDS
from tests.conftest import run_rbi, run_rbi_inprocess


def _help(*args: str) -> str:
    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "80"
    try:
        proc = run_rbi_inprocess(*args, "--help")
    finally:
        if saved is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = saved
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


@pytest.mark.parametrize("command", list(COMMANDS))
def test_every_command_help_has_a_runnable_looking_example(command):
    text = _help(command)
    assert "Example" in text
    assert f"rbi {command} " in text.split("Example", 1)[1]


@pytest.mark.parametrize("command", list(COMMANDS))
def test_usage_lines_read_naturally(command):
    text = _help(command)
    usage = text.splitlines()[0]
    assert "{" not in usage and "<str>" not in text and "<float>" not in text, usage


def test_summaries_are_whole_on_an_80_column_terminal():
    proc = run_rbi("--help")
    env_text = _help()
    for text in (proc.stdout, env_text):
        assert "..." not in text.split("Commands:", 1)[1]
    commands = env_text.split("Commands:", 1)[1].splitlines()[1:]
    # one line per command: no summary wrapped onto a second line
    assert [line.split()[0] for line in commands if line.strip()] == list(COMMANDS)


def test_every_summary_fits_in_seventy_characters():
    assert all(len(summary) <= 70 for _, _, summary in COMMANDS.values())


def test_about_errors_list_the_named_points(bodies):
    proc = run_rbi_inprocess("inertia", bodies / "top.yaml", "--about", "middle")
    assert proc.returncode == 2
    assert all(word in proc.stderr for word in ("com", "origin", "pivot", "X,Y,Z"))


def test_dynamics_table_gives_force_and_torque_units(bodies):
    proc = run_rbi_inprocess("dynamics", bodies / "robot_link.yaml", "--alpha", "0,0,10", "--about", "pivot")
    assert proc.returncode == 0, proc.stderr
    force = next(line for line in proc.stdout.splitlines() if line.strip().startswith("force"))
    torque = next(line for line in proc.stdout.splitlines() if line.strip().startswith("torque"))
    assert " N " in force and " N·m " in torque
    # a spec in g and mm: 1 g·mm/s² is 1e-6 N, 1 g·mm²/s² is 1e-9 N·m
    proc = run_rbi_inprocess("dynamics", bodies / "wheel_with_holes.yaml", "--alpha", "0,0,10")
    assert "g·mm/s² (= 1e-06 N)" in proc.stdout and "g·mm²/s² (= 1e-09 N·m)" in proc.stdout


@pytest.mark.parametrize("command", ["inertia", "principal"])
def test_units_help_names_no_option_the_command_lacks(command):
    # `rbi inertia --help` said "Command-line inputs (--about X,Y,Z, --velocity) stay in the
    # file's units", and inertia has no --velocity
    text = _help(command)
    assert "--velocity" not in text
    assert "--about X,Y,Z point) stay in the file's units" in " ".join(text.split())


def test_schema_help_offers_only_the_formats_it_prints():
    # `rbi schema --help` offered <table|json|csv> and `rbi schema -f csv` was refused
    text = _help("schema")
    assert "<table|json>" in text and "csv" not in text
    refused = run_rbi_inprocess("schema", "-f", "csv")
    assert refused.returncode == 2 and "'csv' is not one of 'table', 'json'" in refused.stderr


def test_validate_help_says_it_reads_robot_files(bodies):
    # `rbi validate --help` said "Spec files (YAML) to check." while it checks URDF, SDF, MJCF too
    text = " ".join(_help("validate").split())
    assert "Spec files (YAML)" not in text
    assert all(word in text for word in (".urdf", ".sdf", "MJCF", "JSON", "standard input"))
    assert run_rbi_inprocess("validate", bodies / "two_link_arm.urdf").returncode == 0


@pytest.mark.parametrize("command", ["", *COMMANDS])
def test_no_help_line_is_wider_than_the_terminal(command):
    # at COLUMNS=80, `rbi sweep --help` printed an example of 112 characters (it wrapped in the
    # middle of --vary's value), `rbi bench --help` one of 88 and `rbi audit --help` one of 82
    text = _help(*([command] if command else []))
    wide = [line for line in text.splitlines() if len(line) > 80]
    assert not wide, wide


def test_the_gif_rate_says_its_range(bodies, tmp_path):
    # `rbi animate --help` said only 'Frames per second of a GIF.', and --fps 61 is refused
    # ('must be between 1 and 60'), as is a GIF of more than 1500 frames
    text = " ".join(_help("animate").split())
    assert "Frames per second of a GIF, 1–60;" in text and "at most 1500" in text
    out = tmp_path / "x.gif"
    refused = run_rbi_inprocess("animate", bodies / "top.yaml", "--spin", "100", "--fps", "61", "--out", out)
    assert refused.returncode == 2 and "between 1 and 60" in refused.stderr and not out.exists()
