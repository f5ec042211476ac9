"""`rbi parts`: the body part by part — mass, centre of mass, own inertia, share of the
body's inertia, and the density each solid implies (a check on the spec's units)."""

from __future__ import annotations

import math

from rbi.cli.options import FormatOption, OutputFormat, SpecFile
from rbi.cli.render import emit, number
from rbi.cli.terminal import say

PLAUSIBLE_DENSITY_KG_M3 = (1.0, 25_000.0)
"""Densities a solid can have: from aerogels and foams (a few kg/m³) to osmium (22,590)."""

TYPICAL_DENSITY_KG_M3 = 3000.0
"""The middle of engineering materials, used to guess which units a spec meant."""


def parts(file: SpecFile, format: FormatOption = OutputFormat.table) -> None:
    """Per-part breakdown: mass and its share, centre of mass, inertia about the part's own
    centre of mass, share of the body's inertia, implied density.

    \b
    Examples:
      rbi parts top_bolted.yaml
      rbi parts wheel_with_holes.yaml --format json
    """
    from rbi.core.inertia import inertia_shares
    from rbi.spec.load import load_body
    from rbi.spec.translate import part_volume
    from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

    body = load_body(file)
    spec_parts = list(body.spec.parts) if body.spec is not None else []
    shares = inertia_shares(body.elements, body.props)
    to_si = MASS_UNITS_IN_KG[body.mass_unit] / LENGTH_UNITS_IN_M[body.length_unit] ** 3
    rows = []
    for i, element in enumerate(body.elements):
        part = spec_parts[i] if i < len(spec_parts) else None
        volume = None if part is None else part_volume(part)
        density = abs(element.mass) / volume if volume else None
        rows.append({
            "name": body.part_names[i] or f"parts[{i}]",
            "shape": part.shape if part is not None else "point_cloud",
            "hole": bool(getattr(part, "subtract", False)),
            "mass": element.mass,
            "mass_share": element.mass / body.props.mass,
            "center_of_mass": element.com,
            "inertia_about_com": element.inertia_com,
            "inertia_share": shares[i],
            "volume": volume,
            "implied_density": density,
            "implied_density_si": None if density is None else density * to_si,
        })
    for i, row in enumerate(rows):
        warning = density_warning(row, body, i)
        if warning:
            say(f"warning: {file}: {warning}")
    result = {"name": body.name, "units": body.units, "mass": body.props.mass,
              "center_of_mass": body.props.com, "parts": rows}
    emit(format.value, result, lambda: _table(body, rows), csv_rows=rows)


def density_warning(row: dict, body, index: int) -> str | None:
    """A one-line warning when a solid's implied density is outside what any solid has, with
    the units block that would make it plausible (or None)."""
    from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG

    density = row["implied_density"]
    si = row["implied_density_si"]
    low, high = PLAUSIBLE_DENSITY_KG_M3
    if si is None or low <= si <= high or si == 0.0:
        return None
    best = None
    for length, metres in LENGTH_UNITS_IN_M.items():
        for mass, kilograms in MASS_UNITS_IN_KG.items():
            candidate = density * kilograms / metres ** 3
            if low <= candidate <= high and (length, mass) != (body.length_unit, body.mass_unit):
                distance = abs(math.log(candidate / TYPICAL_DENSITY_KG_M3))
                if best is None or distance < best[0]:
                    best = (distance, length, mass)
    label = f"parts[{index}]" + (f" ({row['name']})" if not row["name"].startswith("parts[") else "")
    text = f"{label}: implied density {si:.3g} kg/m³ is {'more' if si > high else 'less'} than any solid material has"
    if best is not None:
        text += f": is this spec in {best[1]} and {best[2]}? add `units: {{length: {best[1]}, mass: {best[2]}}}`"
    return text


def _table(body, rows):
    from rbi.cli import tables

    labels = body.labels
    density_unit = f"{body.mass_unit}/{body.length_unit}³"
    table = tables.titled(f"{body.name or body.path}: parts")
    for header, justify in (("part", "left"), ("shape", "left"), (tables.unit_header("mass", labels["mass"]), "right"),
                            ("mass share [%]", "right"), (tables.unit_header("centre of mass", labels["length"]), "right"),
                            ("inertia share [%]", "right"), (tables.unit_header("density", density_unit), "right")):
        table.add_column(header, justify=justify, overflow="fold")  # wrapped, never cut short, in a narrow terminal
    for row in rows:
        table.add_row(tables.plain_text(row["name"]), row["shape"] + (" (hole)" if row["hole"] else ""),
                      number(row["mass"]), number(100 * row["mass_share"], 4), tables.vector(row["center_of_mass"]),
                      number(100 * row["inertia_share"], 4),
                      "—" if row["implied_density"] is None else number(row["implied_density"], 4))
    return table
