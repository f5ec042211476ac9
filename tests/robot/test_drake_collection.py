"""The robot files the ``drake`` wheel ships (its examples: 8 SDFormat files, 14 URDFs), audited in
every output form and set against Drake's own parser: whole-robot mass, centre of mass and inertia
about it equal ``MultibodyPlant.CalcSpatialInertia`` over all bodies, expressed in rbi's root link.

Drake is a third independent reader of SDFormat beside pybullet and gym-ignition-models' files: it
applies SDFormat's defaults (1 kg and a unit inertia for a link with no ``<inertial>``) itself."""

from __future__ import annotations

import glob
import json
import os

import numpy as np
import pytest

from tests.conftest import run_rbi_inprocess
from tests.robot.test_output_forms import _three_forms

pydrake = pytest.importorskip("pydrake")

SHARE = os.path.join(os.path.dirname(pydrake.__file__), "share", "drake")
FILES = sorted(
    glob.glob(SHARE + "/**/*.sdf", recursive=True) + glob.glob(SHARE + "/**/*.urdf", recursive=True)
)
REFUSED = {  # urdfdom, pybullet and Pinocchio refuse it too; Drake alone reads 'world' as its world body
    "Acrobot.urdf": "parent: no link named 'world'",
}
WORLD_LINK = {"Pendulum.urdf"}  # a <link name="world">: Drake drops it (the world), rbi counts its 0.01 kg


def _drake_totals(path: str, root: str) -> tuple[float, np.ndarray, np.ndarray]:
    """Drake's (mass kg, CoM m, inertia about the CoM kg·m²) of every body, in the root body's frame."""
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import MultibodyPlant
    from pydrake.multibody.tree import BodyIndex

    plant = MultibodyPlant(0.0)
    Parser(plant).AddModels(path)
    plant.Finalize()
    context = plant.CreateDefaultContext()
    bodies = [BodyIndex(i) for i in range(1, plant.num_bodies())]
    frame = plant.GetBodyByName(root).body_frame()
    spatial = plant.CalcSpatialInertia(context, frame, bodies)
    com = np.asarray(spatial.get_com())
    inertia = spatial.Shift(com).CalcRotationalInertia().CopyToFullMatrix3()
    return float(spatial.get_mass()), com, np.asarray(inertia)


def test_the_wheel_ships_sdf_and_urdf_files():
    names = [os.path.basename(path) for path in FILES]
    assert sum(name.endswith(".sdf") for name in names) >= 8
    assert sum(name.endswith(".urdf") for name in names) >= 14


@pytest.mark.parametrize("path", FILES, ids=lambda path: os.path.relpath(path, SHARE))
def test_every_drake_file_in_every_form_and_against_drake(path):
    name = os.path.basename(path)
    if name in REFUSED:
        for form in ("table", "json", "csv"):
            proc = run_rbi_inprocess("audit", path, "--format", form)
            assert proc.returncode == 2 and REFUSED[name] in proc.stderr, proc.stderr
            assert len(proc.stderr.strip().splitlines()) == 1 and proc.stdout == ""
        return
    links = _three_forms(path)
    proc = run_rbi_inprocess("audit", path, "--format", "json")
    total = json.loads(proc.stdout)["total"]
    assert len(json.loads(proc.stdout)["links"]) == links
    if name in WORLD_LINK:
        return
    mass, com, inertia = _drake_totals(path, total["frame"].removeprefix("root link "))
    assert total["mass"] == pytest.approx(mass, rel=1e-12)
    assert np.allclose(total["center_of_mass"], com, rtol=0, atol=1e-12 * max(1.0, np.abs(com).max()))
    scale = np.abs(inertia).max()
    assert np.allclose(total["inertia_about_com"], inertia, rtol=0, atol=1e-12 * scale)
