"""`rbi animate`: HTML and GIF outputs through the CLI, and its refusals."""

from __future__ import annotations

import json
import re

import pytest

from tests.conftest import one_line_exit_2, run_rbi, run_rbi_inprocess


def _page_data(path) -> dict:
    text = path.read_text(encoding="utf-8")
    return json.loads(
        re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.S).group(1)
    )


def test_html_holds_the_parts_and_the_motion(tmp_path, bodies):
    out = tmp_path / "top.html"
    proc = run_rbi_inprocess(
        "animate", bodies / "top_bolted.yaml", "--spin", "200", "--duration", "1", "--out", out
    )
    assert proc.returncode == 0, proc.stderr
    data = _page_data(out)
    assert [p["name"] for p in data["parts"]] == ["cone", "stem", "bolt"]
    assert data["pivoted"] is True and data["times"][0] == 0.0 and data["times"][-1] == pytest.approx(1.0)
    assert data["omega"][0] == pytest.approx(200.0)
    assert "keyframes" in proc.stdout


def test_free_body_is_animated_about_its_centre_of_mass(tmp_path, bodies):
    out = tmp_path / "tbar.html"
    proc = run_rbi_inprocess(
        "animate", bodies / "tbar.yaml", "--omega", "0.01,5,0", "--duration", "2", "--out", out
    )
    assert proc.returncode == 0, proc.stderr
    data = _page_data(out)
    assert data["pivoted"] is False and data["com"] == pytest.approx([0, 0, 0], abs=1e-12)


def test_gif_end_to_end(tmp_path, bodies):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "top.gif"
    proc = run_rbi(
        "animate",
        bodies / "top.yaml",
        "--spin",
        "300",
        "--tilt",
        "5",
        "--duration",
        "0.4",
        "--fps",
        "10",
        "--out",
        out,
    )
    assert proc.returncode == 0, proc.stderr
    assert Image.open(out).n_frames == 5 and "5 frames" in proc.stdout


@pytest.mark.parametrize(
    "args, words",
    [
        (["--speed", "3"], ["--speed", "0.1 and 2"]),
        (["--fps", "0"], ["--fps"]),
        (["--tilt", "nan"], ["--tilt"]),
    ],
)
def test_bad_options_are_one_line_and_write_nothing(tmp_path, bodies, args, words):
    out = tmp_path / "a.html"
    proc = run_rbi_inprocess("animate", bodies / "top.yaml", "--spin", "100", "--out", out, *args)
    one_line_exit_2(proc, *words)
    assert not out.exists()


def test_an_extension_it_cannot_write_is_refused(tmp_path, bodies):
    one_line_exit_2(
        run_rbi_inprocess("animate", bodies / "top.yaml", "--spin", "100", "--out", tmp_path / "a.mp4"),
        "--out",
    )


def test_the_spec_itself_is_never_overwritten(tmp_path, bodies):
    spec = tmp_path / "top.html"
    spec.write_text((bodies / "top.yaml").read_text())
    before = spec.read_text()
    proc = run_rbi_inprocess("animate", spec, "--spin", "100", "--out", spec)
    one_line_exit_2(proc, "--out")
    assert spec.read_text() == before


def test_a_gif_too_long_is_refused_before_any_work(tmp_path, bodies):
    out = tmp_path / "a.gif"
    proc = run_rbi_inprocess("animate", bodies / "dumbbell.yaml", "--duration", "1e9", "--out", out)
    one_line_exit_2(proc, "--duration", "frames")
    assert list(tmp_path.iterdir()) == []


def test_a_motion_too_fast_to_keyframe_is_refused(tmp_path, bodies):
    # 1e6 rad/s for 1 s turns the body 1e6 rad: 2e6 keyframes of at most 0.5 rad each
    out = tmp_path / "a.html"
    proc = run_rbi_inprocess(
        "animate", bodies / "top.yaml", "--spin", "1e6", "--duration", "1", "--yes", "--out", out
    )
    one_line_exit_2(proc, "--duration", "keyframes")
    assert not out.exists()


def test_a_long_slow_gif_still_plays_in_real_time(tmp_path, bodies):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "a.gif"
    # fewer keyframes are needed than frames: the run is sampled at least once per frame
    proc = run_rbi_inprocess(
        "animate",
        bodies / "dumbbell.yaml",
        "--omega",
        "0,0,0.1",
        "--duration",
        "30",
        "--fps",
        "20",
        "--out",
        out,
    )
    assert proc.returncode == 0, proc.stderr
    assert Image.open(out).n_frames == 601


def test_the_page_path_is_printed_escaped(tmp_path, monkeypatch, bodies):
    # as `rbi show --out`: the ESC byte of the path reached stdout as it was
    monkeypatch.chdir(tmp_path)
    proc = run_rbi_inprocess(
        "animate", bodies / "top_bolted.yaml", "--spin", "200", "--duration", "1", "--out", "a\x1b[31mX.html"
    )
    assert proc.returncode == 0, proc.stderr
    assert "\x1b" not in proc.stdout
    assert proc.stdout.startswith("a\\x1b[31mX.html: ") and "keyframes" in proc.stdout
