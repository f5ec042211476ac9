"""Where the mesh a robot file names is: ``package://NAME/...``, ``model://NAME/...``,
``file:///...`` and paths relative to the robot file's folder.

- ``package://NAME/REST`` (and SDF's ``model://NAME/REST``): in the folder given for NAME by
  ``--package-path NAME=DIR``, else in ``DIR/NAME`` for each DIR of ``ROS_PACKAGE_PATH`` (and, for
  ``model://``, ``GZ_SIM_RESOURCE_PATH``/``GAZEBO_MODEL_PATH``), else in the folder ``NAME`` beside
  the robot file (or the robot file's own folder when it is called NAME, or REST directly beside
  it, as pybullet does). A folder the user named (option or environment) is trusted; the file
  must stay inside it.
- ``file://`` and plain paths follow the spec path rules (:mod:`rbi.formats.paths`): inside the
  robot file's folder unless ``--allow-outside-paths``.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from urllib.parse import unquote

from rbi.errors import ArgumentError, InputError, literal
from rbi.formats.paths import inside, spec_relative_file
from rbi.formats.robot import Where, short


def parse_package_paths(values: Mapping[str, str] | Sequence[str] | None) -> dict[str, list[Path]]:
    """``NAME=DIR`` strings (``--package-path``), or ``{NAME: DIR}``, as a mapping;
    ArgumentError naming ``package_paths`` for a malformed one."""
    if isinstance(values, Mapping):
        values = [
            f"{name}={os.fspath(folder)}" if isinstance(folder, (str, os.PathLike)) else folder
            for name, folder in values.items()
        ]
    elif isinstance(values, (str, bytes)):
        values = [values] if isinstance(values, str) else [values.decode(errors="replace")]
    elif values is not None and not isinstance(values, Iterable):
        values = [values]  # refused below, named
    found: dict[str, list[Path]] = {}
    for value in values or []:
        if not isinstance(value, str):
            raise ArgumentError(
                "package_paths",
                f"expected NAME=DIR strings or a mapping of NAME to DIR, got {literal(value)}",
            )
        name, sep, folder = value.partition("=")
        if not sep or not name.strip() or not folder.strip():
            raise ArgumentError(
                "package_paths", f"{literal(value)}: give NAME=DIR (the package's name and its folder)"
            )
        if not os.path.isdir(folder):
            raise ArgumentError("package_paths", f"{literal(value, quoted=False)}: no such folder")
        found.setdefault(name.strip(), []).append(Path(folder))
    return found


def resolve_mesh(where: Where, uri: str, what: str, package_paths: dict[str, list[Path]] | None) -> Path:
    """The mesh file ``uri`` names in the robot file at ``where.path``; InputError (the file,
    the link, ``what`` and the URI first) when it cannot be found or may not be read."""
    robot_path, label = where.path, f"{where.path}: {where.label}: {what}: {short(uri, 1000)}"
    if "\x00" in uri:
        raise InputError(f"{label}: not a usable path (it contains a NUL character)")
    for scheme in ("package://", "model://"):
        if uri.startswith(scheme):
            # package:///NAME/REST (an empty authority) names the package after the slash, as
            # Pinocchio and ROS read it
            rest = uri[len(scheme) :].lstrip("/")
            return _in_package(robot_path, rest, label, package_paths or {}, scheme)
    if uri.startswith("file://"):
        uri = unquote(uri[len("file://") :])
    return spec_relative_file(robot_path, uri, label, "robot file")


def _in_package(
    robot_path: str, rest: str, label: str, package_paths: dict[str, list[Path]], scheme: str
) -> Path:
    name, _, inner = rest.partition("/")
    trusted = list(package_paths.get(name, []))
    variables = ["ROS_PACKAGE_PATH"] + (
        ["GZ_SIM_RESOURCE_PATH", "GAZEBO_MODEL_PATH"] if scheme == "model://" else []
    )
    for variable in variables:
        for folder in filter(None, os.environ.get(variable, "").split(os.pathsep)):
            trusted.append(Path(folder) / name)
    for folder in trusted:
        candidate = folder / inner
        if inside(candidate, folder) and candidate.is_file():
            return candidate
    here = Path(robot_path).parent
    beside = [f"{name}/{inner}", rest]
    if here.resolve().name == name:
        beside.insert(0, inner)
    for relative in beside:
        if (here / relative).is_file():
            return spec_relative_file(robot_path, relative, label, "robot file")
    if not name:
        raise InputError(
            f"{label}: no such file: the URI names no package ({scheme} then a slash), and "
            f"{rest!r} is not beside the robot file"
        )
    raise InputError(
        f"{label}: no such file (looked in --package-path {name}=DIR, ROS_PACKAGE_PATH and "
        f"beside the robot file); give the package's folder with --package-path {name}=DIR"
    )
