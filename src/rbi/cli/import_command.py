"""`rbi import`: the links of a URDF, SDF or MJCF file as rbi specs (one custom part each), or
the solids of a STEP file as one spec (one ``shape: step`` part each)."""

from __future__ import annotations

import re
import sys
from typing import Annotated

import typer

from rbi.cli.audit_command import PackagePathOption
from rbi.cli.options import FormatOption, OutputFormat
from rbi.spec.errors import InputError

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
        raise InputError(
            f"{'--density' if density is not None else '--material'}: applies to STEP files only"
        )
    _import_robot(file, link, out, format, package_path)


def _import_robot(file: str, link, out: str | None, format: OutputFormat, package_path) -> None:
    """`rbi import ROBOT_FILE`: each link's spec, printed or written, or the listing."""
    from rbi.cli.terminal import say
    from rbi.formats.robot_files import link_problems, read_robot
    from rbi.formats.robot_paths import parse_package_paths

    packages = parse_package_paths(package_path)
    robot = read_robot(file, packages)
    links = _selected(robot, link or [])
    if not links:
        raise InputError(f"{file}: no {robot.link_word} with an <inertial> element to import")
    targets = _targets(robot, links, out, file) if out is not None else None
    if not link:
        for label, reason in robot.skipped:
            say(f"note: {file}: {label}: skipped: {reason}")
    for each in links:
        for line in link_problems(robot, each):
            say(f"warning: {line}")
    if targets is not None:
        _write(robot, targets)
    if format is OutputFormat.table:
        if targets is None and len(links) > 1:
            sys.stdout.write(_robot_yaml_text(robot))
        elif targets is None:
            sys.stdout.write(_yaml_text(robot, links[0]))
        else:
            from rbi.text import visible

            for target, _ in targets:
                print(visible(str(target.given)))
        return
    _emit_listing(format, robot, links, targets)


def _import_step(file: str, link, out: str | None, format: OutputFormat, density, material) -> None:
    """`rbi import FILE.step`: the spec (YAML, printed or written to --out FILE.yaml), or with
    --format json/csv the solids and their mass properties at the density given."""
    import os

    from rbi.api import import_step

    if link:
        raise InputError(
            "--link: a STEP file has solids, not links: the spec lists them all (pick with solid:)"
        )
    target = None
    if out is not None:
        from rbi.cli.output import output_target

        target = output_target(out, "--out", ("yaml", "yml"), inputs=[file])
    home = os.path.dirname(os.path.abspath(out)) if out is not None else None
    try:
        imported = import_step(file, density=density, material=material, relative_to=home)
    except InputError as exc:
        if exc.field in ("density", "material"):
            raise InputError(f"--{exc}") from None
        raise
    if format is not OutputFormat.table:
        _emit_step_listing(format, file, imported)
    if target is not None:
        from rbi.cli.output import write_output

        write_output(target, _step_yaml_text(file, imported))
    elif format is OutputFormat.table:
        sys.stdout.write(_step_yaml_text(file, imported))


def _step_yaml_text(file: str, imported) -> str:
    import os

    from rbi.spec.yaml_writer import comment, dump

    lines = [
        f"rbi import of {os.path.basename(file)}: one part per solid, integrated on the exact STEP geometry;",
        "SI units (the file's own length unit is honoured), the file's origin and axes.",
    ]
    if imported.placeholder:
        lines.append(
            f"density: {imported.density:g} kg/m³ is a placeholder: give yours (--density D or --material NAME)."
        )
    return comment(*lines) + dump(imported.spec)


def _emit_step_listing(format: OutputFormat, file: str, imported) -> None:
    """The solids with their mass properties at the spec's density, SI."""
    from rbi.cli.render import emit
    from rbi.text import visible

    density = imported.density
    rows = [
        {
            "name": solid.name,
            "index": i,
            "volume": solid.volume,
            "mass": density * solid.volume,
            "center_of_mass": solid.props.center_of_mass,
            "inertia_about_com": density * solid.props.inertia_about_com,
            "integration_error": solid.integration_error,
        }
        for i, solid in enumerate(imported.solids)
    ]
    result = {
        "file": file,
        "format": "step",
        "file_unit": imported.unit,
        "units": {"length": "m", "mass": "kg"},
        "density": density,
        "solids": rows,
    }
    csv_rows = [{k: (visible(v) if isinstance(v, str) else v) for k, v in row.items()} for row in rows]
    emit(format.value, result, lambda: None, csv_rows=csv_rows)


def _selected(robot, names: list[str]):
    if not names:
        return robot.inertial_links
    by_name = {each.name: each for each in robot.inertial_links}
    missing = [name for name in names if name not in by_name]
    if missing:
        import difflib

        hint = difflib.get_close_matches(missing[0], [n for n in by_name if n], n=1)
        raise InputError(
            f"--link: {robot.path} has no {robot.link_word} named {missing[0]!r} with an <inertial>"
            + (f" (did you mean {hint[0]!r}?)" if hint else "")
        )
    return [by_name[name] for name in dict.fromkeys(names)]


def _targets(robot, links, out: str, source: str):
    """(checked output target, link) pairs, all checked before anything is written."""
    import os

    from rbi.cli.output import check_distinct, output_target

    if os.path.isdir(out) or out.endswith(("/", os.sep)):
        if not os.path.isdir(out):
            raise InputError(f"--out: {out}: folder does not exist")
        names = _file_names(links, robot.link_word)
        targets = [
            (output_target(os.path.join(out, name), "--out", ("yaml",), inputs=[source]), each)
            for name, each in zip(names, links)
        ]
    else:
        if len(links) != 1:
            raise InputError(
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


def _yaml_text(robot, link) -> str:
    """One link's spec: a comment header, then the spec written by the YAML dumper. Names from
    the file (the file's own, the link's) are data: escaped in the comment, quoted and escaped
    by the dumper where they hold anything but visible characters (rbi.spec.yaml_writer)."""
    import os

    from rbi.formats.robot_files import link_spec
    from rbi.spec.yaml_writer import comment, dump

    source = {"urdf": "URDF", "sdf": "SDF", "mjcf": "MJCF"}[robot.format]
    header = comment(
        f"rbi import of {os.path.basename(robot.path)}, {link.label}, from its {source} <inertial>:",
        "SI units, link frame; the inertia is about the centre of mass in the inertial frame's axes,",
        "turned into link axes by `rotation`.",
    )
    return header + dump(link_spec(robot, link))


def _robot_yaml_text(model) -> str:
    """The whole robot as one spec (each link with mass a custom part, placed at the reference
    configuration): what `rbi inertia -` reads back."""
    import os

    from rbi.robot.specs import robot_spec
    from rbi.spec.yaml_writer import comment, dump

    spec, left_out = robot_spec(model)
    frame = (
        "the world frame at qpos0" if model.format == "mjcf" else "the root link's frame, every joint at zero"
    )
    lines = [
        f"rbi import of {os.path.basename(model.path)}: the whole robot, one custom part per "
        f"{model.link_word} with mass,",
        f"placed in {frame}; SI units.",
        "One link alone, in its own frame: --link NAME; one spec per link: --out DIR/.",
    ]
    if left_out:
        lines.append(f"Without mass (left out): {', '.join(left_out)}.")
    return comment(*lines) + dump(spec)


def _write(robot, targets) -> None:
    from rbi.cli.output import write_output

    for target, each in targets:
        write_output(target, _yaml_text(robot, each))


def _emit_listing(format: OutputFormat, robot, links, targets) -> None:
    from rbi.cli.render import emit
    from rbi.formats.robot_files import link_problems

    written = {id(each): target.given for target, each in targets or []}
    rows = []
    for each in links:
        rows.append(
            {
                "name": each.name,
                "index": each.index,
                "mass": each.inertial.mass,
                "center_of_mass": each.inertial.properties.center_of_mass,
                "inertia": each.inertial.properties.inertia_about_com,
                "inertial_quaternion": _quaternion(each.inertial),
                "problems": link_problems(robot, each),
                "file": written.get(id(each)),
            }
        )
    result = {
        "file": robot.path,
        "format": robot.format,
        "model": robot.name,
        "units": {"length": "m", "mass": "kg"},
        "links": rows,
        "skipped": [{"link": label, "reason": reason} for label, reason in robot.skipped],
    }
    from rbi.text import visible

    csv_rows = [
        {k: (visible(v) if isinstance(v, str) else v) for k, v in row.items() if k != "problems"}
        | {"ok": not row["problems"]}
        for row in rows
    ]  # names escaped: CSV often reaches a terminal
    emit(format.value, result, lambda: None, csv_rows=csv_rows)


def _quaternion(inertial):
    """``[w, x, y, z]`` of the inertial frame: the file's own quaternion, else the identity or the
    rotation's."""
    import numpy as np

    from rbi.core.rotation import matrix_to_quaternion

    if inertial.quaternion is not None and inertial.rpy is None:
        return inertial.quaternion
    R = inertial.rotation
    return np.array([1.0, 0.0, 0.0, 0.0]) if R is None else matrix_to_quaternion(R)
