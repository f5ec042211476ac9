"""`rbi show`: a picture of the body as specified (PNG, SVG, or a 3D HTML page)."""

from __future__ import annotations

import rbi
from rbi.cli.options import REQUIRED, SpecFile, command, needs, out_option, require_matplotlib
from rbi.cli.render import say_warnings
from rbi.cli.terminal import terminal_safe


@command(
    out_option(
        "FILE.png|FILE.svg|FILE.html",
        f"The picture: .png or .svg ({needs('matplotlib', 'plot')}), or .html (3D, opens offline).",
        default=REQUIRED,
    )
)
def show(file: SpecFile, *, out: str) -> None:
    """Draw the body as specified: every part in place (holes red and translucent), the centre
    of mass, the principal axes about it (lengths in proportion to their moments, labelled
    with them) and the pivot. The commonest spec mistakes, a part in the wrong place or in the
    wrong unit, show at a glance.

    \b
    Examples:
      rbi show bodies/top_bolted.yaml --out top.png
      rbi show bodies/wheel_with_holes.yaml --out wheel.svg
      rbi show bodies/cubesat.yaml --out cubesat.html
    """

    if out.lower().endswith((".png", ".svg")):  # rbi.show checks the path (and its format)
        require_matplotlib("--out")
    body = rbi.load(file)
    say_warnings(body.warnings)
    count = rbi.show(body, out, title=body.name or file)
    print(f"{terminal_safe(out)}: {count} parts drawn")
