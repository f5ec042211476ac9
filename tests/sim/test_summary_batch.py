"""A sweep summarises the runs of one scene together (summary.sweep_figures_batch): the same
numbers, bit for bit, as summarising each run alone the way rbi simulate does."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.sim.api import simulate
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.sim.summary import motion_figures, sweep_figures, sweep_figures_batch


def _top_scene(pivoted: bool):

    props = MassProperties(
        mass=0.5,
        center_of_mass=np.array([0.0, 0.0, 0.05]),
        inertia_about_com=np.diag([2.6e-4, 2.6e-4, 1.95e-4]),
    )
    return scene_from_properties(props, np.zeros(3) if pivoted else None, 9.80665)


@pytest.mark.parametrize("pivoted", [True, False])
def test_batch_equals_one_by_one(pivoted):
    scene = _top_scene(pivoted)
    runs = [
        simulate(scene, *initial_state(tilt, [0.3 * k, 0.0, spin]), 1.0, 121)
        for k, (spin, tilt) in enumerate([(150, 0.0), (208, 0.01), (260, 1.0), (180, 20.0)])
    ]
    q = np.array([r.q for r in runs])
    omega = np.array([r.omega for r in runs])
    batch = sweep_figures_batch(scene, runs[0].t, q, omega)
    for run, got in zip(runs, batch):
        assert got == sweep_figures(scene, run.t, run.q, run.omega)
        # and the per-run figures are rbi simulate's own
        full = motion_figures(scene, run.t, run.q, run.omega)
        assert got["energy_drift"] == full["conserved"]["energy"]["drift"]
        assert got["max_tilt_deg"] == full["max_tilt_deg"]
    # an upright start without a transverse spin stays upright: no precession rate is claimed
    assert batch[0]["precession_rate_deg_s"] is None
    assert batch[2]["max_tilt_deg"] >= 1.0 - 1e-9
