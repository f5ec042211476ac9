"""`rbi show`: a picture of every bundled body, in each format, and its refusals."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from tests.conftest import BODIES, one_line_exit_2, run_rbi, run_rbi_inprocess

SPECS = sorted(p.name for p in BODIES.glob("*.yaml"))


@pytest.mark.parametrize("name", SPECS)
def test_every_bundled_body_is_drawn(tmp_path, name):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "body.png"
    proc = run_rbi_inprocess("show", BODIES / name, "--out", out)
    assert proc.returncode == 0, proc.stderr
    image = np.asarray(Image.open(out).convert("RGB"), dtype=int)
    assert ((image.max(axis=2) - image.min(axis=2)) > 60).sum() > 2000  # coloured parts, not an empty frame


@pytest.mark.parametrize("name", SPECS)
def test_every_bundled_body_has_a_page(tmp_path, name):
    out = tmp_path / "body.html"
    proc = run_rbi_inprocess("show", BODIES / name, "--out", out)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text(encoding="utf-8")
    data = json.loads(
        re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.S).group(1)
    )
    assert len(data["times"]) == 1 and len(data["principal_axes"]) == 3


def test_principal_axes_are_scaled_by_their_moments_and_labelled(tmp_path, bodies):
    out = tmp_path / "top.html"
    assert run_rbi_inprocess("show", bodies / "wheel_with_holes.yaml", "--out", out).returncode == 0
    text = out.read_text(encoding="utf-8")
    axes = json.loads(re.search(r'id="data">(.*?)</script>', text, re.S).group(1))["principal_axes"]
    moments = [a["moment"] for a in axes]
    lengths = [a["half_length"] for a in axes]
    assert moments == sorted(moments)
    np.testing.assert_allclose(np.array(lengths) / lengths[-1], np.array(moments) / moments[-1], rtol=1e-12)
    # a wheel with evenly spaced holes: equal moments about two diameters, the largest about the axle (z)
    assert moments[0] == pytest.approx(moments[1], rel=1e-9)
    assert abs(axes[2]["direction"][2]) == pytest.approx(1.0, abs=1e-12)
    assert all(a["label"].startswith(f"I{k + 1} = ") and "g·mm²" in a["label"] for k, a in enumerate(axes))


def test_svg_end_to_end(tmp_path, bodies):
    pytest.importorskip("matplotlib")
    out = tmp_path / "top.svg"
    proc = run_rbi("show", bodies / "top_bolted.yaml", "--out", out)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text()
    assert "<svg" in text and "centre of mass" in text and "pivot" in text


def test_bad_extension_and_bad_spec(tmp_path, write_spec):
    one_line_exit_2(run_rbi_inprocess("show", BODIES / "top.yaml", "--out", tmp_path / "a.gif"), "--out")
    bad = write_spec(
        "parts:\n  - {name: stem, shape: cylinder, mass: 1, radius: -1, start: [0,0,0], end: [0,0,1]}\n"
    )
    proc = run_rbi_inprocess("show", bad, "--out", tmp_path / "a.png")
    one_line_exit_2(proc, "stem", "radius")
    assert not (tmp_path / "a.png").exists()


@pytest.mark.parametrize("name", SPECS)
def test_rbi_parts_works_on_every_bundled_body(name):
    """The part masses add up to the body's mass, and the inertia shares to one."""
    proc = run_rbi_inprocess("parts", BODIES / name, "--format", "json")
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    assert sum(p["mass"] for p in result["parts"]) == pytest.approx(result["mass"], rel=1e-12)
    assert sum(p["inertia_share"] for p in result["parts"]) == pytest.approx(1.0, rel=1e-9)


def test_a_picture_without_matplotlib_names_the_option_that_asked_for_it(monkeypatch, tmp_path, bodies):
    """show and animate take the picture from --out; simulate and sweep from --plot."""
    import sys

    from tests.conftest import run_rbi_inprocess

    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib now raises ImportError
    shown = run_rbi_inprocess("show", bodies / "top.yaml", "--out", tmp_path / "top.png")
    gif = run_rbi_inprocess("animate", bodies / "top.yaml", "--out", tmp_path / "top.gif")
    plot = run_rbi_inprocess("simulate", bodies / "top.yaml", "--plot", tmp_path / "run.png")
    for proc, option in ((shown, "--out"), (gif, "--out"), (plot, "--plot")):
        assert proc.returncode == 2
        assert proc.stderr.startswith(f"rbi: {option}: needs matplotlib"), proc.stderr
    assert not any(tmp_path.iterdir())


def test_the_picture_path_is_printed_escaped(tmp_path, monkeypatch, bodies):
    # `rbi show bodies/top.yaml --out $'/tmp/a\x1b[31mX.html'` wrote the ESC byte to stdout: the
    # path a user gave reaches the terminal escaped, as in rbi's messages (\x1b)
    monkeypatch.chdir(tmp_path)
    proc = run_rbi_inprocess("show", bodies / "top.yaml", "--out", "a\x1b[31mX.html")
    assert proc.returncode == 0, proc.stderr
    assert "\x1b" not in proc.stdout
    assert proc.stdout.startswith("a\\x1b[31mX.html: ") and proc.stdout.endswith(" parts drawn\n")
