"""rbi.formats.step: each solid of a STEP file written by OpenCascade integrated to 1e-9 of its
closed form (worked out by hand in tests/step_builders.py), in files written in metres and in
millimetres; names from the product tree; every refusal."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.formats.step import MAX_STEP_BYTES, read_step, select_solids, step_triangles  # noqa: E402
from tests.step_builders import (
    CLOSED_FORMS,
    box,
    faces_only,
    moved,
    open_box_solid,
    sphere,
    write_plain_step,
    write_step,
)

MM = 1e-3


def relative_errors(solid, closed) -> dict[str, float]:
    """Relative errors of a read solid (m) against a closed form (mm, unit density)."""
    volume = closed.volume * MM**3
    inertia = closed.inertia * MM**5
    size = np.sqrt(np.trace(closed.inertia) / closed.volume) * MM
    return {
        "volume": abs(solid.volume - volume) / volume,
        "com": float(np.linalg.norm(solid.props.center_of_mass - closed.com * MM)) / size,
        "inertia": float(np.max(np.abs(solid.props.inertia_about_com - inertia)))
        / float(np.max(np.abs(inertia))),
    }


@pytest.mark.parametrize("unit", ["m", "mm"])
@pytest.mark.parametrize("name", sorted(CLOSED_FORMS))
def test_closed_forms_to_1e_9_in_metres_and_millimetres(tmp_path, name, unit):
    closed = CLOSED_FORMS[name]()
    path = write_step(tmp_path / "part.step", closed.shape, unit)
    step = read_step(path)
    assert step.unit == unit
    assert len(step.solids) == 1
    errors = relative_errors(step.solids[0], closed)
    assert max(errors.values()) < 1e-9, errors
    assert 0.0 <= step.solids[0].integration_error < 1e-9


def test_the_error_estimate_sees_a_coarse_integration(monkeypatch, tmp_path):
    """With the check integration made coarse (Eps 1e-6), the reported estimate grows past
    1e-9: it measures the inertia, not only the volume."""
    import rbi.formats.step as step_module

    monkeypatch.setattr(step_module, "ADAPTIVE_EPS", 1e-6)
    monkeypatch.setattr(step_module, "_CACHE", type(step_module._CACHE)())
    path = write_step(tmp_path / "torus.step", CLOSED_FORMS["torus"]().shape, "mm")
    assert read_step(path).solids[0].integration_error > 1e-9


def test_assembly_names_order_and_placement(tmp_path):
    ball = sphere(5.0)
    path = write_step(
        tmp_path / "asm.step",
        [
            ("base: plate", box(10, 20, 30).shape),
            ("ball", moved(ball.shape, (100, 0, 0))),
            ("ball", moved(ball.shape, (-100, 0, 0))),
            (None, moved(sphere(4.0).shape, (0, 50, 0))),
        ],
        "mm",
        assembly="plate assembly",
    )
    step = read_step(path)
    assert [s.name for s in step.solids] == ["base: plate", "ball", "ball-2", "solid 3"]
    np.testing.assert_allclose(step.solids[1].props.center_of_mass, [0.1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(step.solids[2].props.center_of_mass, [-0.1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(step.solids[3].props.center_of_mass, [0, 0.05, 0], atol=1e-15)
    assert select_solids(step, None) == [0, 1, 2, 3]
    assert select_solids(step, "ball-2") == [2]
    assert select_solids(step, 3) == [3]
    with pytest.raises(ValueError, match=r"no solid named 'bal'.*'ball', 'ball-2'"):
        select_solids(step, "bal")
    with pytest.raises(ValueError, match="out of range: the file has 4 solids, 0 to 3"):
        select_solids(step, 4)


def test_triangles_for_the_picture_enclose_the_volume(tmp_path):
    """The tessellation is for pictures only, but it must be the solid: its enclosed volume is
    the sphere's to within the facets' sag, and it is in metres."""
    from rbi.core.mesh import mesh_distribution, weld_vertices

    path = write_step(tmp_path / "ball.step", sphere(10.0).shape, "mm")
    vertices, faces = step_triangles(path, [0], 0.001)
    assert len(faces) > 100
    volume = mesh_distribution(*weld_vertices(vertices, faces), "exact").unit.mass
    assert volume == pytest.approx(4 / 3 * np.pi * 0.01**3, rel=2e-2)


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda p: p.write_text("solid box\nendsolid box\n"), "not a STEP file"),
        (lambda p: p.write_text(""), "file is empty"),
        (lambda p: p.write_text("ISO-10303-21;\nHEADER;\nrubbish(\n"), "cannot be read as STEP|no shape"),
        (lambda p: write_plain_step(p, faces_only()), "holds no solid, only 6 shells"),
        (lambda p: write_plain_step(p, open_box_solid()), "holds no solid, only 1 shell .an open shell"),
    ],
    ids=["stl text", "empty", "damaged", "surfaces only", "open shell"],
)
def test_refusals(tmp_path, make, message):
    path = tmp_path / "bad.step"
    make(path)
    with pytest.raises(ValueError, match=message):
        read_step(path)


def test_a_huge_file_is_refused_before_parsing(tmp_path):
    path = tmp_path / "huge.step"
    with open(path, "wb") as stream:
        stream.write(b"ISO-10303-21;\n")
        stream.truncate(MAX_STEP_BYTES + 1)
    with pytest.raises(ValueError, match="too large"):
        read_step(path)


def test_an_open_solid_is_refused_naming_its_free_edges():
    """A solid whose shell misses a face (as a CAD tool can hand one over in memory)."""
    from rbi.formats.step import _check_closed, _ocp

    with pytest.raises(
        ValueError, match=r"solid 0 \(lid\) is open: 4 edges of its boundary belong to one face"
    ):
        _check_closed(_ocp(), open_box_solid(), 0, "lid")
    _check_closed(_ocp(), CLOSED_FORMS["tube"]().shape, 0, "tube")  # seams are not free edges
    _check_closed(_ocp(), CLOSED_FORMS["cone"]().shape, 0, "cone")  # nor is a degenerate apex
