"""Names from a spec as picture labels: shown as written, never as markup, never too long.

matplotlib typesets text between ``$`` signs as mathtext, so a part named ``$\\frac{$`` would
make the picture fail and ``$x^2$`` would be drawn as a formula. Every text that holds a name
is drawn with mathtext off (:func:`plain`, :func:`plain_legend`) and made from :func:`label`:
hidden characters shown as escapes (one line), cut to :data:`MAX_LABEL_CHARS` (a 1 MB name
took minutes to lay out).
"""

from __future__ import annotations

import functools
from collections.abc import Iterable

from rbi.text import number, visible


def pyplot():
    """matplotlib's pyplot on the Agg backend (pictures written to files, no window)."""
    import matplotlib  # optional extra `plot`, loaded only to draw

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # optional extra `plot`, loaded only to draw

    return plt


MAX_LABEL_CHARS = 60
"""Longest name drawn in a picture (characters); a longer one is cut and ends in ``…``."""


def label(text: object, limit: int = MAX_LABEL_CHARS) -> str:
    """``text`` as one line of at most ``limit`` visible characters: hidden characters as
    escapes (``\\n``, ``\\u202e``), a longer text cut and ended with ``…``."""
    text = str(text)[: 4 * limit]  # nothing past this can show; escapes at most quadruple it
    shown = visible(text)
    return shown if len(shown) <= limit else shown[: limit - 1] + "…"


def motion_title(
    name: object,
    omega0: Iterable[float],
    spin_axis: Iterable[float] | None,
    nudge_deg: float,
    limit: int = MAX_LABEL_CHARS,
) -> str:
    """The title of a run's pictures (``simulate --plot``, ``animate``): the body's ``name``, its
    start and the nudge (degrees). ``omega0`` (body axes, rad/s) along the unit ``spin_axis``
    (body axes) is ``spin W rad/s``; any other is written out, ``ω₀ [wx, wy, wz] rad/s``, so
    that an --omega run is not titled with a spin it was not given (None: a run given its ω,
    whose direction is its spin axis, is written out too)."""
    omega = [float(w) for w in omega0]
    axis = [] if spin_axis is None else [float(a) for a in spin_axis]
    along = sum(w * a for w, a in zip(omega, axis))
    off = max((abs(w - along * a) for w, a in zip(omega, axis)), default=float("inf"))
    start = (
        f"spin {number(along)} rad/s"
        if off <= 1e-12 * max(abs(along), 1e-300)
        else "ω₀ [" + ", ".join(number(w) for w in omega) + "] rad/s"
    )
    return f"{label(name, limit)}: {start}, nudge {number(nudge_deg)}°"


def plain(*texts):
    """Turn mathtext off on matplotlib Text objects (``$`` is then just a dollar sign), and
    write each character their font cannot draw as an escape (``\\u540d``) rather than a box
    and a warning per glyph on stderr; returns the first, for chaining."""
    for text in texts:
        text.set_parse_math(False)
        text.set_text(_drawable(text.get_text(), text.get_fontproperties()))
    return texts[0] if texts else None


def _drawable(text: str, font) -> str:
    if text.isascii():
        return text
    covered = _characters_of(font)
    return "".join(c if ord(c) in covered or c == "\n" else f"\\u{ord(c):04x}" for c in text)


def _characters_of(font) -> frozenset[int]:
    """Code points the fonts matplotlib would use for ``font`` can draw (with its fallbacks)."""
    from matplotlib.font_manager import fontManager  # optional extra `plot`, loaded only to draw

    return _charmaps(tuple(fontManager._find_fonts_by_props(font)))


@functools.cache
def _charmaps(paths: tuple[str, ...]) -> frozenset[int]:
    from matplotlib.ft2font import FT2Font  # optional extra `plot`, loaded only to draw

    return frozenset(code for path in paths for code in FT2Font(str(path)).get_charmap())


def plain_legend(legend):
    """:func:`plain` on every text of a matplotlib legend (None passes)."""
    if legend is not None:
        plain(*legend.get_texts())
    return legend
