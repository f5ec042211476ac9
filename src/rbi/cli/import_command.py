"""`rbi import`: the links of a URDF, SDF or MJCF file as rbi specs (one custom part each), or
the solids of a STEP file as one spec (one ``shape: step`` part each)."""

from __future__ import annotations

import os
import sys

import rbi
from rbi.cli.options import FORMAT, PACKAGE_PATHS, OutputFormat, argument, command, option, out_option
from rbi.cli.render import emit_result
from rbi.cli.terminal import say, terminal_safe

ImportFile = argument(str, "Robot description (.urdf, .sdf, MJCF .xml) or CAD file (.step, .stp).", "FILE")


@command(
    option(
        list[str] | None,
        "--link",
        "-l",
        name="links",
        metavar="NAME",
        help="Import only this link (MJCF: body); repeat for several.",
    ),
    out_option(
        "DIR|FILE.yaml",
        "Write the specs: into folder DIR as one NAME.yaml per link, or into FILE.yaml when one "
        "link is imported. Without it one spec is printed: the link given with --link, or the whole "
        "robot (one part per link, placed at the zero configuration).",
    ),
    PACKAGE_PATHS,
    FORMAT,
    option(
        float | None,
        "--density",
        metavar="D",
        help="STEP files: density of every solid, kg/m³ (default 1000, a placeholder).",
    ),
    option(
        str | None,
        "--material",
        metavar="NAME",
        help="STEP files: a built-in material for every solid (e.g. steel).",
    ),
    api=rbi.import_robot,
)
def import_robot(file: ImportFile, *, format: OutputFormat, **settings) -> None:
    """Turn each link of a robot file into an rbi spec: its mass, centre of mass and inertia as a custom part.

    A STEP file (.step, .stp) becomes one spec with a `shape: step` part per solid, named after
    the solid, in SI units (the file's own length unit is honoured): --density D or --material
    NAME fill them; --format json lists the solids with their volume and mass properties.

    The specs are in SI units and in the link's own frame; the inertial frame's orientation
    (URDF/SDF rpy, MJCF quat) becomes the part's rotation. --format json lists the links with
    their mass properties (inertia in link axes) instead of printing YAML; a link whose inertia
    is not physical is warned about on stderr (rbi validate FILE gates on it).

    \b
    Examples:
      rbi import two_link_arm.urdf
      rbi import two_link_arm.urdf --link forearm --out forearm.yaml
      rbi import robot.sdf --out specs/
      rbi import humanoid.xml --format json
      rbi import bracket.step --material aluminium
    """
    imported = rbi.import_robot(file, **settings)
    out = settings["out"]
    if isinstance(imported, rbi.RobotImport):  # notes and warnings on stderr
        if not settings["links"]:
            for label, reason in imported.skipped:
                say(f"note: {file}: {label}: skipped: {reason}")
        for each in imported.links:
            for line in each.problems:
                say(f"warning: {line}")
    else:  # a STEP file's spec written where it names the STEP file outside its folder: a note
        named = {str(part.get("file", "")) for part in imported.spec.get("parts", [])}
        outside = sorted(n for n in named if os.path.isabs(n) or n.split("/")[0] == "..")
        if out is not None and outside:
            say(
                f"note: {terminal_safe(str(out))} names {terminal_safe(outside[0])}, outside its folder: "
                "read it back with --allow-outside-paths, or save the spec beside the STEP file"
            )
    if format is not OutputFormat.table:
        # every text cell is escaped by the CSV cell rule (rbi.text.csv_cell): CSV often reaches a terminal
        emit_result(format.value, imported, file=file)
    elif out is None:  # the spec printed (a robot's: one link's, or the whole robot's)
        sys.stdout.write(imported.yaml())
    elif isinstance(imported, rbi.RobotImport):  # the files written
        for path in imported.written.values():
            print(terminal_safe(str(path)))
