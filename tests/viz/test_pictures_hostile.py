"""Issue 18, principle 4, for pictures: a name from a spec (the body's, a part's, the file's,
a --vary path) is a label, never markup, and never makes a picture slow.

matplotlib reads text between ``$`` signs as mathtext: a part named ``$\\frac{$`` made every
PNG, SVG and GIF fail (internal error), and ``$x^2$`` was typeset rather than shown. A 1 MB
name took minutes to lay out. Labels are drawn with mathtext off, hidden characters shown as
escapes, and cut to a readable length.
"""

from __future__ import annotations

import json
import time

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from rbi.viz.labels import MAX_LABEL_CHARS, label
from tests.conftest import one_line_exit_2, run_rbi_inprocess

pytest.importorskip("matplotlib")

BAD_MATH = [
    "$\\frac{$",
    "$x^$",
    "a $\\alpha$ b",
    "$",
    "$$",
    "\\$",
    "cost $5 and $6",
    "$\\mathrm{",
    "$\\left($",
]


def spec(name: str, part: str) -> str:
    """A top of two parts, written by PyYAML (which escapes any name correctly)."""
    import yaml

    return yaml.safe_dump(
        {
            "name": name,
            "pivot": [0, 0, 0],
            "parts": [
                {
                    "name": part,
                    "shape": "cylinder",
                    "mass": 1,
                    "radius": 0.05,
                    "start": [0, 0, 0],
                    "end": [0, 0, 0.2],
                },
                {"name": part + "2", "shape": "point", "mass": 0.1, "position": [0.05, 0, 0.2]},
            ],
        },
        allow_unicode=False,
    )


def svg_text(path) -> str:
    return path.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", BAD_MATH[:4])  # all of them at once below
def test_show_draws_dollar_names_as_written(write_spec, tmp_path, name):
    path = write_spec(spec(name, name))
    out = tmp_path / "body.svg"
    proc = run_rbi_inprocess("show", path, "--out", out)
    assert proc.returncode == 0, proc.stderr
    # matplotlib writes each text as an SVG comment holding the string it drew
    assert name in svg_text(out)


@pytest.mark.parametrize("fmt", ["png", "svg"])
def test_show_with_every_bad_name_at_once(write_spec, tmp_path, fmt):
    text = 'name: "$\\\\frac{$"\nparts:\n' + "".join(
        f"  - {{name: {json.dumps(n + str(i))}, shape: point, mass: 1, position: [{i}, 0, 0]}}\n"
        for i, n in enumerate(BAD_MATH)
    )
    out = tmp_path / f"body.{fmt}"
    proc = run_rbi_inprocess("show", write_spec(text, "$x^$.yaml"), "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert out.stat().st_size > 1000


def test_simulate_plot_and_sweep_plot_with_dollar_names(write_spec, tmp_path):
    path = write_spec(spec("$\\frac{$", "$x^$"), "$\\frac{$.yaml")
    proc = run_rbi_inprocess(
        "simulate", path, "--spin", "30", "--tilt", "5", "--duration", "0.2", "--plot", tmp_path / "run.png"
    )
    assert proc.returncode == 0, proc.stderr
    proc = run_rbi_inprocess(
        "sweep", path, "--spin", "10:30:2", "--duration", "0.2", "--plot", tmp_path / "map.png"
    )
    assert proc.returncode == 0, proc.stderr
    proc = run_rbi_inprocess(
        "sweep",
        path,
        "--mass-properties",
        "--vary",
        "parts.$x^$2.mass=0.1:0.2:3",
        "--plot",
        tmp_path / "vary.svg",
    )
    assert proc.returncode in (0, 2), proc.stderr  # the path may not resolve; it must not crash


def test_gif_with_a_dollar_name(write_spec, tmp_path):
    path = write_spec(spec("$\\frac{$", "$x^$"))
    out = tmp_path / "top.gif"
    proc = run_rbi_inprocess(
        "animate", path, "--spin", "30", "--duration", "0.12", "--fps", "10", "--out", out
    )
    assert proc.returncode == 0, proc.stderr
    assert out.stat().st_size > 1000


def test_a_megabyte_name_draws_in_seconds(write_spec, tmp_path):
    long = "n" * 1_000_000
    path = write_spec(spec(long, long))
    out = tmp_path / "body.svg"
    start = time.perf_counter()
    proc = run_rbi_inprocess("show", path, "--out", out)
    elapsed = time.perf_counter() - start
    assert proc.returncode == 0, proc.stderr
    assert elapsed < 20, elapsed
    assert "n" * (MAX_LABEL_CHARS + 1) not in svg_text(out)  # cut to a readable length
    assert "n" * (MAX_LABEL_CHARS // 2) in svg_text(out)


def test_hidden_characters_in_names_are_drawn_as_escapes(write_spec, tmp_path):
    path = write_spec(spec("top\nsecond line\u202e", "a\x9bb\tc"))
    out = tmp_path / "body.svg"
    assert run_rbi_inprocess("show", path, "--out", out).returncode == 0
    text = svg_text(out)
    assert "top\\nsecond line\\u202e" in text and "a\\x9bb\\tc" in text


@given(st.text(max_size=300))
@settings(max_examples=300, deadline=None)
def test_label_is_one_short_line_of_visible_characters(text):
    shown = label(text)
    assert len(shown) <= MAX_LABEL_CHARS
    assert shown.isprintable() or shown == ""
    if len(text) <= MAX_LABEL_CHARS // 4 and text.isprintable():
        assert shown == text


names = st.text(st.characters(blacklist_categories=("Cs",)), min_size=1, max_size=40)


@given(names, st.lists(names, min_size=1, max_size=8, unique=True))
@example("08", ["08", "1e3", "0o7"])  # found by hypothesis: PyYAML writes them unquoted, rbi refused them
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_show_draws_any_names(tmp_path, name, parts):
    import yaml

    path = tmp_path / "body.yaml"
    path.write_text(
        yaml.safe_dump(
            {
                "name": name,
                "parts": [
                    {"name": part, "shape": "point", "mass": 1, "position": [i, 0, 0]}
                    for i, part in enumerate(parts)
                ],
            }
        ),
        encoding="utf-8",
    )
    out = tmp_path / "body.svg"
    proc = run_rbi_inprocess("show", path, "--out", out)
    assert proc.returncode == 0 and proc.stderr == "", (name, parts, proc.stderr)


def test_characters_the_font_lacks_are_escapes_not_warnings(write_spec, tmp_path):
    """Found: a CJK or emoji name printed two lines of 'UserWarning: Glyph … missing from
    font(s)' on stderr per character and drew empty boxes."""
    out = tmp_path / "body.svg"
    proc = run_rbi_inprocess("show", write_spec(spec("名前 🚀", "部品")), "--out", out)
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr
    assert "\\u540d\\u524d" in svg_text(out) and "\\u90e8\\u54c1" in svg_text(out)


def test_names_that_look_like_markup_are_text_on_the_page(write_spec, tmp_path):
    """A name is text on the HTML page: it cannot close the data script or add elements."""
    import re

    name = "</script><img src=x onerror=alert(1)><!--"
    out = tmp_path / "body.html"
    assert run_rbi_inprocess("show", write_spec(spec(name, name)), "--out", out).returncode == 0
    page = out.read_text(encoding="utf-8")
    data_text = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S).group(1)
    assert json.loads(data_text)["part_legend"][0]["name"] == name
    assert "<img" not in page.split("<script>")[0]  # the head and heading hold no raw name


@pytest.mark.parametrize(
    "part",
    [
        "{shape: box, mass: 1, size: [1.0e-300, 1, 1], center: [0, 0, 0]}",
        "{shape: sphere, mass: 1, radius: 1.0e+100, center: [0, 0, 0]}",
        "{shape: torus, mass: 1, major_radius: 1.0e+150, minor_radius: 1.0e+150, center: [0, 0, 0], axis: [0, 0, 1.0e+300]}",
        "{shape: point, mass: 1, position: [1.0e+17, 0, 0]}",
    ],
)
@pytest.mark.parametrize("fmt", ["png", "html"])
def test_bodies_of_extreme_size_are_drawn(write_spec, tmp_path, part, fmt):
    text = f"parts:\n  - {part}\n  - {{shape: point, mass: 1, position: [0, 0, 1]}}\n"
    out = tmp_path / f"body.{fmt}"
    proc = run_rbi_inprocess("show", write_spec(text), "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert out.stat().st_size > 1000


@pytest.mark.parametrize("fmt", ["png", "html"])
def test_a_body_whose_moments_underflow_is_refused_not_drawn(write_spec, tmp_path, fmt):
    """A 1 kg sphere of radius 1e-300 m has moments of 4e-601 kg·m², beyond doubles (they would
    be exact zeros): refused in one line as every command refuses it, and no picture written."""
    text = "parts:\n  - {shape: sphere, mass: 1, radius: 1.0e-300, center: [0, 0, 0]}\n"
    out = tmp_path / f"body.{fmt}"
    one_line_exit_2(
        run_rbi_inprocess("show", write_spec(text), "--out", out), "parts[0]", "numbers too small"
    )
    assert not out.exists()


def test_an_svg_stays_well_formed_xml_whatever_the_names(write_spec, tmp_path):
    import xml.etree.ElementTree as ET

    out = tmp_path / "body.svg"
    assert (
        run_rbi_inprocess(
            "show", write_spec(spec("t-->x<y&z]]>", "a-->b<!--c&d\x85\u2028")), "--out", out
        ).returncode
        == 0
    )
    ET.parse(out)  # raises on a comment or text a name broke
