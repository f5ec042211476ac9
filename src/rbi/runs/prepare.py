"""A run prepared from a loaded body: the scene, the initial state and the step budget."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbi.errors import InputError
from rbi.runs.values import vector_value


@dataclass(frozen=True)
class PreparedRun:
    """Everything a run needs, checked.

    body: the :class:`~rbi.spec.translate.LoadedBody` (spec units). scene: the
    :class:`~rbi.sim.scene.Scene` (pivot or free body, gravity in the spec's length unit/s²).
    q0: initial orientation [w, x, y, z], body → world. omega0: initial angular velocity, body
    frame, rad/s. tilt_deg, tilt_axis: the nudge, the body's turn at t=0 about a world axis
    (the tilt is then the angle of the scene's spin axis from the vertical). duration (s),
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


def scene_of(body, gravity_si: float | None, spin_axis=None):
    """The scene of a loaded body: a heavy top on its pivot (a spec with ``pivot``) or a free
    body, under gravity ``gravity_si`` m/s² (None: standard gravity), converted to the spec's
    length unit, spinning about :func:`body_spin_axis` (``spin_axis``: a ``--spin-axis``
    value, or None). :class:`InputError` when the body cannot be simulated (no mass, a singular
    inertia)."""
    from rbi.sim.scene import scene_from_properties
    from rbi.spec.units import STANDARD_GRAVITY_SI, gravity_in

    g_si = STANDARD_GRAVITY_SI if gravity_si is None else float(gravity_si)
    axis = body_spin_axis(body, spin_axis)
    try:
        return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit, g_si), axis)
    except ValueError as exc:
        where = "pivot: " if body.pivot is not None else ""
        raise InputError(f"{body.path}: {where}cannot simulate: {exc}") from None


def body_spin_axis(body, given=None) -> np.ndarray:
    """The spin axis of a loaded body (unit, body frame): ``given`` (a ``--spin-axis`` value, see
    :func:`spin_axis_value`), else the spec's ``spin_axis:``, else
    :func:`rbi.core.spin_axis.default_spin_axis` of the inertia about the pivot (about the
    centre of mass of a free body)."""
    from rbi.core.rotation import unit_vector
    from rbi.core.spin_axis import default_spin_axis

    axis = spin_axis_value(given)
    if axis is not None:
        return np.array(axis)
    if body.spin_axis is not None:
        return unit_vector(body.spin_axis)
    fixed = np.asarray(body.props.center_of_mass if body.pivot is None else body.pivot, dtype=float)
    return default_spin_axis(
        body.props.inertia_about(fixed), np.asarray(body.props.center_of_mass, dtype=float) - fixed
    )


def initial_omega(spin, omega, spin_axis=(0.0, 0.0, 1.0)) -> list[float]:
    """The initial angular velocity (body frame, rad/s): ``omega`` (text ``"WX,WY,WZ"`` or three
    numbers) when given, else ``spin`` about the unit ``spin_axis`` (body frame), else rest."""
    if omega is not None:
        return vector_value(omega, "--omega")
    if spin is None:
        return [0.0, 0.0, 0.0]
    return [float(spin) * float(c) for c in spin_axis]


def spin_axis_value(value) -> list[float] | None:
    """A spin axis as given on the command line or to the API: ``x``, ``y``, ``z`` (optionally
    signed, ``-y``), ``"X,Y,Z"`` or three numbers (any length, not zero); None stays None (the
    spec's or the default axis)."""
    if value is None:
        return None
    if isinstance(value, str):
        named = {"x": [1.0, 0.0, 0.0], "y": [0.0, 1.0, 0.0], "z": [0.0, 0.0, 1.0]}
        text = value.strip().lower()
        sign = -1.0 if text.startswith("-") else 1.0
        if text.lstrip("+-") in named:
            return [sign * c + 0.0 for c in named[text.lstrip("+-")]]
        if "," not in text:
            raise InputError(
                f"--spin-axis: must be x, y, z or a direction X,Y,Z in body axes (got {value!r})"
            )
    vector = vector_value(value, "--spin-axis")
    if not any(vector):
        raise InputError(
            "--spin-axis: must not be zero [0, 0, 0]: give a direction in body axes, e.g. 0,1,0 or y"
        )
    from rbi.core.rotation import unit_vector

    return unit_vector(vector).tolist()


def prepare_run(
    body,
    *,
    spin=None,
    omega=None,
    tilt=0.0,
    tilt_axis="y",
    gravity=None,
    duration=4.0,
    method="default",
    rtol=None,
    max_steps=None,
    yes=False,
    spin_axis=None,
) -> PreparedRun:
    """Set up the run of a loaded ``body`` whose settings passed
    :func:`rbi.runs.settings.check_run_options`. A run estimated to need more integration steps
    than the budget (``max_steps``, default :data:`rbi.sim.budget.DEFAULT_MAX_STEPS`) is
    refused with :class:`InputError` unless ``yes``. ``spin_axis``: see :func:`scene_of` (a
    ``--spin-axis`` value: name or direction)."""
    from rbi.sim.budget import DEFAULT_MAX_STEPS, estimated_steps
    from rbi.sim.scene import initial_state

    scene = scene_of(body, gravity, spin_axis)
    w0 = initial_omega(spin, omega, scene.spin_axis)
    q0, omega0 = initial_state(tilt, w0, tilt_axis.lower())
    budget = DEFAULT_MAX_STEPS if max_steps is None else int(max_steps)
    if method != "exact":
        needed = estimated_steps(scene, omega0, duration, method, rtol)
        if needed > budget and not yes:
            raise InputError(
                f"{body.path}: this run is estimated to need about {needed:.2g} integration steps, more than the "
                f"budget of {budget:.2g}: shorten --duration, lower the spin, loosen --rtol, or raise the budget "
                f"with --max-steps N (or --yes to try anyway)"
            )
    return PreparedRun(
        body=body,
        scene=scene,
        q0=q0,
        omega0=omega0,
        tilt_deg=float(tilt),
        tilt_axis=tilt_axis.lower(),
        duration=float(duration),
        method=method,
        rtol=rtol,
        budget=budget,
    )
