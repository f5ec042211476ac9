"""One self-contained HTML page that shows a body in 3D with three.js, and plays its motion.

The page inlines the vendored three.js bundle (``vendor/three``, MIT licence) and its data as
JSON, so it opens offline and asks the network for nothing. Data that came from a spec (names)
is escaped: ``<`` is written ``\\u003c`` inside the JSON, so no name can close the script.
"""

from __future__ import annotations

import html
import json
import re
from importlib import resources
from typing import Any


def _resource(*parts: str) -> str:
    return resources.files("rbi.viz").joinpath(*parts).read_text(encoding="utf-8")


SCRIPT_ESCAPES = str.maketrans({c: f"\\u{ord(c):04x}" for c in "<>&\u2028\u2029"})
"""The characters JSON may hold but a ``<script>`` element may not, each as its ``\\uXXXX`` escape."""


def script_safe_json(data: Any) -> str:
    """JSON text that can sit inside a ``<script>`` element whatever strings it holds."""
    text = json.dumps(data, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return text.translate(SCRIPT_ESCAPES)


def html_page(data: dict[str, Any], speed: float = 1.0) -> str:
    """The page for ``data`` (see :func:`rbi.viz.motion.animation_data`; a single time makes a
    still view without the play controls)."""
    three = _resource("vendor", "three", "three.bundle.min.js")
    if "</script" in three.lower():  # pragma: no cover - checked when the bundle is vendored
        raise ValueError("the three.js bundle cannot be inlined")
    fill = {
        "TITLE": html.escape(str(data.get("title", "rbi"))),
        "SPEED": f"{float(speed):g}",
        "DATA": script_safe_json(data),
        "THREE": three,
    }
    # one pass over the template: text put in is never searched for placeholders again
    template = _resource("templates", "page.html")
    return re.sub(r"__(TITLE|SPEED|DATA|THREE)__", lambda m: fill[m.group(1)], template)
