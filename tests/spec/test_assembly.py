"""`shape: assembly`: a sub-assembly equals the same parts written out in one file (placed with
scipy's rotations, converted with the unit tables by hand) in every combination of units,
rotation forms and patterns, nested three deep; a measured mass scales mass and inertia and
keeps the centre of mass; `expanded` lists the parts; the files it reads; refusals (a cycle,
a chain of 1,000 files, a file outside the folder, a FIFO, a bad sub-spec)."""

from __future__ import annotations

import itertools
import json
import os
import time

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rbi
from rbi.spec.assembly import expanded
from tests.conftest import one_line_exit_2, run_rbi_inprocess

METRES = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
KILOGRAMS = {"kg": 1.0, "g": 0.001, "lb": 0.45359237}

LEAF = [  # parts of the innermost file, in its own units
    {"name": "plate", "shape": "box", "mass": 2.0, "center": [0.1, 0.2, -0.3], "size": [0.4, 0.2, 0.05]}
    | {"rotation": {"axis": [1, 1, 0], "angle_deg": 30}},
    {
        "name": "shaft",
        "shape": "cylinder",
        "mass": 0.7,
        "radius": 0.02,
        "start": [0, 0, 0],
        "end": [0.1, 0.3, 0.5],
    },
    {"name": "bolt", "shape": "point", "mass": 0.05, "position": [0.3, -0.1, 0.2]},
]
ROTATIONS = {
    "axis": (
        {"axis": [1, 2, 3], "angle_deg": 40},
        Rotation.from_rotvec(np.radians(40) * np.array([1, 2, 3]) / np.sqrt(14)),
    ),
    "quaternion": ({"quaternion": [0.9, 0.1, -0.3, 0.2]}, Rotation.from_quat([0.1, -0.3, 0.2, 0.9])),
    "euler": (
        {"euler_deg": [10, 70, -20], "sequence": "ZYX"},
        Rotation.from_euler("ZYX", [10, 70, -20], degrees=True),
    ),
}
PATTERNS = {
    "none": None,
    "ring": {"count": 3, "axis": [0, 0, 1], "through": [0.5, 0, 0]},
    "row": {"count": 2, "step": [0, 0.7, 0]},
}


def moved(parts, R: Rotation, t, length: float = 1.0, mass: float = 1.0) -> list[dict]:
    """The parts seen from the parent: lengths × ``length``, masses × ``mass``, turned by ``R``
    about the sub-assembly's origin, then moved by ``t``; a box's own turn kept as ``_R``."""
    out = []
    for part in parts:
        p = dict(part, mass=part["mass"] * mass)
        for key in ("center", "start", "end", "position"):
            if key in p:
                p[key] = (R.apply(np.asarray(p[key]) * length) + t).tolist()
        if "size" in p:
            p["size"] = [s * length for s in p["size"]]
        if "radius" in p:
            p["radius"] *= length
        if p["shape"] == "box":
            own = p.get("_R", Rotation.from_rotvec(np.radians(30) * np.array([1, 1, 0]) / np.sqrt(2)))
            p["_R"] = R * own
        out.append(p)
    return out


def copies(pattern) -> list[tuple[Rotation, np.ndarray]]:
    """Each copy's motion x -> R x + t, by hand from the contract's words."""
    if pattern is None:
        return [(Rotation.identity(), np.zeros(3))]
    if "step" in pattern:
        return [
            (Rotation.identity(), k * np.asarray(pattern["step"], float)) for k in range(pattern["count"])
        ]
    axis, through = np.asarray(pattern["axis"], float), np.asarray(pattern["through"], float)
    turns = [
        Rotation.from_rotvec(axis / np.linalg.norm(axis) * 2 * np.pi * k / pattern["count"])
        for k in range(pattern["count"])
    ]
    return [(R, through - R.apply(through)) for R in turns]


def written(parts) -> list[dict]:
    out = []
    for part in parts:
        p = {k: v for k, v in part.items() if k not in ("_R", "name")}  # copies share a name
        if "_R" in part:
            x, y, z, w = part["_R"].as_quat()
            p["rotation"] = {"quaternion": [w, x, y, z]}
        out.append(p)
    return out


def placed(parts, R, position, length, mass, pattern=None) -> list[dict]:
    once = moved(parts, R, position, length, mass)
    return [p for Rc, tc in copies(pattern) for p in moved(once, Rc, tc)]


def write(folder, name, units, parts):
    (folder / name).write_text(json.dumps({"units": dict(zip(("length", "mass"), units)), "parts": parts}))
    return folder / name


def assert_same(a: rbi.Body, b: rbi.Body):
    assert a.mass == pytest.approx(b.mass, rel=1e-13)
    np.testing.assert_allclose(
        a.center_of_mass, b.center_of_mass, rtol=1e-12, atol=1e-13 * np.abs(b.center_of_mass).max()
    )
    scale = np.abs(b.inertia()).max()
    np.testing.assert_allclose(a.inertia(), b.inertia(), rtol=1e-12, atol=1e-12 * scale)


CASES = list(
    itertools.product(
        [("mm", "g"), ("in", "lb"), ("m", "kg")], [("cm", "kg"), ("ft", "g")], ROTATIONS, PATTERNS
    )
)


@pytest.mark.parametrize(("sub_units", "units", "rotation", "pattern"), CASES[::2] + [CASES[-1]])
def test_a_sub_assembly_is_its_parts_written_out(tmp_path, sub_units, units, rotation, pattern):
    write(tmp_path, "sub.yaml", sub_units, LEAF)
    form, R = ROTATIONS[rotation]
    position = [0.3, -0.2, 1.1]
    sub = {"name": "sub", "shape": "assembly", "file": "sub.yaml", "position": position, "rotation": form}
    if PATTERNS[pattern]:
        sub["pattern"] = PATTERNS[pattern]
    length = METRES[sub_units[0]] / METRES[units[0]]
    mass = KILOGRAMS[sub_units[1]] / KILOGRAMS[units[1]]
    core = {"name": "core", "shape": "sphere", "mass": 1.0, "radius": 0.1, "center": [0, 0, 0]}
    top = rbi.load(write(tmp_path, "top.yaml", units, [core, sub]))
    flat = written([core, *placed(LEAF, R, position, length, mass, PATTERNS[pattern])])
    flat = rbi.load(write(tmp_path, "flat.yaml", units, flat))
    assert_same(top, flat)


def test_nested_three_deep_across_units_rotations_and_patterns(tmp_path):
    write(tmp_path, "c.yaml", ("mm", "g"), LEAF)
    levels = [  # each file, its units, and how it places the file below it
        ("b.yaml", ("in", "lb"), "c.yaml", [1.0, 2.0, 3.0], "euler", {"count": 2, "step": [0, 0, 5]}),
        ("a.yaml", ("cm", "g"), "b.yaml", [-4.0, 0.5, 2.0], "quaternion", None),
        (
            "top.yaml",
            ("m", "kg"),
            "a.yaml",
            [0.1, 0.2, 0.3],
            "axis",
            {"count": 4, "axis": [0, 1, 0], "through": [0, 0, 1]},
        ),
    ]
    flat, flat_units = LEAF, ("mm", "g")
    for name, units, below, position, rotation, pattern in levels:
        form, R = ROTATIONS[rotation]
        part = {"name": below[0], "shape": "assembly", "file": below, "position": position, "rotation": form}
        extra = {"name": "ballast", "shape": "point", "mass": 0.5, "position": [1.0, 0.0, 0.0]}
        write(tmp_path, name, units, [extra, part | ({"pattern": pattern} if pattern else {})])
        length = METRES[flat_units[0]] / METRES[units[0]]
        mass = KILOGRAMS[flat_units[1]] / KILOGRAMS[units[1]]
        flat, flat_units = [extra, *placed(flat, R, position, length, mass, pattern)], units
    top = rbi.load(tmp_path / "top.yaml")
    assert_same(top, rbi.load(write(tmp_path, "flat.yaml", ("m", "kg"), written(flat))))
    rows = expanded(top._loaded)  # what `rbi parts --expand` lists: the same parts, in the same order
    assert len(rows.names) == len(rows.elements) == len(flat) == 1 + 4 * (1 + 1 + 2 * 3)
    names = rows.names
    assert names[:4] == ["ballast", "a[0]/ballast", "a[0]/b/ballast", "a[0]/b/c[0]/plate"]
    assert names[-1] == "a[3]/b/c[1]/bolt"
    for element, part in zip(rows.elements, rbi.load({"parts": written(flat)}).parts()):
        assert element.mass == pytest.approx(part.mass, rel=1e-13)
        np.testing.assert_allclose(element.center_of_mass, part.center_of_mass, rtol=1e-12, atol=1e-14)


def test_a_measured_mass_scales_mass_and_inertia_and_keeps_the_centre(tmp_path):
    write(tmp_path, "sub.yaml", ("m", "kg"), LEAF)
    plain = {"name": "s", "shape": "assembly", "file": "sub.yaml", "position": [1, 2, 3]}
    a = rbi.load(write(tmp_path, "a.yaml", ("m", "kg"), [plain]))
    b = rbi.load(write(tmp_path, "b.yaml", ("m", "kg"), [plain | {"mass": 8.25}]))
    assert b.mass == 8.25
    np.testing.assert_allclose(b.center_of_mass, a.center_of_mass, rtol=1e-15)
    np.testing.assert_allclose(b.inertia(), a.inertia() * 8.25 / a.mass, rtol=1e-14)
    rows = expanded(b._loaded)
    assert rows.names == ["s/plate", "s/shaft", "s/bolt"]
    np.testing.assert_allclose(rows.elements.mass, [2.0 * 3, 0.7 * 3, 0.05 * 3], rtol=1e-14)


def test_files_read_names_the_sub_assemblies(tmp_path):
    write(tmp_path, "c.yaml", ("m", "kg"), LEAF)
    write(tmp_path, "b.yaml", ("m", "kg"), [{"shape": "assembly", "file": "c.yaml"}])
    top = rbi.load(write(tmp_path, "a.yaml", ("m", "kg"), [{"shape": "assembly", "file": "b.yaml"}]))
    assert {os.path.basename(f) for f in top.files_read} == {"a.yaml", "b.yaml", "c.yaml"}


def assembly_of(name: str) -> str:
    return json.dumps({"parts": [{"name": "sub", "shape": "assembly", "file": name}]})


def test_cycles_are_refused_naming_the_chain(tmp_path):
    (tmp_path / "self.yaml").write_text(assembly_of("self.yaml"))
    one_line_exit_2(
        run_rbi_inprocess("inertia", tmp_path / "self.yaml"), "parts[0] (sub)", "cycle", "self.yaml -> "
    )
    (tmp_path / "a.yaml").write_text(assembly_of("b.yaml"))
    (tmp_path / "b.yaml").write_text(assembly_of("c.yaml"))
    (tmp_path / "c.yaml").write_text(assembly_of("a.yaml"))
    proc = run_rbi_inprocess("inertia", tmp_path / "a.yaml")
    one_line_exit_2(proc, "cycle of sub-assemblies")
    assert proc.stderr.split("cycle of sub-assemblies: ")[1].strip().split(" -> ") == [
        str(tmp_path / n) for n in ("a.yaml", "b.yaml", "c.yaml", "a.yaml")
    ]


def test_a_chain_of_1000_files_is_refused_in_bounded_time(tmp_path):
    for i in range(1000):
        (tmp_path / f"f{i}.yaml").write_text(assembly_of(f"f{i + 1}.yaml"))
    started = time.process_time()
    one_line_exit_2(run_rbi_inprocess("inertia", tmp_path / "f0.yaml"), "nest deeper than 10 files")
    assert time.process_time() - started < 10


def test_files_outside_the_folder_fifos_and_bad_sub_specs(tmp_path):
    inside = tmp_path / "in"
    inside.mkdir()
    write(tmp_path, "out.yaml", ("m", "kg"), LEAF)
    (inside / "top.yaml").write_text(assembly_of("../out.yaml"))
    one_line_exit_2(
        run_rbi_inprocess("inertia", inside / "top.yaml"), "parts[0] (sub)", "file: ../out.yaml", "leaves"
    )
    assert run_rbi_inprocess("--allow-outside-paths", "inertia", inside / "top.yaml").returncode == 0
    os.mkfifo(inside / "pipe.yaml")
    (inside / "fifo.yaml").write_text(assembly_of("pipe.yaml"))
    one_line_exit_2(
        run_rbi_inprocess("inertia", inside / "fifo.yaml"), "file: pipe.yaml", "not a regular file"
    )
    (inside / "bad.yaml").write_text(
        "parts: [{name: disc, shape: cylinder, mass: 1, radius: -1, start: [0, 0, 0], end: [0, 0, 1]}]\n"
    )
    (inside / "uses_bad.yaml").write_text(assembly_of("bad.yaml"))
    proc = run_rbi_inprocess("inertia", inside / "uses_bad.yaml")
    one_line_exit_2(
        proc, "uses_bad.yaml: parts[0] (sub): file: bad.yaml: parts[0] (disc): radius: must be greater than 0"
    )
    (inside / "not_spec.yaml").write_text(assembly_of("missing.yaml"))
    one_line_exit_2(
        run_rbi_inprocess("inertia", inside / "not_spec.yaml"), "file: missing.yaml", "no such file"
    )


def test_a_wide_tree_of_sub_assemblies_reads_each_file_once(tmp_path):
    # 4 levels of 30 sub-assemblies each: 810,000 point masses, 5 files; a sub-assembly of one
    # point mass has no moments of its own, and that is not an underflow
    for i in range(4):
        parts = [{"shape": "assembly", "file": f"f{i + 1}.yaml", "position": [k, 0, 0]} for k in range(30)]
        (tmp_path / f"f{i}.yaml").write_text(json.dumps({"parts": parts}))
    (tmp_path / "f4.yaml").write_text("parts: [{shape: point, mass: 1, position: [0, 0, 0]}]\n")
    started = time.process_time()
    top = rbi.load(tmp_path / "f0.yaml")
    assert time.process_time() - started < 20
    assert top.mass == 30**4
    np.testing.assert_allclose(top.center_of_mass, [4 * 14.5, 0, 0], rtol=1e-14)


def test_a_sub_assemblys_warnings_are_the_bodys(tmp_path):
    # a steel ball of radius 10 in a file without units: 20 m of steel, lengths look like mm
    (tmp_path / "ball.yaml").write_text(
        "parts: [{name: ball, shape: sphere, radius: 10, density: steel, center: [0, 0, 0]}]\n"
    )
    (tmp_path / "top.yaml").write_text(assembly_of("ball.yaml"))
    warnings = rbi.load(tmp_path / "top.yaml").warnings
    assert len(warnings) == 1 and warnings[0].startswith(f"{tmp_path / 'ball.yaml'}: parts[0] (ball): ")
    assert "millimetres" in warnings[0]


def test_one_file_used_from_files_in_other_units_is_listed_in_each_ones(tmp_path):
    write(tmp_path, "leaf.yaml", ("m", "kg"), LEAF)
    leaf = {"name": "leaf", "shape": "assembly", "file": "leaf.yaml"}
    write(tmp_path, "mm.yaml", ("mm", "g"), [leaf])
    top = rbi.load(
        write(
            tmp_path, "top.yaml", ("cm", "kg"), [leaf, {"name": "mm", "shape": "assembly", "file": "mm.yaml"}]
        )
    )
    rows = expanded(top._loaded)
    assert rows.names == [
        "leaf/plate",
        "leaf/shaft",
        "leaf/bolt",
        "mm/leaf/plate",
        "mm/leaf/shaft",
        "mm/leaf/bolt",
    ]
    np.testing.assert_allclose(rows.elements.mass[:3], rows.elements.mass[3:], rtol=1e-14)
    np.testing.assert_allclose(rows.elements.center_of_mass[:3], rows.elements.center_of_mass[3:], rtol=1e-14)
    assert rows.elements.mass.sum() == pytest.approx(top.mass, rel=1e-14)
