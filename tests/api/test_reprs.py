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


def test_audit_report_shows_as_a_table_and_repr_is_one_line(tmp_path):
    """The audit report: a rich table and HTML naming each link, and a one-line repr (the
    dataclass's own printed the whole robot file's text, 3 kB here, 10 MB for a big robot)."""
    text = (
        '<robot name="arm"><link name="base"/><link name="upper"><inertial><origin xyz="0.5 0 0"/>'
        '<mass value="2"/><inertia ixx="0.01" iyy="0.2" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial></link>'
        '<joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>'
        '<limit effort="100" velocity="1" lower="-3" upper="3"/></joint></robot>' + "<!-- padding -->" * 200
    )
    (tmp_path / "arm.urdf").write_text(text)
    report = rbi.audit(tmp_path / "arm.urdf")
    line = repr(report)
    assert "\n" not in line and len(line) < 200 and "2 links" in line and "1 joints" in line, line
    assert "upper" in rendered(report) and "upper" in report._repr_html_()


def test_numbers_in_the_tables_are_written_by_the_one_formatter():
    """rbi.text.number: a sweep's -0.0 (spin -0) shows as 0, as in the CLI's tables (it showed
    -0 when the reprs formatted cells by hand); a missing value as —."""
    # run 1 fails (its step budget): its figures are missing
    table = rbi.sweep(
        BODIES / "top.yaml", spin=[-0.0, 200], tilt_deg=-0.0, duration=0.1, samples=5, workers=1, max_steps=20
    )
    html = table._repr_html_()
    assert ">-0<" not in html and html.count('right">0<') >= 2 and ">—<" in html
