"""Whole-process behaviour of the entry point: usage errors and overflow are one line, exit 2."""

import pytest

from tests.conftest import BODIES, run_rbi

TOP = BODIES / "top.yaml"


@pytest.mark.parametrize(
    "args, needle",
    [
        (["momentum", TOP], "--omega"),  # a required option missing
        (["inertia", TOP, "--format", "xml"], "--format"),  # a bad choice
        (["bogus"], "bogus"),  # an unknown command
        (["inertia", TOP, "--about", "1e200,0,0", "-f", "json"], "overflows"),  # overflow, not nulls
        (["momentum", TOP, "--omega", "1e200,0,0"], "not finite"),
    ],
)
def test_bad_invocations_exit_2_with_one_line(args, needle):
    proc = run_rbi(*args)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], proc.stderr
    assert proc.stdout == ""


def test_no_arguments_prints_the_command_list():
    proc = run_rbi()
    assert proc.returncode == 0
    for command in ("inertia", "principal", "momentum", "simulate"):
        assert command in proc.stdout


def test_a_missing_choice_option_lists_its_choices_on_the_one_line():
    # click lays the choices out one per line; escaped, that read 'Choose from:\n\turdf,\n\tmjcf'
    proc = run_rbi("export", TOP)
    assert proc.returncode == 2
    assert (
        proc.stderr
        == "rbi: Missing option '--to' / '-t'. Choose from: urdf, mjcf, sdf (see `rbi export --help`)\n"
    )
