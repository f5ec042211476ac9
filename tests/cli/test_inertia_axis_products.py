"""`rbi inertia --axis/--products`, radii of gyration in `rbi principal`, and the help examples,
against closed forms."""

from __future__ import annotations

import json

import numpy as np
import pytest

import rbi
from tests.conftest import one_line_exit_2, run_rbi_inprocess

CYLINDER = """
name: rod-like
parts:
  - {name: bar, shape: cylinder, mass: 2.0, radius: 0.05, start: [0, 0, 0], end: [0, 0, 0.4]}
"""
M, R, L = 2.0, 0.05, 0.4

POINTS = """
name: two-points
parts:
  - {name: a, shape: point, mass: 2.0, position: [0.3, 0.2, 0.5]}
  - {name: b, shape: point, mass: 1.0, position: [0.0, 0.0, 0.0]}
"""


def json_of(*args) -> dict:
    proc = run_rbi_inprocess(*args, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_moment_about_a_diameter_through_the_end_face(write_spec):
    path = write_spec(CYLINDER)
    result = json_of("inertia", path, "--about", "origin", "--axis", "3,4,0")
    assert result["moment_about_axis"] == pytest.approx(M * (R**2 / 4 + L**2 / 3), rel=1e-13)
    assert result["axis"] == pytest.approx([0.6, 0.8, 0.0], rel=1e-15)
    assert result["about"] == [0.0, 0.0, 0.0]


def test_axis_is_in_the_rotated_axes_after_rotate(write_spec):
    # Turned 90° about y, the bar lies along world x: about world x through the CoM, m r²/2;
    # about world z through the CoM, m(3r² + L²)/12.
    path = write_spec(CYLINDER)
    along = json_of("inertia", path, "--rotate", "y:90", "--axis", "1,0,0")
    across = json_of("inertia", path, "--rotate", "y:90", "--axis", "0,0,-2")
    assert along["moment_about_axis"] == pytest.approx(M * R**2 / 2, rel=1e-12)
    assert across["moment_about_axis"] == pytest.approx(M * (3 * R**2 + L**2) / 12, rel=1e-12)


def test_axis_in_other_output_units(write_spec):
    path = write_spec(CYLINDER)
    result = json_of("inertia", path, "--about", "origin", "--axis", "1,0,0", "--units", "mm,g")
    assert result["moment_about_axis"] == pytest.approx(M * (R**2 / 4 + L**2 / 3) * 1e9, rel=1e-13)


def test_axis_appears_in_the_table(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec(CYLINDER), "--axis", "0,0,1")
    assert proc.returncode == 0, proc.stderr
    assert "moment about axis" in proc.stdout
    assert "0.0025" in proc.stdout  # m r²/2 = 2 · 0.0025 / 2


@pytest.mark.parametrize("value", ["0,0,0", "1,2", "a,b,c", "nan,0,1"])
def test_bad_axis_is_one_line_exit_2(write_spec, value):
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(CYLINDER), "--axis", value), "--axis")


def test_cad_products_are_positive_integrals_and_labelled(write_spec):
    # About the origin only point a contributes to products: ∫xy dm = 2·0.3·0.2 = 0.12,
    # ∫xz dm = 2·0.3·0.5 = 0.3, ∫yz dm = 2·0.2·0.5 = 0.2; the tensor entries are their negatives.
    path = write_spec(POINTS)
    tensor = json_of("inertia", path, "--about", "origin")
    cad = json_of("inertia", path, "--about", "origin", "--products", "cad")
    assert tensor["products_sign"] == "tensor" and cad["products_sign"] == "cad"
    assert [cad["inertia"][0][1], cad["inertia"][0][2], cad["inertia"][1][2]] == pytest.approx(
        [0.12, 0.3, 0.2]
    )
    assert [tensor["inertia"][0][1], tensor["inertia"][0][2], tensor["inertia"][1][2]] == pytest.approx(
        [-0.12, -0.3, -0.2]
    )
    assert cad["inertia"][1][0] == cad["inertia"][0][1]
    # the moments do not change: Ixx = Σ m (y² + z²) = 2 (0.04 + 0.25)
    assert cad["inertia"][0][0] == tensor["inertia"][0][0] == pytest.approx(0.58)
    table = run_rbi_inprocess("inertia", path, "--products", "cad").stdout
    assert "CAD products" in table
    assert (
        "products" in run_rbi_inprocess("inertia", path).stdout
        and "CAD" not in run_rbi_inprocess("inertia", path).stdout
    )


def test_moment_about_axis_does_not_depend_on_the_products_sign(write_spec):
    path = write_spec(POINTS)
    a = json_of("inertia", path, "--axis", "1,1,1")["moment_about_axis"]
    b = json_of("inertia", path, "--axis", "1,1,1", "--products", "cad")["moment_about_axis"]
    assert a == b


def test_products_sign_in_csv(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec(POINTS), "--products", "cad", "--format", "csv")
    header, row = proc.stdout.splitlines()[:2]
    assert row.split(",")[header.split(",").index("products_sign")] == "cad"


def test_bad_products_value_is_exit_2(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec(POINTS), "--products", "positive")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


def test_export_keeps_the_tensor_sign(write_spec):
    proc = run_rbi_inprocess("export", write_spec(POINTS), "--to", "urdf", "--products", "cad")
    assert proc.returncode == 2  # export has no --products: robot formats take the matrix entries
    xml = run_rbi_inprocess("export", write_spec(POINTS), "--to", "urdf").stdout
    assert 'ixy="-' in xml  # about the CoM the xy product of this body is negative in the tensor sign


def test_radii_of_gyration_of_a_sphere(write_spec):
    path = write_spec("parts:\n  - {shape: sphere, mass: 3.0, radius: 0.2, center: [1, 2, 3]}\n")
    result = json_of("principal", path)
    assert [k**2 for k in result["radii_of_gyration"]] == pytest.approx([2 * 0.2**2 / 5] * 3, rel=1e-13)
    table = run_rbi_inprocess("principal", path).stdout
    assert "radius of gyration [m]" in table


def test_radii_of_gyration_about_the_end_of_a_bar(write_spec):
    # About the end face's centre the cylinder's two transverse moments are m(r²/4 + L²/3): k² = r²/4 + L²/3.
    result = json_of("principal", write_spec(CYLINDER), "--about", "origin")
    k_axial, k_transverse, _ = result["radii_of_gyration"]
    assert k_axial**2 == pytest.approx(R**2 / 2, rel=1e-13)
    assert k_transverse**2 == pytest.approx(R**2 / 4 + L**2 / 3, rel=1e-13)


@pytest.mark.parametrize("command", ["inertia", "principal", "momentum", "import"])
def test_help_has_examples(command):
    proc = run_rbi_inprocess(command, "--help")
    assert proc.returncode == 0
    assert "Examples:" in proc.stdout and f"rbi {command} " in proc.stdout


def test_radii_in_csv_are_numbered_like_the_moments(write_spec):
    path = write_spec("parts:\n  - {shape: box, mass: 12.0, size: [1, 2, 3], center: [0, 0, 0]}\n")
    header, row = run_rbi_inprocess("principal", path, "--format", "csv").stdout.splitlines()[:2]
    values = dict(zip(header.split(","), row.split(",")))
    # box 1 × 2 × 3, 12 kg: moments m(b² + c²)/12 → 5, 10, 13; k_i² = I_i / m
    assert [float(values[f"radii_of_gyration_{i}"]) ** 2 for i in (1, 2, 3)] == pytest.approx(
        [5 / 12, 10 / 12, 13 / 12]
    )


def test_cad_products_are_the_positive_integrals():
    # One point mass m at (a, b, c) about the origin: ∫xy dm = m a b, and the tensor entry is −m a b.
    m, (a, b, c) = 2.0, (0.3, -0.4, 0.5)
    body = rbi.load({"parts": [{"shape": "point", "mass": m, "position": [a, b, c]}]})
    I = body.inertia_report("origin").matrix
    cad = body.inertia_report("origin", products="cad").matrix
    assert cad[0, 1] == pytest.approx(m * a * b) and cad[1, 0] == pytest.approx(m * a * b)
    assert cad[0, 2] == pytest.approx(m * a * c) and cad[1, 2] == pytest.approx(m * b * c)
    assert I[0, 1] == pytest.approx(-m * a * b)
    assert np.array_equal(np.diag(cad), np.diag(I))
    assert np.array_equal(body.inertia("origin"), I)  # tensor: the matrix itself
    box = rbi.load({"parts": [{"shape": "box", "mass": 1.0, "size": [1, 2, 3], "center": [0, 0, 0]}]})
    assert not np.signbit(
        box.inertia_report(products="cad").matrix
    ).any()  # no −0.0 printed for a zero product
    with pytest.raises(ValueError):
        body.inertia_report(products="solidworks")
