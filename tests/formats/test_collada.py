"""Collada meshes: every triangle, double precision, node transforms, ``<unit meter>`` applied
and ``<up_axis>`` ignored (as RViz reads robot meshes); checked against closed forms and against
trimesh (pycollada) on example-robot-data's meshes."""

from __future__ import annotations

import glob
import json
import os

import numpy as np
import pytest

from rbi.core.mesh import mesh_distribution
from rbi.formats.collada import parse_collada
from rbi.formats.mesh_file import read_mesh_arrays
from tests.conftest import run_rbi_inprocess

CUBE_POSITIONS = "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1"
CUBE_QUADS = "0 3 2 1  4 5 6 7  0 1 5 4  1 2 6 5  2 3 7 6  3 0 4 7"  # outward, counter-clockwise


def cube_dae(unit: str = "1", up: str = "Z_UP", transform: str = "", primitive: str = "polylist") -> str:
    if primitive == "polylist":
        counts = "4 " * 6
        body = f'<polylist count="6"><input semantic="VERTEX" source="#v" offset="0"/><vcount>{counts}</vcount><p>{CUBE_QUADS}</p></polylist>'
    elif primitive == "triangles":
        quads = np.array(CUBE_QUADS.split(), int).reshape(6, 4)
        tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]).ravel()
        pairs = " ".join(f"{i} 0" for i in tris)
        body = f'<triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/><input semantic="NORMAL" source="#v" offset="1"/><p>{pairs}</p></triangles>'
    elif primitive == "tristrips":  # one strip per face, a b d c: its second triangle runs d b c
        quads = np.array(CUBE_QUADS.split(), int).reshape(6, 4)
        strips = "".join("<p>" + " ".join(map(str, q[[0, 1, 3, 2]])) + "</p>" for q in quads)
        body = f'<tristrips count="6"><input semantic="VERTEX" source="#v" offset="0"/>{strips}</tristrips>'
    else:  # one fan per face
        quads = np.array(CUBE_QUADS.split(), int).reshape(6, 4)
        fans = "".join("<p>" + " ".join(map(str, q)) + "</p>" for q in quads)
        body = f'<trifans count="6"><input semantic="VERTEX" source="#v" offset="0"/>{fans}</trifans>'
    return f"""<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="u" meter="{unit}"/><up_axis>{up}</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="24">{CUBE_POSITIONS}</float_array>
      <technique_common><accessor source="#pa" count="8" stride="3"/></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    {body}
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n">{transform}<instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>"""


@pytest.mark.parametrize("primitive", ["polylist", "triangles", "trifans", "tristrips"])
def test_cube_every_primitive(primitive):
    vertices, faces = parse_collada(cube_dae(primitive=primitive).encode())
    assert faces.shape == (12, 3)
    found = mesh_distribution(vertices, faces, "exact")
    assert found.unit.mass == pytest.approx(1.0, rel=1e-15)
    np.testing.assert_allclose(found.unit.center_of_mass, [0.5, 0.5, 0.5], rtol=1e-15)


def test_unit_applied_up_axis_ignored_and_node_transforms_composed():
    transform = "<translate>10 0 0</translate><rotate>0 0 1 90</rotate><scale>2 3 4</scale>"
    for up in ("Z_UP", "Y_UP", "X_UP"):
        vertices, faces = parse_collada(cube_dae("0.001", up, transform).encode())
        found = mesh_distribution(vertices, faces, "exact")
        # a 2 x 3 x 4 box (mm), turned 90 deg about z, moved 10 mm along x
        assert found.unit.mass == pytest.approx(24e-9, rel=1e-14)
        np.testing.assert_allclose(
            found.unit.center_of_mass, [0.010 - 0.0015, 0.001, 0.002], rtol=1e-14, atol=1e-18
        )
        # turned 90 deg about z: the 3 mm edge lies along x
        a, b, c = 0.003, 0.002, 0.004
        np.testing.assert_allclose(
            np.diag(found.unit.inertia_about_com),
            24e-9 / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b]),
            rtol=1e-12,
        )


def test_double_precision_is_kept():
    exact = "0.1234567890123456789"
    text = cube_dae().replace(CUBE_POSITIONS, CUBE_POSITIONS.replace("0 0 0", f"{exact} 0 0", 1))
    vertices, _ = parse_collada(text.encode())
    assert float(exact) in vertices[:, 0]


def test_matrix_node_and_instance_node():
    text = cube_dae(transform="<matrix>1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1</matrix>")
    vertices, faces = parse_collada(text.encode())
    np.testing.assert_allclose(
        mesh_distribution(vertices, faces, "exact").unit.center_of_mass, [5.5, 6.5, 7.5]
    )


@pytest.mark.parametrize(
    "change, words",
    [
        (("#g", "#missing"), "no element with that id"),
        (("<vcount>", "<vcount>4 "), "vcount"),
        (("0 3 2 1", "0 3 2 99"), "out of range"),
        (('meter="1"', 'meter="-1"'), "meter"),
    ],
)
def test_malformed_documents_are_value_errors(change, words):
    with pytest.raises(ValueError, match=words):
        parse_collada(cube_dae().replace(*change).encode())


def test_entities_are_refused():
    text = '<?xml version="1.0"?><!DOCTYPE c [<!ENTITY e "x">]><COLLADA>&e;</COLLADA>'
    with pytest.raises(ValueError, match="entities"):
        parse_collada(text.encode())


def _robot_meshes(limit: int):
    base = None
    try:
        import example_robot_data  # noqa: F401
    except ImportError:
        pass
    for entry in __import__("site").getsitepackages():
        candidate = os.path.join(entry, "cmeel.prefix", "share", "example-robot-data", "robots")
        if os.path.isdir(candidate):
            base = candidate
    if base is None:
        return []
    files = sorted(glob.glob(os.path.join(base, "**", "*.dae"), recursive=True))
    return files[:: max(1, len(files) // limit)][:limit]


@pytest.mark.parametrize("path", _robot_meshes(6), ids=os.path.basename)
def test_agrees_with_trimesh_on_example_robot_data(path):
    """trimesh (through pycollada) reads float32: its triangles agree to 1e-6 of the mesh's size."""
    trimesh = pytest.importorskip("trimesh")
    pytest.importorskip("collada")
    theirs = trimesh.load(path, force="mesh", process=False)
    vertices, faces = parse_collada(open(path, "rb").read())
    ours = np.sort(vertices[faces].mean(axis=1), axis=0)
    other = np.sort(np.asarray(theirs.vertices)[np.asarray(theirs.faces)].mean(axis=1), axis=0)
    assert ours.shape == other.shape
    assert np.max(np.abs(ours - other)) <= 1e-6 * np.max(np.abs(vertices))


def test_audit_a_urdf_with_a_collada_mesh_in_every_output_form(tmp_path):
    (tmp_path / "box.dae").write_text(cube_dae("0.1", "Y_UP", "<scale>2 1 0.5</scale>"))
    (tmp_path / "r.urdf").write_text(
        '<robot name="r"><link name="a"><inertial><mass value="2"/>'
        '<inertia ixx="0.0020833333333333333" iyy="0.007083333333333333" izz="0.008333333333333333" ixy="0" ixz="0" iyz="0"/>'
        '</inertial><collision><origin xyz="-0.1 -0.05 -0.025"/><geometry><mesh filename="box.dae"/></geometry></collision></link></robot>'
    )
    vertices, faces = read_mesh_arrays(__import__("pathlib").Path(tmp_path / "box.dae"))
    assert len(faces) == 12
    proc = run_rbi_inprocess("audit", str(tmp_path / "r.urdf"), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    link = json.loads(proc.stdout)["links"][0]
    assert link["geometry"]["volume"] == pytest.approx(0.001, rel=1e-13)
    np.testing.assert_allclose(link["moment_ratios"], [1, 1, 1], rtol=1e-12)
    for form in ("csv", "table"):
        assert run_rbi_inprocess("audit", str(tmp_path / "r.urdf"), "--format", form).returncode == 0
