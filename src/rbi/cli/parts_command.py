"""`rbi parts`: the body part by part — mass, volume, centre of mass, own inertia and its
principal moments, share of the body's inertia, and the density each solid implies (a check on
the spec's units) — with a total row for the whole body.
"""

from __future__ import annotations

import rbi
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import FORMAT, OutputFormat, SpecFiles, command, option


@command(
    FORMAT,
    option(bool, "--expand", help="List each sub-assembly's own parts (ASSEMBLY/PART), not one row."),
    api=rbi.Body.parts,
)
def parts(files: SpecFiles, *, format: OutputFormat, expand: bool) -> int:
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

    # the body's warnings hold the mesh notes (repair, overlaps) too
    return report_each(files, lambda file: FileReport(rbi.load(file).parts(expand)), format.value)
