"""Every solid part of a body drawn by `rbi show` has a colour of its own, the same in the PNG,
its legend and the HTML page (one palette: rbi.viz.frames.PALETTE)."""

from __future__ import annotations

import json
import re
from importlib import resources

from tests.conftest import run_rbi_inprocess


def _page_data(path) -> dict:
    text = path.read_text(encoding="utf-8")
    return json.loads(
        re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.S).group(1)
    )


def test_no_two_solid_parts_of_the_cubesat_share_a_colour(tmp_path, bodies):
    # bodies/cubesat.yaml: 11 parts, 9 of them solids (2 holes). With 8 colours, `rbi show`
    # drew the bus and the antenna horn both #3f7fbf, the tank and the magnetometer boom both
    # #4f9f5f: two legend entries of one colour
    out = tmp_path / "cubesat.html"
    assert run_rbi_inprocess("show", bodies / "cubesat.yaml", "--out", out).returncode == 0
    legend = _page_data(out)["part_legend"]
    solids = {entry["name"]: entry["colour"] for entry in legend if not entry["hole"]}
    assert len(solids) == 9
    assert len(set(solids.values())) == 9, solids
    assert solids["bus"] != solids["antenna-horn"] and solids["tank"] != solids["magnetometer-boom"]


def test_the_page_draws_parts_in_the_legends_colours(tmp_path, bodies):
    # the page had a palette of its own written into page.html; now it draws with the one it
    # is given, the list the legend and the PNG take their colours from
    out = tmp_path / "cubesat.html"
    assert run_rbi_inprocess("show", bodies / "cubesat.yaml", "--out", out).returncode == 0
    data = _page_data(out)
    for index, entry in enumerate(data["part_legend"]):  # cubesat: one drawn item per written part
        if not entry["hole"]:
            assert data["palette"][index % len(data["palette"])] == entry["colour"], entry["name"]
    template = resources.files("rbi.viz").joinpath("templates", "page.html").read_text(encoding="utf-8")
    assert "0x3f7fbf" not in template and "data.palette" in template
