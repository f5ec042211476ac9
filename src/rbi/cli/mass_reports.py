"""What `rbi inertia` and `rbi principal` print for each file, given options already parsed.

:mod:`rbi.cli.mass_commands` declares the options.
Every number is in the spec's units unless ``--units`` asks for others.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from rbi import api
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.option_values import in_output_units, parse_about, parse_rotation, parse_vector
from rbi.cli.render import body_size, matrix_digits, number

PRODUCT_SIGNS = ("tensor", "cad")
"""Signs of the off-diagonal entries: ``tensor`` (the matrix, ``I_xy = −∫xy dm``) or ``cad``
(the positive integrals ``+∫xy dm`` SolidWorks and CATIA print)."""

PRODUCT_SIGN_TITLES = {
    "tensor": "products −∫xy dm",
    "cad": "CAD products +∫xy dm",
}


def load_body(file: str) -> api.Body:
    """The `rbi.Body` of the spec ``file`` (``-``: standard input)."""
    return api.load(file)


def header(body: api.Body, about_label: str, about_point) -> dict:
    """The keys every mass-properties result starts with."""
    return {
        "name": body.name,
        "units": body.units,
        "mass": body.mass,
        "center_of_mass": body.center_of_mass,
        "about": about_point,
        "about_label": about_label,
        "warnings": list(body.warnings),
    }


def with_product_sign(inertia, sign: str):
    """The inertia matrix with its off-diagonal entries in convention ``sign`` (see
    :data:`PRODUCT_SIGNS`); the moments on the diagonal never change."""

    shown = np.array(inertia, dtype=float)
    if sign == "tensor":
        return shown
    if sign == "cad":
        off_diagonal = ~np.eye(3, dtype=bool)
        shown[off_diagonal] = 0.0 - shown[off_diagonal]  # 0.0 - 0.0 is +0.0, no '-0' printed
        return shown
    raise ValueError(f"unknown products sign {sign!r} (expected one of {PRODUCT_SIGNS})")


def place_rows(body: api.Body, about_label: str, point) -> list[tuple[str, str, str]]:
    """The rows every mass-properties table starts with: the mass, the centre of mass and the
    ``--about`` point (a coordinate below 1e-12 of the body's size printed 0)."""
    # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
    from rbi.cli import tables

    labels, size = body.unit_labels, body_size(body)
    return [
        ("mass", labels["mass"], number(body.mass, 8)),
        ("centre of mass", labels["length"], tables.vector(body.center_of_mass, size)),
        (f"about ({about_label})", labels["length"], tables.vector(point, size)),
    ]


def title(body, what: str) -> str:
    return f"{body.name or body.path} — {what}"


def inertia(
    files: Sequence[str],
    about: str = "com",
    rotate: Sequence[str] | None = None,
    axis: str | None = None,
    products: str = "tensor",
    units: str | None = None,
    fmt: str = "table",
) -> int:
    """`rbi inertia FILE...`: the exit status (see :func:`rbi.cli.each_file.report_each`)."""
    turns = [parse_rotation(r) for r in rotate or []]
    direction = None
    if axis is not None:
        try:
            direction = api.unit_vector(parse_vector(axis, "--axis"))
        except ValueError:
            raise api.SpecError(f"--axis: must be a non-zero direction X,Y,Z (got {axis!r})") from None
    return report_each(files, lambda file: _inertia_of(file, about, turns, direction, products, units), fmt)


def _inertia_of(file: str, about: str, turns, direction, products: str, units: str | None):

    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    axes = turns or None
    shown = with_product_sign(body.inertia(point, axes), products)
    result = header(body, about_label, point) | {
        "frame": "world (rotated)" if turns else "body",
        "rotations": [f"{a}:{np.degrees(np.radians(d)):g}" for a, d in turns],
        "products_sign": products,
        "inertia": shown,
    }
    if direction is not None:
        result |= {"axis": direction, "moment_about_axis": body.moment_about_axis(direction, point, axes)}

    def table():
        # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
        from rbi.cli import tables

        labels = body.unit_labels
        frame = "world axes after " + ", then ".join(result["rotations"]) if turns else "body axes"
        rows = [
            *place_rows(body, about_label, point),
        ]
        if direction is not None:
            rows += [
                ("axis (unit)", "", tables.vector(direction)),
                ("moment about axis", labels["inertia"], number(result["moment_about_axis"], 8)),
            ]
        return tables.stack(
            tables.quantities(title(body, "inertia"), rows),
            tables.matrix(
                f"Inertia about {about_label}, {frame}; {PRODUCT_SIGN_TITLES[products]}",
                shown,
                labels["inertia"],
            ),
        )

    return FileReport(result, table)


def principal(files: Sequence[str], about: str = "com", units: str | None = None, fmt: str = "table") -> int:
    """`rbi principal FILE...`: the exit status (see :func:`rbi.cli.each_file.report_each`)."""

    return report_each(files, lambda file: _principal_of(file, about, units), fmt)


def _principal_of(file: str, about: str, units: str | None):
    body = load_body(file)
    about_label, point = parse_about(about, body)
    body, (point,) = in_output_units(body, units, point)
    principal = body.principal(point)
    moments, axes, radii = principal.moments, principal.axes, principal.radii_of_gyration
    result = header(body, about_label, point) | {"moments": moments, "axes": axes, "radii_of_gyration": radii}

    def table():
        # not at top level: `rbi inertia --format json` would load rbi.cli.tables too
        from rbi.cli import tables

        labels = body.unit_labels
        scale, scale_text = matrix_digits(moments)
        t = tables.titled(f"Principal axes about {about_label} (body frame)")
        t.add_column("#")
        t.add_column(tables.unit_header("moment", labels["inertia"], scale_text), justify="right")
        for c in "xyz":
            t.add_column(f"axis {c}", justify="right")
        t.add_column(tables.unit_header("radius of gyration", labels["length"]), justify="right")
        for i, (m, a, k) in enumerate(zip(moments, axes, radii), start=1):
            t.add_row(f"I{i}", number(m / scale, 7), *(number(v, 7) for v in a), number(k, 7))
        return tables.stack(
            tables.quantities(
                title(body, "principal"),
                place_rows(body, about_label, point),
            ),
            t,
        )

    # CSV: radii numbered like the moments they belong to (radii_of_gyration_1 ...), not _x, _y, _z
    csv_row = {k: v for k, v in result.items() if k != "radii_of_gyration"}
    csv_row |= {f"radii_of_gyration_{i}": k for i, k in enumerate(radii, start=1)}
    return FileReport(result, table, csv_rows=[csv_row])
