"""rbi bench's cad section: the 200-hole plate read as STEP is exact to 1e-9 of its closed form
(worked out here again, independently of the bench's own), its STL tessellation is not; both
rows reach the report's table and Markdown (that check reads the quick run's cad section: in
test_bench_command.py, which makes the run)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("OCP")


def test_plate_closed_form_by_a_second_route():
    """The bench's closed form against one summed hole by hole in another way: the plate as the
    box's moments about its centre minus each hole's, all taken about the origin first."""
    from rbi.bench import cad

    volume, com, inertia = cad.closed_form()
    a, b, c = cad.PLATE_MM
    r = cad.HOLE_RADIUS_MM
    holes = cad.hole_centres()
    assert len(holes) == 200
    v_hole = math.pi * r * r * c
    assert volume == pytest.approx(a * b * c - 200 * v_hole, rel=1e-15)
    assert com[0] == pytest.approx(-v_hole * 200 * cad.GRID_OFFSET_MM[0] / volume, rel=1e-12)
    # Izz about the origin: box a b c (a² + b²)/12 − Σ holes (r²/2 + x² + y²) v_hole
    izz_origin = a * b * c * (a * a + b * b) / 12 - v_hole * np.sum(
        r * r / 2 + holes[:, 0] ** 2 + holes[:, 1] ** 2
    )
    assert inertia[2, 2] == pytest.approx(izz_origin - volume * (com[0] ** 2 + com[1] ** 2), rel=1e-13)
