"""`rbi audit`: a robot file's inertials against its own geometry, link by link, with the whole
robot's totals; `--fix` writes a copy with the flagged inertials replaced.

Exit 0 when no link has an error-level flag, 1 when one has (so it gates CI like `rbi check`),
2 on bad input. With `--fix --out FILE`: 0 when the written file has no error-level flag left,
1 when some flagged link could not be fixed.
"""

from __future__ import annotations

import sys

import typer

import rbi
from rbi.cli.options import FORMAT, PACKAGE_PATHS, OutputFormat, RobotFile, command, option, out_option
from rbi.cli.render import emit_result, print_table
from rbi.cli.terminal import say, status_kept, terminal_safe

OPTIONS = (
    PACKAGE_PATHS,
    option(
        str,
        "--geometry",
        metavar="collision|visual|none",
        help="Which geometry gives a link's volume (a link without it falls back to the other); none: "
        "read no geometry, check the declared inertials and totals only.",
    ),
    option(
        float | None, "--density", metavar="KG_PER_M3", help="Density for links that declare no mass (kg/m³)."
    ),
    option(
        str | None,
        "--material",
        metavar="NAME",
        help="Built-in material for links that declare no mass (steel, aluminium, ...).",
    ),
    option(
        str,
        "--mesh-inertia",
        metavar="auto|exact|convex|shell",
        help="Mass of a mesh: auto (the solid a closed mesh encloses, else its convex hull, flagged 'mesh'), "
        "exact (the mesh must be closed), convex (its hull), or shell (its surface, as MuJoCo).",
    ),
    option(
        bool,
        "--mesh-repair",
        help="Close meshes' small holes (three or four edges) first; the area added is reported.",
    ),
    option(
        list[str] | None,
        "--joints",
        metavar="NAME=VALUE",
        help="Joint coordinate for the totals (radians for revolute/hinge, metres for prismatic/slide); "
        "several after one --joints (--joints a=1 b=2) or the option repeated. Default: zero (MJCF: qpos0).",
    ),
    option(
        bool,
        "--fix",
        help="Replace each flagged inertial by its geometry's; without --out, show the changes only.",
    ),
    out_option("FILE", "With --fix: where to write the fixed copy of the robot file."),
    FORMAT,
)


@command(*OPTIONS, api=rbi.audit)
def audit(file: RobotFile, *, format: OutputFormat, **settings) -> None:
    """Check each link's mass, centre of mass and inertia against its own geometry.

    Per link: the declared mass properties, the geometry's at the same mass (with the density
    that implies), the ratio of each declared moment to the geometry's, and flags: unphysical,
    placeholder, mismatch, density, massless. Then the whole robot's mass, centre of mass and
    inertia at the zero configuration (MJCF: qpos0) or at --joints. Exit 1 when a link has an
    error-level flag.

    \b
    Examples:
      rbi audit robot.urdf
      rbi audit robot.urdf --package-path my_robot=~/ws/src/my_robot
      rbi audit humanoid.xml --format json
      rbi audit robot.urdf --fix           (dry run: the changes as a diff)
      rbi audit robot.urdf --fix --out fixed.urdf
    """

    report = rbi.audit(file, **settings)
    code = report.exit_code
    with status_kept(code):  # a reader that left does not clear a flagged link
        if format is not OutputFormat.table:
            emit_result(format.value, report, file=report.model.path)
        else:
            _table(report)
            if report.fix is not None:
                _fix_text(report.fix, file)
    if code:
        raise typer.Exit(code)


def _table(report) -> None:
    from rbi.cli.tables import drawn  # heavy: rich (not for --format json)

    links, total, *joints = report.rows()
    print_table(drawn([links]))
    for each in report.links:
        _say_flags(each.link.label, each.flags)
    # three short lines, not one of up to ~100 characters that a terminal of 80 would break
    # inside a number; the moments are a list, shown without the vector's brackets
    print(terminal_safe(f"{total.title}: mass {total.cells[0][2]} kg"))
    print(f"  centre of mass [m]: {total.cells[1][2]}")
    print(f"  principal moments about it [kg·m²]: {total.cells[2][2]}")
    word = report.model.link_word
    if report.left_out:
        print(terminal_safe(f"  left out: the moments of mass-0 {word}(s) (unphysical): {total.cells[3][2]}"))
    if joints:
        print_table(drawn(joints))
        for joint in report.joints:
            _say_flags(f"joint {joint.name}", joint.flags)
    for note in report.notes:
        say(f"note: {note}")
    errors = sum(each.has_error for each in report.links)
    warnings = sum(any(f.level == "warning" for f in each.flags) for each in report.links)
    say(f"{errors} {word}(s) with errors (flag!), {warnings} with warnings")
    sys.stdout.flush()


def _say_flags(where: str, flags) -> None:
    """Each flag of a link or a joint, one line: level, where, code, what is wrong."""
    for flag in flags:
        print(terminal_safe(f"{flag.level}: {where}: {flag.code}: {flag.message}"))


def _fix_text(plan, file: str) -> None:
    """The fix planned (``report.fix``): the changes as a diff (a dry run), or where the fixed
    copy was written; then each link that could not be fixed."""
    if plan.out is None:
        sys.stdout.write(terminal_safe(plan.diff(file), keep="\n"))
        print(f"--fix: {len(plan.changes)} inertial(s) would change (dry run; --out FILE writes the copy)")
    else:
        print(f"--fix: {len(plan.changes)} inertial(s) replaced; wrote {terminal_safe(plan.out)}")
    for label, why in plan.unfixable:
        print(terminal_safe(f"--fix: {label}: not fixed: {why}"))
