"""STEP files for the tests, written by OpenCascade itself (OCP): primitives, booleans, named
assemblies, files in metres and in millimetres; and the closed form of every solid, worked out
here by hand (not by rbi) so the tests check rbi's reading against independent numbers.

Solids are built in millimetres (OpenCascade's working unit here); ``write_step`` writes them
in the unit asked for, so a file "in metres" holds coordinates a thousandth of those below.
Closed forms are at unit density, in millimetres: volume (mm³), centre of mass (mm) and
inertia about it (mm⁵).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pytest

pytest.importorskip("OCP")

from OCP.BRep import BRep_Builder  # noqa: E402
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse  # noqa: E402
from OCP.BRepPrimAPI import (  # noqa: E402
    BRepPrimAPI_MakeBox,
    BRepPrimAPI_MakeCone,
    BRepPrimAPI_MakeCylinder,
    BRepPrimAPI_MakeSphere,
    BRepPrimAPI_MakeTorus,
)
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec  # noqa: E402
from OCP.Interface import Interface_Static  # noqa: E402
from OCP.Message import Message  # noqa: E402
from OCP.STEPCAFControl import STEPCAFControl_Writer  # noqa: E402
from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer  # noqa: E402
from OCP.TCollection import TCollection_ExtendedString  # noqa: E402
from OCP.TDataStd import TDataStd_Name  # noqa: E402
from OCP.TDocStd import TDocStd_Document  # noqa: E402
from OCP.TopAbs import TopAbs_FACE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopLoc import TopLoc_Location  # noqa: E402
from OCP.TopoDS import TopoDS_Compound, TopoDS_Shell, TopoDS_Solid  # noqa: E402
from OCP.XCAFDoc import XCAFDoc_DocumentTool  # noqa: E402

for _printer in list(Message.DefaultMessenger_s().Printers()):
    Message.DefaultMessenger_s().RemovePrinter(_printer)

PI = math.pi


class Solid(NamedTuple):
    """A solid (mm) and its closed form at unit density: volume mm³, centre of mass mm,
    inertia about it mm⁵."""

    shape: object
    volume: float
    com: np.ndarray
    inertia: np.ndarray


def _axes(origin=(0.0, 0.0, 0.0), direction=(0.0, 0.0, 1.0)) -> gp_Ax2:
    return gp_Ax2(gp_Pnt(*origin), gp_Dir(*direction))


def _shift(inertia, volume, offset) -> np.ndarray:
    """Parallel axis: the inertia about a point ``offset`` from the centre of mass."""
    d = np.asarray(offset, dtype=float)
    return inertia + volume * (d @ d * np.eye(3) - np.outer(d, d))


def _box_form(a, b, c):
    v = a * b * c
    return v, v / 12.0 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])


def _cylinder_form(r, h):
    v = PI * r * r * h
    return v, np.diag([v * (3 * r * r + h * h) / 12.0] * 2 + [v * r * r / 2.0])


def box(a=40.0, b=30.0, c=20.0) -> Solid:
    """A box a × b × c centred on the origin."""
    v, inertia = _box_form(a, b, c)
    return Solid(
        BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -b / 2, -c / 2), a, b, c).Shape(), v, np.zeros(3), inertia
    )


def cylinder(r=7.0, h=25.0) -> Solid:
    """A cylinder along z centred on the origin."""
    v, inertia = _cylinder_form(r, h)
    return Solid(BRepPrimAPI_MakeCylinder(_axes((0, 0, -h / 2)), r, h).Shape(), v, np.zeros(3), inertia)


def cone(r=7.0, h=25.0) -> Solid:
    """A cone with its base on z = 0 and its tip at z = h."""
    v = PI * r * r * h / 3.0
    across = v * (3 * r * r / 20.0 + 3 * h * h / 80.0)
    shape = BRepPrimAPI_MakeCone(_axes(), r, 0.0, h).Shape()
    return Solid(shape, v, np.array([0.0, 0.0, h / 4.0]), np.diag([across, across, 0.3 * v * r * r]))


def sphere(r=12.0) -> Solid:
    v = 4.0 / 3.0 * PI * r**3
    return Solid(BRepPrimAPI_MakeSphere(r).Shape(), v, np.zeros(3), 0.4 * v * r * r * np.eye(3))


def torus(major=20.0, minor=6.0) -> Solid:
    """A ring about z centred on the origin."""
    v = 2 * PI * PI * major * minor * minor
    axial = v * (major * major + 0.75 * minor * minor)
    across = v * (major * major / 2.0 + 5.0 / 8.0 * minor * minor)
    return Solid(
        BRepPrimAPI_MakeTorus(_axes(), major, minor).Shape(), v, np.zeros(3), np.diag([across, across, axial])
    )


def tube(outer=10.0, inner=7.0, h=30.0) -> Solid:
    """A cylinder with a coaxial bore, along z, centred on the origin (a boolean cut)."""
    vo, io = _cylinder_form(outer, h)
    vi, ii = _cylinder_form(inner, h)
    shape = BRepAlgoAPI_Cut(
        BRepPrimAPI_MakeCylinder(_axes((0, 0, -h / 2)), outer, h).Shape(),
        BRepPrimAPI_MakeCylinder(_axes((0, 0, -h / 2 - 1)), inner, h + 2).Shape(),
    ).Shape()
    return Solid(shape, vo - vi, np.zeros(3), io - ii)


def bored_plate(a=100.0, b=60.0, c=10.0, r=10.0, x_hole=10.0) -> Solid:
    """A plate a × b × c centred on the origin with a through bore of radius r along z at
    x = x_hole."""
    vb, ib = _box_form(a, b, c)
    vc, ic = _cylinder_form(r, c)
    v = vb - vc
    cx = -vc * x_hole / v
    inertia = _shift(ib, vb, [-cx, 0, 0]) - _shift(ic, vc, [x_hole - cx, 0, 0])
    shape = BRepAlgoAPI_Cut(
        BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -b / 2, -c / 2), a, b, c).Shape(),
        BRepPrimAPI_MakeCylinder(_axes((x_hole, 0, -c)), r, 2 * c).Shape(),
    ).Shape()
    return Solid(shape, v, np.array([cx, 0.0, 0.0]), inertia)


def union(a=20.0, r=5.0, h=15.0) -> Solid:
    """A cube of edge a centred on the origin fused with a cylinder standing on its top face."""
    vb, ib = _box_form(a, a, a)
    vc, ic = _cylinder_form(r, h)
    v = vb + vc
    cz = vc * (a / 2 + h / 2) / v
    inertia = _shift(ib, vb, [0, 0, -cz]) + _shift(ic, vc, [0, 0, a / 2 + h / 2 - cz])
    shape = BRepAlgoAPI_Fuse(
        BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -a / 2, -a / 2), a, a, a).Shape(),
        BRepPrimAPI_MakeCylinder(_axes((0, 0, a / 2)), r, h).Shape(),
    ).Shape()
    return Solid(shape, v, np.array([0.0, 0.0, cz]), inertia)


def difference(a=30.0, r=8.0, offset=(4.0, -3.0, 2.0)) -> Solid:
    """A cube of edge a centred on the origin with a spherical cavity of radius r at offset
    (a boolean cut that leaves an inner shell)."""
    vb, ib = _box_form(a, a, a)
    vs = 4.0 / 3.0 * PI * r**3
    v = vb - vs
    com = -vs * np.asarray(offset) / v
    inertia = _shift(ib, vb, -com) - _shift(0.4 * vs * r * r * np.eye(3), vs, np.asarray(offset) - com)
    shape = BRepAlgoAPI_Cut(
        BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -a / 2, -a / 2), a, a, a).Shape(),
        BRepPrimAPI_MakeSphere(gp_Pnt(*offset), r).Shape(),
    ).Shape()
    return Solid(shape, v, com, inertia)


CLOSED_FORMS = {
    "box": box,
    "bored plate": bored_plate,
    "cylinder": cylinder,
    "cone": cone,
    "sphere": sphere,
    "torus": torus,
    "tube": tube,
    "union": union,
    "difference": difference,
}
"""Every solid with a closed form, by name."""


def moved(shape, offset):
    """The shape translated by ``offset`` (mm)."""
    transform = gp_Trsf()
    transform.SetTranslation(gp_Vec(*offset))
    return shape.Moved(TopLoc_Location(transform))


def write_step(path: Path, solids, unit: str = "mm", assembly: str | None = None) -> Path:
    """Write ``solids`` — a shape, or a list of ``(name, shape)`` (name None for none) — to
    ``path`` as STEP AP214 in ``unit`` (``"mm"`` or ``"m"``); with ``assembly``, the solids are
    the named components of an assembly of that name."""
    if not isinstance(solids, list):
        solids = [(None, solids)]
    document = TDocStd_Document(TCollection_ExtendedString("XmlXCAF"))
    XCAFDoc_DocumentTool.SetLengthUnit_s(document, 0.001)  # the shapes are in millimetres
    tool = XCAFDoc_DocumentTool.ShapeTool_s(document.Main())
    top = tool.NewShape() if assembly is not None else None
    if top is not None:
        TDataStd_Name.Set_s(top, TCollection_ExtendedString(assembly))
    for name, shape in solids:
        label = tool.AddShape(shape, False)
        if name is not None:
            TDataStd_Name.Set_s(label, TCollection_ExtendedString(name))
        if top is not None:
            tool.AddComponent(top, label, TopLoc_Location())
    tool.UpdateAssemblies()
    writer = STEPCAFControl_Writer()  # (its constructor resets the writing unit: set it after)
    Interface_Static.SetCVal_s("write.step.unit", {"mm": "MM", "m": "M"}[unit])
    writer.Transfer(document, STEPControl_AsIs)
    assert int(writer.Write(str(path))) == 1, "OpenCascade could not write the STEP file"
    return path


def write_plain_step(path: Path, shape) -> Path:
    """Write any shape (a shell, a face, a compound) with the plain STEP writer, in mm."""
    writer = STEPControl_Writer()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer.Transfer(shape, STEPControl_AsIs)
    assert int(writer.Write(str(path))) == 1
    return path


def _cube_faces(a: float) -> list:
    """The six faces of a cube of edge a (mm)."""
    explorer = TopExp_Explorer(BRepPrimAPI_MakeBox(a, a, a).Shape(), TopAbs_FACE)
    faces = []
    while explorer.More():
        faces.append(explorer.Current())
        explorer.Next()
    return faces


def open_box_solid(a=10.0):
    """A solid whose shell is a cube with its top face missing (an open shell)."""
    builder = BRep_Builder()
    shell = TopoDS_Shell()
    builder.MakeShell(shell)
    for face in _cube_faces(a)[:-1]:
        builder.Add(shell, face)
    solid = TopoDS_Solid()
    builder.MakeSolid(solid)
    builder.Add(solid, shell)
    return solid


def faces_only(a=10.0):
    """The faces of a cube as a compound: a surface model, no solid."""
    builder = BRep_Builder()
    compound = TopoDS_Compound()
    builder.MakeCompound(compound)
    for face in _cube_faces(a):
        builder.Add(compound, face)
    return compound


def write_nested_assembly(path: Path, part, depth: int, copies: int, step: float = 100.0) -> Path:
    """Write ``part`` (a shape, mm) as an assembly nested ``depth`` levels deep, each level
    ``copies`` instances of the level below, instance ``k`` moved ``k * step * 10**level`` mm
    along x (so ``copies**depth`` solids, every one at its own place), in mm. The file stays
    small: each level is written once."""
    document = TDocStd_Document(TCollection_ExtendedString("XmlXCAF"))
    XCAFDoc_DocumentTool.SetLengthUnit_s(document, 0.001)
    tool = XCAFDoc_DocumentTool.ShapeTool_s(document.Main())
    below = tool.AddShape(part, False)
    TDataStd_Name.Set_s(below, TCollection_ExtendedString("part"))
    for level in range(depth):
        assembly = tool.NewShape()
        TDataStd_Name.Set_s(assembly, TCollection_ExtendedString(f"level{level}"))
        for k in range(copies):
            transform = gp_Trsf()
            transform.SetTranslation(gp_Vec(k * step * copies**level, 0.0, 0.0))
            tool.AddComponent(assembly, below, TopLoc_Location(transform))
        below = assembly
    tool.UpdateAssemblies()
    writer = STEPCAFControl_Writer()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer.Transfer(document, STEPControl_AsIs)
    assert int(writer.Write(str(path))) == 1, "OpenCascade could not write the STEP file"
    return path
