"""The spin axis is the body's: checked against the physics of gyroscopes and tops, not against
rbi's own output.

The horizontal gyroscope (bodies/gyroscope.yaml): a wheel on an axle along body y, held at the
axle's end. Its closed forms, from the bodies' dimensions alone:
- steady precession at tilt 90°: exactly Ω = m g d / (I_s ω_s) (the Lagrange top's steady
  precession condition m g d = Ω I_s ω_s − I_t Ω² cos θ at cos θ = 0), when the body starts with
  ω = ω_s (axis) + Ω (vertical);
- released with spin alone, for fast spin it precesses on average at the same rate.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES, run_rbi_inprocess

G = 9.81
WHEEL = dict(mass=1.0, radius=0.1, y0=0.19, y1=0.21)
AXLE = dict(mass=0.05, radius=0.004, y0=0.0, y1=0.25)
MASS = WHEEL["mass"] + AXLE["mass"]
D = (WHEEL["mass"] * 0.2 + AXLE["mass"] * 0.125) / MASS  # pivot to centre of mass, m
I_SPIN = 0.5 * WHEEL["mass"] * WHEEL["radius"] ** 2 + 0.5 * AXLE["mass"] * AXLE["radius"] ** 2


def steady_rate(spin: float) -> float:
    return MASS * G * D / (I_SPIN * spin)


def gyroscope():
    return rbi.load(BODIES / "gyroscope.yaml")


def test_the_gyroscope_spins_about_its_axle_by_default():
    assert gyroscope().spin_axis.tolist() == [0.0, 1.0, 0.0]


def test_exact_steady_precession_of_the_horizontal_gyroscope():
    spin = 150.0
    rate = steady_rate(spin)
    run = rbi.simulate(
        gyroscope(), omega=[0.0, spin, rate], spin_axis="y", duration=1.0, samples=201, error_estimate=False
    )
    assert np.max(np.abs(run.tilt_deg - 90.0)) < 1e-6
    measured = np.radians(run.precession_deg[-1] - run.precession_deg[0]) / 1.0
    assert measured == pytest.approx(rate, rel=1e-7)
    assert run.summary.stability["com_position"] == "level"


def test_a_fast_gyroscope_released_with_spin_alone_precesses_at_m_g_d_over_i_omega():
    spin = 400.0
    run = rbi.simulate(gyroscope(), spin=spin, duration=2.0, samples=2001, error_estimate=False)
    # the azimuth wobbles by (Ω/ω_nutation) rad within each nutation: fit the mean rate
    measured = np.polyfit(run.t, np.radians(run.precession_deg), 1)[0]
    assert measured == pytest.approx(steady_rate(spin), rel=2e-3)
    assert np.max(np.abs(run.tilt_deg - 90.0)) < 3.0  # it dips a little, it does not fall
    assert run.summary.stability["gyroscopic_precession_rad_s"] == pytest.approx(steady_rate(spin), rel=1e-9)
    assert "level with the pivot" in run.summary.stability["verdict"]
    assert run.summary.spin_axis.tolist() == [0.0, 1.0, 0.0]
    assert run.omega[0].tolist() == [0.0, spin, 0.0]


def _top_along(axis) -> dict:
    """The chapter's top (cone and stem) built along the unit ``axis`` from the pivot."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    at = lambda d: (d * a).tolist()  # noqa: E731
    return {
        "pivot": [0, 0, 0],
        "parts": [
            {
                "name": "cone",
                "shape": "cone",
                "mass": 0.4,
                "radius": 0.04,
                "apex": [0, 0, 0],
                "base": at(0.06),
            },
            {
                "name": "stem",
                "shape": "cylinder",
                "mass": 0.1,
                "radius": 0.008,
                "start": at(0.06),
                "end": at(0.10),
            },
        ],
    }


@pytest.mark.parametrize("axis", [[1, 0, 0], [0, 1, 0], [1, 1, 1], [0.3, -0.5, 0.8]])
def test_the_same_top_built_along_any_axis_moves_the_same(axis):
    """Built along ``axis`` and left at rest orientation, the top's axis stands at the tilt
    θ = acos(a_z); the top built along z and nudged by θ is the same physical state turned about
    the vertical: the tilt series agree and the precession angles differ by a constant."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    theta = math.degrees(math.acos(a[2]))
    along = rbi.simulate(
        rbi.load(_top_along(axis)), spin=150.0, duration=0.5, samples=101, error_estimate=False
    )
    upright = rbi.simulate(
        rbi.load(_top_along([0, 0, 1])),
        spin=150.0,
        tilt_deg=theta,
        duration=0.5,
        samples=101,
        error_estimate=False,
    )
    assert np.allclose(along.summary.spin_axis, a, atol=1e-12)
    assert np.max(np.abs(along.tilt_deg - upright.tilt_deg)) < 1e-6
    offset = along.precession_deg - upright.precession_deg
    assert np.ptp(offset) < 1e-6


def test_the_sleeping_top_threshold_of_a_top_built_along_y_is_the_one_built_along_z():
    # 4 m g l I1 / I3^2 from the chapter's numbers, as tests/test_seed_numbers.py quotes them
    z_built = rbi.simulate(
        rbi.load(_top_along([0, 0, 1])),
        spin=150.0,
        tilt_deg=0.01,
        duration=0.01,
        samples=2,
        error_estimate=False,
    )
    y_built = rbi.simulate(
        rbi.load(_top_along([0, 1, 0])),
        spin=150.0,
        tilt_deg=90.01,
        tilt_axis="x",
        duration=0.01,
        samples=2,
        error_estimate=False,
    )
    a, b = z_built.summary.stability, y_built.summary.stability
    assert b["sleeping_threshold_rad_s"] == pytest.approx(a["sleeping_threshold_rad_s"], rel=1e-12)
    assert b["com_position"] == a["com_position"] == "above"
    assert "unstable" in b["verdict"] and b["spin_rad_s"] == pytest.approx(150.0)
    hanging = rbi.simulate(
        rbi.load(_top_along([0, 1, 0])),
        spin=150.0,
        tilt_deg=-90,
        tilt_axis="x",
        duration=0.01,
        samples=2,
        error_estimate=False,
    )
    assert hanging.summary.stability["com_position"] == "below"
    assert hanging.tilt_deg[0] == pytest.approx(180.0)


def test_spin_axis_option_spec_field_and_default_in_that_order(tmp_path):
    spec = tmp_path / "wheel.yaml"
    spec.write_text((BODIES / "gyroscope.yaml").read_text() + "spin_axis: [0, 0, 2]\n")

    def axis(*extra):
        out = run_rbi_inprocess(
            "simulate",
            spec,
            "--spin",
            "10",
            "--duration",
            "0.01",
            "--samples",
            "2",
            "--format",
            "json",
            *extra,
        )
        assert out.returncode == 0, out.stderr
        return json.loads(out.stdout)["spin_axis"]

    assert axis() == [0.0, 0.0, 1.0]
    assert axis("--spin-axis", "x") == [1.0, 0.0, 0.0]
    assert axis("--spin-axis", "1,1,0") == pytest.approx([2**-0.5, 2**-0.5, 0.0], abs=1e-15)
    spec.write_text((BODIES / "gyroscope.yaml").read_text())
    assert axis() == [0.0, 1.0, 0.0]


@pytest.mark.parametrize(
    "bad, words", [("0,0,0", "must not be zero"), ("w", "x, y, z"), ("1,nan,0", "finite")]
)
def test_a_bad_spin_axis_is_one_line_and_exit_2(bad, words):
    out = run_rbi_inprocess("simulate", BODIES / "gyroscope.yaml", "--spin", "10", "--spin-axis", bad)
    assert (
        out.returncode == 2
        and out.stderr.count("\n") == 1
        and "--spin-axis" in out.stderr
        and words in out.stderr
    )
