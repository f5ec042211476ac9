"""`rbi check`: the `expect:` block, exit 0 / 1 / 2, and each output format.

The seed's top (bodies/top.yaml) has mass 0.5 kg, CoM (0, 0, 0.052) m, principal moments
about the CoM 0.0001952 and 0.000262933… kg·m², and Ixx = Iyy = 0.0016149333… about the tip."""

from __future__ import annotations

import csv
import io
import json

import pytest

from tests.conftest import BODIES, run_rbi, run_rbi_inprocess

TOP = (BODIES / "top.yaml").read_text()


def with_expect(write_spec, block: str):
    return write_spec(TOP + "expect:\n" + block)


def test_all_hold_exit_0(write_spec):
    path = with_expect(
        write_spec,
        """
  mass: {value: 0.5, tol: 0.1%}
  center_of_mass: {value: [0, 0, 0.052], tol: 1e-9}
  moments: {value: [0.0002629, 0.0001952, 0.0002629], tol: 0.05%}
  inertia: {value: {ixx: 0.00161493, iyy: 0.00161493, izz: 0.0001952}, tol: 1e-8, about: pivot}
""",
    )
    proc = run_rbi_inprocess("check", path, "-f", "json")
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["ok"] is True and out["passed"] == 4 and out["failed"] == 0
    assert [c["quantity"] for c in out["checks"]] == ["mass", "center_of_mass", "moments", "inertia"]
    assert out["checks"][2]["expected"] == [0.0001952, 0.0002629, 0.0002629]  # compared in ascending order


def test_contract_example_fails_the_mass_by_4_percent_exit_1(write_spec):
    # The contract's example expects 0.52 kg: the top is 0.5 kg, 3.8 % off, outside 1 %.
    path = with_expect(
        write_spec,
        "  mass: {value: 0.52, tol: 1%}\n  center_of_mass: {value: [0.0015, 0, 0.0523], tol: 0.0001}\n",
    )
    proc = run_rbi_inprocess("check", path, "-f", "json")
    assert proc.returncode == 1
    mass, com = json.loads(proc.stdout)["checks"]
    assert (
        mass["pass"] is False
        and mass["allowed"] == pytest.approx(0.0052)
        and mass["deviation"] == pytest.approx(0.02)
    )
    assert com["pass"] is False and com["deviation"] == pytest.approx(0.0015)


def test_percentage_is_of_the_largest_expected_magnitude(write_spec):
    # 1 % of |0.052| = 0.00052 applies to every component, so x = 0.0005 off still passes.
    path = with_expect(write_spec, "  center_of_mass: {value: [0.0005, 0, 0.052], tol: 1%}\n")
    assert run_rbi_inprocess("check", path).returncode == 0
    path = with_expect(write_spec, "  center_of_mass: {value: [0.0006, 0, 0.052], tol: 1%}\n")
    assert run_rbi_inprocess("check", path).returncode == 1


def test_csv_has_one_row_per_component_and_table_marks_failures(write_spec):
    path = with_expect(
        write_spec,
        "  mass: {value: 0.52, tol: 1%}\n  inertia: {value: [[2.6e-4, 0, 0], [0, 2.6e-4, 0], [0, 0, 1.95e-4]], tol: 2%}\n",
    )
    rows = list(csv.DictReader(io.StringIO(run_rbi_inprocess("check", path, "-f", "csv").stdout)))
    assert [r["component"] for r in rows] == ["mass", "Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"]
    assert rows[0]["pass"] == "False" and all(r["pass"] == "True" for r in rows[1:])
    table = run_rbi_inprocess("check", path)
    assert table.returncode == 1 and "FAIL" in table.stdout and "1 of 2 expectations FAIL" in table.stdout


@pytest.mark.parametrize(
    "block, words",
    [
        ("  mass: {value: 0.5, tol: abc}\n", "expect.mass.tol: must be a percentage such as 1%"),
        ("  mass: {value: 0.5, tol: -1}\n", "expect.mass.tol: must not be negative"),
        ("  mass: {value: 0.5}\n", "expect.mass.tol: missing required field"),
        ("  masss: {value: 0.5, tol: 1%}\n", "expect.masss: unknown field"),
        (
            "  center_of_mass: {value: [0, 0], tol: 1%}\n",
            "expect.center_of_mass.value: must be a list of 3 numbers",
        ),
        ("  inertia: {value: [[1, 0, 0]], tol: 1%}\n", "expect.inertia.value: must be a 3×3 matrix"),
        (
            "  inertia: {value: {ixx: 1, iyy: 1, izz: 1}, tol: 1%, about: tip}\n",
            "expect.inertia.about: must be com, origin, pivot",
        ),
        ("  {}\n", "expect: give at least one of"),
    ],
)
def test_bad_expect_block_exits_2_naming_the_field(write_spec, block, words):
    proc = run_rbi_inprocess("check", with_expect(write_spec, block))
    assert proc.returncode == 2 and words in proc.stderr, proc.stderr
    assert "Traceback" not in proc.stderr


def test_no_expect_block_exits_2():
    proc = run_rbi_inprocess("check", BODIES / "top.yaml")
    assert proc.returncode == 2 and "no `expect:` block" in proc.stderr


def test_installed_command_exit_status(write_spec):
    assert run_rbi("check", with_expect(write_spec, "  mass: {value: 0.5, tol: 0}\n")).returncode == 0


FREE_TOP = TOP.replace("pivot: [0, 0, 0]\n", "")
"""The top without its pivot; its tip stays at the origin (Ixx = 0.0016149333… kg·m² about it)."""


@pytest.mark.parametrize("about, label", [("origin", "origin"), ("[0, 0, 0]", "point")])
def test_inertia_about_the_origin_or_a_point_of_a_free_body(write_spec, about, label):
    block = f"  inertia: {{value: {{ixx: 0.00161493, iyy: 0.00161493, izz: 0.0001952}}, tol: 1e-8, about: {about}}}\n"
    path = write_spec(FREE_TOP + "expect:\n" + block)
    out = json.loads(run_rbi_inprocess("check", path, "-f", "json").stdout)
    assert out["ok"] is True and out["checks"][0]["about"] == label


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_about_pivot_of_a_free_body_exits_2_in_every_form(write_spec, form):
    block = "  moments: {value: [1, 1, 1], tol: 1%, about: pivot}\n"
    path = write_spec(FREE_TOP + "expect:\n" + block)
    proc = run_rbi_inprocess("check", path, "-f", form)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.strip().endswith(
        f"{path}: expect: about: pivot needs a `pivot` in the spec, and there is none"
    ), proc.stderr
