"""The HTML page: self-contained (no network), names escaped, still mode without controls."""

from __future__ import annotations

import json
import re

from rbi.viz.page import html_page, script_safe_json


def _data(**extra):
    data = {
        "title": "t",
        "length_unit": "m",
        "pivoted": True,
        "size": 1.0,
        "parts": [],
        "com": [0, 0, 0.5],
        "axis_tip": [0, 0, 1],
        "times": [0.0, 1.0],
        "quaternions": [[0, 0, 0, 1], [0, 0, 0, 1]],
        "tilt_deg": [0, 0],
        "omega": [1, 1],
        "trace": [[0, 0, 1], [0, 0, 1]],
        "trail_seconds": 0.5,
    }
    return data | extra


def test_page_loads_nothing_from_the_network():
    page = html_page(_data())
    assert not re.search(r"""<(script|link|img|iframe)[^>]*\b(src|href)\s*=""", page, re.I)
    assert not re.search(r"""\b(src|href)\s*=\s*["']?(https?:)?//""", page, re.I)
    assert "THREE.WebGLRenderer" in page and "QuaternionKeyframeTrack" in page
    assert page.count("<script") == page.lower().count("</script>")


def test_a_name_cannot_close_the_script():
    evil = "</script><script>alert(1)</script>"
    page = html_page(_data(title=evil, parts=[{"kind": "point", "position": [0, 0, 0], "name": evil}]))
    assert evil not in page
    block = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S).group(1)
    assert json.loads(block)["parts"][0]["name"] == evil


def test_script_safe_json_round_trips_line_separators():
    text = script_safe_json({"a": "x\u2028y<&>"})
    assert "\u2028" not in text and "<" not in text
    assert json.loads(text) == {"a": "x\u2028y<&>"}


def test_speed_is_written_into_the_control():
    assert 'value="0.25"' in html_page(_data(), speed=0.25)
