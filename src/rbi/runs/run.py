"""One simulation run of a loaded body, from its settings to its summary: the settings checked
(before any work), the run prepared (scene, initial state, step budget), integrated by the
compiled kernel (or the method asked for) and summarised as ``rbi simulate --format json``
prints it.

The path of a run: :func:`rbi.simulate` → :func:`prepare_run` → :meth:`PreparedRun.simulate`
→ :func:`rbi.sim.api.simulate` (the kernel). Errors name the settings as the Python API spells
them (:class:`~rbi.errors.ArgumentError`); a spec that cannot be simulated is an
:class:`~rbi.errors.InputError` naming the spec.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields, replace
from typing import Any, Self

import numpy as np

from rbi.core.rotation import angle_is_kept, turn_lost_to_rounding, unit_vector
from rbi.core.spin_axis import default_spin_axis
from rbi.core.validity import finite, require_flags, whole
from rbi.errors import ArgumentError, InputError, literal
from rbi.runs.values import require_numbers, vector_value
from rbi.sim.api import SimulationError, check_duration, check_method, check_rtol, check_samples, simulate
from rbi.sim.budget import DEFAULT_MAX_STEPS, estimated_steps
from rbi.sim.diagnostics import tilt_deg
from rbi.sim.scene import Scene, initial_state, scene_from_properties
from rbi.sim.summary import CSV_COLUMNS, columns_of, sample_columns, summarize
from rbi.sim.summary import error_estimate as estimate
from rbi.spec.units import STANDARD_GRAVITY_SI, gravity_in
from rbi.text import csv_cell

SCENE_NAMES = {True: "heavy top on a fixed pivot", False: "free body (torque-free about the centre of mass)"}

Progress = Callable[[float], None]


def check_run_settings(settings: Any) -> None:
    """Refuse the settings that `simulate`, `animate` and `sweep` all take (``settings``: a
    :class:`RunSettings` or a :class:`~rbi.sweeps.study.SweepSettings`): duration (s, >= 0),
    tilt axis (world x or y), gravity (m/s², >= 0, or None for 9.81), step budget (1 to 2**63 - 1,
    or None) and tolerance (in :data:`rbi.sim.api.RTOL_RANGE`, or None for the method's own)."""

    tilt_axis, gravity, max_steps = settings.tilt_axis, settings.gravity, settings.max_steps
    require_numbers(duration=settings.duration, gravity=gravity, rtol=settings.rtol)
    require_numbers(integral=True, max_steps=max_steps)
    require_flags(check_budget=settings.check_budget, error_estimate=settings.error_estimate)
    check_duration(settings.duration)
    if not isinstance(tilt_axis, str) or tilt_axis.lower() not in ("x", "y"):
        raise ArgumentError("tilt_axis", f"must be x or y (got {literal(tilt_axis)})")
    if gravity is not None and not (finite(gravity) and gravity >= 0.0):
        raise ArgumentError("gravity", f"must be a finite number of m/s² >= 0 (got {literal(gravity)})")
    if max_steps is not None and not (whole(max_steps) and 1 <= max_steps < 2**63):  # the kernel's int64
        raise ArgumentError("max_steps", f"must be at least 1 and below 2**63 (got {literal(max_steps)})")
    check_rtol(settings.rtol)


def check_tilt(tilt_deg: float) -> None:
    """Refuse a finite tilt (deg) too large to be a turn (rounding loses it): the one check of
    a run's tilt, for `simulate` and `animate` and for every value of a sweep's tilt axis."""
    if not angle_is_kept(tilt_deg):
        raise ArgumentError("tilt_deg", turn_lost_to_rounding(literal(tilt_deg)))


def spin_axis_value(value: str | Sequence[float] | None) -> list[float] | None:
    """A spin axis as the API takes it: ``"x"``, ``"y"``, ``"z"`` (optionally signed, ``"-y"``)
    or three numbers (any length, not zero), made a unit vector; None stays None (the spec's or
    the default axis)."""
    if value is None:
        return None
    if isinstance(value, str):
        named = {"x": [1.0, 0.0, 0.0], "y": [0.0, 1.0, 0.0], "z": [0.0, 0.0, 1.0]}
        text = value.strip().lower()
        sign = -1.0 if text.startswith("-") else 1.0
        if text.lstrip("+-") not in named:
            raise ArgumentError(
                "spin_axis", f"must be x, y, z or a direction (3 numbers) in body axes (got {literal(value)})"
            )
        return [sign * c + 0.0 for c in named[text.lstrip("+-")]]
    vector = vector_value(value, "spin_axis")
    if not any(vector):
        raise ArgumentError(
            "spin_axis", "must not be zero [0, 0, 0]: give a direction in body axes, e.g. y or (0, 1, 0)"
        )

    return unit_vector(vector).tolist()


def body_spin_axis(body: Any, given: str | Sequence[float] | None = None) -> np.ndarray:
    """The spin axis of a loaded body (unit, body frame): ``given`` (see :func:`spin_axis_value`),
    else the spec's ``spin_axis:``, else :func:`rbi.core.spin_axis.default_spin_axis` of the
    inertia about the pivot (about the centre of mass of a free body)."""

    axis = spin_axis_value(given)
    if axis is not None:
        return np.array(axis)
    if body.spin_axis is not None:
        return unit_vector(body.spin_axis)
    fixed_point = Scene(body.props, 0.0, body.pivot)  # the inertia about it, before any check
    return default_spin_axis(fixed_point.inertia, fixed_point.com_from_pivot)


def scene_of(body: Any, gravity_si: float | None, spin_axis: str | Sequence[float] | None = None) -> Any:
    """The :class:`~rbi.sim.scene.Scene` of a loaded body: a heavy top on its pivot (a spec with
    ``pivot``) or a free body, under gravity ``gravity_si`` m/s² (None: standard gravity),
    converted to the spec's length unit, spinning about :func:`body_spin_axis`.
    :class:`InputError` when the body cannot be simulated (no mass, a singular inertia)."""

    g_si = STANDARD_GRAVITY_SI if gravity_si is None else float(gravity_si)
    axis = body_spin_axis(body, spin_axis)
    try:
        return scene_from_properties(body.props, body.pivot, gravity_in(body.length_unit, g_si), axis)
    except ValueError as exc:
        where = "pivot: " if body.pivot is not None else ""
        raise InputError(f"{body.path}: {where}cannot simulate: {exc}") from None


@dataclass(frozen=True)
class RunSettings:
    """The settings of one run, declared once: what :func:`rbi.simulate` takes (and
    :func:`rbi.animate`, and each run of a sweep), passed down whole to :func:`prepare_run`.

    spin (rad/s about the spin axis) or omega (the initial angular velocity, body frame, rad/s;
    its direction is the spin axis unless ``spin_axis`` is given); tilt_deg, tilt_axis: the
    nudge at t = 0 about the world ``"x"`` or ``"y"`` axis; gravity: m/s² (None: 9.81);
    duration (s), samples; method, rtol (None: the method's own); max_steps (None: rbi's
    budget), check_budget: refuse a run estimated past it; spin_axis: ``"x"``, ``"-y"`` ... or
    a direction; error_estimate: estimate the error by a tighter second run.
    """

    spin: float | None = None
    omega: Sequence[float] | None = None
    tilt_deg: float = 0.0
    tilt_axis: str = "y"
    gravity: float | None = None
    duration: float = 4.0
    samples: int = 481
    method: str = "default"
    rtol: float | None = None
    max_steps: int | None = None
    check_budget: bool = True
    spin_axis: str | Sequence[float] | None = None
    error_estimate: bool = True

    @classmethod
    def of(cls, values: dict[str, Any]) -> Self:
        """The settings among ``values`` (a function's keywords by name: ``locals()``)."""
        return cls(**{f.name: values[f.name] for f in fields(cls) if f.name in values})

    def checked(self) -> RunSettings:
        """These settings checked (:class:`ArgumentError` naming the parameter, TypeError for
        what is no number), the tilt axis in lower case and omega as three floats."""
        samples = check_samples(self.samples)
        check_method(self.method)
        require_numbers(spin=self.spin, tilt_deg=self.tilt_deg)
        if self.spin is not None and self.omega is not None:
            raise ArgumentError(("spin", "omega"), "give one or the other, not both")
        if self.spin is not None and not finite(self.spin):
            raise ArgumentError("spin", f"must be a finite number (got {literal(self.spin)})")
        if not finite(self.tilt_deg):
            raise ArgumentError("tilt_deg", f"must be a finite number (got {literal(self.tilt_deg)})")
        check_tilt(self.tilt_deg)
        check_run_settings(self)
        omega = None if self.omega is None else vector_value(self.omega, "omega")
        return replace(self, omega=omega, samples=samples, tilt_axis=self.tilt_axis.lower())


OPTIONAL_FIGURES = ("angle_to_h_deg", "input_uncertainty")
"""The summary's keys that are left out of its JSON when they do not apply."""


@dataclass(frozen=True, kw_only=True)
class RunSummary:
    """What a run reports, typed: the fields of ``rbi simulate --format json`` in its order
    (:meth:`to_dict`). Numbers in the spec's units; angles in degrees where the name says so.

    name, units, warnings: the body's. scene: a heavy top or a free body; pivot (None for a free
    body), gravity (length/s²). duration (s), samples. initial ``{t, q, omega, tilt_deg,
    nudge_deg}``, final ``{t, q, omega, tilt_deg}``; spin_axis (unit, body frame). method,
    integrator, rtol, steps, rejected_steps, rhs_evals, wall_seconds, load_seconds: the cost.
    tilt_min_deg, tilt_max_deg, mean_precession_rate_deg_s (and _rad_s; None while the axis
    stood vertical). angle_to_h_deg ``{min, max, final}``: a free body's spin axis to its
    angular momentum (None for a top). conserved (each ``{initial, drift, unit}``),
    max_relative_drift, quaternion_norm_error, stability ``{kind, verdict, ...}``, closed_form
    (or None), error_estimate (or None), input_uncertainty (the spread ``--draws`` gives, or None).
    """

    name: str | None
    units: dict[str, str]
    warnings: list[str]
    scene: str
    pivot: np.ndarray | None
    gravity: float
    duration: float
    samples: int
    initial: dict[str, Any]
    spin_axis: np.ndarray
    final: dict[str, Any]
    method: str
    integrator: str
    rtol: float | None
    steps: int
    rejected_steps: int
    rhs_evals: int
    wall_seconds: float
    load_seconds: float
    tilt_min_deg: float
    tilt_max_deg: float
    mean_precession_rate_deg_s: float | None
    mean_precession_rate_rad_s: float | None
    angle_to_h_deg: dict[str, float | None] | None = None
    conserved: dict[str, dict[str, Any]]
    max_relative_drift: float
    quaternion_norm_error: float
    stability: dict[str, Any]
    closed_form: dict[str, Any] | None
    error_estimate: dict[str, Any] | None
    input_uncertainty: dict[str, Any] | None = None

    def to_dict(self) -> dict[str, Any]:
        """The fields by name, in order (numpy arrays as they are; a top has no
        ``angle_to_h_deg``, a run without ``--draws`` no ``input_uncertainty``)."""
        out = {f.name: getattr(self, f.name) for f in fields(self)}
        return {k: v for k, v in out.items() if v is not None or k not in OPTIONAL_FIGURES}


@dataclass(frozen=True)
class SimulationRun:
    """A finished run (spec units): ``t``, ``q`` ([w, x, y, z], body → world), ``omega`` (body
    frame, rad/s), ``tilt_deg``, ``precession_deg``, ``energy``: the samples, the CSV's columns
    (:meth:`columns`); ``summary`` (:class:`RunSummary`), the ``settings`` it was run with and
    ``dense``: the same integration sampled for a plot (as :meth:`columns`), when asked."""

    t: np.ndarray
    q: np.ndarray
    omega: np.ndarray
    tilt_deg: np.ndarray
    precession_deg: np.ndarray
    energy: np.ndarray
    summary: RunSummary | None = None
    settings: RunSettings | None = field(default=None, compare=False)
    """The settings it was run with (None for a trajectory made by hand)."""
    dense: dict[str, np.ndarray] | None = field(default=None, compare=False)
    """The same integration sampled more densely for a plot, as columns."""

    def columns(self) -> dict[str, np.ndarray]:
        """The CSV's columns by name (``t``, ``qw`` … ``energy``), each (N,)."""
        return columns_of(self.t, self.q, self.omega, self.tilt_deg, self.precession_deg, self.energy)

    def to_csv(self) -> str:
        """The trajectory as the CSV ``rbi simulate --out`` writes (columns t, qw, qx, qy, qz, wx,
        wy, wz, tilt_deg, precession_deg, energy; full precision)."""
        return trajectory_csv(self.columns())


@dataclass(frozen=True)
class PreparedRun:
    """Everything a run needs, checked.

    body: the :class:`~rbi.spec.load.LoadedBody` (spec units). settings: :class:`RunSettings`,
    checked. scene: the :class:`~rbi.sim.scene.Scene` (pivot or free body, gravity in the
    spec's length unit/s²). q0: initial orientation [w, x, y, z], body → world (the nudge
    applied: the tilt is then the angle of the scene's spin axis from the vertical). omega0:
    initial angular velocity, body frame, rad/s. budget: most integration steps.
    """

    body: Any
    settings: RunSettings
    scene: Any
    q0: np.ndarray
    omega0: np.ndarray
    budget: int

    @property
    def omega_given(self) -> bool:
        """The run was given a non-zero ω (not a spin about the axis)."""
        return any(self.settings.omega or ())

    def integrate(self, samples: int, progress: Progress | None = None, dense: int = 0) -> Any:
        """The trajectory (:class:`rbi.sim.api.Trajectory`) at ``samples`` equally spaced times
        (and ``dense`` more, see :func:`rbi.sim.api.simulate`), from the kernel;
        :class:`InputError` (naming the spec) when the integration fails."""

        settings = self.settings
        try:
            return simulate(
                self.scene,
                self.q0,
                self.omega0,
                settings.duration,
                samples,
                method=settings.method,
                rtol=settings.rtol,
                progress=progress,
                max_steps=self.budget,
                dense=dense,
            )
        except SimulationError as exc:
            raise InputError(f"{self.body.path}: {exc}") from None

    def simulate(self, progress: Progress | None = None, dense: int = 0) -> SimulationRun:
        """Integrate at the settings' samples (and ``dense`` more for a plot, in the same
        integration), summarise and (unless the settings say no or the method is the closed
        form) estimate the error by a tighter second run. A trajectory that overflowed is
        refused with :class:`InputError` (absurd spin or inertia)."""

        settings = self.settings
        trajectory = self.integrate(settings.samples, progress, dense)
        try:
            figures = summarize(self.scene, trajectory, self.q0, self.omega0)
            figures["error_estimate"] = (
                estimate(self.scene, trajectory, self.q0, self.omega0, max_steps=self.budget)
                if settings.error_estimate and settings.method != "exact"
                else None
            )
        except SimulationError as exc:
            raise InputError(f"{self.body.path}: {exc}") from None
        columns = sample_columns(self.scene, trajectory)
        refuse_non_finite(self.body.path, columns)
        fine = None if trajectory.dense is None else sample_columns(self.scene, trajectory.dense)
        summary = RunSummary(**self._head(trajectory), **figures)
        tilt, precession, energy = (columns[name] for name in ("tilt_deg", "precession_deg", "energy"))
        return SimulationRun(
            trajectory.t, trajectory.q, trajectory.omega, tilt, precession, energy, summary, settings, fine
        )

    def _head(self, trajectory: Any) -> dict[str, Any]:
        """The summary's first entries: the body, the scene and the initial state."""

        body, scene = self.body, self.scene
        return {
            "name": body.name,
            "units": body.units,
            "warnings": list(body.warnings),
            "scene": SCENE_NAMES[bool(scene.pivoted)],
            "pivot": scene.pivot,
            "gravity": scene.gravity,
            "duration": float(self.settings.duration),
            "samples": int(trajectory.t.size),
            "initial": {
                "t": 0.0,
                "q": self.q0,
                "omega": self.omega0,
                "tilt_deg": float(tilt_deg(self.q0, scene.spin_frame)[0]),
                "nudge_deg": float(self.settings.tilt_deg),
            },
        }


def prepare_run(body: Any, settings: RunSettings) -> PreparedRun:
    """Check the ``settings`` (:meth:`RunSettings.checked`) and set up the run of a loaded
    ``body``. A run estimated to need more integration steps than the budget (``max_steps``,
    default :data:`rbi.sim.budget.DEFAULT_MAX_STEPS`) is refused with :class:`ArgumentError`
    when ``check_budget``. An ω without a spin axis given turns about its own direction (the
    contract's rule); a spin turns about :func:`body_spin_axis`."""

    settings = settings.checked()
    given = settings.omega
    axis = settings.spin_axis if settings.spin_axis is not None or not any(given or ()) else given
    scene = scene_of(body, settings.gravity, axis)
    w0 = given if given is not None else [float(settings.spin or 0.0) * float(c) for c in scene.spin_axis]
    q0, omega0 = initial_state(settings.tilt_deg, w0, settings.tilt_axis)
    budget = DEFAULT_MAX_STEPS if settings.max_steps is None else int(settings.max_steps)
    if settings.method != "exact" and settings.check_budget:
        needed = estimated_steps(scene, omega0, settings.duration, settings.method, settings.rtol)
        if needed > budget:
            raise ArgumentError(
                (),
                f"{body.path}: this run is estimated to need about {needed:.2g} integration steps, more than "
                f"the budget of {budget:.2g}: shorten {{duration}}, lower the spin, loosen {{rtol}}, or raise "
                "the budget with {max_steps} (or {check_budget=False} to try anyway)",
            )
    return PreparedRun(body, settings, scene, q0, omega0, budget)


def refuse_non_finite(path: str, columns: dict[str, np.ndarray]) -> None:
    """A trajectory that overflowed is bad input (absurd spin or inertia), never written out."""
    for name, values in columns.items():
        if name != "precession_deg" and not np.all(np.isfinite(values)):
            raise InputError(
                f"{path}: the trajectory's {name} is not finite: the input values are too large "
                "for double precision"
            )


def trajectory_csv(columns: dict[str, np.ndarray]) -> str:
    """The CSV `rbi simulate --out` writes: a header of :data:`rbi.sim.summary.CSV_COLUMNS`,
    then one line a sample, each number through the one CSV cell rule (:func:`rbi.text.csv_cell`:
    full precision, its shortest round-tripping ``repr``; an undefined value, NaN, as an empty
    cell), ``-0.0`` written as ``0.0`` as in the CLI's other CSV and JSON
    (:func:`rbi.cli.render.plain`). Lines are joined here rather than by :func:`rbi.text.csv_lines`
    (no number needs quoting): its csv.writer took 1.4 times as long for 200,000 samples."""

    table = np.column_stack([np.asarray(columns[name], dtype=float) for name in CSV_COLUMNS])
    lines = [",".join(CSV_COLUMNS)]
    lines.extend(",".join(map(csv_cell, row)) for row in table.tolist())
    return "\n".join(lines) + "\n"
