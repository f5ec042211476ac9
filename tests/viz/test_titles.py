"""The title of a run's pictures says how the run started: a spin about the spin axis as
`spin W rad/s`, any other start as the ω₀ the user gave."""

from __future__ import annotations

from rbi.viz.labels import motion_title
from tests.conftest import run_rbi_inprocess
from tests.viz.test_pictures_as_specified import page_data


def test_an_omega_run_is_titled_with_its_omega(tmp_path, bodies):
    # rbi animate bodies/tbar.yaml --omega 0.01,0.01,3 titled its page and GIF 't-handle: spin
    # 3.00003 rad/s' (|ω₀| = sqrt(0.01² + 0.01² + 3²), a spin nobody gave), as did simulate --plot
    out = tmp_path / "flip.html"
    proc = run_rbi_inprocess(
        "animate", bodies / "tbar.yaml", "--omega", "0.01,0.01,3", "--duration", "1", "--out", out
    )
    assert proc.returncode == 0, proc.stderr
    assert page_data(out)["title"] == "t-handle: ω₀ [0.01, 0.01, 3] rad/s, nudge 0°"


def test_a_spin_is_titled_with_its_sign():
    # --spin -150 was titled 'spin 150 rad/s' (the norm of ω₀)
    assert motion_title("top", [0, 0, -150], [0, 0, 1], 5) == "top: spin -150 rad/s, nudge 5°"
    assert motion_title("top", [0, 0, 200], [0, 0, 1], 0.01) == "top: spin 200 rad/s, nudge 0.01°"
    # about a slanted spin axis (0.6, 0, 0.8): ω₀ = 10 (0.6, 0, 0.8)
    assert motion_title("disc", [6, 0, 8], [0.6, 0, 0.8], 0) == "disc: spin 10 rad/s, nudge 0°"
    assert motion_title("disc", [0, 0, 0], [0, 0, 1], 0) == "disc: spin 0 rad/s, nudge 0°"
