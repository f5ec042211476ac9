"""rbi.show, rbi.animate and Trajectory.plot: the pictures `rbi show`, `rbi animate` and
`rbi simulate --plot` write, made from Python, with numbers checked against hand-worked answers."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import rbi
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as run_rbi

FREE_CYLINDER = {
    "name": "free cylinder",
    "parts": [{"shape": "cylinder", "mass": 2.0, "radius": 0.1, "start": [0, 0, 0], "end": [0, 0, 0.05]}],
}
"""A flat disc-like cylinder, no pivot: spun about its axis (the largest moment), that axis
keeps its direction in space (torque-free, ω along a principal axis)."""


def page_data(path) -> dict:
    """The JSON a 3D page plays, read back from the page."""
    text = path.read_text()
    match = re.search(r'<script[^>]*id="data"[^>]*>(.*?)</script>', text, re.S)
    assert match, "no data block in the page"
    return json.loads(match.group(1))


def test_show_writes_a_page_with_the_hand_worked_centre_of_mass(tmp_path):
    body = rbi.load(BODIES / "top_bolted.yaml")
    out = tmp_path / "top.html"
    assert rbi.show(body, out) == 3  # cone, stem, bolt
    data = page_data(out)
    # cone (0.4 kg) CoM 3/4 of the way from apex to base, z = 0.045; stem (0.1 kg) z = 0.08;
    # bolt (0.02 kg) at (0.04, 0, 0.06)
    expected = np.array([0.02 * 0.04, 0.0, 0.4 * 0.045 + 0.1 * 0.08 + 0.02 * 0.06]) / 0.52
    np.testing.assert_allclose(data["com"], expected, rtol=1e-12, atol=1e-15)
    assert data["title"] == "bolted-top"


@pytest.mark.parametrize("suffix, magic", [("png", b"\x89PNG\r\n\x1a\n"), ("svg", b"<?xml")])
def test_show_draws_a_still_of_the_same_file_as_the_cli(tmp_path, suffix, magic):
    pytest.importorskip("matplotlib")
    body = rbi.load(BODIES / "wheel_with_holes.yaml")
    out = tmp_path / f"wheel.{suffix}"
    count = rbi.show(body, out, title="wheel")
    assert out.read_bytes().startswith(magic)
    proc = run_rbi("show", BODIES / "wheel_with_holes.yaml", "--out", tmp_path / f"cli.{suffix}")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip().endswith(f"{count} parts drawn")


def test_show_refuses_a_path_naming_the_parameter(tmp_path):
    body = rbi.load(BODIES / "top.yaml")
    with pytest.raises(
        rbi.SpecError,
        match=r"^path: .*cannot write '\.txt' \(this output is written as \.png, \.svg, \.html\)",
    ):
        rbi.show(body, tmp_path / "top.txt")
    assert list(tmp_path.iterdir()) == []


def test_animate_a_free_body_spun_about_its_axis_keeps_the_nudge(tmp_path):
    body = rbi.load(FREE_CYLINDER)
    out = tmp_path / "disc.html"
    made = rbi.animate(body, out, spin=30.0, tilt_deg=10.0, duration=1.0)
    assert made.max_tilt_deg == pytest.approx(10.0, abs=1e-9)  # the axis keeps its direction
    assert made.path == str(out)
    data = page_data(out)
    assert made.frames == len(data["times"]) and data["times"][-1] == pytest.approx(1.0)


def test_animate_a_gif_has_a_frame_per_tick_of_the_clock(tmp_path):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "disc.gif"
    calls = []
    made = rbi.animate(
        rbi.load(FREE_CYLINDER), out, spin=5.0, duration=1.0, fps=10, progress=lambda *a: calls.append(a)
    )
    assert made.frames == 11  # t = 0, 0.1, ... 1.0 s
    with Image.open(out) as gif:
        assert gif.n_frames == 11
    assert calls[-1] == (11, 11)


@pytest.mark.parametrize(
    "settings, message",
    [
        ({"speed": 5.0}, r"^speed: must be between 0\.1 and 2 \(got 5\.0\)$"),
        ({"fps": 0}, r"^fps: must be between 1 and 60 \(got 0\)$"),
        ({"duration": -1.0}, r"^duration: "),
    ],
)
def test_animate_names_its_parameters(tmp_path, settings, message):
    with pytest.raises(ValueError, match=message):
        rbi.animate(rbi.load(FREE_CYLINDER), tmp_path / "a.html", spin=5.0, **settings)


def test_animate_refuses_a_gif_longer_than_a_file_may_hold(tmp_path):
    with pytest.raises(
        ValueError, match=r"^duration: a GIF of 100 s at 60 frames per second would have 6e\+03"
    ):
        rbi.animate(rbi.load(FREE_CYLINDER), tmp_path / "a.gif", spin=1.0, duration=100.0, fps=60)


@pytest.mark.parametrize("suffix, magic", [("png", b"\x89PNG\r\n\x1a\n"), ("pdf", b"%PDF")])
def test_trajectory_plot_writes_the_figure(tmp_path, suffix, magic):
    pytest.importorskip("matplotlib")
    run = rbi.simulate(rbi.load(FREE_CYLINDER), spin=3.0, tilt_deg=5.0, duration=0.5, samples=51)
    assert run.body is not None and run.body.name == "free cylinder"
    out = tmp_path / f"run.{suffix}"
    run.plot(out)
    assert out.read_bytes().startswith(magic)


def test_a_trajectory_made_by_hand_cannot_be_plotted(tmp_path):
    t = np.linspace(0.0, 1.0, 3)
    hand = rbi.Trajectory(t, np.tile([1.0, 0, 0, 0], (3, 1)), np.zeros((3, 3)), t, t, t)
    with pytest.raises(ValueError, match="^body: plot needs the Body of the run"):
        hand.plot(tmp_path / "x.png")
