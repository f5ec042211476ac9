"""OpenCascade is loaded only for a spec with a STEP part (tests/test_startup.py's probe)."""

from __future__ import annotations

from tests.step_builders import box, write_step
from tests.test_startup import BODIES, _any, loaded


def test_inertia_of_a_spec_without_step_parts_does_not_import_ocp():
    modules, status, out = loaded("inertia", BODIES / "top.yaml", "--format", "json")
    assert status in (0, None) and "0.5" in out
    assert not _any(modules, "OCP")
    assert not _any(modules, "rbi.formats.step")


def test_a_spec_with_a_step_part_imports_it(tmp_path):
    write_step(tmp_path / "box.step", box().shape, "mm")
    spec = tmp_path / "body.yaml"
    spec.write_text("units: {length: mm}\nparts:\n  - {shape: step, file: box.step, mass: 1}\n")
    modules, status, out = loaded("inertia", spec, "--format", "json")
    assert status in (0, None), out
    # the file is read by a child process (issue 38: a damaged file crashed OpenCascade and rbi
    # with it): rbi's own process loads the reader, OpenCascade is loaded in the child only
    assert _any(modules, "rbi.formats.step")
    assert not _any(modules, "OCP")
