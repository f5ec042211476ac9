"""Robot files: `audit` one, `import_robot` its links (`RobotImport`, `ImportedLink`) or a
STEP file's solids."""

from __future__ import annotations

import difflib
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from rbi.api.outputs import checked_output, path_text
from rbi.core.rotation import matrix_to_quaternion
from rbi.errors import ArgumentError, SpecError, literal
from rbi.files.output import Destination, check_distinct, write_output
from rbi.formats.paths import outside_paths_setting
from rbi.formats.robot_files import link_problems, link_spec, read_robot
from rbi.formats.robot_paths import parse_package_paths
from rbi.reprs import Result, Rows
from rbi.robot import audit as run_audit
from rbi.robot.audit import AuditReport, AuditSettings
from rbi.robot.fix import check_out_not_read
from rbi.robot.specs import robot_spec
from rbi.spec.from_step import StepImport, import_step
from rbi.spec.yaml_writer import comment, dump
from rbi.text import number, vector_text


def audit(
    robot_file: str | os.PathLike,
    *,
    package_paths: dict[str, str] | Sequence[str] | None = None,
    geometry: str = "collision",
    density: float | None = None,
    material: str | None = None,
    mesh_inertia: str = "auto",
    joints: dict[str, float] | Sequence[str] | None = None,
    fix: bool = False,
    out: Destination | None = None,
    allow_outside_paths: bool | None = None,
    mesh_repair: bool = False,
) -> AuditReport:
    """Audit a robot file (URDF ``.urdf``, SDF ``.sdf``, MJCF ``.xml``, or ``.xacro`` with the
    ``xacro`` extra) as ``rbi audit`` does: each link's declared mass properties against its own
    geometry, with flags, and the whole robot's totals. SI units; vectors and matrices in each
    link's frame (totals: the root link's frame for URDF/SDF, the world for MJCF). Returns an
    `AuditReport`: ``.links`` (each with ``.declared``, ``.geometry``, ``.ratios``, ``.flags``),
    ``.total``, ``.notes``, ``.exit_code`` (1 when a link has an error-level flag, else 0) and
    ``.as_dict()`` (what ``rbi audit --format json`` prints).

    Args:
        robot_file: the file's path.
        package_paths: ``{NAME: DIR}`` or ``["NAME=DIR", ...]`` for ``package://NAME/`` meshes
            (``ROS_PACKAGE_PATH`` is searched too).
        geometry: ``"collision"`` or ``"visual"``: which geometry gives a link's volume (a link
            without it falls back to the other); ``"none"``: the declared inertials and totals only.
        density: kg/m³, for links that declare no mass.
        material: instead of ``density``, a built-in material name.
        mesh_inertia: ``"auto"`` (exact where a mesh is closed, else its convex hull, flagged
            ``mesh``), ``"exact"``, ``"convex"`` (its hull) or ``"shell"`` (mass on the surface).
        joints: ``{NAME: VALUE}`` or ``["NAME=VALUE", ...]``: radians for revolute/hinge joints,
            metres for prismatic/slide; the others at zero (MJCF: ``qpos0``).
        fix: also plan the fixed copy (``report.fix``: ``.content``, bytes; ``.changes``, ``.unfixable``).
        out: write it there (the robot file's own form; never a file the robot reads), atomically.
        allow_outside_paths: let the file name meshes and includes outside its folder; None:
            as an enclosing `outside_paths_allowed` block says (not allowed outside one).
        mesh_repair: close meshes' holes of three or four edges first (listed in ``report.notes``).

    Raises:
        SpecError: the file cannot be read, is malformed, names a mesh that cannot be found or
            read, or repeats a link name; ``out`` cannot be written.
    """
    chosen = {k: v for k, v in locals().items() if k not in ("robot_file", "out", "allow_outside_paths")}
    if out is not None and not fix:
        raise ArgumentError("out", "writes the fixed copy, so it needs {fix=True}")
    path = path_text(robot_file)
    target = None if out is None else checked_output(out, _fixed_format(path), path, "out")
    allowed = outside_paths_setting(allow_outside_paths)
    report = run_audit(path, AuditSettings(allow_outside_paths=allowed, **chosen))
    if target is not None:  # never a file the robot reads: an include, a mesh or the robot file itself
        check_out_not_read(target.path, report.model)
        write_output(target, report.fix.content)
        report.fix.out = target.given
    return report


def _fixed_format(path: str) -> tuple[str]:
    """The one form the fixed copy of ``path`` is written in: its own (a .xacro is never
    rewritten: its fixed copy is the expanded robot, a .urdf)."""
    extension = os.path.splitext(path)[1].lower().lstrip(".") or "xml"
    return ("urdf",) if extension == "xacro" else (extension,)


@dataclass(frozen=True)
class ImportedLink:
    """One link of a robot file with mass properties, as ``rbi import`` turns it into a spec
    (SI units: kg, m, kg·m²; the link's own frame).

    Attributes:
        name: the link's name (None for an unnamed MJCF body); ``label``: how messages name it.
        index: its place among the file's links.
        mass: kg. center_of_mass: (3,) m, link frame.
        inertia: (3, 3) kg·m² about the centre of mass, in the link's axes.
        inertial_quaternion: (4,) [w, x, y, z], the inertial frame's orientation in the link frame.
        problems: why the declared values are not physical, one line each (empty when fine).
        yaml: the link's spec (one custom part) as YAML text under a comment header.
    """

    name: str | None
    label: str
    index: int
    mass: float
    center_of_mass: np.ndarray
    inertia: np.ndarray
    inertial_quaternion: np.ndarray
    problems: list[str]
    yaml: str


@dataclass(frozen=True, repr=False)
class RobotImport(Result):
    """A robot file read as ``rbi import`` reads it: ``path``; ``format`` (``"urdf"``, ``"sdf"``,
    ``"mjcf"``); ``name`` (the model's); ``link_word`` (``"link"``, or ``"body"`` for MJCF);
    ``links``, the `ImportedLink` s asked for; ``skipped``, ``(label, reason)`` of each link
    without mass properties; ``robot_yaml()``, the whole robot as one spec; ``yaml()``, what
    ``rbi import`` prints."""

    path: str
    format: str
    name: str | None
    link_word: str
    links: list[ImportedLink]
    skipped: list[tuple[str, str]]
    model: Any = field(default=None, repr=False)
    """The file as rbi reads it (its links, with their geometry)."""
    written: dict[int, str] = field(default_factory=dict)
    """Where each link's spec was written (link index → the path as given), when it was."""

    def yaml(self) -> str:
        """What ``rbi import`` prints: the one link's spec, or with several the whole robot's
        (:meth:`robot_yaml`)."""
        return self.robot_yaml() if len(self.links) > 1 else self.links[0].yaml

    def robot_yaml(self) -> str:
        """The whole robot as one spec (YAML text under a comment header): one custom part per
        link with mass, placed at the zero configuration (MJCF: ``qpos0``), SI units."""
        model = self.model
        spec, left_out = robot_spec(model)
        frame = (
            "the world frame at qpos0"
            if model.format == "mjcf"
            else "the root link's frame, every joint at zero"
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

    def __repr__(self) -> str:
        return f"<rbi.RobotImport {self.path!r} ({self.format}): {len(self.links)} {self.link_word}(s)>"

    def rows(self) -> list[Rows]:
        """One row a link: mass, centre of mass, principal moments, problems."""
        cells: list[tuple[str, ...]] = [
            (
                each.label,
                number(each.mass, 6),
                vector_text(each.center_of_mass, 6),
                vector_text(np.linalg.eigvalsh(0.5 * (each.inertia + each.inertia.T)), 6)[1:-1],
                "; ".join(each.problems) or "ok",
            )
            for each in self.links
        ]
        columns = (self.link_word, "mass kg", "centre of mass m", "principal moments kg·m²", "problems")
        return [Rows(f"{self.path}: {len(self.links)} {self.link_word}(s) imported", columns, cells)]

    def to_dict(self) -> dict[str, Any]:
        """What ``rbi import --format json`` prints, less ``"file"``: each link's ``"file"`` is
        where its spec was written (:attr:`written`), else None."""
        links = [
            {k: v for k, v in vars(each).items() if k not in ("label", "yaml")}
            | {"file": self.written.get(each.index)}
            for each in self.links
        ]
        return {
            "format": self.format,
            "model": self.name,
            "units": {"length": "m", "mass": "kg"},
            "links": links,
            "skipped": [{"link": label, "reason": reason} for label, reason in self.skipped],
        }

    def csv_rows(self) -> list[dict[str, Any]]:
        """``rbi import --format csv``: one row a link, ``ok`` for no problems."""
        return [
            {k: v for k, v in row.items() if k != "problems"} | {"ok": not row["problems"]}
            for row in self.to_dict()["links"]
        ]


def import_robot(
    robot_file: str | os.PathLike[str],
    *,
    links: Sequence[str] | None = None,
    package_paths: dict[str, str] | Sequence[str] | None = None,
    out: str | os.PathLike[str] | None = None,
    density: float | None = None,
    material: str | None = None,
) -> RobotImport | StepImport:
    """Read the links of a robot file (URDF, SDF, MJCF) that have mass properties, as ``rbi
    import`` does: each one's mass, centre of mass and inertia (SI, link frame) and its spec.
    A STEP file (``.step``, ``.stp``; needs the extra ``cad``) gives its solids instead: a
    ``StepImport`` (``.spec``, one ``shape: step`` part per solid; ``.yaml()``, ``.to_dict()``).

    Args:
        robot_file: the file's path.
        links: the names of the links to import (MJCF: bodies), in order; None: every one.
        package_paths: as `audit`'s, for ``package://NAME/`` paths.
        out: write the specs there, every path checked before any is written: a folder
            (``DIR/``: one ``NAME.yaml`` a link) or one ``.yaml`` file (one link; a STEP file's
            spec, naming the STEP file relative to it). ``.written``: link index → path.
        density: a STEP file's solids' density, kg/m³ (default 1000, a placeholder).
        material: instead of ``density``, a built-in material's.

    Raises:
        SpecError: the file cannot be read or is malformed; no link has mass properties;
            ``out`` cannot be written.
        ValueError: a name in ``links`` names no link with an ``<inertial>``; ``density`` or
            ``material`` for a robot file, ``links`` for a STEP file.
    """
    path = path_text(robot_file)
    if path.lower().endswith((".step", ".stp")):
        return _import_step(path, links, out, density, material)
    if density is not None or material is not None:
        raise ArgumentError("density" if density is not None else "material", "applies to STEP files only")
    packages = parse_package_paths(package_paths)
    robot = read_robot(path, packages)
    chosen = _chosen_links(robot, _link_names(links))
    if not chosen:
        raise SpecError(f"{robot.path}: no {robot.link_word} with an <inertial> element to import")
    imported = [
        ImportedLink(
            link.name,
            link.label,
            link.index,
            float(link.inertial.mass),
            np.asarray(link.inertial.properties.center_of_mass),
            np.asarray(link.inertial.properties.inertia_about_com),
            _inertial_quaternion(link.inertial),
            link_problems(robot, link),
            _link_yaml(robot, link),
        )
        for link in chosen
    ]
    found = RobotImport(robot.path, robot.format, robot.name, robot.link_word, imported, robot.skipped, robot)
    return found if out is None else _written(found, path_text(out, "out"))


def _import_step(path: str, links: Any, out: Any, density: float | None, material: str | None) -> StepImport:
    """A STEP file imported as `import_robot` does, its spec written at ``out`` (checked before
    the file is read)."""
    if links:
        raise ArgumentError(
            "links", "a STEP file has solids, not links: the spec lists them all (pick with solid:)"
        )
    target = None if out is None else checked_output(out, ("yaml", "yml"), path, "out")
    home = None if out is None else os.path.dirname(os.path.abspath(os.fspath(out)))
    imported = import_step(path, density=density, material=material, relative_to=home)
    if target is not None:
        write_output(target, imported.yaml())
    return imported


def _written(robot: RobotImport, out: str) -> RobotImport:
    """``robot`` with each link's spec written under ``out`` (a folder: one ``NAME.yaml`` a link,
    :func:`_file_names`; else one link's file), every path checked before any is written."""
    links = robot.links
    formats: tuple[str, ...] = ("yaml", "yml")
    if os.path.isdir(out) or out.endswith(("/", os.sep)):
        if not os.path.isdir(out):
            raise ArgumentError("out", f"{literal(out, quoted=False)}: folder does not exist")
        paths, formats = [os.path.join(out, name) for name in _file_names(links, robot.link_word)], ("yaml",)
    elif len(links) == 1:
        paths = [out]
    else:
        raise ArgumentError(
            "out",
            f"{literal(out, quoted=False)}: {len(links)} {robot.link_word}s to import; name a folder "
            "({out=DIR/}) or pick one with {links=NAME}",
        )
    targets = [checked_output(each, formats, robot.path, "out") for each in paths]
    check_distinct(targets)
    for target, each in zip(targets, links):
        write_output(target, each.yaml)
    return replace(robot, written={each.index: target.given for target, each in zip(targets, links)})


_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")


def _file_names(links: list[ImportedLink], word: str) -> list[str]:
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


def _inertial_quaternion(inertial: Any) -> np.ndarray:
    """``[w, x, y, z]`` of the inertial frame: the file's own quaternion, else the identity or the
    rotation's."""

    if inertial.quaternion is not None and inertial.rpy is None:
        return np.asarray(inertial.quaternion)
    R = inertial.rotation
    return np.array([1.0, 0.0, 0.0, 0.0]) if R is None else matrix_to_quaternion(R)


def _link_yaml(robot: Any, link: Any) -> str:
    """One link's spec: a comment header, then the spec written by the YAML dumper. Names from
    the file are data: escaped in the comment, quoted and escaped by the dumper where they hold
    anything but visible characters (:mod:`rbi.spec.yaml_writer`)."""
    source = {"urdf": "URDF", "sdf": "SDF", "mjcf": "MJCF"}[robot.format]
    header = comment(
        f"rbi import of {os.path.basename(robot.path)}, {link.label}, from its {source} <inertial>:",
        "SI units, link frame; the inertia is about the centre of mass in the inertial frame's axes,",
        "turned into link axes by `rotation`.",
    )
    return header + dump(link_spec(robot, link))


def _link_names(links: Any) -> list[str]:
    """``links`` of :func:`import_robot` as a list of names (one name given as text is that
    name); ArgumentError naming ``links`` for anything else."""
    if links is None or isinstance(links, str):
        return [] if links is None else [links]
    names = list(links) if isinstance(links, Iterable) else None
    if names is None or not all(isinstance(name, str) for name in names):
        raise ArgumentError("links", f"expected link names (str), got {literal(links)}")
    return names


def _chosen_links(robot: Any, names: list[str]) -> list[Any]:
    """The links named in ``names`` (every one when empty), each once, in the order named."""
    if not names:
        return robot.inertial_links
    by_name = {each.name: each for each in robot.inertial_links}
    missing = [name for name in names if name not in by_name]
    if missing:
        hint = difflib.get_close_matches(missing[0], [n for n in by_name if n], n=1)
        raise ArgumentError(
            "links",
            f"{robot.path} has no {robot.link_word} named {literal(missing[0])} with an <inertial>"
            + (f" (did you mean {literal(hint[0])}?)" if hint else ""),
        )
    return [by_name[name] for name in dict.fromkeys(names)]
