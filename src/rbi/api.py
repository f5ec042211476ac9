"""The public Python API of rbi: load a body, ask for its mass properties, simulate its motion.

```python
import rbi

body = rbi.load("bodies/top_bolted.yaml")
body.mass                      # kg (the spec's mass unit)
body.principal().moments       # ascending, kg·m² (the spec's units)
run = rbi.simulate(body, spin=200.0, tilt_deg=0.01, duration=2.0)
run.t, run.q, run.omega        # numpy arrays: s; [w, x, y, z] body → world; body frame rad/s
```

Every number is in the spec's own units (``body.units``) unless a name says otherwise: lengths in
``units["length"]``, masses in ``units["mass"]``, inertias in mass·length². Points and vectors are
in the body frame (the spec's coordinates) unless a name says ``world``. Bad input of any kind
raises `SpecError`, whose ``str()`` is the one line the CLI prints for the same mistake.
"""

from __future__ import annotations

import numbers
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rbi.errors import SpecError

if TYPE_CHECKING:
    from rbi.robot.audit import AuditReport

__all__ = [
    "load",
    "Body",
    "Principal",
    "Part",
    "Momentum",
    "simulate",
    "Trajectory",
    "sweep",
    "audit",
    "AuditReport",
    "SpecError",
]

Point = Any
"""A reference point: ``"com"``, ``"origin"``, ``"pivot"``, or (x, y, z) in body coordinates
(spec length unit); text ``"x,y,z"`` is accepted too."""


def load(source: str | os.PathLike | dict, *, allow_outside_paths: bool = False) -> Body:
    """Read, validate and translate a body spec.

    Args:
        source: a path to a spec file (``str`` or ``os.PathLike``; ``"-"`` reads standard
            input, named ``<stdin>`` in messages); YAML or JSON text (a ``str`` holding a
            newline, named ``<string>``); or a ``dict`` shaped like the YAML spec (named
            ``<dict>``). Files the spec names (meshes, point clouds) are looked for beside the
            spec file, or in the current folder for text and dicts.
        allow_outside_paths: let the spec name files outside its own folder (the CLI's
            ``--allow-outside-paths``).

    Returns:
        The `Body`.

    Raises:
        SpecError: the file is missing or unreadable, the YAML is malformed, or the spec is
            invalid; ``str(error)`` is ``file: part: field: what is wrong``.
    """
    from rbi.formats.paths import outside_paths_allowed

    try:
        with outside_paths_allowed(allow_outside_paths):
            loaded, raw = _load(source)
    except SpecError as exc:
        label = _label(source)
        if exc.file is None and label is not None and str(exc).startswith(label + ": "):
            exc.file = label
        raise
    return Body(loaded, raw)


def _label(source) -> str | None:
    """How messages name ``source``."""
    if isinstance(source, dict):
        return "<dict>"
    if isinstance(source, str):
        return "<stdin>" if source == "-" else "<string>" if "\n" in source else source
    if isinstance(source, os.PathLike):
        return os.fsdecode(os.fspath(source))
    return None


def load_file(path: str) -> Body:
    """The body of the spec file at ``path`` (never read as text, whatever it holds); ``-``
    reads one spec from standard input (named ``<stdin>``), as the CLI's FILE ``-``."""
    from rbi.spec import load as spec_load

    raw = spec_load.read_yaml(path)  # "-" reads standard input
    return Body(spec_load.body_from_raw(raw, spec_load.spec_label(path)), raw)


def _load(source):
    from rbi.spec import load as spec_load

    if isinstance(source, dict):
        spec_load.refuse_lone_surrogates(source, "<dict>")
        return spec_load.body_from_raw(source, "<dict>"), source
    if isinstance(source, str) and ("\n" in source or source == "-"):
        if source == "-":
            label, text = spec_load.STDIN_LABEL, spec_load.read_stdin_text()
        else:
            label, text = "<string>", spec_load.check_spec_text(source, "<string>")
        raw = spec_load.parse_spec_text(text, label)
        return spec_load.body_from_raw(raw, label), raw
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if isinstance(path, bytes):
            path = os.fsdecode(path)
        raw = spec_load.read_yaml(path)
        return spec_load.body_from_raw(raw, path), raw
    raise SpecError(f"rbi.load: expected a path, spec text or a dict (got {type(source).__name__})")


@dataclass(frozen=True)
class Principal:
    """Principal moments and axes about a point.

    Attributes:
        moments: (3,) ascending, mass·length² (spec units).
        axes: (3, 3) unit vectors in the body frame, one per **row** (``axes[i]`` belongs to
            ``moments[i]``), right-handed — as ``rbi principal`` prints them.
        radii_of_gyration: (3,) ``sqrt(moment / mass)``, length unit.
        about: (3,) the reference point, body frame, length unit.
    """

    moments: np.ndarray
    axes: np.ndarray
    radii_of_gyration: np.ndarray
    about: np.ndarray


@dataclass(frozen=True)
class Part:
    """One part of a body, in file order (spec units, body frame).

    Attributes:
        name: the part's ``name`` (``parts[i]`` when it has none).
        shape: the part's shape (``cylinder``, ``mesh`` ... or ``point_cloud``).
        hole: True for a part removed from the body (``subtract: true``).
        mass: the part's mass (negative for a hole).
        center_of_mass: (3,) the part's centre of mass.
        inertia_about_com: (3, 3) the part's inertia about its own centre of mass, body axes.
        volume: the solid's volume (length³), or None when it has none (points, custom parts).
    """

    name: str
    shape: str
    hole: bool
    mass: float
    center_of_mass: np.ndarray
    inertia_about_com: np.ndarray
    volume: float | None


@dataclass(frozen=True)
class Momentum:
    """Angular momentum and kinetic energy of the body at one instant (spec units, body axes).

    Attributes:
        omega: (3,) angular velocity, rad/s.
        about: (3,) the reference point.
        com_velocity: (3,) velocity of the centre of mass, length/s.
        angular_momentum: (3,) about ``about``, mass·length²/s.
        angle_deg: angle between the angular momentum and ω, degrees (None when either is zero).
        kinetic_energy: mass·length²/s².
    """

    omega: np.ndarray
    about: np.ndarray
    com_velocity: np.ndarray
    angular_momentum: np.ndarray
    angle_deg: float | None
    kinetic_energy: float


class Body:
    """A validated rigid body, as `load` returns it (not constructed directly).

    All numbers are in the spec's own units (`units`) and the body frame (the spec's
    coordinates). A Body does not change; every method returns new arrays.
    """

    def __init__(self, loaded, raw=None) -> None:
        self._loaded = loaded
        self._raw = raw
        self.warnings: list[str] = list(loaded.warnings)
        """Warnings about the spec (units that look wrong for a spec without ``units:``: one
        line naming the part and the ``units:`` that would fit), the lines the CLI prints on
        stderr and puts in JSON as ``"warnings"``."""

    @property
    def path(self) -> str:
        """Where the spec came from: its path, or ``<stdin>``, ``<string>``, ``<dict>``."""
        return self._loaded.path

    @property
    def name(self) -> str | None:
        """The spec's ``name``, or None."""
        return self._loaded.name

    @property
    def units(self) -> dict[str, str]:
        """The spec's units: ``{"length": ..., "mass": ...}``, e.g. ``{"length": "m", "mass": "kg"}``."""
        return dict(self._loaded.units)

    @property
    def mass(self) -> float:
        """Total mass (holes subtracted), mass unit."""
        return float(self._loaded.props.mass)

    @property
    def center_of_mass(self) -> np.ndarray:
        """(3,) centre of mass, body frame, length unit."""
        return np.array(self._loaded.props.center_of_mass, dtype=float)

    @property
    def pivot(self) -> np.ndarray | None:
        """(3,) the fixed point of a top, body frame, length unit; None for a free body."""
        return None if self._loaded.pivot is None else np.array(self._loaded.pivot, dtype=float)

    @property
    def spin_axis(self) -> np.ndarray:
        """(3,) unit vector, body frame: the axis `simulate`'s ``spin`` turns about and whose
        tilt and precession it reports, unless told otherwise — the spec's ``spin_axis``, else
        the body's symmetry axis (exactly two equal principal moments about the pivot, or about
        the centre of mass of a free body), pointing from the pivot towards the centre of mass
        (or with its largest component positive), else body z."""
        from rbi.runs.prepare import body_spin_axis

        return body_spin_axis(self._loaded)

    def point(self, about: Point = "com") -> np.ndarray:
        """The reference point ``about`` as (3,) body coordinates, length unit.

        ``"com"``: the centre of mass; ``"origin"``: (0, 0, 0); ``"pivot"``: the spec's pivot
        (`SpecError` when there is none); or a point (x, y, z)."""
        if isinstance(about, str):
            key = about.strip().lower()
            if key == "com":
                return self.center_of_mass
            if key == "origin":
                return np.zeros(3)
            if key == "pivot":
                if self._loaded.pivot is None:
                    raise SpecError(
                        f"{self.path}: pivot: --about pivot needs a `pivot` in the spec, and there is none",
                        file=self.path,
                        field="pivot",
                    )
                return self.pivot
        from rbi.runs.values import vector_value

        try:
            return np.array(vector_value(about, "--about"))
        except SpecError:
            raise SpecError(
                f"--about: expected com, origin, pivot or a point X,Y,Z (three numbers separated by "
                f"commas, file units), got {about!r}",
                field="about",
            ) from None

    def inertia(
        self, about: Point = "com", axes: Sequence[tuple[str, float]] | np.ndarray | None = None
    ) -> np.ndarray:
        """The (3, 3) inertia matrix about a point, mass·length² (tensor sign: ``I_xy = -∫xy dm``).

        Args:
            about: the reference point (see `point`): ``"com"`` (default), ``"origin"``,
                ``"pivot"`` or (x, y, z) in body coordinates.
            axes: None for body axes; or turns of the body about world axes, applied in
                order, as the CLI's ``--rotate`` — a list of ``("x"|"y"|"z", degrees)``;
                or a (3, 3) rotation matrix R, body → world. The matrix is then given in
                world axes: ``R I Rᵀ``.
        """
        from rbi.core.inertia import re_express

        matrix = self._loaded.props.inertia_about(self.point(about))
        if axes is None:
            return matrix
        return re_express(matrix, _rotation(axes))

    def principal(self, about: Point = "com") -> Principal:
        """Principal moments (ascending) and axes (rows, body frame, right-handed) about a point
        (default the centre of mass), as ``rbi principal`` prints them."""
        from rbi.core.inertia import principal_axes, radii_of_gyration

        point = self.point(about)
        moments, axes = principal_axes(self._loaded.props.inertia_about(point))
        # + 0.0: no -0.0 components (the CLI prints 0 there too)
        return Principal(
            moments=np.asarray(moments) + 0.0,
            axes=np.asarray(axes) + 0.0,
            radii_of_gyration=np.asarray(radii_of_gyration(moments, self.mass)),
            about=point,
        )

    def parts(self) -> list[Part]:
        """Each part's mass properties, in file order (see `Part`)."""
        from rbi.spec.volumes import part_volume

        loaded = self._loaded
        spec_parts = list(loaded.spec.parts) if loaded.spec is not None else []
        out = []
        for i, element in enumerate(loaded.elements):
            part = spec_parts[i] if i < len(spec_parts) else None
            out.append(
                Part(
                    name=loaded.part_names[i] or f"parts[{i}]",
                    shape=part.shape if part is not None else "point_cloud",
                    hole=bool(getattr(part, "subtract", False)),
                    mass=float(element.mass),
                    center_of_mass=np.array(element.center_of_mass, dtype=float),
                    inertia_about_com=np.array(element.inertia_about_com, dtype=float),
                    volume=None if part is None else part_volume(part),
                )
            )
        return out

    def momentum(
        self,
        omega: Sequence[float] | str,
        about: Point = "com",
        velocity: Sequence[float] | str | None = None,
    ) -> Momentum:
        """Angular momentum about a point and kinetic energy, for angular velocity ``omega``
        (body axes, rad/s).

        Args:
            omega: (3,) angular velocity, rad/s, body axes.
            about: the reference point (see `point`).
            velocity: (3,) velocity of the centre of mass, length/s, body axes. None: the
                ``about`` point is fixed and the body turns about it (``v = ω × r``).
        """
        from rbi.core.dynamics import angle_between_deg, angular_momentum_about_point, kinetic_energy
        from rbi.runs.values import vector_value

        w = np.array(vector_value(omega, "--omega"))
        point = self.point(about)
        props = self._loaded.props
        com_from_point = props.center_of_mass - point
        v_com = (
            np.cross(w, com_from_point)
            if velocity is None
            else np.array(vector_value(velocity, "--velocity"))
        )
        h = angular_momentum_about_point(props.inertia_about_com, props.mass, com_from_point, w, v_com)
        return Momentum(
            omega=w,
            about=point,
            com_velocity=v_com,
            angular_momentum=np.asarray(h),
            angle_deg=angle_between_deg(h, w),
            kinetic_energy=float(kinetic_energy(props.inertia_about_com, w, props.mass, v_com)),
        )

    def __repr__(self) -> str:
        units = self.units
        return (
            f"<rbi.Body {self.name or self.path!r}: mass {self.mass:.6g} {units['mass']}, "
            f"{len(self._loaded.elements)} parts, {'pivot' if self._loaded.pivot is not None else 'free'}>"
        )

    def _summary_rows(self) -> list[tuple[str, str, str]]:
        units = self.units
        inertia_unit = f"{units['mass']}·{units['length']}²"
        principal = self.principal()
        rows = [
            ("mass", units["mass"], f"{self.mass:.8g}"),
            ("centre of mass", units["length"], _vector_text(self.center_of_mass)),
        ]
        if self._loaded.pivot is not None:
            rows.append(("pivot", units["length"], _vector_text(self.pivot)))
        rows.append(("principal moments about CoM", inertia_unit, _vector_text(principal.moments)))
        for i, axis in enumerate(principal.axes, start=1):
            rows.append((f"principal axis {i}", "", _vector_text(axis)))
        rows.append(("parts", "", str(len(self._loaded.elements))))
        return rows

    def __rich__(self):
        return _rich_table(f"{self.name or self.path}", self._summary_rows())

    def _repr_html_(self) -> str:
        return _html_table(f"{self.name or self.path}", self._summary_rows())


def _rotation(axes) -> np.ndarray:
    """A body → world rotation matrix from ``axes`` (see `Body.inertia`)."""
    from rbi.core.rotation import angle_is_kept, compose_world_rotations

    array = np.asarray(axes, dtype=object)
    if array.shape == (3, 3):
        R = np.asarray(axes, dtype=float)
        if not (
            np.all(np.isfinite(R)) and np.allclose(R @ R.T, np.eye(3), atol=1e-9) and np.linalg.det(R) > 0
        ):
            raise SpecError(
                "axes: a 3x3 matrix must be a rotation (orthonormal, determinant +1)", field="axes"
            )
        return R
    turns = []
    for turn in axes:
        try:
            axis, degrees = turn
            axis, degrees = str(axis).strip().lower(), float(degrees)
        except (TypeError, ValueError):
            axis, degrees = "", float("nan")
        if axis not in ("x", "y", "z") or not np.isfinite(degrees):
            raise SpecError(
                f"--rotate: expected AXIS:DEG with AXIS one of x, y, z (e.g. y:30), got {turn!r}",
                field="axes",
            )
        if not angle_is_kept(degrees):
            raise SpecError(
                f"axes: {degrees!r} degrees is too large to be a turn: rounding loses it", field="axes"
            )
        turns.append((axis, np.radians(degrees)))
    return compose_world_rotations(turns)


@dataclass(frozen=True, repr=False)
class Trajectory:
    """A simulated motion, sampled at equally spaced times (spec units).

    Attributes:
        t: (N,) time, s.
        q: (N, 4) unit quaternions [w, x, y, z] (scalar first), body → world.
        omega: (N, 3) angular velocity in the body frame, rad/s.
        tilt_deg: (N,) angle of the spin axis (body z unless ``spin_axis`` says otherwise) from
            the upward vertical, degrees.
        precession_deg: (N,) azimuth of that axis seen from above, degrees (unwrapped; NaN
            while the axis stands vertical).
        energy: (N,) total energy (kinetic + potential), mass·length²/s².
        summary: what ``rbi simulate --format json`` prints for the run (initial state, final
            state, tilt bounds, conserved quantities and their drift, error estimate, cost,
            stability), as plain values and numpy arrays.
    """

    t: np.ndarray
    q: np.ndarray
    omega: np.ndarray
    tilt_deg: np.ndarray
    precession_deg: np.ndarray
    energy: np.ndarray
    summary: dict = field(default_factory=dict)

    def to_csv(self) -> str:
        """The trajectory as the CSV ``rbi simulate --out`` writes (columns t, qw, qx, qy, qz, wx,
        wy, wz, tilt_deg, precession_deg, energy; full precision)."""
        from rbi.runs.simulation import trajectory_csv

        return trajectory_csv(self.columns())

    def columns(self) -> dict[str, np.ndarray]:
        """The CSV's columns by name (``t``, ``qw`` … ``energy``), each (N,)."""
        q, w = self.q, self.omega
        return {
            "t": self.t,
            "qw": q[:, 0],
            "qx": q[:, 1],
            "qy": q[:, 2],
            "qz": q[:, 3],
            "wx": w[:, 0],
            "wy": w[:, 1],
            "wz": w[:, 2],
            "tilt_deg": self.tilt_deg,
            "precession_deg": self.precession_deg,
            "energy": self.energy,
        }

    def __repr__(self) -> str:
        return (
            f"<rbi.Trajectory {self.t.size} samples over {float(self.t[-1]):g} s, "
            f"{self.summary.get('method', '')}>"
        )

    def _summary_rows(self) -> list[tuple[str, str, str]]:
        s = self.summary
        final = s.get("final", {})
        rows = [
            ("scene", "", str(s.get("scene", ""))),
            ("method", "", str(s.get("method", ""))),
            ("duration, samples", "s", f"{float(self.t[-1]):g}, {self.t.size}"),
            ("final q [w, x, y, z]", "", _vector_text(self.q[-1])),
            ("final ω (body axes)", "rad/s", _vector_text(self.omega[-1])),
            (f"final tilt of {_axis_name(s.get('spin_axis'))}", "deg", f"{float(self.tilt_deg[-1]):.6g}"),
            ("tilt min … max", "deg", f"{np.min(self.tilt_deg):.6g} … {np.max(self.tilt_deg):.6g}"),
        ]
        if final and "energy" in s.get("conserved", {}):
            rows.append(("energy drift", "", f"{s['conserved']['energy']['drift']:.2g}"))
        return rows

    def __rich__(self):
        return _rich_table(f"{self.summary.get('name') or 'trajectory'} — simulate", self._summary_rows())

    def _repr_html_(self) -> str:
        return _html_table(f"{self.summary.get('name') or 'trajectory'} — simulate", self._summary_rows())


def simulate(
    body: Body,
    *,
    spin: float | None = None,
    omega: Sequence[float] | None = None,
    tilt_deg: float = 0.0,
    tilt_axis: str = "y",
    duration: float = 4.0,
    samples: int = 481,
    gravity: float | None = None,
    method: str = "default",
    rtol: float | None = None,
    max_steps: int | None = None,
    error_estimate: bool = True,
    check_budget: bool = True,
    progress: Callable[[float], None] | None = None,
    spin_axis: str | Sequence[float] | None = None,
) -> Trajectory:
    """Simulate the body: a heavy top on its pivot (a spec with ``pivot``) or a torque-free body
    about its centre of mass — the run ``rbi simulate`` makes with the same settings.

    Args:
        body: the `Body`.
        spin: initial spin about the spin axis, rad/s (ω = spin × the unit spin axis).
        omega: initial angular velocity (3,), body axes, rad/s (instead of ``spin``).
        tilt_deg: the nudge: the body is turned at t = 0 by this angle (degrees) about the
            world axis ``tilt_axis`` (``"x"`` or ``"y"``). The tilt the trajectory reports is
            the angle of the spin axis from the upward vertical.
        duration: simulated time, s.
        samples: samples, equally spaced from t = 0 to ``duration`` (1: only the end).
        gravity: gravity's magnitude in m/s² (SI whatever the spec's units); 0 switches it
            off; None is 9.81.
        method: ``"default"`` (compiled adaptive DOP853), ``"rk45"``, ``"dop853"`` (scipy) or
            ``"exact"`` (closed forms, where they apply).
        rtol: integrator tolerance (None: 1e-12 for default, 1e-8 for the scipy methods).
        max_steps: most integration steps (None: rbi's default budget).
        error_estimate: estimate the error with a second run 1000× tighter.
        check_budget: refuse a run estimated to exceed ``max_steps`` before it starts (the
            budget stops it in any case).
        progress: called now and then with the fraction done (0…1).
        spin_axis: the body-frame axis of ``spin`` and of the reported tilt and precession:
            ``"x"``, ``"y"``, ``"z"`` or a direction (3,); None for the spec's ``spin_axis``,
            else `Body.spin_axis`'s default (the symmetry axis, else z).

    Returns:
        The `Trajectory`.

    Raises:
        SpecError: a setting is out of range (named as the CLI's option, e.g.
            ``--duration: ...``), or the run cannot be made (no mass, too many steps,
            overflow).
    """
    from rbi.runs.prepare import prepare_run
    from rbi.runs.settings import check_run_options, check_samples
    from rbi.runs.simulation import simulate_run

    if not isinstance(body, Body):
        raise SpecError(f"rbi.simulate: expected a Body from rbi.load (got {type(body).__name__})")
    _numbers_only("rbi.simulate", spin=spin, tilt_deg=tilt_deg, duration=duration, gravity=gravity, rtol=rtol)
    _numbers_only("rbi.simulate", integral=True, samples=samples, max_steps=max_steps)
    check_run_options(method, spin, omega, tilt_deg, duration, tilt_axis, gravity, max_steps, rtol)
    check_samples(samples)
    prepared = prepare_run(
        body._loaded,
        spin=spin,
        omega=omega,
        tilt=tilt_deg,
        tilt_axis=tilt_axis,
        gravity=gravity,
        duration=duration,
        method=method,
        rtol=rtol,
        max_steps=max_steps,
        yes=not check_budget,
        spin_axis=spin_axis,
    )
    run = simulate_run(prepared, samples, error_estimate=error_estimate, progress=progress)
    columns = run.columns
    return Trajectory(
        t=columns["t"],
        q=run.trajectory.q,
        omega=run.trajectory.omega,
        tilt_deg=columns["tilt_deg"],
        precession_deg=columns["precession_deg"],
        energy=columns["energy"],
        summary=run.summary,
    )


def _numbers_only(function: str, integral: bool = False, **values) -> None:
    """TypeError naming the parameter when one of ``values`` (None allowed) is not a number
    (``spin=True``, ``duration="4"``); with ``integral``, not a whole number."""
    kind = numbers.Integral if integral else numbers.Real
    for name, value in values.items():
        if value is not None and (isinstance(value, bool) or not isinstance(value, kind)):
            what = "a whole number" if integral else "a number"
            raise TypeError(f"{function}: {name} must be {what} (got {type(value).__name__} {value!r})")


def _axis_name(axis) -> str:
    """``body y`` for a coordinate axis of the body frame, else ``the spin axis [x, y, z]``."""
    if axis is None:
        return "the spin axis"
    axis = np.asarray(axis, dtype=float)
    for index, name in enumerate("xyz"):
        if axis[index] == 1.0:
            return f"body {name}"
    return f"the spin axis {_vector_text(axis)}"


def _spin_axis_text(axis) -> str | None:
    """A spin axis as `sweep`'s settings spell it: a name, or ``"X,Y,Z"``."""
    if axis is None or isinstance(axis, str):
        return axis
    return ",".join(repr(float(c)) for c in axis)


def sweep(
    body: Body,
    *,
    spin: float | str | Sequence[float] | None = None,
    tilt: float | str | Sequence[float] | None = None,
    vary: dict[str, Any] | Sequence[str] | None = None,
    runs: int = 1,
    seed: int = 0,
    duration: float = 4.0,
    samples: int = 481,
    rtol: float = 1e-12,
    gravity: float | None = None,
    tilt_axis: str = "y",
    max_steps: int | None = None,
    workers: int | None = None,
    mass_properties: bool = False,
    check_budget: bool = True,
    spin_axis: str | Sequence[float] | None = None,
) -> list[dict]:
    """Many simulations of one body — a grid over spin, tilt and numbers of the spec, or Monte
    Carlo draws — as ``rbi sweep`` runs them (on every core). One failed run never stops the
    others: its row says why in ``status``.

    Args:
        body: the `Body` (its spec is varied; files it names are read beside its path).
        spin: initial spin about the spin axis, rad/s: one value, ``(start, stop, count)`` or
            the text ``"START:STOP:COUNT"``; None for 0.
        tilt: initial tilt, degrees, given the same way; None for 0.
        vary: numbers of the spec to vary: ``{"parts.bolt.mass": (0.01, 0.03, 5)}`` (a grid),
            ``{"parts.bolt.position[0]": "normal(0.04, 0.001)"}`` or ``"uniform(LOW,HIGH)"``
            (draws, with ``runs``); or a list of ``"PATH=RANGE"`` texts as ``--vary`` takes.
        runs: Monte Carlo draws of every ``normal``/``uniform`` variation per grid point.
        seed: seed of the draws (same seed, same rows).
        duration, samples, rtol, gravity, tilt_axis, max_steps, spin_axis: as `simulate`
            (per run; one spin axis for every run, the nominal body's unless given).
        workers: cores to use (None: all).
        mass_properties: simulate nothing; each row gives the mass properties (mass, centre of
            mass, principal moments, principal-axis tilts) at the varied values.
        check_budget: refuse a sweep estimated to exceed rbi's step budget (about four hours
            of one core) before it starts.

    Returns:
        One dict per run, in run order: ``run``, the swept values (``spin``, ``tilt_deg``, each
        varied path) and the results — ``max_tilt_deg``, ``final_tilt_deg``, ``min_tilt_deg``,
        ``precession_rate_deg_s``, ``energy_drift``, ``steps``, ``status`` (``"ok"`` or why the
        run failed); with ``mass_properties``, ``mass``, ``com_*``, ``moment_*`` and
        ``axis_*_tilt_deg`` instead.

    Raises:
        SpecError: a setting or a variation is invalid (named as the CLI's option), or the
            sweep has more than 100,000 runs (``rbi sweep --out`` streams larger ones to a file).
    """
    from rbi.sweep.study import Study, SweepSettings, check_mass_properties, check_settings

    if not isinstance(body, Body):
        raise SpecError(f"rbi.sweep: expected a Body from rbi.load (got {type(body).__name__})")
    settings = SweepSettings(
        spin=_range_text(spin, "--spin"),
        tilt=_range_text(tilt, "--tilt"),
        vary=_vary_texts(vary),
        runs=runs,
        seed=seed,
        duration=duration,
        samples=samples,
        rtol=rtol,
        gravity=gravity,
        tilt_axis=tilt_axis,
        max_steps=max_steps,
        workers=workers,
        mass_properties=mass_properties,
        yes=not check_budget,
        spin_axis=_spin_axis_text(spin_axis),
    )
    check_settings(settings)
    check_mass_properties(settings)
    study = Study(body.path, body._raw, settings)
    return [dict(zip(study.columns, row)) for row in study.run()]


def audit(
    robot_file: str | os.PathLike,
    *,
    package_paths: dict[str, str] | Sequence[str] | None = None,
    geometry: str = "collision",
    density: float | None = None,
    material: str | None = None,
    mesh_inertia: str = "auto",
    joints: dict[str, float] | Sequence[str] | None = None,
    fix: bool = False,
    allow_outside_paths: bool = False,
    mesh_repair: bool = False,
) -> AuditReport:
    """Audit a robot file (URDF ``.urdf``, SDF ``.sdf``, MJCF ``.xml``, or ``.xacro`` with the
    ``xacro`` extra) as ``rbi audit`` does: each link's declared mass properties against its own
    geometry, with flags, and the whole robot's totals. SI units; vectors and matrices in each
    link's frame (totals: the root link's frame for URDF/SDF, the world for MJCF).

    Args:
        robot_file: the file's path.
        package_paths: ``{NAME: DIR}`` or ``["NAME=DIR", ...]`` for ``package://NAME/`` meshes
            (``ROS_PACKAGE_PATH`` is searched too).
        geometry: ``"collision"`` or ``"visual"``: which geometry gives a link's volume (a link
            without it falls back to the other); ``"none"``: no geometry, the declared inertials
            and totals only.
        density, material: kg/m³, or a built-in material name, for links that declare no mass.
        mesh_inertia: ``"auto"`` (exact where a mesh is closed, else its convex hull, flagged
            ``mesh``), ``"exact"`` (the solid a closed mesh encloses), ``"convex"`` (its hull)
            or ``"shell"`` (mass on the surface).
        joints: ``{NAME: VALUE}`` or ``["NAME=VALUE", ...]``: radians for revolute/hinge joints,
            metres for prismatic/slide; the others at zero (MJCF: ``qpos0``).
        fix: also plan the fixed copy: ``report.fix.content`` (bytes), ``.changes``, ``.unfixable``.
        allow_outside_paths: let the file name meshes and includes outside its folder.
        mesh_repair: close meshes' holes of three or four edges first (each repair, with the
            area it added, is listed in ``report.notes``).

    Returns:
        An `AuditReport`: ``.links`` (each with ``.declared``, ``.geometry``, ``.ratios``,
        ``.flags``), ``.total``, ``.notes``, ``.exit_code`` (0, or 1 when a link has an
        error-level flag) and ``.as_dict()`` (what ``rbi audit --format json`` prints).

    Raises:
        SpecError: the file cannot be read, is malformed, names a mesh that cannot be found or
            read, or repeats a link name.
    """
    from rbi.robot import audit as run_audit

    return run_audit(
        robot_file,
        package_paths=package_paths,
        geometry=geometry,
        density=density,
        material=material,
        mesh_inertia=mesh_inertia,
        joints=joints,
        fix=fix,
        allow_outside_paths=allow_outside_paths,
        mesh_repair=mesh_repair,
    )


def __getattr__(name: str):
    if name == "AuditReport":  # imported on first use: the audit's modules stay unloaded for `import rbi.api`
        from rbi.robot.audit import AuditReport

        return AuditReport
    raise AttributeError(f"module 'rbi.api' has no attribute {name!r}")


def _range_text(value, option: str) -> str | None:
    """A sweep axis as ``--spin`` takes it: one value, ``(start, stop, count)`` or the text."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float, np.floating, np.integer)):
        return repr(float(value))
    try:
        start, stop, count = value
        return f"{float(start)!r}:{float(stop)!r}:{int(count)}"
    except (TypeError, ValueError):
        raise SpecError(
            f"{option}: expected a number, (start, stop, count) or 'START:STOP:COUNT' (got {value!r})"
        ) from None


def _vary_texts(vary) -> tuple[str, ...]:
    if vary is None:
        return ()
    if isinstance(vary, dict):
        return tuple(f"{path}={_range_text(value, f'--vary {path}')}" for path, value in vary.items())
    return tuple(vary)


def _vector_text(v) -> str:
    return "[" + ", ".join(f"{float(x) + 0.0:.6g}" for x in np.asarray(v).ravel()) + "]"


def _rich_table(title: str, rows):
    from rich.table import Table
    from rich.text import Text

    table = Table(title=Text(title))  # Text: a name holding [brackets] is shown, not read as markup
    table.add_column("quantity")
    table.add_column("unit")
    table.add_column("value", justify="right")
    for row in rows:
        table.add_row(*(Text(cell) for cell in row))
    return table


def _html_table(title: str, rows) -> str:
    from html import escape

    body = "".join(
        f'<tr><td>{escape(a)}</td><td>{escape(b)}</td><td style="text-align:right">{escape(c)}</td></tr>'
        for a, b, c in rows
    )
    return (
        f"<table><caption>{escape(title)}</caption>"
        f"<thead><tr><th>quantity</th><th>unit</th><th>value</th></tr></thead><tbody>{body}</tbody></table>"
    )
