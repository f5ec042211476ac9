"""`rbi parts`: the body part by part — mass, volume, centre of mass, own inertia and its
principal moments, share of the body's inertia, and the density each solid implies (a check on
the spec's units) — with a total row for the whole body.

The options are declared here; what it prints for each file is in :mod:`rbi.cli.parts_report`."""

from __future__ import annotations

from rbi.cli import parts_report
from rbi.cli.options import FormatOption, OutputFormat, SpecFiles


def parts(files: SpecFiles, format: FormatOption = OutputFormat.table) -> int:
    """Per-part breakdown: mass and its share, volume, centre of mass, inertia about the part's
    own centre of mass and its principal moments, share of the body's inertia, implied
    density; a total row for the body.

    \b
    Examples:
      rbi parts top_bolted.yaml
      rbi parts wheel_with_holes.yaml --format json
      rbi parts *.yaml --format csv
    """

    return parts_report.parts(files, format.value)
