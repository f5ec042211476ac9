"""Write bodies/flange.step: a pipe flange as a STEP file (AP214, millimetres), with OpenCascade.

The flange is a disc Ø120 × 12 mm with a hub Ø60 standing 30 mm on it (z up, the disc's
bottom face on z = 0), a Ø40 bore through both, and six Ø14 bolt holes on a Ø90 circle
(the first on +x). Every face is a plane or a cylinder, so its mass properties have a closed
form: docs/step.md prints rbi's numbers beside it. The disc and the hub are fused; the bore
and the holes are cut (OpenCascade booleans).

Run from the project root (needs the extra cad): .venv/bin/python docs/scripts/make_flange_step.py
"""

from __future__ import annotations

import math
from pathlib import Path

from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt
from OCP.Interface import Interface_Static
from OCP.Message import Message
from OCP.STEPCAFControl import STEPCAFControl_Writer
from OCP.STEPControl import STEPControl_AsIs
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.XCAFDoc import XCAFDoc_DocumentTool

DISC_RADIUS, DISC_THICKNESS = 60.0, 12.0
HUB_RADIUS, HUB_HEIGHT = 30.0, 30.0  # the hub stands on the disc: z from 12 to 42
BORE_RADIUS = 20.0
HOLE_RADIUS, HOLE_CIRCLE_RADIUS, HOLES = 7.0, 45.0, 6


def cylinder(radius: float, z0: float, height: float, x: float = 0.0, y: float = 0.0):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), radius, height).Shape()


def flange():
    """The flange solid, in millimetres."""
    body = BRepAlgoAPI_Fuse(
        cylinder(DISC_RADIUS, 0.0, DISC_THICKNESS), cylinder(HUB_RADIUS, DISC_THICKNESS, HUB_HEIGHT)
    ).Shape()
    body = BRepAlgoAPI_Cut(body, cylinder(BORE_RADIUS, -1.0, DISC_THICKNESS + HUB_HEIGHT + 2.0)).Shape()
    for k in range(HOLES):
        angle = 2.0 * math.pi * k / HOLES
        x, y = HOLE_CIRCLE_RADIUS * math.cos(angle), HOLE_CIRCLE_RADIUS * math.sin(angle)
        body = BRepAlgoAPI_Cut(body, cylinder(HOLE_RADIUS, -1.0, DISC_THICKNESS + 2.0, x, y)).Shape()
    return body


def write(path: Path) -> None:
    for printer in list(Message.DefaultMessenger_s().Printers()):
        Message.DefaultMessenger_s().RemovePrinter(printer)
    document = TDocStd_Document(TCollection_ExtendedString("XmlXCAF"))
    XCAFDoc_DocumentTool.SetLengthUnit_s(document, 0.001)
    tool = XCAFDoc_DocumentTool.ShapeTool_s(document.Main())
    label = tool.AddShape(flange(), False)
    TDataStd_Name.Set_s(label, TCollection_ExtendedString("flange DN40"))
    writer = STEPCAFControl_Writer()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer.Transfer(document, STEPControl_AsIs)
    if int(writer.Write(str(path))) != 1:
        raise SystemExit(f"could not write {path}")


if __name__ == "__main__":
    target = Path(__file__).resolve().parents[2] / "bodies" / "flange.step"
    write(target)
    print(f"wrote {target} ({target.stat().st_size} bytes)")
