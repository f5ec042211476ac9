"""A run prepared from a loaded body: the scene, the initial state and the step budget."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbi.errors import InputError
from rbi.runs.values import vector_value


@dataclass(frozen=True)
class PreparedRun:
    """Everything a run needs, checked.

    body: the :class:`~rbi.spec.load.LoadedBody` (spec units). scene: the
    :class:`~rbi.sim.scene.Scene` (pivot or free body, gravity in the spec's length unit/s²).
    q0: initial orientation [w, x, y, z], body → world. omega0: initial angular velocity, body
    frame, rad/s. tilt_deg, tilt_axis: the initial turn about a world axis. duration (s),
    method, rtol (None: the method's own), budget: most integration steps.
    """

    body: object
    scene: object
    q0: np.ndarray
    omega0: np.ndarray
    tilt_deg: float
    tilt_axis: str
    duration: float
    method: str
    rtol: float | None
    budget: int


def scene_of(body, gravity_si: float | None):
    """The scene of a loaded body: a heavy top on its pivot (a spec with ``pivot``) or a free
    body, under gravity ``gravity_si`` m/s² (None: standard gravity), converted to the spec's
    length unit. :class:`InputError` when the body cannot be simulated (no mass, a singular
    inertia)."""
    from rbi.sim.scene import scene_from_properties
    from rbi.spec.units import STANDARD_GRAVITY_SI, gravity_in

    g_si = STANDARD_GRAVITY_SI if gravity_si is None else float(gravity_si)
    try:
        return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit, g_si))
    except ValueError as exc:
        where = "pivot: " if body.pivot is not None else ""
        raise InputError(f"{body.path}: {where}cannot simulate: {exc}") from None


def initial_omega(spin, omega) -> list[float]:
    """The initial angular velocity (body frame, rad/s): ``omega`` (text ``"WX,WY,WZ"`` or three
    numbers) when given, else ``spin`` about the body z axis, else rest."""
    if omega is not None:
        return vector_value(omega, "--omega")
    return [0.0, 0.0, 0.0 if spin is None else float(spin)]


def prepare_run(body, *, spin=None, omega=None, tilt=0.0, tilt_axis="y", gravity=None, duration=4.0,
                method="default", rtol=None, max_steps=None, yes=False) -> PreparedRun:
    """Set up the run of a loaded ``body`` whose settings passed
    :func:`rbi.runs.settings.check_run_options`. A run estimated to need more integration steps
    than the budget (``max_steps``, default :data:`rbi.sim.budget.DEFAULT_MAX_STEPS`) is
    refused with :class:`InputError` unless ``yes``."""
    from rbi.sim.budget import DEFAULT_MAX_STEPS, estimated_steps
    from rbi.sim.scene import initial_state

    w0 = initial_omega(spin, omega)
    scene = scene_of(body, gravity)
    q0, omega0 = initial_state(tilt, w0, tilt_axis.lower())
    budget = DEFAULT_MAX_STEPS if max_steps is None else int(max_steps)
    if method != "exact":
        needed = estimated_steps(scene, omega0, duration, method, rtol)
        if needed > budget and not yes:
            raise InputError(
                f"{body.path}: this run is estimated to need about {needed:.2g} integration steps, more than the "
                f"budget of {budget:.2g}: shorten --duration, lower the spin, loosen --rtol, or raise the budget "
                f"with --max-steps N (or --yes to try anyway)")
    return PreparedRun(body=body, scene=scene, q0=q0, omega0=omega0, tilt_deg=float(tilt),
                       tilt_axis=tilt_axis.lower(), duration=float(duration), method=method, rtol=rtol, budget=budget)
