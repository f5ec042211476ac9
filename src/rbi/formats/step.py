"""STEP files (ISO 10303-21: AP203, AP214, AP242) that a spec names (``shape: step``) or that
``rbi import`` reads: each solid of the file with its mass properties integrated on the exact
boundary representation (OpenCascade's ``BRepGProp``, through the optional extra ``cad``).

The file is read in its own length unit (the unit it declares, so no coordinate is rescaled
while reading) and every result is returned in metres: a solid's volume in m³, its centre of
mass in m and its inertia in m⁵ (per unit density) in the file's axes. OpenCascade is imported
here only, and only when a STEP file is read.

Integration and its error: each distinct solid is integrated twice. When every face is a plane,
cylinder, cone, sphere or torus, by OpenCascade's Gauss rule (exact for their polynomial
parametrisations), returned, and by its adaptive rule at a relative tolerance of
:data:`ADAPTIVE_EPS`; else (a face stored as NURBS, on which the Gauss rule is 0.9 % off a
cylinder) by the adaptive rule at :data:`NURBS_EPS`, returned, and at :data:`NURBS_CHECK_EPS`.
The larger relative difference between the two (volume, centre of mass against the solid's
radius of gyration, inertia against its largest entry) is returned as the integration's error
estimate. (The adaptive rule tests the volume only: at ``Eps = 1e-12`` a NURBS torus's inertia
is 4e-7 off while it reports 1e-16.)

Names: a solid is named after its label in the file's product tree (the instance's name when
the file gives one, else the product's), ``NAME[k]`` for the k-th solid of a shape holding
several, ``solid N`` when the tree names none; repeated names get ``-2``, ``-3``, ... so each
is unique. Solids are numbered from 0 in the order of the tree, depth first.

Apart: OpenCascade reads a file in a child Python process (``python -c``, from ``/``), whose
standard output and error go to /dev/null for its whole life, and the answer comes back as JSON
on a private descriptor. A damaged file that crashes OpenCascade (one deleted entity line,
a dangling ``#reference``: SIGSEGV) is then a one-line refusal, not the end of rbi or of the
caller's notebook; the process that calls :func:`read_step` never loads OpenCascade, and threads
reading at once share no file descriptors.

Bounded work: a product tree of more than :data:`MAX_STEP_SOLIDS` solid instances (or
:data:`MAX_STEP_NODES` nodes) is refused as it is walked; each distinct solid is checked and
integrated once and its instances are placed by their rigid transformation.

Messages name what is wrong, never the file's content.
"""

from __future__ import annotations

import contextlib
import importlib
import importlib.util
import json
import os
import pickle
import re
import signal
import subprocess
import sys
from collections import OrderedDict
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from rbi.core.mass import MassProperties
from rbi.files.safe import open_input_file
from rbi.formats.collada import joined
from rbi.formats.paths import file_key
from rbi.memory import cached

MAX_STEP_BYTES = 32 * 2**20
"""Largest STEP file rbi reads (32 MiB). Measured: OpenCascade's libraries take 290 MB once
loaded and a 0.79 MB file (a plate with 200 holes) adds 7 MB and 2.5 s of CPU to read and
integrate, so a file at the cap stays near 0.6 GB and some 100 s."""

CAD_EXTRA_HINT = "pip install '.[cad]' in rbi's source folder"
"""How to get OpenCascade's wheels (the optional extra ``cad``: cadquery-ocp-novtk)."""

ADAPTIVE_EPS = 1e-12
"""Relative tolerance of the adaptive integration the Gauss result is checked against."""

NURBS_EPS = 1e-30
"""Relative tolerance of the adaptive rule on a solid with a face stored as NURBS: below any
reachable difference, so the rule refines each face until OpenCascade's own cap on its steps.
Measured on the NURBS forms of a cylinder, a torus and a sphere (tests/step_builders.py):
volume, centre of mass and inertia within 2e-15 of the closed forms in 0.13, 0.21 and 0.13 s
of CPU, where ``Eps = 1e-12`` left the inertia 1.7e-7, 4.2e-7 and 1.1e-9 off. (OpenCascade's
Gauss-Kronrod rule, ``VolumePropertiesGK`` with spans, took over 60 s on the torus at 1e-6.)"""

NURBS_CHECK_EPS = 1e-20
"""Tolerance of the second, coarser integration of a NURBS solid whose difference from the
first is the error estimate (the inertia of the same three solids 1.6e-10, 3.9e-10 and 4e-13
off at it, so the estimate bounds the returned result's error from above)."""

MAX_STEP_SOLIDS = 10_000
"""Most solid instances rbi reads from one file (a 48 KB file of assemblies nested 5 deep, 10
instances each, places 10⁵)."""

MAX_STEP_NODES = 100_000
"""Most nodes (assemblies, instances, parts) rbi walks in one file's product tree."""

STEP_TIME_LIMIT_S = 600.0
"""Wall-clock seconds the child process reading one file may take (a file at
:data:`MAX_STEP_BYTES` takes some 100 s)."""

_UNIT_SYMBOLS = {
    1.0: "m",
    1e-3: "mm",
    1e-2: "cm",
    1e-6: "µm",
    1e3: "km",
    0.0254: "in",
    0.3048: "ft",
    2.54e-5: "mil",
    0.9144: "yd",
    1609.344: "mi",
    2.54e-8: "µin",
}


class CadExtraMissing(ValueError):
    """OpenCascade (the optional extra ``cad``) is not installed."""


class StepSolid(NamedTuple):
    """One solid of a STEP file: ``name`` (unique in the file), ``props`` at unit density in
    metres and the file's axes (``mass`` is the volume in m³, ``center_of_mass`` in m,
    ``inertia_about_com`` in m⁵; frame ``"step file"``), and ``integration_error``, the relative error estimate of the integration."""

    name: str
    props: MassProperties
    integration_error: float

    @property
    def volume(self) -> float:
        """Volume, m³."""
        return float(self.props.mass)


class StepFile(NamedTuple):
    """What a STEP file holds: its ``solids`` in file order, the length unit it declares
    (``unit``, a symbol such as ``mm``) and that unit in metres (``unit_metres``)."""

    solids: tuple[StepSolid, ...]
    unit: str
    unit_metres: float


def read_step(path: Path) -> StepFile:
    """Read the STEP file at ``path`` and integrate each of its solids (see the module's text),
    in a child process.

    Raises :class:`CadExtraMissing` without OpenCascade, ``ValueError`` for a file that is too
    large, not STEP, holds no solid or too many, whose solid is open or inside out, or that
    crashes OpenCascade; the caller adds the file and part to the message.
    """
    key = file_key(path)
    return cached(_CACHE, _CACHE_ENTRIES, key, lambda: _apart(_read_here, path, ADAPTIVE_EPS))


def select_solids(step: StepFile, solid: str | int | None) -> list[int]:
    """Indices of the solids a part's ``solid:`` picks: every solid for None, the one at a
    0-based index, or the one of that name. Raises ``ValueError`` naming the choices."""
    count = len(step.solids)
    if solid is None:
        return list(range(count))
    if isinstance(solid, int):
        if 0 <= solid < count:
            return [solid]
        raise ValueError(
            f"solid: {solid} is out of range: the file has {count} solid{'s' * (count != 1)}, 0 to {count - 1}"
        )
    names = [one.name for one in step.solids]
    if solid in names:
        return [names.index(solid)]
    listed = ", ".join(repr(name) for name in names[:12]) + (", ..." if count > 12 else "")
    raise ValueError(
        f"solid: no solid named {solid!r} in the file; its solids are {listed} (or give a 0-based index)"
    )


def step_triangles(
    path: Path, indices: list[int], deflection: float, angle: float = 0.5
) -> tuple[np.ndarray, np.ndarray]:
    """Triangles of the solids ``indices`` of the STEP file at ``path`` (BRepMesh), for a
    picture or a comparison, never for mass properties: vertices (N, 3) in metres in the file's
    axes and faces (F, 3), wound outwards. ``deflection`` is the largest distance of a facet
    from the surface as a fraction of each edge's size, ``angle`` the largest angle (radians)
    between neighbouring facets."""
    return _apart(_triangles_here, path, [int(i) for i in indices], deflection, angle)


# --- reading ----------------------------------------------------------------------------------


_CACHE: OrderedDict[tuple, StepFile] = OrderedDict()
"""Files already read in this process (a sweep translates the same spec many times), keyed by
resolved path, size and modification time."""

_CACHE_ENTRIES = 4

_CHILD = "import sys; from rbi.formats.step import {0}; {0}(sys.argv[1])"
"""What the child process runs (formatted with :func:`_child`'s name)."""


def _apart(operation: Callable, path: Path, *arguments) -> Any:
    """What ``operation`` (a function of this module taking the file's path and ``arguments``)
    returns in the child process, once the file is checked (:func:`_check_text`); ValueError
    (CadExtraMissing) for its refusal, its crash or its time limit. The answer comes back
    pickled: from rbi's own child, built by rbi's code (numbers, names, arrays), never read
    from the file."""
    _check_text(path)
    request = (operation.__name__, os.path.abspath(path), *arguments)
    home = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # holds rbi/
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [home, os.environ.get("PYTHONPATH")])))
    try:
        done = subprocess.run(
            [sys.executable, "-c", _CHILD.format(_child.__name__), json.dumps(request)],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            cwd=os.sep,  # nothing imported from the caller's folder
            env=env,
            timeout=STEP_TIME_LIMIT_S,
        )
    except subprocess.TimeoutExpired:
        raise ValueError(
            f"OpenCascade took longer than {STEP_TIME_LIMIT_S:g} s to read it; refused"
        ) from None
    if done.returncode < 0:
        with contextlib.suppress(ValueError):
            name = signal.Signals(-done.returncode).name
        raise ValueError(
            f"OpenCascade crashed reading it ({name if 'name' in locals() else -done.returncode}): the "
            "file is damaged (an entity it refers to is missing or of the wrong kind)"
        )
    try:
        answer = pickle.loads(done.stdout)
    except Exception:  # noqa: BLE001 - a child that ended without a whole answer
        raise ValueError(f"OpenCascade failed reading it (exit status {done.returncode})") from None
    if isinstance(answer, ValueError):
        raise answer
    return answer


def _child(request: str) -> None:
    """The child process: answer ``request`` (JSON: the operation's name, the file, its
    arguments) on what was standard output, with standard output and error sent to /dev/null
    (OpenCascade prints)."""
    answer_fd = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    operation, path, *arguments = json.loads(request)
    answer: Any
    try:
        answer = {"_read_here": _read_here, "_triangles_here": _triangles_here}[operation](
            Path(path), *arguments
        )
    except CadExtraMissing as exc:
        answer = CadExtraMissing(str(exc))
    except ValueError as exc:
        answer = ValueError(str(exc))
    except MemoryError:
        answer = ValueError("OpenCascade ran out of memory reading it")
    except Exception as exc:  # noqa: BLE001 - OpenCascade's own failures: named, never echoed
        answer = ValueError(f"OpenCascade could not read it ({type(exc).__name__})")
    with os.fdopen(answer_fd, "wb") as stream:
        pickle.dump(answer, stream)


def _read_here(path: Path, eps: float) -> StepFile:
    """The file read and integrated (in the child): its unit and each solid's name, volume (m³),
    centre of mass (m), inertia (m⁵) and error estimate."""
    ocp, instances, unit_metres = _instances(path)
    names = _unique([instance[0] for instance in instances])
    distinct: dict[Any, tuple] = {}
    solids = []
    for index, (_, key, solid, location) in enumerate(instances):
        if key not in distinct:
            _check_closed(ocp, solid, index, names[index])
            distinct[key] = _integrate(ocp, solid, index, names[index], eps)
        props, error = _placed(ocp, distinct[key], solid, location, index, names[index], eps)
        s = unit_metres  # the file's unit -> m
        metres = MassProperties(
            props.mass * s**3, props.center_of_mass * s, props.inertia_about_com * s**5, "step file"
        )
        solids.append(StepSolid(names[index], metres, float(error)))
    return StepFile(tuple(solids), _UNIT_SYMBOLS.get(unit_metres, f"{unit_metres:g} m"), unit_metres)


def _triangles_here(
    path: Path, indices: list[int], deflection: float, angle: float
) -> tuple[np.ndarray, np.ndarray]:
    ocp, instances, unit_metres = _instances(path)
    vertices, faces = joined(
        [
            (points.reshape(-1, 3) * unit_metres, triangles.reshape(-1, 3))
            for _, _, solid, location in (instances[i] for i in indices)
            for points, triangles in _tessellate(ocp, solid.Moved(location), deflection, angle)
        ]
    )
    return vertices, faces.astype(np.int64)


def _instances(path: Path):
    """OpenCascade's names, the file's solid instances (name, key of the distinct solid, the
    solid, its placement) in the file's unit, and that unit in metres."""
    ocp = _ocp()
    unit_metres = _declared_unit(path)
    document = _transfer(ocp, path, unit_metres)
    instances = _labelled_solids(ocp, document)
    if not instances:
        raise ValueError(_no_solid(ocp, document))
    return ocp, instances, unit_metres


def _check_text(path: Path) -> None:
    """Refuse, before OpenCascade parses anything, what :func:`rbi.files.safe.open_input_file`
    refuses (not a regular file, beyond :data:`MAX_STEP_BYTES`) or a file that does not start
    as ISO 10303-21 text does."""
    try:
        with open_input_file(path, "STEP file", MAX_STEP_BYTES) as stream:
            head = stream.read(4096)
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or type(exc).__name__}") from None
    text = head.removeprefix(b"\xef\xbb\xbf").lstrip()
    if not text:
        raise ValueError("file is empty")
    if not text.upper().startswith(b"ISO-10303-21"):
        raise ValueError("not a STEP file (ISO 10303-21 text starts with 'ISO-10303-21;')")


class _OpenCascade:
    """OpenCascade's names the reader uses, each imported when first used from its package: the
    part of the name before its first ``_`` (``BRep_Tool`` from ``OCP.BRep``, ``TopoDS`` from
    ``OCP.TopoDS``), as OpenCascade names its classes; ``collections`` is OCP's module of
    collection types."""

    def __getattr__(self, name: str) -> Any:
        if name == "collections":
            value = importlib.import_module("OCP.OCP.collections")
        else:
            value = getattr(importlib.import_module("OCP." + name.split("_", 1)[0]), name)
        setattr(self, name, value)
        return value


def require_cad() -> None:
    """:class:`CadExtraMissing` when OpenCascade (the extra ``cad``) is not installed: checked
    before anything else about a STEP part, so a user without it is told what to install, not
    what else is wrong (OpenCascade is looked up, not imported)."""

    if importlib.util.find_spec("OCP") is None:
        raise CadExtraMissing(f"reading STEP files needs OpenCascade: {CAD_EXTRA_HINT}")


def _ocp() -> _OpenCascade:
    """OpenCascade's names the reader uses, with its console messages switched off; raises
    :class:`CadExtraMissing` when the extra ``cad`` is not installed."""

    try:
        # OCP: optional (the 'cad' extra), imported only when used
        from OCP.Message import Message
    except ImportError:
        raise CadExtraMissing(f"reading STEP files needs OpenCascade: {CAD_EXTRA_HINT}") from None
    messenger = Message.DefaultMessenger_s()
    for printer in list(messenger.Printers()):
        messenger.RemovePrinter(printer)
    return _OpenCascade()


def _transfer(ocp, path: Path, unit_metres: float):
    """The XCAF document of the file, read in the file's own length unit (``unit_metres``)."""
    reader = ocp.STEPCAFControl_Reader()
    reader.SetNameMode(True)
    if reader.ReadFile(str(path)) != ocp.IFSelect_RetDone:
        raise ValueError("cannot be read as STEP (damaged, or not ISO 10303-21)")
    document = ocp.TDocStd_Document(ocp.TCollection_ExtendedString("XmlXCAF"))
    ocp.XCAFDoc_DocumentTool.SetLengthUnit_s(document, unit_metres)
    if not reader.Transfer(document):
        raise ValueError("cannot be read as STEP: OpenCascade found no shape to transfer in it")
    return document


_SI_PREFIX = {"": 1.0, "$": 1.0, "KILO": 1e3, "HECTO": 1e2, "DECA": 10.0, "DECI": 0.1, "CENTI": 1e-2}
_SI_PREFIX |= {"MILLI": 1e-3, "MICRO": 1e-6, "NANO": 1e-9, "PICO": 1e-12}
_SI_METRE = r"SI_UNIT\s*\(\s*\.?(\w*|\$)\.?\s*,\s*\.METRE\.\s*\)"
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _declared_unit(path: Path) -> float:
    """The length unit the file declares, in metres, read from its text: an SI unit (``METRE``
    with a prefix) or a conversion-based one (``'INCH'``, ``'MIL'``, ``'YARD'``, ...: by its own
    factor). Metres when it declares none, or several. A factor that is not positive (a
    negative one mirrors every solid) is refused."""
    with open_input_file(path, "STEP file", MAX_STEP_BYTES) as stream:
        text = stream.read().decode("latin-1")
    converted, si = set(), set()  # an SI unit may be only the base of a conversion-based one
    for match in re.finditer(r"\(([^;]*\bLENGTH_UNIT\s*\(\s*\)[^;]*)\)\s*;", text):
        entity = match.group(1)
        if found := re.search(r"CONVERSION_BASED_UNIT\s*\(\s*'([^']*)'\s*,\s*#(\d+)\s*\)", entity):
            converted.add(_converted(text, found.group(1), found.group(2)))
        elif found := re.search(_SI_METRE, entity):
            si.add(_SI_PREFIX.get(found.group(1).upper(), 1.0))
    units = converted or si
    return units.pop() if len(units) == 1 else 1.0


def _converted(text: str, name: str, reference: str) -> float:
    """A conversion-based length unit's size in metres: its measure times its base unit."""
    measure = re.search(rf"#{reference}\s*=\s*([^;]*);", text)
    value = measure and re.search(
        rf"\(\s*(?:LENGTH_MEASURE\s*\(\s*)?({_NUMBER})\s*\)?\s*,\s*#(\d+)", measure.group(1)
    )
    base = value and re.search(rf"#{value.group(2)}\s*=\s*([^;]*);", text)
    si = base and re.search(_SI_METRE, base.group(1))
    label = "".join(c for c in name if c.isalnum() or c in " -_")[:20]
    if not (value and si):
        raise ValueError(f"its length unit {label!r} is not defined as a length in metres")
    metres = float(value.group(1)) * _SI_PREFIX.get(si.group(1).upper(), 1.0)
    if not 0.0 < metres < float("inf"):
        raise ValueError(
            f"its length unit {label!r} is {float(value.group(1)):g} of a metre unit: a unit must be "
            "positive (a negative one mirrors every solid)"
        )
    return metres


def _label_name(ocp, label) -> str | None:
    attribute = ocp.TDataStd_Name()
    if label.FindAttribute(ocp.TDataStd_Name.GetID_s(), attribute):
        name = "".join(c if c.isprintable() else " " for c in attribute.Get().ToExtString()).strip()[:120]
        if name and not name.startswith("=>"):  # "=>[0:1:1:2]": OpenCascade's name of an unnamed instance
            return name
    return None


def _labelled_solids(ocp, document) -> list[tuple[str, Any, Any, Any]]:
    """(name, key of the distinct solid, the solid as its part holds it, its placement in the
    file's frame) of every solid instance in the product tree, depth first."""
    found: list[tuple[str | None, Any, Any, Any]] = []
    nodes = [0]
    for label in _free_labels(ocp, document):
        _walk(ocp, label, ocp.TopLoc_Location(), None, found, 0, nodes)
    return [
        (name if name else f"solid {i}", key, solid, at) for i, (name, key, solid, at) in enumerate(found)
    ]


def _free_labels(ocp, document) -> list:
    """The labels of the document's free shapes (the roots of its product tree)."""
    free = ocp.collections.Sequence_TDF_Label()
    ocp.XCAFDoc_DocumentTool.ShapeTool_s(document.Main()).GetFreeShapes(free)
    return [free.Value(i) for i in range(1, free.Length() + 1)]


def _no_solid(ocp, document) -> str:
    """What a file without a solid holds instead, as the end of its refusal."""
    shells = faces = 0
    for label in _free_labels(ocp, document):
        shape = ocp.XCAFDoc_ShapeTool.GetShape_s(label)
        shells += len(_each(ocp, shape, ocp.TopAbs_SHELL, ocp.TopoDS.Shell))
        faces += len(_each(ocp, shape, ocp.TopAbs_FACE, ocp.TopoDS.Face))
    if shells or faces:
        held = f"{shells} shell{'s' * (shells != 1)}" if shells else f"{faces} face{'s' * (faces != 1)}"
        return (
            f"holds no solid, only {held} (an open shell or a surface model encloses no volume: "
            "close it into a solid in the CAD tool)"
        )
    return "holds no solid (no shape with a volume: curves or points only)"


def _walk(ocp, label, location, instance_name: str | None, found: list, depth: int, nodes: list) -> None:
    shape_tool = ocp.XCAFDoc_ShapeTool
    if depth > 64:
        raise ValueError("its product tree is nested more than 64 deep (a cycle?)")
    nodes[0] += 1
    if nodes[0] > MAX_STEP_NODES:
        raise ValueError(
            f"its product tree has more than {MAX_STEP_NODES:,} nodes; rbi reads at most that many"
        )
    if shape_tool.IsReference_s(label):
        referred = ocp.TDF_Label()
        shape_tool.GetReferredShape_s(label, referred)
        placed = location.Multiplied(shape_tool.GetLocation_s(label))
        _walk(ocp, referred, placed, _label_name(ocp, label), found, depth + 1, nodes)
        return
    name = instance_name or _label_name(ocp, label)
    if shape_tool.IsAssembly_s(label):
        components = ocp.collections.Sequence_TDF_Label()
        shape_tool.GetComponents_s(label, components)
        for i in range(1, components.Length() + 1):
            _walk(ocp, components.Value(i), location, None, found, depth + 1, nodes)
        return
    entry = ocp.TCollection_AsciiString()
    ocp.TDF_Tool.Entry_s(label, entry)
    solids = _each(ocp, shape_tool.GetShape_s(label), ocp.TopAbs_SOLID, ocp.TopoDS.Solid)
    if len(found) + len(solids) > MAX_STEP_SOLIDS:
        raise ValueError(
            f"holds more than {MAX_STEP_SOLIDS:,} solids (instances of parts in its product tree); "
            f"rbi reads at most {MAX_STEP_SOLIDS:,}"
        )
    for k, solid in enumerate(solids):
        label_k = name if len(solids) == 1 or name is None else f"{name}[{k}]"
        found.append((label_k, (entry.ToCString(), k), solid, location))


def _each(ocp, shape, kind, cast) -> list:
    """The sub-shapes of ``kind`` of ``shape`` in OpenCascade's order, each ``cast`` (as
    ``TopoDS.Face``) as it is met."""
    explorer = ocp.TopExp_Explorer(shape, kind)
    found = []
    while explorer.More():
        found.append(cast(explorer.Current()))
        explorer.Next()
    return found


def _unique(names: list[str]) -> list[str]:
    """The names with ``-2``, ``-3``, ... added to repeats, so that each is unique (never taking
    a name the file gives another solid); linear in the number of names (each name's count
    resumes where it stopped)."""
    given, taken, last, out = set(names), set(), {}, []
    for name in names:
        candidate, n = name, last.get(name, 1)
        while candidate in taken or (candidate != name and candidate in given):
            n += 1
            candidate = f"{name}-{n}"
        last[name] = n
        taken.add(candidate)
        out.append(candidate)
    return out


def _check_closed(ocp, solid, index: int, name: str) -> None:
    """Refuse a solid whose boundary has an edge that only one face uses (an open shell):
    what it encloses is not defined. Seam edges (a cylinder's) and degenerate edges (a cone's
    apex, a sphere's poles) are not free."""
    faces_of = ocp.collections.IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher()
    ocp.TopExp.MapShapesAndAncestors_s(solid, ocp.TopAbs_EDGE, ocp.TopAbs_FACE, faces_of)
    free = 0
    for i in range(1, faces_of.Extent() + 1):
        edge = ocp.TopoDS.Edge(faces_of.FindKey(i))
        if ocp.BRep_Tool.Degenerated_s(edge):
            continue
        faces = faces_of.FindFromIndex(i)
        if faces.Size() >= 2:
            continue
        if faces.Size() == 1 and ocp.BRep_Tool.IsClosed_s(edge, ocp.TopoDS.Face(faces.First())):
            continue  # a seam: the face meets itself along it
        free += 1
    if free:
        raise ValueError(
            f"solid {index} ({name}) is open: {free} edge{'s' * (free != 1)} of its boundary "
            f"belong{'s' * (free == 1)} to one face only, so it encloses no definite volume "
            "(sew or close it in the CAD tool)"
        )


def _gprops(ocp, solid, eps: float | None):
    props = ocp.GProp_GProps()
    if eps is None:
        ocp.BRepGProp.VolumeProperties_s(solid, props)
    else:
        ocp.BRepGProp.VolumeProperties_s(solid, props, eps, True)
    centre = props.CentreOfMass()
    matrix = props.MatrixOfInertia()
    inertia = np.array([[matrix.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)])
    return float(props.Mass()), np.array([centre.X(), centre.Y(), centre.Z()]), inertia


def _analytic(ocp, solid) -> bool:
    """Is every face of the solid a plane, cylinder, cone, sphere or torus (on which the Gauss
    rule is exact)?"""
    kinds = (ocp.GeomAbs_Plane, ocp.GeomAbs_Cylinder, ocp.GeomAbs_Cone, ocp.GeomAbs_Sphere, ocp.GeomAbs_Torus)
    faces = _each(ocp, solid, ocp.TopAbs_FACE, ocp.TopoDS.Face)
    return all(ocp.BRepAdaptor_Surface(face).GetType() in kinds for face in faces)


def _integrate(ocp, solid, index: int, name: str, eps: float) -> tuple[MassProperties, float]:
    """The solid's mass properties at unit density in the file's unit, and the relative
    difference between two integrations (the error estimate): the Gauss rule checked by the
    adaptive one at ``eps`` when every face is analytic, else the adaptive rule at
    :data:`NURBS_EPS` checked by it at :data:`NURBS_CHECK_EPS` (a surface stored as NURBS: the
    Gauss rule is 0.9 % off a cylinder)."""
    exact = _analytic(ocp, solid)
    volume, com, inertia = _gprops(ocp, solid, None if exact else NURBS_EPS)
    check_volume, check_com, check_inertia = _gprops(ocp, solid, eps if exact else NURBS_CHECK_EPS)
    if not (volume > 0.0 and np.all(np.isfinite(inertia)) and np.all(np.isfinite(com))):
        raise ValueError(
            f"solid {index} ({name}) has {'no' if volume == 0 else 'a negative'} volume "
            "(an inside-out or degenerate solid)"
        )
    largest = float(np.max(np.abs(inertia)))
    radius = np.sqrt(max(np.trace(inertia), 0.0) / (2.0 * volume)) or 1.0
    error = max(
        abs(check_volume - volume) / volume,
        float(np.linalg.norm(check_com - com)) / radius,
        float(np.max(np.abs(check_inertia - inertia))) / largest if largest > 0 else 0.0,
    )
    return MassProperties(volume, com, 0.5 * (inertia + inertia.T), "step file"), error


def _placed(
    ocp, integrated, solid, location, index: int, name: str, eps: float
) -> tuple[MassProperties, float]:
    """An instance's mass properties: its distinct solid's (``integrated``) turned and moved by
    its placement, or the placed solid integrated itself when the placement is not rigid."""
    props, error = integrated
    if location.IsIdentity():
        return props, error
    trsf = location.Transformation()
    if abs(trsf.ScaleFactor() - 1.0) > 1e-12 or trsf.IsNegative():
        return _integrate(ocp, solid.Moved(location), index, name, eps)
    rotation = np.array([[trsf.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)])
    return props.transformed(rotation, [trsf.Value(i, 4) for i in (1, 2, 3)]), error


def _tessellate(ocp, solid, deflection: float, angle: float):
    """Triangles of one solid by BRepMesh (``deflection`` relative to each edge's size), in
    the file's unit, faces turned outwards: (points (N, 3), triangles (T, 3) indexing them) for
    each face of the solid."""
    parameters = ocp.IMeshTools_Parameters()
    parameters.Deflection, parameters.Relative, parameters.Angle = deflection, True, angle
    parameters.MeshAlgo = (
        ocp.IMeshTools_MeshAlgoType_Delabella  # twice as fast as the default on plates with holes
    )
    ocp.BRepTools.Clean_s(solid)  # a triangulation made earlier at other settings
    ocp.BRepMesh_IncrementalMesh(solid, parameters)
    for face in _each(ocp, solid, ocp.TopAbs_FACE, ocp.TopoDS.Face):
        location = ocp.TopLoc_Location()
        mesh = ocp.BRep_Tool.Triangulation_s(face, location)
        if mesh is None:
            continue
        transform = location.Transformation()
        nodes = (mesh.Node(i).Transformed(transform) for i in range(1, mesh.NbNodes() + 1))
        points = np.array([(node.X(), node.Y(), node.Z()) for node in nodes])
        triangles = np.array([mesh.Triangle(i).Get() for i in range(1, mesh.NbTriangles() + 1)]) - 1
        if face.Orientation() == ocp.TopAbs_REVERSED:
            triangles = triangles[:, ::-1]
        yield points, triangles
