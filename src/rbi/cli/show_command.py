"""`rbi show`: a picture of the body as specified (PNG, SVG, or a 3D HTML page)."""

from __future__ import annotations

from typing import Annotated

import typer

from rbi.cli.extras import needs
from rbi.cli.options import SpecFile

OutOption = Annotated[
    str,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE.png|FILE.svg|FILE.html",
        help=f"The picture: .png or .svg ({needs('matplotlib', 'plot')}), or .html (3D, opens offline).",
    ),
]


def show(
    file: SpecFile,
    out: OutOption,
) -> None:
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
    from rbi.cli.output import output_target, write_output

    target = output_target(out, "--out", ("png", "svg", "html"), inputs=[file])
    if target.format != "html":
        from rbi.cli.plot import require_matplotlib

        require_matplotlib("--out")
    from rbi.spec.geometry import part_geometry
    from rbi.spec.load import load_body
    from rbi.viz.still import part_count, view_data

    body = load_body(file)
    from rbi.cli.render import say_warnings

    say_warnings(body.warnings)
    data = view_data(
        body.name or file,
        part_geometry(body),
        body.props.center_of_mass,
        body.props.inertia_about_com,
        body.pivot,
        body.length_unit,
        body.labels["inertia"],
    )
    if target.format == "html":
        from rbi.viz.page import html_page

        data["legend"] = (
            f"{part_count(data['parts'])} parts · black dot: centre of mass · coloured lines: principal "
            "axes · "
            + " · ".join(a["label"] for a in data["principal_axes"])
            + f" · grey arrows: the spec's x, y, z from its origin · lengths in {body.length_unit}"
        )
        write_output(target, html_page(data))
    else:
        from rbi.viz.still import draw_still

        write_output(target, writer=lambda path: draw_still(data, path, format=target.format))
    print(f"{out}: {part_count(data['parts'])} parts drawn")
