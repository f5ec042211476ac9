"""`rbi parts`: the body part by part — mass, volume, centre of mass, own inertia and its
principal moments, share of the body's inertia, and the density each solid implies (a check on
the spec's units) — with a total row for the whole body.
"""

from __future__ import annotations

from typing import Annotated

import typer
from rich.text import Text

from rbi import api
from rbi.api import LENGTH_UNITS, MASS_UNITS
from rbi.cli import tables
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import FormatOption, OutputFormat, SpecFiles
from rbi.cli.render import body_size, matrix_digits, number, without_noise


def parts(
    files: SpecFiles,
    format: FormatOption = OutputFormat.table,
    expand: Annotated[
        bool,
        typer.Option("--expand", help="List each sub-assembly's own parts (ASSEMBLY/PART), not one row."),
    ] = False,
) -> int:
    """Per-part breakdown: mass and its share, volume, centre of mass, inertia about the part's
    own centre of mass and its principal moments, share of the body's inertia, implied
    density; a total row for the body.

    \b
    Examples:
      rbi parts top_bolted.yaml
      rbi parts wheel_with_holes.yaml --format json
      rbi parts *.yaml --format csv
      rbi parts cubesat_assembly.yaml --expand
    """

    return report_each(files, lambda file: parts_of(file, expand), format.value)


def parts_of(file: str, expand: bool = False):
    """What `rbi parts` gives for one file (:class:`rbi.cli.each_file.FileReport`).

    JSON: the keys docs/parts.md lists, and for each part ``volume`` (length³, all copies of a pattern;
    negative for a hole, as its mass; null for a part without one), ``principal_moments`` (ascending, about the part's own centre
    of mass; negative for a hole); at the top ``volume``, the solids' volume with holes taken
    away (parts without a volume add none), ``mean_density`` (mass / volume, null unless every
    part has a volume) and ``principal_moments`` of the body about its centre of mass.
    """
    body = api.load(file)  # its warnings hold the mesh notes (repair, overlaps) too
    rows = _part_rows(body, expand)
    volume = sum(row["volume"] for row in rows if row["volume"] is not None)  # a hole's is negative
    every_part_has_volume = all(row["volume"] is not None for row in rows)
    total = {
        "volume": volume if any(row["volume"] is not None for row in rows) else None,
        "mean_density": body.mass / volume if every_part_has_volume and volume > 0 else None,
        "principal_moments": body.principal().moments,  # about the centre of mass, ascending
    }
    result = {
        "name": body.name,
        "units": body.units,
        "warnings": list(body.warnings),
        "mass": body.mass,
        "center_of_mass": body.center_of_mass,
        "volume": total["volume"],
        "mean_density": total["mean_density"],
        "principal_moments": total["principal_moments"],
        "parts": rows,
    }
    summary = {key: value for key, value in result.items() if key != "warnings"} | {"parts": len(rows)}
    return FileReport(result, lambda: _table(body, rows, total), csv_rows=rows, summary=summary)


def _part_rows(body, expand: bool = False) -> list[dict]:
    """One row per part: its mass, share, centre of mass, inertia about it, principal moments,
    share of the inertia, volume and the density they imply (file units and SI)."""

    units = body.units
    to_si = MASS_UNITS[units["mass"]] / LENGTH_UNITS[units["length"]] ** 3
    parts = body.parts(expand)
    rows = []
    for part in parts:
        density = abs(part.mass / part.volume) if part.volume else None
        rows.append(
            {
                "name": part.name,
                "shape": part.shape,
                "hole": part.hole,
                "mass": part.mass,
                "mass_share": part.mass / body.mass,
                "center_of_mass": part.center_of_mass,
                "inertia_about_com": part.inertia_about_com,
                "principal_moments": part.principal_moments,
                "inertia_share": part.inertia_share,
                "volume": part.volume,  # negative for a hole, as the mass: the parts add up to the total
                "implied_density": density,
                "implied_density_si": None if density is None else density * to_si,
            }
        )
    if any(part.shape == "step" for part in parts):  # the error estimate of each STEP part
        for row, part in zip(rows, parts):
            row["integration_error"] = part.integration_error
    return rows


def _table(body, rows, total):
    """Three tables, each narrow enough for 80 columns: mass and volume; centre of mass and
    share of the inertia; principal moments. Each ends with the whole body's row."""

    labels, units = body.unit_labels, body.units
    name = body.name or body.path
    names = [tables.plain_text(row["name"]) for row in rows]
    length = labels["length"]
    masses = _titled_table(
        f"{name}: parts — mass and volume",
        names,
        (
            "shape",
            f"mass\n[{labels['mass']}]",
            "mass\nshare [%]",
            f"volume\n[{units['length']}³]",
            f"density\n[{units['mass']}/{units['length']}³]",
        ),
        [
            (
                row["shape"] + (" (hole)" if row["hole"] else ""),
                number(row["mass"]),
                number(100 * row["mass_share"], 4),
                "—" if row["volume"] is None else number(row["volume"]),
                number(row["implied_density"], 4),
            )
            for row in rows
        ],
        (
            "",
            number(body.mass),
            number(100.0, 4),
            number(total["volume"]),
            number(total["mean_density"], 4),
        ),
    )
    places = _places_table(body, rows, names, length, f"{name}: parts — centre of mass")
    scale, scale_text = matrix_digits(
        [total["principal_moments"], *(row["principal_moments"] for row in rows)]
    )
    unit = f"[{labels['inertia']}]" + (f" {scale_text}" if scale_text else "")
    moments = _titled_table(
        f"{name}: parts — principal moments (own CoM)",
        names,
        (f"I1\n{unit}", f"I2\n{unit}", f"I3\n{unit}"),
        [tuple(number(m / scale, 5) for m in row["principal_moments"]) for row in rows],
        tuple(number(m / scale, 5) for m in total["principal_moments"]),
    )
    return tables.stack(masses, places, moments)


def _places_table(body, rows, names: list, length: str, title: str):
    """Each part's centre of mass (a coordinate below 1e-12 of the body's size is rounding
    noise, printed 0) and its share of the inertia."""
    size = body_size(body)
    return _titled_table(
        title,
        names,
        (f"centre of\nmass x [{length}]", f"\ny [{length}]", f"\nz [{length}]", "inertia\nshare [%]"),
        [
            (
                *(number(c) for c in without_noise(row["center_of_mass"], size)),
                number(100 * row["inertia_share"], 4),
            )
            for row in rows
        ],
        (*(number(c) for c in without_noise(body.center_of_mass, size)), number(100.0, 4)),
    )


MAX_TABLE_PARTS = 200
"""Most parts a table lists (then a line saying how many more): 10,000 rows took rich 25 s to
lay out, and a person reads the CSV or JSON of a body that large, which list every part."""


def _titled_table(title: str, names: list, headers, cells, total_row):
    """Numbers never wrap (a column of them is as wide as its widest number); part names
    and shapes wrap in a narrow terminal. At most :data:`MAX_TABLE_PARTS` parts are listed."""

    t = tables.titled(title)
    t.add_column("part", overflow="fold")
    for header in headers:
        numbers = not header.startswith("shape")
        # the label over its unit (a rich Text: rbi's own words, never read as markup)
        t.add_column(
            Text(header, justify="right" if numbers else "left"),
            justify="right" if numbers else "left",
            no_wrap=numbers,
            overflow="fold",
        )
    for part_name, row in zip(names[:MAX_TABLE_PARTS], cells):
        t.add_row(part_name, *row)
    if len(names) > MAX_TABLE_PARTS:
        t.add_row(f"… {len(names) - MAX_TABLE_PARTS} more parts")  # CSV and JSON list them all
    t.add_section()
    t.add_row("total", *total_row)
    return t
