"""Every solid part of a body drawn by `rbi show` has a colour of its own, the same in the PNG,
its legend and the HTML page (one palette: rbi.viz.frames.PALETTE)."""

from __future__ import annotations

import re
from importlib import resources

import pytest

from tests.conftest import run_rbi_inprocess
from tests.viz.test_pictures_as_specified import CHROMIUM, shown_page
from tests.viz.test_pictures_as_specified import page_data as _page_data


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


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium is not installed (apt-get install chromium)")
def test_the_page_says_which_coloured_line_is_which_principal_axis(tmp_path, bodies):
    # the page's legend read "coloured lines: principal axes · I1 = 0.000225 kg·m² · I2 = ..."
    # in grey, so which of the red, green and blue lines was I1 could not be told; now each
    # moment stands beside a line of its axis's colour (the PNG labels the lines I1, I2, I3)
    dom = shown_page(tmp_path, bodies / "top_bolted.yaml")
    axes = re.findall(
        r'<span class="axis"><span class="line" style="background: ([^;"]+);?"></span>(.*?)</span>', dom
    )
    # the bolted top's principal moments about its centre of mass: 2.250022e-4, 2.651311e-4,
    # 2.949333e-4 kg·m² (I3 = I_yy: the bolt at y = 0 leaves y a principal axis)
    assert [text for _, text in axes] == [
        "I1 = 0.000225 kg·m²",
        "I2 = 0.0002651 kg·m²",
        "I3 = 0.0002949 kg·m²",
    ], axes
    assert [colour for colour, _ in axes] == ["rgb(214, 39, 40)", "rgb(44, 160, 44)", "rgb(31, 119, 180)"]
