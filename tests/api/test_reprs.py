"""A Body and a Trajectory show as a table in a notebook (HTML) and in a rich console."""

from __future__ import annotations

import io
import re

import pytest
from rich.console import Console

import rbi
from tests.conftest import BODIES

SPEC = {
    "name": "<b>[bold]odd</b>",
    "pivot": [0, 0, 0],
    "parts": [
        {
            "name": "rod",
            "shape": "cylinder",
            "mass": 2.0,
            "radius": 0.01,
            "start": [0, 0, 0],
            "end": [0, 0, 1],
        }
    ],
}


def rendered(value) -> str:
    console = Console(file=io.StringIO(), width=100, color_system=None)
    console.print(value)
    return console.file.getvalue()


@pytest.fixture(scope="module")
def bolted():
    return rbi.load(BODIES / "top_bolted.yaml")


def test_body_as_a_rich_table(bolted):
    text = rendered(bolted)
    assert "bolted-top" in text and "┃ quantity" in text
    assert re.search(r"mass\s+│ kg\s+│\s+0\.52 │", text)
    assert "0.000225002" in text  # the smallest principal moment, kg·m²
    assert "0.155234" in text  # the first principal axis


def test_body_as_html(bolted):
    html = bolted._repr_html_()
    assert html.startswith("<table>") and html.endswith("</table>")
    assert "<caption>bolted-top</caption>" in html
    assert "<td>mass</td><td>kg</td>" in html and ">0.52<" in html


def test_names_are_shown_as_text_not_markup():
    body = rbi.load(SPEC)
    assert "&lt;b&gt;[bold]odd&lt;/b&gt;" in body._repr_html_()
    assert "<b>[bold]odd</b>" in rendered(body)


def test_trajectory_as_a_table(bolted):
    run = rbi.simulate(bolted, spin=200.0, tilt_deg=0.01, duration=0.2, samples=21)
    text = rendered(run)
    assert "bolted-top — simulate" in text and "heavy top on a fixed pivot" in text
    assert f"{run.tilt_deg[-1]:.6g}" in text
    html = run._repr_html_()
    assert html.startswith("<table>") and "final tilt of body z" in html and "21" in html
    assert "21 samples" in repr(run)
