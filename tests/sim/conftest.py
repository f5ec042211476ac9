"""Scenes used across the simulation tests."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.core.rotation import axis_angle_matrix
from rbi.sim.scene import scene_from_properties
from rbi.spec.load import load_body
from rbi.spec.units import gravity_in
from tests.conftest import BODIES


def body_scene(name: str):
    body = load_body(BODIES / name)
    return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit))


@pytest.fixture(scope="session")
def top_scene():
    """The seed chapter's axisymmetric top (Lagrange top)."""
    return body_scene("top.yaml")


@pytest.fixture(scope="session")
def bolted_scene():
    return body_scene("top_bolted.yaml")


@pytest.fixture(scope="session")
def free_scene():
    """A free body with principal moments 1, 2, 3 along axes turned away from the body axes."""
    R = axis_angle_matrix(np.array([1.0, 2.0, 3.0]), 0.7)
    return scene_from_properties(
        MassProperties(2.0, np.zeros(3), R @ np.diag([1.0, 2.0, 3.0]) @ R.T), None, 9.81
    )
