"""CAD solids: one plate with 200 holes read as a STEP file (integrated on the exact boundary
representation, :mod:`rbi.formats.step`) and as an STL of about 10⁵ triangles (the STEP's own
tessellation; :mod:`rbi.formats.mesh_file`), each the whole load of a spec naming it, timed
cold (nothing cached) and compared with the plate's closed form.

The plate: 210 × 110 × 6 mm, centred on the origin, with a 20 × 10 grid of through holes of
radius 2.5 mm at a 10 mm pitch, the grid 2 mm off centre along x (so the centre of mass is
off the origin). A quick run tessellates the STL coarser (about 2 × 10⁴ triangles): OpenCascade
needs some 10 s to mesh the plate at 10⁵.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import trimesh

from rbi.bench import Progress
from rbi.bench.timing import measure
from rbi.core.inertia import parallel_axis, parallel_axis_to_com
from rbi.formats import mesh_file, step
from rbi.formats.step import _ocp, step_triangles
from rbi.spec.load import load_body
from rbi.spec.materials import density_in_units
from rbi.spec.volumes import part_volume

PLATE_MM = (210.0, 110.0, 6.0)
HOLE_RADIUS_MM = 2.5
GRID = (20, 10)
PITCH_MM = 10.0
GRID_OFFSET_MM = (2.0, 0.0)
DENSITY = "steel"
STL_ANGLE = {True: 0.5, False: 0.1}
"""BRepMesh's angular deflection (radians) for the STL: quick run, full run (about 2 × 10⁴ and
10⁵ triangles)."""


def hole_centres() -> np.ndarray:
    """(200, 2) hole centres, mm."""
    nx, ny = GRID
    xs = (np.arange(nx) - (nx - 1) / 2) * PITCH_MM + GRID_OFFSET_MM[0]
    ys = (np.arange(ny) - (ny - 1) / 2) * PITCH_MM + GRID_OFFSET_MM[1]
    return np.array([(x, y) for x in xs for y in ys])


def closed_form() -> tuple[float, np.ndarray, np.ndarray]:
    """Volume (mm³), centre of mass (mm) and inertia about it at unit density (mm⁵) of the
    plate: the box's, less each hole's (a cylinder, moved by the parallel-axis theorem)."""
    a, b, c = PLATE_MM
    r = HOLE_RADIUS_MM
    v_box = a * b * c
    v_hole = math.pi * r * r * c
    centres = np.column_stack([hole_centres(), np.zeros(len(hole_centres()))])
    volume = v_box - v_hole * len(centres)
    com = -v_hole * centres.sum(axis=0) / volume
    about_origin = v_box / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    own = np.diag([v_hole * (3 * r * r + c * c) / 12] * 2 + [v_hole * r * r / 2])
    for d in centres:
        about_origin -= parallel_axis(own, v_hole, d)
    return volume, com, parallel_axis_to_com(about_origin, volume, com)


def write_plate_step(path: Path) -> None:
    """The plate as a STEP file in millimetres, built and written by OpenCascade."""
    # OCP: optional (the 'cad' extra), imported only when used
    from OCP.BRep import BRep_Builder
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder
    from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt
    from OCP.Interface import Interface_Static
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
    from OCP.TopoDS import TopoDS_Compound

    _ocp()  # OpenCascade's console messages off
    a, b, c = PLATE_MM
    holes = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(holes)
    for x, y in hole_centres():
        axes = gp_Ax2(gp_Pnt(float(x), float(y), -c), gp_Dir(0, 0, 1))
        builder.Add(holes, BRepPrimAPI_MakeCylinder(axes, HOLE_RADIUS_MM, 2 * c).Shape())
    plate = BRepAlgoAPI_Cut(
        BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -b / 2, -c / 2), a, b, c).Shape(), holes
    ).Shape()
    writer = STEPControl_Writer()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer.Transfer(plate, STEPControl_AsIs)
    if int(writer.Write(str(path))) != 1:
        raise RuntimeError("OpenCascade could not write the plate's STEP file")


def _errors(props, volume_mm3: float, closed) -> dict:
    """Relative errors of a loaded body (mm, g) against the closed form at steel's density."""

    density = density_in_units(DENSITY, "mm", "g")
    volume, com, inertia = closed
    size = math.sqrt(np.trace(inertia) / volume)
    expected = inertia * density
    return {
        "volume_error": abs(volume_mm3 - volume) / volume,
        "com_error": float(np.linalg.norm(np.asarray(props.center_of_mass) - com)) / size,
        "inertia_error": float(np.max(np.abs(props.inertia_about_com - expected)) / np.max(np.abs(expected))),
    }


def _row(kind: str, path: Path, shape: str, repeats: int, closed, extra: dict) -> dict:
    """One file's row: its size, the median seconds of the whole load of a spec naming it (a
    ``shape`` part, written next to it) with the file caches emptied first, and its errors
    against the closed form."""
    spec = path.with_name(f"plate-{path.suffix[1:]}.yaml")
    spec.write_text(
        "units: {length: mm, mass: g}\n"
        f"parts:\n  - {{name: plate, shape: {shape}, file: {path.name}, density: {DENSITY}}}\n"
    )

    def load():
        step._CACHE.clear()
        mesh_file._CACHE.clear()
        return load_body(spec)

    timing = measure(load, repeats, repeats, 0.0)
    part = timing.result.spec.parts[0]
    row = {"file": kind, "bytes": path.stat().st_size, "seconds": timing.median, "repeats": repeats}
    row |= _errors(timing.result.props, part_volume(part), closed) | extra
    if kind == "STEP":
        row["integration_error"] = part._integration_error
    return row


def run(quick: bool, progress: Progress, folder: Path) -> dict:
    progress("CAD: plate with 200 holes, STEP against STL")
    try:
        import OCP  # noqa: F401
    except ImportError:
        return {"error": "needs OpenCascade: pip install '.[cad]' in rbi's source folder", "files": []}

    closed = closed_form()
    repeats = 1 if quick else 3
    step_path, stl_path = folder / "plate.step", folder / "plate.stl"
    write_plate_step(step_path)
    vertices, faces = step_triangles(step_path, [0], 0.001, STL_ANGLE[quick])
    trimesh.Trimesh(vertices * 1000.0, faces, process=False).export(stl_path)  # binary STL, mm
    return {
        "plate_mm": list(PLATE_MM),
        "holes": len(hole_centres()),
        "hole_radius_mm": HOLE_RADIUS_MM,
        "files": [
            _row("STEP", step_path, "step", repeats, closed, {"triangles": None}),
            _row("STL", stl_path, "mesh", repeats, closed, {"triangles": int(len(faces))}),
        ],
    }
