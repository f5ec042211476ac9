"""The pictures the docs show are what the commands beside them draw today.

docs/simulate.md showed simulate_top.png titled 'spinning-top: spin 200 rad/s, tilt 0.01°' with
a panel 'body z axis seen from above', where `rbi simulate ... --plot` now titles it
'... nudge 0.01°' and 'spin axis seen from above' (likewise simulate_tbar.png, and the animation
page and GIF of docs/animate.md). Each picture is drawn again here with the command its page
gives and compared pixel by pixel: at most 0.1 % of the pixels may differ (anti-aliasing), a
changed title or label differs in far more.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import ROOT, run_rbi_inprocess

pytest.importorskip("matplotlib")
Image = pytest.importorskip("PIL.Image")

PICTURES = {
    "simulate_top.png": ("simulate", "bodies/top.yaml", "--spin", "200", "--tilt", "0.01", "--plot"),
    "simulate_tbar.png": (
        "simulate",
        "bodies/tbar.yaml",
        "--omega",
        "0.01,0.01,3",
        "--duration",
        "20",
        "--plot",
    ),
    "show_top_bolted.png": ("show", "bodies/top_bolted.yaml", "--out"),
    "show_wheel_with_holes.png": ("show", "bodies/wheel_with_holes.yaml", "--out"),
    "show_robot_link.png": ("show", "bodies/robot_link.yaml", "--out"),
}


@pytest.mark.parametrize("name", sorted(PICTURES))
def test_the_docs_picture_is_what_the_command_draws(name, tmp_path):
    command, spec, *options = PICTURES[name]
    out = tmp_path / name
    proc = run_rbi_inprocess(command, ROOT / spec, *options, out)
    assert proc.returncode == 0, proc.stderr
    drawn = np.asarray(Image.open(out).convert("RGB"), dtype=int)
    shown = np.asarray(Image.open(ROOT / "docs" / name).convert("RGB"), dtype=int)
    assert drawn.shape == shown.shape, (drawn.shape, shown.shape)
    changed = np.any(np.abs(drawn - shown) > 24, axis=2).mean()
    assert changed <= 0.001, (
        f"docs/{name}: {changed:.2%} of the pixels differ; draw it again with rbi {command}"
    )
