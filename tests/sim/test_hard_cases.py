"""Hard cases for the simulator, beyond tests/sim (which covers the Lagrange top at 1e4 rad/s,
the bolted top over 1000 s, the sleeping top at ±2 % of its threshold, the flip period of a
synthetic body and the refusal of a needle on its pivot): an asymmetric free body at 1e4
rad/s and over 1000 s against Euler–Poinsot, the bolted top at 1e4 rad/s, the sleeping-top
threshold to 0.1 % against the turning points of the energy cubic, the T-handle's flip period
through the command line against moments worked out by hand, and singular bodies refused.
Reference values are derived here from textbook formulas, not taken from rbi."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from scipy.special import ellipk

from rbi.sim.api import simulate
from rbi.sim.diagnostics import conserved_quantities, orientation_error_deg, tilt_deg
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.spec.load import load_body
from rbi.spec.units import gravity_in
from tests.conftest import BODIES, run_rbi

UNIT_Q = 4 * np.finfo(float).eps  # | |q| − 1 | allowed after the projection to unit length


def scene(name: str):
    body = load_body(BODIES / name)
    return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit))


def largest_drift(scene_, run) -> float:
    return max(d["drift"] for d in conserved_quantities(scene_, run.q, run.omega).values())


# --- high spin ------------------------------------------------------------------------------


@pytest.mark.parametrize("omega", [[6e3, 0.0, 8e3], [3e3, 4e3, 5e3 * math.sqrt(2.0)]])
def test_free_tumbling_at_ten_thousand_rad_per_s_follows_euler_poinsot(omega):
    # About 1600 turns in one second, a generic tumble of the T-handle.
    free = scene("tbar.yaml")
    q0, w0 = initial_state(0.0, omega)
    run = simulate(free, q0, w0, 1.0, 1001)
    closed = simulate(free, q0, w0, 1.0, 1001, method="exact")
    assert np.max(np.abs(np.linalg.norm(run.q, axis=1) - 1.0)) <= UNIT_Q
    assert np.max(orientation_error_deg(run.q, closed.q)) < 3e-4
    assert np.max(np.abs(run.omega - closed.omega)) < 1e-6 * np.linalg.norm(omega)
    assert largest_drift(free, run) < 3e-9


def test_bolted_top_at_ten_thousand_rad_per_s_converges():
    # No closed form: a run at the default tolerance against one 100 times tighter.
    bolted = scene("top_bolted.yaml")
    q0, w0 = initial_state(5.0, [0.0, 0.0, 1e4])
    run = simulate(bolted, q0, w0, 1.0, 101)
    tight = simulate(bolted, q0, w0, 1.0, 101, rtol=1e-14)
    assert np.max(orientation_error_deg(run.q, tight.q)) < 2e-4
    assert np.max(np.abs(run.omega - tight.omega)) < 1e-8 * 1e4
    assert largest_drift(bolted, run) < 3e-9
    assert np.max(np.abs(np.linalg.norm(run.q, axis=1) - 1.0)) <= UNIT_Q


# --- long runs ------------------------------------------------------------------------------


def test_a_thousand_seconds_of_tumbling_against_the_closed_form():
    free = scene("tbar.yaml")
    q0, w0 = initial_state(0.0, [12.0, 16.0, 20.0])  # ~ 2600 periods of ω
    run = simulate(free, q0, w0, 1000.0, 2001)
    closed = simulate(free, q0, w0, 1000.0, 2001, method="exact")
    assert np.max(np.abs(np.linalg.norm(run.q, axis=1) - 1.0)) <= UNIT_Q
    drifts = conserved_quantities(free, run.q, run.omega)
    assert drifts["energy"]["drift"] < 1e-8 and drifts["h_world"]["drift"] < 1e-8
    # The phase error grows about linearly: after 1000 s still a few thousandths of a degree.
    errors = orientation_error_deg(run.q, closed.q)
    assert errors[-1] < 5e-3
    assert errors[: errors.size // 10].max() < errors[-1]  # it grows, it does not jump


# --- the sleeping-top threshold, from both sides ----------------------------------------------


def lowest_turning_point_deg(top, tilt0_deg: float, spin: float) -> float:
    """Largest tilt of a symmetric top started at tilt θ₀ with pure spin ω₃ and no other
    motion: u = cos θ moves between u₀ = cos θ₀ and the lower root of
    β(1 − u²) − b²(u₀ − u) = 0 (β = 2mgl/I₁, b = I₃ω₃/I₁), the other factor of the energy
    cubic f(u) = (u₀ − u)[β(1 − u²) − b²(u₀ − u)]. Written as c/u_high to avoid cancellation."""
    m, g, l = top.mass, top.gravity, float(top.com_from_pivot[2])
    I1, I3 = top.inertia[0, 0], top.inertia[2, 2]
    beta = 2 * m * g * l / I1
    b2 = (I3 * spin / I1) ** 2
    u0 = math.cos(math.radians(tilt0_deg))
    root = math.sqrt((b2 - 2 * beta) ** 2 + 4 * beta * b2 * (1 - u0))
    u_high = (b2 + root) / (2 * beta)
    u_low = (b2 * u0 - beta) / beta / u_high  # product of the roots of β u² − b² u + (b² u₀ − β)
    return math.degrees(math.acos(min(u_low, 1.0)))


@pytest.mark.parametrize("fraction", [0.99, 0.999, 1.001, 1.01])
def test_sleeping_threshold_to_a_tenth_of_a_percent(fraction):
    top = scene("top.yaml")
    m, g, l = top.mass, top.gravity, float(top.com_from_pivot[2])
    I1, I3 = top.inertia[0, 0], top.inertia[2, 2]
    threshold = math.sqrt(4 * m * g * l * I1) / I3  # ω₃² = 4 m g l I₁ / I₃²
    spin = fraction * threshold
    tilt0 = 0.01
    run = simulate(top, *initial_state(tilt0, [0.0, 0.0, spin]), 20.0, 20001)
    highest = float(np.max(tilt_deg(run.q)))
    expected = lowest_turning_point_deg(top, tilt0, spin)
    # Sampled every millisecond, the largest sample sits within 1e-5 of the turning point.
    assert highest == pytest.approx(expected, rel=1e-5)
    if fraction < 1:
        assert highest > 5.0  # it falls: 0.1 % below the threshold already 5 degrees
    else:
        assert highest < 0.25  # it stays up within a quarter of a degree


# --- the Dzhanibekov flip through the command line -------------------------------------------


def t_handle_moments() -> tuple[float, float, float]:
    """Central moments of bodies/tbar.yaml about x, y, z, worked out by hand: handle (0.3 kg,
    r 0.01, length 0.2 along x, centred at the origin) and shank (0.2 kg, r 0.008, length 0.12
    along z from the origin); centre of mass at z = 0.2·0.06/0.5 = 0.024."""
    mh, rh, Lh = 0.3, 0.01, 0.2
    ms, rs, Ls = 0.2, 0.008, 0.12
    zc = ms * 0.06 / (mh + ms)
    dh, ds = zc, 0.06 - zc
    handle_axial, handle_transverse = mh * rh**2 / 2, mh * (3 * rh**2 + Lh**2) / 12
    shank_axial, shank_transverse = ms * rs**2 / 2, ms * (3 * rs**2 + Ls**2) / 12
    Ixx = handle_axial + mh * dh**2 + shank_transverse + ms * ds**2
    Iyy = handle_transverse + mh * dh**2 + shank_transverse + ms * ds**2
    Izz = handle_transverse + shank_axial
    return Ixx, Iyy, Izz


def test_t_handle_flips_with_the_elliptic_period_through_the_command_line(tmp_path):
    Ixx, Iyy, Izz = t_handle_moments()
    I1, I2, I3 = Ixx, Izz, Iyy  # minor x, intermediate z, major y
    assert I1 < I2 < I3
    w = {"x": 0.05, "y": 0.0, "z": 10.0}  # spun about the intermediate axis, nudged towards x
    two_T = Ixx * w["x"] ** 2 + Izz * w["z"] ** 2
    M2 = (Ixx * w["x"]) ** 2 + (Izz * w["z"]) ** 2
    assert M2 < two_T * I2  # ω circulates about the minor axis (Landau's case with 1 and 3 swapped)
    lam = math.sqrt((I2 - I1) * (two_T * I3 - M2) / (I1 * I2 * I3))
    k2 = (I3 - I2) * (M2 - two_T * I1) / ((I2 - I1) * (two_T * I3 - M2))
    half_period = 2 * float(ellipk(k2)) / lam  # ω_z ∝ sn changes sign every 2K/λ
    out = tmp_path / "flip.csv"
    duration = 3.5 * half_period
    run_rbi(
        "simulate",
        BODIES / "tbar.yaml",
        "--omega",
        f"{w['x']},{w['y']},{w['z']}",
        "--duration",
        repr(duration),
        "--samples",
        "20001",
        "--out",
        out,
        "--format",
        "json",
        check=True,
    )
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    t = np.array([float(r["t"]) for r in rows])
    wz = np.array([float(r["wz"]) for r in rows])
    crossing = np.flatnonzero(np.sign(wz[1:]) != np.sign(wz[:-1]))
    times = t[crossing] - wz[crossing] * (t[crossing + 1] - t[crossing]) / (wz[crossing + 1] - wz[crossing])
    assert len(times) == 3
    np.testing.assert_allclose(np.diff(times), half_period, rtol=1e-6)


# --- singular bodies ---------------------------------------------------------------------------


@pytest.mark.parametrize("pivot", [None, "[-0.5, -0.5, -0.5]"])
def test_bodies_of_collinear_points_cannot_be_simulated(write_spec, tmp_path, pivot):
    # Point masses on the slanted line through (1, 1, 1): no inertia about that line, through
    # their centre of mass (free body) or through a pivot on the same line.
    spec = write_spec(
        ("" if pivot is None else f"pivot: {pivot}\n")
        + """parts:
  - {shape: point, mass: 1.0, position: [1.0, 1.0, 1.0]}
  - {shape: point, mass: 2.0, position: [2.0, 2.0, 2.0]}
  - {shape: point, mass: 0.5, position: [-3.0, -3.0, -3.0]}
"""
    )
    out = tmp_path / "never.csv"
    proc = run_rbi("simulate", spec, "--omega", "1,2,3", "--out", out)
    assert proc.returncode == 2
    assert "singular" in proc.stderr and str(spec) in proc.stderr
    assert "Traceback" not in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_a_body_of_1e290_inertia_is_simulated_in_every_form(write_spec):
    """A solid cylinder of mass 1e150, radius 1e70, length 2e70 spinning at 20 rad/s: every
    number is a finite double (I_zz = M R²/2 = 5e289, |h| = 1e291, E = 1e292), but |h|² is not.
    The table and JSON refused it ('result conserved is not finite', the angular momentum's
    drift computed as inf/inf) while the CSV of the same run was written: all three now agree."""
    path = write_spec(
        "name: huge\nparts:\n  - {shape: cylinder, mass: 1e150, radius: 1e70, start: [0, 0, -1e70], end: [0, 0, 1e70]}\n"
    )
    args = ["simulate", path, "--spin", "20", "--tilt", "5", "--duration", "0.05", "--samples", "5"]
    table, js, cs = (run_rbi(*args, "--format", form) for form in ("table", "json", "csv"))
    assert (table.returncode, js.returncode, cs.returncode) == (0, 0, 0), (table.stderr, js.stderr)
    summary = __import__("json").loads(js.stdout)
    conserved = summary["conserved"]
    assert conserved["energy"]["initial"] == pytest.approx(0.5 * 5e289 * 20**2, rel=1e-12)
    assert math.hypot(*conserved["h_world"]["initial"]) == pytest.approx(5e289 * 20, rel=1e-12)
    assert 0 <= conserved["h_world"]["drift"] < 1e-12 and summary["max_relative_drift"] < 1e-12
    rows = list(csv.DictReader(io.StringIO(cs.stdout)))
    assert float(rows[-1]["energy"]) == pytest.approx(1e292, rel=1e-12)
