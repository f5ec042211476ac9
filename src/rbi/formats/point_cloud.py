"""Point clouds: many point masses read from one file instead of one YAML entry each.

A spec names the file with ``point_cloud: {file: cloud.csv}``; the path is relative to the
spec file's folder (one leaving it is refused unless ``--allow-outside-paths`` is given) and
every number is in the spec's own units. Two formats:

- ``.csv``: a header row naming the columns ``mass``, ``x``, ``y``, ``z`` (any order, each
  once; further columns are ignored), then one point a row. Lines starting with ``#`` are
  comments; a UTF-8 byte-order mark is skipped.
- ``.npy``: a float array of shape (N, 4) with the columns ``mass, x, y, z`` — the fastest
  to load (no text to parse).

The cloud reaches the core as arrays and is reduced by :func:`rbi.core.mass.combine` in
one vectorised pass: it never becomes a Python list of per-point objects.
"""

from __future__ import annotations

import io
import os
import re
import warnings
from pathlib import Path
from typing import BinaryIO

import numpy as np
from numpy.lib import format as npy

from rbi.core.mass import MassProperties, combine
from rbi.errors import InputError
from rbi.files.safe import InputFileRefused, open_input_file
from rbi.formats.paths import spec_relative_file

COLUMNS = ("mass", "x", "y", "z")
MAX_CSV_BYTES = 4 * 1024**3
"""Largest CSV cloud read (4 GiB, some 5 × 10⁷ points); a larger cloud belongs in a ``.npy``."""
_HEADER_LINE_CHARS = 4096


def read_point_cloud(path: str | Path, label: str) -> tuple[np.ndarray, np.ndarray]:
    """Masses (N,) and positions (N, 3) of a cloud file; :class:`InputError` prefixed with
    ``label`` (for instance ``top.yaml: point_cloud: file: cloud.csv``) on any problem.

    Messages name the line, column or point at fault but never quote the file's content: the
    file may be one a spec named to leak it."""
    npy_file = Path(path).suffix.lower() == ".npy"
    try:
        cap = None if npy_file else MAX_CSV_BYTES
        with open_input_file(path, "point cloud", cap, " from CSV: save it as .npy") as stream:
            table = _read_npy(stream, label) if npy_file else _read_csv(stream, label)
    except InputFileRefused as exc:
        raise InputError(f"{label}: {exc}") from None
    except OSError as exc:  # unreadable: permissions, an I/O error, a kernel file that refuses reads
        raise InputError(f"{label}: cannot read: {exc.strerror or type(exc).__name__}") from None
    _check_values(table, label)
    return table[:, 0].copy(), table[:, 1:4]


def cloud_element(spec_path: str, file: str) -> MassProperties:
    """The whole cloud as one part: its mass, centre of mass and inertia about that centre.
    ``file`` is resolved against the spec's folder (see :func:`rbi.formats.paths.spec_relative_file`)."""
    label = f"{spec_path}: point_cloud: file: {file}"
    masses, positions = read_point_cloud(spec_relative_file(spec_path, file, label), label)
    props = combine(masses, positions)
    if not (np.isfinite(props.mass) and np.all(np.isfinite(props.inertia_about_com))):
        raise InputError(f"{label}: numbers too large: mass or inertia overflows")
    return props


def _read_npy(stream: BinaryIO, label: str) -> np.ndarray:
    """The (N, 4) table of an open ``.npy`` file, its header checked against the file's size
    before any array is allocated."""

    not_npy = f"{label}: not a readable .npy array (expected a numeric array of shape (N, 4) with columns mass, x, y, z)"
    try:
        version = npy.read_magic(stream)
        if version == (1, 0):
            shape, fortran_order, dtype = npy.read_array_header_1_0(stream)
        elif version in ((2, 0), (3, 0)):
            shape, fortran_order, dtype = npy.read_array_header_2_0(stream)
        else:
            raise ValueError("unknown version")
    except (ValueError, SyntaxError, TypeError, EOFError, UnicodeDecodeError):
        raise InputError(not_npy) from None
    if dtype.hasobject or dtype.kind not in "fiu" or dtype.shape != () or len(shape) != 2 or shape[1] != 4:
        raise InputError(
            f"{label}: a .npy cloud must be a numeric array of shape (N, 4) with columns "
            f"mass, x, y, z (got shape {tuple(shape)}, dtype {_plain_dtype_name(dtype)})"
        )
    if shape[0] == 0:
        raise InputError(f"{label}: holds no points (an array of shape (0, 4))")
    data_bytes = os.fstat(stream.fileno()).st_size - stream.tell()
    if data_bytes != shape[0] * 4 * dtype.itemsize:
        raise InputError(
            f"{label}: the header says {shape[0]:,} points ({shape[0] * 4 * dtype.itemsize:,} bytes) "
            f"but the file holds {data_bytes:,} bytes of data (truncated or not a .npy file)"
        )
    stream.seek(0)
    try:
        table = npy.read_array(stream, allow_pickle=False)
    except ValueError:
        raise InputError(not_npy) from None
    return np.asarray(table, dtype=float)


def _plain_dtype_name(dtype: np.dtype) -> str:
    """A dtype's name when it is a plain number type; never a structured dtype's field names
    (text from the file)."""
    plain = dtype.fields is None and dtype.shape == () and dtype.kind in "biufc"
    return str(dtype) if plain else "not a plain number type"


def _read_csv(stream: BinaryIO, label: str) -> np.ndarray:
    header, header_line = _header(stream, label)
    missing = [c for c in COLUMNS if c not in header]
    if missing:
        raise InputError(
            f"{label}: line {header_line}: header must name the columns mass, x, y, z "
            f"(missing {', '.join(missing)})"
        )
    twice = [c for c in COLUMNS if header.count(c) > 1]
    if twice:
        raise InputError(f"{label}: line {header_line}: column {twice[0]} is named twice in the header")
    usecols = [header.index(c) for c in COLUMNS]
    stream.seek(0)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # "no data": reported below instead
            table = np.loadtxt(
                io.TextIOWrapper(stream, encoding="utf-8-sig"),  # read as numpy reads a path
                delimiter=",",
                skiprows=header_line,
                usecols=usecols,
                ndmin=2,
                dtype=float,
                comments="#",
                encoding="utf-8-sig",
            )
    except ValueError as exc:
        # numpy counts rows after the skipped header; name the line a text editor shows.
        raise InputError(f"{label}: {_describe_parse_error(str(exc), header_line)}") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{label}: not UTF-8 text (byte {exc.start})") from None
    if table.shape[0] == 0:
        raise InputError(f"{label}: holds no points (a header and no rows)")
    return table


def _header(file: BinaryIO, label: str) -> tuple[list[str], int]:
    """Column names of the first non-comment, non-blank line, and that line's number (a
    byte-order mark, as spreadsheets write, is skipped)."""
    stream = io.TextIOWrapper(file, encoding="utf-8-sig", newline="")
    try:
        number = 0
        while True:
            line = stream.readline(_HEADER_LINE_CHARS)
            if not line:
                break
            number += 1
            if "\x00" in line:
                raise InputError(f"{label}: not a text file (binary data)")
            if len(line) >= _HEADER_LINE_CHARS and not line.endswith("\n"):
                raise InputError(
                    f"{label}: line {number}: longer than {_HEADER_LINE_CHARS} characters "
                    "(expected a header row mass,x,y,z)"
                )
            text = line.strip()
            if text and not text.startswith("#"):
                return [c.strip().lower() for c in text.split(",")], number
    except UnicodeDecodeError as exc:
        raise InputError(f"{label}: not UTF-8 text (byte {exc.start})") from None
    finally:
        stream.detach()  # the file stays open: its rows are read next
    raise InputError(f"{label}: file is empty (expected a header row mass,x,y,z and one row per point)")


def _describe_parse_error(message: str, header_line: int) -> str:
    """numpy's loadtxt message turned into a file line and column, without the offending text."""

    # numpy counts the rows after the header from 0 in conversion errors, from 1 in column errors.
    convert = re.search(r"could not convert string .* to float64 at row (\d+), column (\d+)", message)
    if convert:
        line = int(convert.group(1)) + header_line + 1
        return f"line {line}: column {convert.group(2)}: must be a number"
    columns = re.search(r"at row (\d+) with (\d+) columns?", message)
    if columns:
        line = int(columns.group(1)) + header_line
        return f"line {line}: has {columns.group(2)} columns, fewer than the header names"
    return "cannot be read as rows of comma-separated numbers"


def _check_values(table: np.ndarray, label: str) -> None:
    finite = np.isfinite(table)
    if not finite.all():
        row, col = np.argwhere(~finite)[0]
        raise InputError(f"{label}: point {row}: {COLUMNS[col]}: must be a finite number")
    bad = np.flatnonzero(table[:, 0] <= 0.0)
    if bad.size:
        raise InputError(f"{label}: point {int(bad[0])}: mass: must be greater than 0")
