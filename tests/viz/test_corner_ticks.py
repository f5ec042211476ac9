"""`rbi show` PNG/SVG: the x and y tick labels do not print into one another at the corner where
the two axes meet (x's upper end, y's lower end, seen from azimuth -55°)."""

from __future__ import annotations

import pytest

from tests.conftest import run_rbi_inprocess
from tests.viz.test_pictures_as_specified import svg_ticks


def test_the_wheels_corner_has_one_tick_label(tmp_path, bodies):
    # bodies/wheel_with_holes.yaml, a rim of 100 mm outer radius: the frame is ±100 mm on x and y,
    # and both x's 100 and y's -100 were labelled at the one corner, printed as '100−100'
    pytest.importorskip("matplotlib")
    out = tmp_path / "wheel.svg"
    assert run_rbi_inprocess("show", bodies / "wheel_with_holes.yaml", "--out", out).returncode == 0
    x, y, _ = svg_ticks(out)
    assert max(x) == 100 and min(x) == -100, x
    assert min(y) == -75 and max(y) == 100, y  # no label at y = -100
