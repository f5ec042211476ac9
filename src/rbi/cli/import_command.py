"""`rbi import`: the links of a URDF, SDF or MJCF file as rbi specs (one custom part each), or
the solids of a STEP file as one spec (one ``shape: step`` part each)."""

from __future__ import annotations

import os
import re
import sys
from typing import Annotated

import typer

from rbi import api
from rbi.api import SpecError, check_distinct, output_target, write_output
from rbi.cli.options import FormatOption, OutputFormat, PackagePathOption
from rbi.cli.render import emit
from rbi.cli.terminal import say, terminal_safe

ImportFile = Annotated[
    str,
    typer.Argument(
        help="Robot description (.urdf, .sdf, MJCF .xml) or CAD file (.step, .stp).",
        show_default=False,
        metavar="FILE",
    ),
]
DensityOption = Annotated[
    float | None,
    typer.Option(
        "--density",
        metavar="D",
        help="STEP files: density of every solid, kg/m³ (default 1000, a placeholder).",
    ),
]
MaterialOption = Annotated[
    str | None,
    typer.Option(
        "--material", metavar="NAME", help="STEP files: a built-in material for every solid (e.g. steel)."
    ),
]
LinkOption = Annotated[
    list[str] | None,
    typer.Option(
        "--link", "-l", metavar="NAME", help="Import only this link (MJCF: body); repeat for several."
    ),
]
OutOption = Annotated[
    str | None,
    typer.Option(
        "--out",
        "-o",
        metavar="DIR|FILE.yaml",
        help="Write the specs: into folder DIR as one NAME.yaml per link, or into FILE.yaml when one "
        "link is imported. Without it one spec is printed: the link given with --link, or the whole "
        "robot (one part per link, placed at the zero configuration).",
    ),
]


def import_robot(
    file: ImportFile,
    link: LinkOption = None,
    out: OutOption = None,
    package_path: PackagePathOption = None,
    format: FormatOption = OutputFormat.table,
    density: DensityOption = None,
    material: MaterialOption = None,
) -> None:
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
    if file.lower().endswith((".step", ".stp")):
        _import_step(file, link, out, format, density, material)
        return
    if density is not None or material is not None:
        raise SpecError(f"{'--density' if density is not None else '--material'}: applies to STEP files only")
    _import_robot(file, link, out, format, package_path)


def _import_robot(file: str, link, out: str | None, format: OutputFormat, package_path) -> None:
    """`rbi import ROBOT_FILE`: each link's spec, printed or written, or the listing."""

    robot = api.import_robot(file, links=link, package_paths=package_path)
    targets = _targets(robot, out, file) if out is not None else None
    if not link:
        for label, reason in robot.skipped:
            say(f"note: {file}: {label}: skipped: {reason}")
    for each in robot.links:
        for line in each.problems:
            say(f"warning: {line}")
    if targets is not None:
        for target, each in targets:
            write_output(target, each.yaml)
    if format is OutputFormat.table:
        if targets is None and len(robot.links) > 1:
            sys.stdout.write(robot.robot_yaml())
        elif targets is None:
            sys.stdout.write(robot.links[0].yaml)
        else:
            for target, _ in targets:
                print(terminal_safe(str(target.given)))
        return
    _emit_listing(format, robot, targets)


def _import_step(file: str, link, out: str | None, format: OutputFormat, density, material) -> None:
    """`rbi import FILE.step`: the spec (YAML, printed or written to --out FILE.yaml), or with
    --format json/csv the solids and their mass properties at the density given."""

    if link:
        raise SpecError(
            "--link: a STEP file has solids, not links: the spec lists them all (pick with solid:)"
        )
    target = None
    if out is not None:
        target = output_target(out, "--out", ("yaml", "yml"), inputs=[file])
    home = os.path.dirname(os.path.abspath(out)) if out is not None else None
    imported = api.import_step(file, density=density, material=material, relative_to=home)
    named = {str(part.get("file", "")) for part in imported.spec.get("parts", [])}
    outside = sorted(n for n in named if os.path.isabs(n) or n.split("/")[0] == "..")
    if target is not None and outside:
        say(
            f"note: {terminal_safe(str(out))} names {terminal_safe(outside[0])}, outside its folder: "
            "read it back with --allow-outside-paths, or save the spec beside the STEP file"
        )
    if format is not OutputFormat.table:
        _emit_step_listing(format, file, imported)
    if target is not None:
        write_output(target, imported.yaml())
    elif format is OutputFormat.table:
        sys.stdout.write(imported.yaml())


def _emit_step_listing(format: OutputFormat, file: str, imported) -> None:
    """The solids with their mass properties at the spec's density, SI."""
    emit(format.value, {"file": file, **imported.to_dict()}, lambda: None, csv_rows=imported.csv_rows())


def _targets(robot, out: str, source: str):
    """(checked output target, link) pairs, all checked before anything is written."""

    links = robot.links
    if os.path.isdir(out) or out.endswith(("/", os.sep)):
        if not os.path.isdir(out):
            raise SpecError(f"--out: {out}: folder does not exist")
        names = _file_names(links, robot.link_word)
        targets = [
            (output_target(os.path.join(out, name), "--out", ("yaml",), inputs=[source]), each)
            for name, each in zip(names, links)
        ]
    else:
        if len(links) != 1:
            raise SpecError(
                f"--out: {out}: {len(links)} {robot.link_word}s to import; name a folder "
                f"(--out DIR/) or pick one with --link NAME"
            )
        targets = [(output_target(out, "--out", ("yaml", "yml"), inputs=[source]), links[0])]
    check_distinct([target for target, _ in targets])
    return targets


_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")


def _file_names(links, word: str) -> list[str]:
    """A safe, distinct ``NAME.yaml`` for each link (characters other than letters, digits,
    ``.``, ``_`` and ``-`` become ``_``; a clash gets the link's index appended)."""
    names, seen = [], set()
    for each in links:
        stem = _UNSAFE.sub("_", each.name or "").strip("._") or f"{word}{each.index}"
        stem = stem[:200]
        if stem.lower() in seen:
            stem = f"{stem}_{each.index}"
        seen.add(stem.lower())
        names.append(stem + ".yaml")
    return names


def _emit_listing(format: OutputFormat, robot, targets) -> None:
    written = {each.index: target.given for target, each in targets or []}
    result = {"file": robot.path, **robot.to_dict(written)}
    # every text cell is escaped by the CSV cell rule (rbi.text.csv_cell): CSV often reaches a terminal
    emit(format.value, result, lambda: None, csv_rows=robot.csv_rows(written))
