"""`rbi inertia`, `rbi principal`, `rbi momentum`: options and output formats, checked against
the chapter's bolted top worked by hand (closed forms + parallel axis, one part at a time)."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess

# (mass, centre of mass, own central inertia) of each part of bodies/top_bolted.yaml.
m_c, r_c, h_c = 0.4, 0.04, 0.06
m_s, r_s, L_s = 0.1, 0.008, 0.04
PARTS = [
    (m_c, [0, 0, 0.75 * h_c], np.diag([3 * m_c * (4 * r_c**2 + h_c**2) / 80] * 2 + [0.3 * m_c * r_c**2])),
    (m_s, [0, 0, h_c + L_s / 2], np.diag([m_s * (3 * r_s**2 + L_s**2) / 12] * 2 + [m_s * r_s**2 / 2])),
    (0.02, [0.04, 0, 0.06], np.zeros((3, 3))),
]
MASS = sum(m for m, _, _ in PARTS)
COM = sum(m * np.array(c, dtype=float) for m, c, _ in PARTS) / MASS


def hand_inertia(point):
    total = np.zeros((3, 3))
    for m, c, own in PARTS:
        d = np.array(c, dtype=float) - point
        total += own + m * (d @ d * np.eye(3) - np.outer(d, d))
    return total


def rot(axis, degrees):
    t = math.radians(degrees)
    c, s = math.cos(t), math.sin(t)
    return {
        "x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


def run_ok(*args):
    proc = run_rbi_inprocess(*args)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    return proc.stdout


def rbi_json(*args):
    text = run_ok(*args, "--format", "json")
    assert text.endswith("\n") and text.count("\n") == 1  # exactly one object, one line
    return json.loads(text)


def assert_matrix(actual, expected, rel=1e-12):
    np.testing.assert_allclose(actual, expected, rtol=rel, atol=rel * np.abs(expected).max())


@pytest.fixture
def bolted(bodies):
    return bodies / "top_bolted.yaml"


def test_inertia_json_has_the_contract_keys(bolted):
    out = rbi_json("inertia", bolted)
    assert {"name", "units", "mass", "center_of_mass", "about", "inertia"} <= out.keys()
    assert out["name"] == "bolted-top" and out["units"] == {"length": "m", "mass": "kg"}
    assert out["mass"] == pytest.approx(MASS, rel=1e-15)
    np.testing.assert_allclose(out["center_of_mass"], COM, rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(out["about"], COM, rtol=1e-14, atol=1e-18)
    assert_matrix(out["inertia"], hand_inertia(COM))


@pytest.mark.parametrize(
    "about, point",
    [
        ("origin", [0.0, 0.0, 0.0]),
        ("pivot", [0.0, 0.0, 0.0]),
        ("0.01,-0.02,0.3", [0.01, -0.02, 0.3]),
        ("com", COM),
    ],
)
def test_inertia_about_a_point(bolted, about, point):
    out = rbi_json("inertia", bolted, "--about", about)
    np.testing.assert_allclose(out["about"], point, rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(out["center_of_mass"], COM, rtol=1e-14, atol=1e-18)
    assert_matrix(out["inertia"], hand_inertia(np.array(point, dtype=float)))


def test_rotations_chain_about_world_axes_in_the_order_given(bolted):
    out = rbi_json("inertia", bolted, "--rotate", "x:90", "--rotate", "z:-30", "--rotate", "y:45")
    R = rot("y", 45) @ rot("z", -30) @ rot("x", 90)
    assert_matrix(out["inertia"], R @ hand_inertia(COM) @ R.T)
    # The CoM and the reference point stay in body coordinates.
    np.testing.assert_allclose(out["center_of_mass"], COM, rtol=1e-14, atol=1e-18)
    reversed_order = rbi_json("inertia", bolted, "--rotate", "y:45", "--rotate", "z:-30", "--rotate", "x:90")
    assert np.abs(np.array(reversed_order["inertia"]) - out["inertia"]).max() > 1e-6  # order matters


def test_rotation_of_the_inertia_about_the_pivot(bolted):
    out = rbi_json("inertia", bolted, "--about", "pivot", "-r", "y:30")
    R = rot("y", 30)
    assert_matrix(out["inertia"], R @ hand_inertia(np.zeros(3)) @ R.T)


@pytest.mark.parametrize("about, point", [("com", COM), ("pivot", np.zeros(3))])
def test_principal_moments_and_axes(bolted, about, point):
    out = rbi_json("principal", bolted, "--about", about)
    I = hand_inertia(point)
    np.testing.assert_allclose(out["moments"], np.linalg.eigvalsh(I), rtol=1e-12)
    axes = np.array(out["axes"])
    np.testing.assert_allclose(axes @ axes.T, np.eye(3), atol=1e-14)
    assert np.linalg.det(axes) == pytest.approx(1.0, abs=1e-14)
    for moment, axis in zip(out["moments"], axes):
        np.testing.assert_allclose(I @ axis, moment * axis, atol=1e-15)


def test_principal_is_deterministic(bolted, bodies):
    for body in (bolted, bodies / "top.yaml"):
        assert run_ok("principal", body, "--format", "json") == run_ok("principal", body, "--format", "json")


def test_momentum_about_the_com(bolted):
    w = np.array([1.5, -2.0, 100.0])
    out = rbi_json("momentum", bolted, "--omega", "1.5,-2,100")
    I = hand_inertia(COM)
    h = I @ w
    np.testing.assert_allclose(out["omega"], w, rtol=0)
    np.testing.assert_allclose(out["angular_momentum"], h, rtol=1e-12)
    cos = h @ w / (np.linalg.norm(h) * np.linalg.norm(w))
    assert out["angle_deg"] == pytest.approx(math.degrees(math.acos(cos)), rel=1e-9)
    assert out["kinetic_energy"] == pytest.approx(0.5 * w @ I @ w, rel=1e-12)


def test_momentum_about_the_held_pivot(bolted):
    # No velocity given: the pivot is fixed, so h_o = I_o ω and T = ½ ωᵀ I_o ω.
    w = np.array([0.3, 0.0, 50.0])
    out = rbi_json("momentum", bolted, "--omega", "0.3,0,50", "--about", "pivot")
    I_o = hand_inertia(np.zeros(3))
    np.testing.assert_allclose(out["angular_momentum"], I_o @ w, rtol=1e-12)
    assert out["kinetic_energy"] == pytest.approx(0.5 * w @ I_o @ w, rel=1e-12)


def test_momentum_about_a_point_with_a_given_velocity(bolted):
    # h_o = I_c ω + m r_{c/o} × v_c and T = ½ ωᵀ I_c ω + ½ m |v_c|² (the chapter's extra term).
    w, v, o = np.array([0.0, 2.0, 10.0]), np.array([0.5, -0.25, 1.0]), np.array([0.1, 0.2, -0.3])
    out = rbi_json(
        "momentum", bolted, "--omega", "0,2,10", "--velocity", "0.5,-0.25,1", "--about", "0.1,0.2,-0.3"
    )
    I_c = hand_inertia(COM)
    np.testing.assert_allclose(out["angular_momentum"], I_c @ w + MASS * np.cross(COM - o, v), rtol=1e-12)
    assert out["kinetic_energy"] == pytest.approx(0.5 * w @ I_c @ w + 0.5 * MASS * v @ v, rel=1e-12)


def test_spin_about_a_principal_axis_has_h_parallel_to_omega(bolted):
    axis = np.array(rbi_json("principal", bolted)["axes"][0])
    out = rbi_json("momentum", bolted, "--omega", ",".join(repr(float(x)) for x in 7.0 * axis))
    assert out["angle_deg"] == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize(
    "args",
    [
        ["inertia"],
        ["inertia", "--about", "pivot", "--rotate", "y:30"],
        ["principal"],
        ["momentum", "--omega", "0,0,100"],
    ],
)
def test_csv_is_a_header_and_one_row_matching_json(bolted, args):
    rows = list(csv.reader(io.StringIO(run_ok(args[0], bolted, *args[1:], "--format", "csv"))))
    assert len(rows) == 2 and len(rows[0]) == len(rows[1])
    row = dict(zip(*rows))
    out = rbi_json(args[0], bolted, *args[1:])
    assert float(row["mass"]) == out["mass"]
    assert [float(row[f"center_of_mass_{c}"]) for c in "xyz"] == out["center_of_mass"]
    if "inertia" in out:  # full precision: exactly the JSON numbers
        assert [[float(row[f"inertia_{a}{b}"]) for b in "xyz"] for a in "xyz"] == out["inertia"]
    if "angular_momentum" in out:
        assert [float(row[f"angular_momentum_{c}"]) for c in "xyz"] == out["angular_momentum"]
        assert float(row["angle_deg"]) == out["angle_deg"]


@pytest.mark.parametrize(
    "args, labels",
    [
        (["inertia"], ["kg·m²", "kg", "0.52"]),
        (["inertia", "--rotate", "y:30"], ["kg·m²", "y:30"]),
        (["principal"], ["kg·m²", "2.250022", "2.949333"]),
        (["momentum", "--omega", "0,0,100"], ["kg·m²/s", "rad/s", "1.55996"]),
    ],
)
def test_table_is_readable_with_units(bolted, args, labels):
    text = run_ok(args[0], bolted, *args[1:])
    for label in labels:
        assert label in text, (label, text)
    assert "{" not in text  # a table, not JSON


@pytest.mark.parametrize("form", ["table", "json", "csv"])
@pytest.mark.parametrize(
    "command",
    [["inertia"], ["principal"], ["momentum", "--omega", "0,0,1"], ["dynamics", "--alpha", "1,0,0"]],
)
def test_about_names_the_same_points_in_the_same_words_as_the_api_and_the_spec(tmp_path, command, form):
    """One list of names (com, origin, pivot) and one wording behind --about, rbi.Body.point's
    about and a spec's expect about (the CLI once said 'pivot: --about pivot needs ...')."""
    import rbi

    free = tmp_path / "free.yaml"
    free.write_text("parts:\n  - {name: ball, shape: sphere, radius: 0.1, mass: 2, center: [0, 0, 1]}\n")
    proc = run_rbi_inprocess(*command[:1], free, *command[1:], "--about", "pivot", "-f", form)
    assert (proc.returncode, proc.stdout) == (2, "")
    assert proc.stderr == f"rbi: {free}: --about: pivot needs a `pivot` in the spec, and there is none\n"
    proc = run_rbi_inprocess(*command[:1], free, *command[1:], "--about", " Tip", "-f", form)
    assert proc.returncode == 2 and proc.stderr == (
        "rbi: --about: expected com, origin, pivot or a point X,Y,Z (three numbers separated by "
        "commas, file units), got ' Tip'\n"
    )
    out = rbi_json(*command[:1], free, *command[1:], "--about", " ORIGIN ")
    assert out["about"] == [0.0, 0.0, 0.0]
    body = rbi.load(free)
    with pytest.raises(ValueError) as refused:
        body.point("pivot")
    assert str(refused.value) == f"{free}: about: pivot needs a `pivot` in the spec, and there is none"
    with pytest.raises(ValueError) as refused:
        body.point(" Tip")
    assert str(refused.value) == "about: expected com, origin, pivot or a point (x, y, z), got ' Tip'"
    free.write_text(free.read_text() + "expect:\n  moments: {value: [1, 1, 1], tol: 1%, about: tip}\n")
    proc = run_rbi_inprocess("check", free)
    assert proc.returncode == 2
    assert "expect.moments.about: must be com, origin, pivot or a point [x, y, z] (got 'tip')" in proc.stderr
