"""Every spelling of an option gives the same bytes and exit status as its long form: ``-f csv``,
``-fcsv``, ``--format=csv`` and ``--format csv``; a repeated option keeps its last value (a
repeatable one, ``--rotate``, keeps them all in order); a trailing ``--`` changes nothing."""

from __future__ import annotations

import pytest

from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as rbi

TOP, BOLTED = BODIES / "top.yaml", BODIES / "top_bolted.yaml"

SAME = [
    (
        ["inertia", BOLTED, "-fjson", "--about", "-0.01,0,0.02", "-r", "y:30", "--rotate=x:-15"],
        [
            "inertia",
            BOLTED,
            "--format",
            "json",
            "--about",
            "-0.01,0,0.02",
            "--rotate",
            "y:30",
            "--rotate",
            "x:-15",
        ],
    ),
    (
        ["inertia", TOP, BOLTED, "--axis", "1,1,0", "--products", "cad", "-f", "csv"],
        ["inertia", TOP, BOLTED, "--axis=1,1,0", "--products=cad", "--format", "csv"],
    ),
    (["inertia", TOP, "--units", "mm,g", "-f", "json"], ["inertia", TOP, "-u", "mm,g", "--format=json"]),
    (["inertia", TOP, "--about", "pivot", "--about", "com"], ["inertia", TOP, "--about", "com"]),
    (
        ["principal", BODIES / "rocket.yaml", "-a", "origin", "-u", "SI"],
        ["principal", BODIES / "rocket.yaml", "--about", "origin", "--units", "SI"],
    ),
    (["principal", TOP, "nope.yaml", "--format", "json"], ["principal", TOP, "nope.yaml", "-fjson"]),
    (
        ["parts", BODIES / "wheel_with_holes.yaml", BODIES / "cubesat.yaml", "--"],
        ["parts", BODIES / "wheel_with_holes.yaml", BODIES / "cubesat.yaml"],
    ),
    (["parts", BOLTED, "-fcsv"], ["parts", BOLTED, "--format", "csv"]),
    (
        ["check", BODIES / "robot_link.yaml", TOP, "-f", "json"],
        ["check", BODIES / "robot_link.yaml", TOP, "--format=json"],
    ),
    (["inertia", TOP, "--axis", "0,0,0", "--"], ["inertia", TOP, "--axis", "0,0,0"]),
]


@pytest.mark.parametrize(
    "short,long", SAME, ids=lambda a: " ".join(str(x).replace(str(BODIES) + "/", "") for x in a)
)
def test_same_bytes_and_status_as_the_long_spelling(short, long, monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")
    a, b = rbi(*short), rbi(*long)
    assert (a.returncode, a.stdout, a.stderr) == (b.returncode, b.stdout, b.stderr)
    assert a.stdout or a.stderr


def test_the_rotations_are_applied_in_order_not_merged(monkeypatch):
    one = rbi("inertia", BOLTED, "-r", "y:30", "-r", "x:-15", "-f", "json").stdout
    other = rbi("inertia", BOLTED, "-r", "x:-15", "-r", "y:30", "-f", "json").stdout
    assert one != other
