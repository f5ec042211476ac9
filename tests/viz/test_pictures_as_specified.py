"""Issue 19, "Pictures that show the body as specified": rbi show in the spec's own coordinates
with a legend of parts (PNG/SVG and HTML), the animation's ground below the lowest point the
body reaches, and a GIF's progress on a terminal's stderr."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

from tests.conftest import BODIES, run_rbi_inprocess

FAR = (
    "pivot: [100, 200, 290]\nparts:\n"
    "  - {name: block, shape: box, mass: 1, size: [2, 2, 2], center: [100, 200, 300]}\n"
    "  - {name: drill, shape: cylinder, radius: 0.2, start: [100, 200, 299], end: [100, 200, 301], "
    "density: 1, subtract: true}\n"
    "  - {name: bolt, shape: point, mass: 0.1, position: [101, 200, 301], "
    "pattern: {count: 4, axis: [0, 0, 1], through: [100, 200, 0]}}\n"
)

PENDULUM = (
    "name: pendulum\npivot: [0, 0, 0]\nparts:\n"
    "  - {name: string, shape: rod, mass: 0.01, start: [0, 0, 0], end: [0, 0, -1]}\n"
    "  - {name: bob, shape: sphere, mass: 1, radius: 0.1, center: [0, 0, -1]}\n"
)


def page_data(path) -> dict:
    text = path.read_text(encoding="utf-8")
    return json.loads(
        re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.S).group(1)
    )


def svg_ticks(path) -> list[list[float]]:
    """The tick labels matplotlib wrote (as comments) before each axis label, per axis."""
    comments = re.findall(r"<!-- (.*?) -->", path.read_text(encoding="utf-8"))
    axes, current = [], []
    for text in comments:
        if re.fullmatch(r"[xyz] \[[^\]]+\]", text):  # `x [m]`, `y [mm]`
            axes.append(current)
            current = []
        else:
            try:
                current.append(float(text.replace("−", "-")))
            except ValueError:
                current = []
    return axes


def test_show_ticks_are_the_specs_coordinates(write_spec, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "far.svg"
    assert run_rbi_inprocess("show", write_spec(FAR), "--out", out).returncode == 0
    x, y, z = svg_ticks(out)
    # the body spans x 99..101, y 199..201, z 290 (pivot)..301: the ticks read the same numbers
    assert min(x) <= 99.5 and max(x) >= 100.5 and all(95 <= v <= 105 for v in x), x
    assert min(y) <= 199.5 and max(y) >= 200.5 and all(195 <= v <= 205 for v in y), y
    assert min(z) <= 290 and max(z) >= 300 and all(285 <= v <= 306 for v in z), z


def test_show_page_has_the_specs_coordinates_and_a_legend_of_parts(write_spec, tmp_path):
    spec = write_spec(FAR)
    out = tmp_path / "far.html"
    assert run_rbi_inprocess("show", spec, "--out", out).returncode == 0
    data = page_data(out)
    truth = json.loads(run_rbi_inprocess("inertia", spec, "--format", "json").stdout)
    np.testing.assert_allclose(data["com"], truth["center_of_mass"], rtol=1e-12)
    assert data["pivot"] == [100.0, 200.0, 290.0]
    block = next(p for p in data["parts"] if p.get("name") == "block")
    np.testing.assert_allclose(block["center"], [100, 200, 300])
    legend = {entry["name"]: entry for entry in data["part_legend"]}
    assert set(legend) == {"block", "drill", "bolt"}
    assert legend["drill"]["hole"] and legend["bolt"]["copies"] == 4 and legend["block"]["shape"] == "box"
    assert data["spec_axes"] >= 1.15 * 301 - 1e-9  # the drawn x, y, z axes reach past the body


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def shown_page(tmp_path, spec) -> str:
    """The DOM of `rbi show SPEC --out F.html` after headless Chromium has run its scripts."""
    out = tmp_path / "shown.html"
    assert run_rbi_inprocess("show", spec, "--out", out).returncode == 0
    dom = subprocess.run(
        [
            CHROMIUM,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader",
            "--no-first-run",
            f"--user-data-dir={tmp_path / 'profile'}",
            "--virtual-time-budget=2000",
            "--dump-dom",
            out.as_uri(),
        ],
        capture_output=True,
        text=True,
        timeout=60,
    ).stdout
    assert '<div id="status" hidden="">ready</div>' in dom, dom[-2000:]
    return dom


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium is not installed (apt-get install chromium)")
def test_the_page_lists_the_parts_in_a_browser(tmp_path, bodies):
    dom = shown_page(tmp_path, bodies / "wheel_with_holes.yaml")
    items = re.findall(r'<li><span class="swatch"[^>]*></span>(.*?)</li>', dom)
    import yaml

    spec_names = [
        part["name"] for part in yaml.safe_load((bodies / "wheel_with_holes.yaml").read_text())["parts"]
    ]
    assert [item.split(":")[0] for item in items] == spec_names, items


def _animation(write_spec, tmp_path, text, *args) -> dict:
    out = tmp_path / "motion.html"
    proc = run_rbi_inprocess("animate", write_spec(text), "--duration", "2", "--out", out, *args)
    assert proc.returncode == 0, proc.stderr
    return page_data(out)


def test_a_hanging_pendulum_hangs_above_the_ground(write_spec, tmp_path):
    data = _animation(write_spec, tmp_path, PENDULUM, "--tilt", "30")
    # swinging through the vertical, the bob's bottom reaches 1 + 0.1 below the pivot
    assert -1.1 - 0.01 < data["ground_z"] <= -1.1 + 1e-4  # (the sphere is drawn as a fine polyhedron)
    low, high = data["height_range"]
    assert low == pytest.approx(-1.1, abs=5e-3)
    assert 0 <= high < 0.01  # the string's top end, drawn as a thin cylinder, at the pivot


def test_a_top_stands_on_the_ground_at_its_pivot(tmp_path, bodies):
    out = tmp_path / "top.html"
    assert (
        run_rbi_inprocess(
            "animate", bodies / "top.yaml", "--spin", "200", "--tilt", "10", "--duration", "0.5", "--out", out
        ).returncode
        == 0
    )
    assert page_data(out)["ground_z"] == 0.0  # the tip stays at the pivot; the rest stays above it


def test_a_free_body_has_no_ground(write_spec, tmp_path):
    data = _animation(
        write_spec,
        tmp_path,
        "parts:\n  - {shape: box, mass: 1, size: [1, 2, 3], center: [0, 0, 0]}\n",
        "--omega",
        "0.1,3,0.1",
    )
    assert data["ground_z"] is None and data["pivoted"] is False


def test_the_gif_frames_show_the_pendulum_below_its_pivot(write_spec, tmp_path):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "pendulum.gif"
    proc = run_rbi_inprocess("animate", write_spec(PENDULUM), "--duration", "0.2", "--fps", "5", "--out", out)
    assert proc.returncode == 0, proc.stderr
    frame = np.asarray(Image.open(out).convert("RGB"), dtype=int)
    bob = np.abs(frame - [0xD0, 0x8A, 0x2A]).max(axis=2) < 60  # the bob's orange (second part colour)
    rows = np.nonzero(bob.any(axis=1))[0]
    assert bob.sum() > 50, "the bob is not in the frame"  # about 100 pixels, a few fewer with the palette
    dark_pivot = np.nonzero((frame.max(axis=2) < 40).any(axis=1))[0]
    assert rows.mean() > dark_pivot.min(), "the bob is drawn above the pivot, not hanging below it"


def _animate_gif_in_a_terminal(out) -> str:
    """stderr of rbi animate … --out GIF run with stderr on a pseudo-terminal."""
    import pty

    controller, terminal = pty.openpty()
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "rbi",
            "animate",
            str(BODIES / "top.yaml"),
            "--spin",
            "100",
            "--duration",
            "0.6",
            "--fps",
            "25",
            "--out",
            str(out),
        ],
        stdout=subprocess.PIPE,
        stderr=terminal,
        env={**os.environ, "COLUMNS": "100"},
    )
    os.close(terminal)
    seen = b""
    while True:
        try:
            chunk = os.read(controller, 4096)
        except OSError:
            break
        if not chunk:
            break
        seen += chunk
    proc.wait(timeout=120)
    os.close(controller)
    assert proc.returncode == 0
    return seen.decode("utf-8", "replace")


def test_a_gif_shows_its_progress_on_a_terminal_and_nothing_in_a_pipe(tmp_path):
    pytest.importorskip("matplotlib")
    shown = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", _animate_gif_in_a_terminal(tmp_path / "top.gif"))
    assert re.search(r"gif ━+ +\d+/16 frames", shown), shown[-500:]
    piped = run_rbi_inprocess(
        "animate",
        BODIES / "top.yaml",
        "--spin",
        "100",
        "--duration",
        "0.2",
        "--fps",
        "10",
        "--out",
        tmp_path / "quiet.gif",
    )
    assert piped.returncode == 0 and piped.stderr == ""
