"""A sweep summarises the runs of one scene together (summary.tilt_figures and
diagnostics.energy_drifts on the stack of runs, as sweeps.runs does): the same numbers, bit for
bit, as summarising each run alone the way rbi simulate does."""

from __future__ import annotations

import numpy as np
import pytest

from rbi.core.mass import MassProperties
from rbi.sim import diagnostics
from rbi.sim.api import simulate
from rbi.sim.scene import initial_state, scene_from_properties
from rbi.sim.summary import summarize, tilt_figures


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
    starts = [
        initial_state(tilt, [0.3 * k, 0.0, spin])
        for k, (spin, tilt) in enumerate([(150, 0.0), (208, 0.01), (260, 1.0), (180, 20.0)])
    ]
    runs = [simulate(scene, q0, w0, 1.0, 121) for q0, w0 in starts]
    q = np.array([r.q for r in runs])
    omega = np.array([r.omega for r in runs])
    drifts = diagnostics.energy_drifts(scene, q, omega)[1]
    batch = tilt_figures(runs[0].t, q, scene.spin_frame)
    batch = [row | {"energy_drift": drift} for row, drift in zip(batch, drifts)]
    for run, (q0, w0), got in zip(runs, starts, batch):
        # the per-run figures are rbi simulate's own
        full = summarize(scene, run, q0, w0)
        assert got["energy_drift"] == full["conserved"]["energy"]["drift"]
        assert got["max_tilt_deg"] == full["tilt_max_deg"]
        assert got["min_tilt_deg"] == full["tilt_min_deg"]
        assert got["final_tilt_deg"] == full["final"]["tilt_deg"]
        assert got["precession_rate_deg_s"] == full["mean_precession_rate_deg_s"]
        # and the tilt is the angle of the spin axis from the vertical, sample by sample
        assert got["max_tilt_deg"] == float(np.max(diagnostics.tilt_deg(run.q, scene.spin_frame)))
        precession = diagnostics.precession_deg(run.q, scene.spin_frame)
        if not np.isnan(precession).any():
            rate = (precession[-1] - precession[0]) / (run.t[-1] - run.t[0])
            assert got["precession_rate_deg_s"] == pytest.approx(rate, rel=1e-12, abs=1e-12)
    # an upright start without a transverse spin stays upright: no precession rate is claimed
    assert batch[0]["precession_rate_deg_s"] is None
    assert batch[2]["max_tilt_deg"] >= 1.0 - 1e-9
