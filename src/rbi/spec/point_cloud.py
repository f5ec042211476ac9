"""Point clouds: many point masses read from one file instead of one YAML entry each.

A spec names the file with ``point_cloud: {file: cloud.csv}``; the path is relative to the
spec file's folder and every number is in the spec's own units. Two formats:

- ``.csv``: a header row naming the columns ``mass``, ``x``, ``y``, ``z`` (any order; further
  columns are ignored), then one point a row. Lines starting with ``#`` are comments.
- ``.npy``: a float array of shape (N, 4) with the columns ``mass, x, y, z`` — the fastest
  to load (no text to parse).

The cloud reaches the core as arrays and is reduced by :func:`rbi.core.inertia.combine` in
one vectorised pass: it never becomes a Python list of per-point objects.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from rbi.core.inertia import combine
from rbi.core.shapes import MassElement
from rbi.spec.errors import InputError

COLUMNS = ("mass", "x", "y", "z")


def resolve(spec_path: str, file: str) -> Path:
    """Where a cloud file named in the spec at ``spec_path`` lives."""
    cloud = Path(file).expanduser()
    return cloud if cloud.is_absolute() else Path(spec_path).parent / cloud


def read_point_cloud(path: str | Path, label: str) -> tuple[np.ndarray, np.ndarray]:
    """Masses (N,) and positions (N, 3) of a cloud file; :class:`InputError` prefixed with
    ``label`` (for instance ``top.yaml: point_cloud: cloud.csv``) on any problem."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{label}: no such file" if not path.exists() else f"{label}: not a file")
    if path.suffix.lower() == ".npy":
        table = _read_npy(path, label)
    else:
        table = _read_csv(path, label)
    _check_values(table, label)
    return table[:, 0].copy(), table[:, 1:4]


def cloud_element(spec_path: str, file: str) -> MassElement:
    """The whole cloud as one part: its mass, centre of mass and inertia about that centre."""
    label = f"{spec_path}: point_cloud: file: {file}"
    masses, positions = read_point_cloud(resolve(spec_path, file), label)
    props = combine(masses, positions)
    if not (np.isfinite(props.mass) and np.all(np.isfinite(props.inertia_com))):
        raise InputError(f"{label}: numbers too large: mass or inertia overflows")
    return MassElement(props.mass, props.com, props.inertia_com)


def _read_npy(path: Path, label: str) -> np.ndarray:
    try:
        table = np.load(path, allow_pickle=False)
    except (OSError, ValueError) as exc:
        raise InputError(f"{label}: not a readable .npy array ({exc})") from None
    if table.ndim != 2 or table.shape[1] != 4 or table.dtype.kind not in "fiu":
        raise InputError(f"{label}: a .npy cloud must be a numeric array of shape (N, 4) with columns "
                         f"mass, x, y, z (got shape {table.shape}, dtype {table.dtype})")
    return np.asarray(table, dtype=float)


def _read_csv(path: Path, label: str) -> np.ndarray:
    header, header_line = _header(path, label)
    missing = [c for c in COLUMNS if c not in header]
    if missing:
        raise InputError(f"{label}: line {header_line}: header must name the columns mass, x, y, z "
                         f"(missing {', '.join(missing)}; got {', '.join(header) or 'nothing'})")
    usecols = [header.index(c) for c in COLUMNS]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # "no data": reported below instead
            table = np.loadtxt(path, delimiter=",", skiprows=header_line, usecols=usecols, ndmin=2,
                               dtype=float, comments="#", encoding="utf-8")
    except ValueError as exc:
        # numpy counts rows after the skipped header; name the line a text editor shows.
        raise InputError(f"{label}: {_describe_parse_error(str(exc), header_line)}") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{label}: not UTF-8 text (byte {exc.start})") from None
    if table.shape[0] == 0:
        raise InputError(f"{label}: holds no points (a header and no rows)")
    return table


def _header(path: Path, label: str) -> tuple[list[str], int]:
    """Column names of the first non-comment, non-blank line, and that line's number."""
    try:
        with open(path, encoding="utf-8") as stream:
            for number, line in enumerate(stream, start=1):
                text = line.strip()
                if text and not text.startswith("#"):
                    return [c.strip().lower() for c in text.split(",")], number
    except UnicodeDecodeError as exc:
        raise InputError(f"{label}: not UTF-8 text (byte {exc.start})") from None
    raise InputError(f"{label}: file is empty (expected a header row mass,x,y,z and one row per point)")


def _describe_parse_error(message: str, header_line: int) -> str:
    """numpy's loadtxt message with its row (counted after the header) turned into a file line."""
    import re

    # numpy counts the rows after the header from 0 in conversion errors, from 1 in column errors.
    convert = re.search(r"could not convert string (.*) to float64 at row (\d+), column (\d+)", message)
    if convert:
        line = int(convert.group(2)) + header_line + 1
        return f"line {line}: column {convert.group(3)}: must be a number (got {convert.group(1)})"
    columns = re.search(r"at row (\d+) with (\d+) columns?", message)
    if columns:
        line = int(columns.group(1)) + header_line
        return f"line {line}: has {columns.group(2)} columns, fewer than the header names"
    return message.rstrip(".")


def _check_values(table: np.ndarray, label: str) -> None:
    finite = np.isfinite(table)
    if not finite.all():
        row, col = np.argwhere(~finite)[0]
        raise InputError(f"{label}: point {row}: {COLUMNS[col]}: must be a finite number (got {float(table[row, col])!r})")
    bad = np.flatnonzero(table[:, 0] <= 0.0)
    if bad.size:
        row = int(bad[0])
        raise InputError(f"{label}: point {row}: mass: must be greater than 0 (got {float(table[row, 0])!r})")
