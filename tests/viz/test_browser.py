"""The animation page in a real browser (headless Chromium, WebGL through SwiftShader): the
body is drawn where the top stands, it moves between two times, and the page logs no error.

Skipped with the reason where Chromium is not installed (`.ci/run` installs Debian's
``chromium`` package when it is missing).
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

from tests.conftest import BODIES, run_rbi

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="headless Chromium is not installed (apt-get install chromium)"
)

WIDTH, HEIGHT = 800, 600


def _chromium(tmp_path, url: str, *action: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [
            CHROMIUM,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--mute-audio",
            f"--user-data-dir={tmp_path / 'profile'}",
            f"--window-size={WIDTH},{HEIGHT}",
            "--virtual-time-budget=2000",
            *action,
            url,
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )


def _screenshot(tmp_path, page, t: float, name: str) -> np.ndarray:
    from PIL import Image

    shot = tmp_path / name
    _chromium(tmp_path, f"{page.as_uri()}?t={t}&pause", f"--screenshot={shot}")
    assert shot.exists(), "Chromium wrote no screenshot"
    return np.asarray(Image.open(shot).convert("RGB"), dtype=int)


def _body_pixels(image: np.ndarray) -> np.ndarray:
    """Strongly coloured pixels (the parts are blue and orange; background and ground are grey)."""
    return (image.max(axis=2) - image.min(axis=2)) > 60


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    folder = tmp_path_factory.mktemp("animate")
    out = folder / "top.html"
    run_rbi(
        "animate", BODIES / "top_bolted.yaml", "--spin", "200", "--duration", "1.5", "--out", out, check=True
    )
    return out


def test_the_top_is_drawn_and_moves(page, tmp_path):
    early = _screenshot(tmp_path, page, 0.05, "early.png")
    late = _screenshot(tmp_path, page, 1.2, "late.png")
    assert early.shape == late.shape == (HEIGHT, WIDTH, 3)
    middle = (slice(HEIGHT // 5, 4 * HEIGHT // 5), slice(WIDTH // 4, 3 * WIDTH // 4))
    for image in (early, late):
        assert _body_pixels(image)[middle].sum() > 2000, "no body where the top stands"
        assert (
            _body_pixels(image).sum() - _body_pixels(image)[middle].sum() < _body_pixels(image)[middle].sum()
        )
    changed = np.abs(early - late).max(axis=2) > 40
    assert changed[middle].sum() > 1000, "the body did not move between t = 0.05 s and t = 1.2 s"


def test_the_page_logs_no_error(page, tmp_path):
    dom = _chromium(tmp_path, f"{page.as_uri()}?t=0.5&pause", "--dump-dom").stdout
    assert '<div id="status" hidden="">ready</div>' in dom, dom[-2000:]
    assert '<div id="errors"></div>' in dom
    assert "t = 0.500 s" in dom  # the readout shows the time it was asked for


def test_a_frame_stamped_before_the_page_loaded_does_not_turn_time_back(page, tmp_path):
    # Chromium may hand requestAnimationFrame a stamp earlier than performance.now() read before
    # it (seen under load: "t = -0.475 s", tilt -0.39°). Replay that: the first frame's stamp is
    # set a second back, and no frame follows it, so the readout shows what that one frame did.
    early_frame = (
        "<script>(function () { const raf = window.requestAnimationFrame.bind(window); let n = 0;"
        " window.requestAnimationFrame = function (cb) {"
        " if (n++ === 0) raf(function (s) { cb(s - 1000);"
        " document.documentElement.setAttribute('data-replayed', 'yes'); }); return n; }; })();</script>"
    )
    replayed = tmp_path / "replayed.html"
    replayed.write_text(page.read_text().replace("<head>", "<head>" + early_frame, 1))
    dom = _chromium(tmp_path, replayed.as_uri(), "--dump-dom").stdout
    assert '<div id="status" hidden="">ready</div>' in dom, dom[-2000:]
    assert 'data-replayed="yes"' in dom  # the early frame ran (the page shows t = 0 before any frame)
    assert "t = 0.000 s" in dom, dom[-600:]


def test_the_show_page_draws_the_body_below_its_legend(tmp_path):
    # rbi show bodies/cubesat.yaml --out F.html: the heading with its 11-part legend covers the
    # top ~260 of 600 pixels, and the camera framed the body in the whole window, so half the
    # bus, the antenna horn and a solar panel were drawn behind the legend (a quarter of the
    # legend's plain right-hand half tinted by them). Now the view is moved down and scaled to
    # the room below the heading: that part of the legend is plain white over plain background.
    page = tmp_path / "cubesat.html"
    assert run_rbi("show", BODIES / "cubesat.yaml", "--out", page).returncode == 0
    shot = _screenshot(tmp_path, page, 0.0, "cubesat.png")
    bottom = 100
    while shot[bottom, WIDTH - 15].min() >= 250:  # the heading's right edge, below its text lines
        bottom += 1
    assert bottom > 200, bottom  # eleven parts listed
    behind = shot[bottom - 120 : bottom - 4, 320 : WIDTH - 20].min(axis=2)  # right of the part names
    assert (behind < 240).mean() == 0, f"{(behind < 240).mean():.1%} of the legend's right half is tinted"
    drawn = shot[bottom:, :].min(axis=2) < 120  # the body, below the heading
    assert drawn.sum() > 5000, drawn.sum()
