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

import difflib
import os
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from rbi.core.dynamics import (
    angle_between_deg,
    angular_momentum_about_point,
    kinetic_energy,
    newton_euler_about,
)
from rbi.core.inertia import moment_about_axis, principal_axes, radii_of_gyration, re_express, unit_axis
from rbi.core.mass import MassProperties, inertia_shares
from rbi.core.rotation import (
    angle_is_kept,
    compose_world_rotations,
    matrix_to_quaternion,
    turn_lost_to_rounding,
)
from rbi.errors import ArgumentError, SpecError, literal
from rbi.files.output import OutputTarget, output_target, write_output
from rbi.files.output import check_distinct as check_distinct
from rbi.formats.paths import outside_paths_allowed, outside_paths_are_allowed
from rbi.memory import collector_paused as collector_paused
from rbi.names import CLI_TOOLS, PUBLIC
from rbi.reprs import QUANTITY_COLUMNS, TableRepr
from rbi.runs.values import vector_value
from rbi.spec.checks import Check, run_checks
from rbi.spec.points import NO_PIVOT, reference_choices, reference_name
from rbi.spec.units import LENGTH_UNITS_IN_M as LENGTH_UNITS
from rbi.spec.units import MASS_UNITS_IN_KG as MASS_UNITS
from rbi.spec.units import convert_body
from rbi.text import csv_lines as csv_lines
from rbi.text import number as number
from rbi.text import vector_text
from rbi.text import visible as visible

if TYPE_CHECKING:  # served by __getattr__ on first use (the sweep's and audit's modules load then)
    from rbi.robot.audit import AuditReport
    from rbi.sim.budget import DEFAULT_MAX_STEPS as DEFAULT_MAX_STEPS
    from rbi.spec.from_step import import_step as import_step
    from rbi.sweeps.execute import available_cores as available_cores
    from rbi.sweeps.plan import Grid, Normal, Uniform
    from rbi.sweeps.study import MAX_ROWS_SHOWN as MAX_ROWS_SHOWN

# listed once, in rbi.names (`import rbi` reads it without this module); the names imported here
# only to be offered are imported `as` themselves, which tells linters they are re-exported
__all__ = [*PUBLIC, *CLI_TOOLS]

SPEC_TEXT_LABELS = ("<stdin>", "<string>", "<dict>")
"""How a spec that is no file is named (`Body.path`): read from standard input, text, a dict."""

Point = str | Sequence[float] | np.ndarray
"""A reference point: ``"com"``, ``"origin"``, ``"pivot"``, or (x, y, z) in body coordinates
(spec length unit)."""


def load(
    source: str | os.PathLike[str] | Mapping[str, Any], *, allow_outside_paths: bool | None = None
) -> Body:
    """Read, validate and translate a body spec.

    Args:
        source: the path of a spec file (``str`` or ``os.PathLike``; a ``str`` is always a
            path, ``"-"`` standard input, named ``<stdin>`` in messages), or a ``dict`` shaped
            like the YAML spec (named ``<dict>``). Text is read by `loads`. Files the spec names
            (meshes, point clouds) are looked for beside the spec file, or in the current folder
            for a dict.
        allow_outside_paths: let the spec name files outside its own folder (the CLI's
            ``--allow-outside-paths``); None: as an enclosing `outside_paths_allowed` block
            says (not allowed outside one).

    Returns:
        The `Body`.

    Raises:
        SpecError: the file is missing or unreadable, the YAML is malformed, or the spec is
            invalid; ``str(error)`` is ``file: part: field: what is wrong``.
        TypeError: ``source`` is neither a path nor a dict.
    """
    # not at top level: `rbi audit` would load rbi.spec.load too
    from rbi.spec import load as spec_load

    if isinstance(source, Mapping):
        spec_load.check_plain_data(dict(source), "<dict>")
        return _body(
            lambda: (spec_load.body_from_raw(dict(source), "<dict>"), dict(source), None),
            "<dict>",
            allow_outside_paths,
        )
    if not isinstance(source, (str, os.PathLike)):
        raise TypeError(
            f"source: expected a path (str or os.PathLike) or a dict, got {type(source).__name__}"
        )
    path = os.fspath(source)
    path = os.fsdecode(path) if isinstance(path, bytes) else path
    if "\n" in path and not os.path.lexists(path):
        raise ArgumentError(
            "source", "is text, not a path (a str is always a path): read spec text with rbi.loads"
        )

    def read() -> tuple[Any, Any, bytes | None]:
        raw, data = spec_load.read_spec(path)  # "-" reads standard input
        return spec_load.body_from_raw(raw, spec_load.spec_label(path)), raw, data

    return _body(read, spec_load.spec_label(path), allow_outside_paths)


def loads(text: str | bytes, *, allow_outside_paths: bool | None = None) -> Body:
    """Read a body spec from YAML or JSON text (named ``<string>`` in messages; files it names
    are looked for in the current folder). Otherwise as `load`."""
    # not at top level: `rbi audit` would load rbi.spec.load too
    from rbi.spec import load as spec_load

    if isinstance(text, bytes):
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise SpecError(f"<string>: not UTF-8 text (byte {exc.start})", file="<string>") from None
    if not isinstance(text, str):
        raise TypeError(f"text: expected YAML or JSON text (str or bytes), got {type(text).__name__}")

    def read() -> tuple[Any, Any, bytes | None]:
        raw = spec_load.parse_spec_text(spec_load.check_spec_text(text, "<string>"), "<string>")
        return spec_load.body_from_raw(raw, "<string>"), raw, None

    return _body(read, "<string>", allow_outside_paths)


def _body(
    read: Callable[[], tuple[Any, Any, bytes | None]], label: str, allow_outside_paths: bool | None
) -> Body:
    """The `Body` ``read()`` gives (loaded body, parsed spec, the bytes of its file or None); a
    `SpecError` whose line starts with ``label`` gets it as its ``file``."""

    allowed = outside_paths_are_allowed() if allow_outside_paths is None else allow_outside_paths
    try:
        with outside_paths_allowed(allowed):
            loaded, raw, data = read()
    except SpecError as exc:
        if exc.file is None and str(exc).startswith(label + ": "):
            exc.file = label
        raise
    return Body(loaded, raw, data)


def validate(
    paths: str | os.PathLike[str] | Sequence[str | os.PathLike[str]],
    *,
    package_paths: Mapping[str, str] | Sequence[str] | None = None,
) -> list[list[str]]:
    """Check spec files without computing anything, as ``rbi validate`` does: for each path,
    the list of its problems, one line each (empty when the file is valid). A robot file (URDF,
    SDF, MJCF) gives every link whose inertia is not physical; ``package_paths`` (``{NAME:
    DIR}`` or ``["NAME=DIR", ...]``) finds its ``package://`` meshes. SpecError for a bad
    ``package_paths``."""
    # not at top level: `rbi inertia` would load rbi.formats.robot_paths too
    from rbi.formats.robot_paths import parse_package_paths

    # not at top level: `rbi audit` would load rbi.spec.load too
    from rbi.spec.load import file_problems

    packages = parse_package_paths(package_paths)
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    if not isinstance(paths, Sequence) or not all(isinstance(p, (str, os.PathLike)) for p in paths):
        raise TypeError(f"paths: expected a path (str or os.PathLike) or a list of them, got {paths!r:.80}")
    return [file_problems(os.fspath(path), packages) for path in paths]


def spec_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a body spec, as ``rbi schema`` prints it (for
    editors: see docs/schema.md)."""
    # not at top level: `rbi audit` would load rbi.spec.models too
    from rbi.spec.models import body_spec_json_schema

    return body_spec_json_schema()


def unit_vector(direction: Sequence[float] | np.ndarray) -> np.ndarray:
    """``direction / |direction|`` as (3,), for any finite non-zero vector however large or
    small its components (1e-300 and 1e300 alike); ArgumentError naming ``direction`` else."""

    try:
        return unit_axis(direction)
    except (ValueError, TypeError):
        raise ArgumentError(
            "direction", f"must be a non-zero finite vector (x, y, z), got {literal(direction)}"
        ) from None


@dataclass(frozen=True)
class Principal(TableRepr):
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

    def _table(self) -> tuple[str, list[list[str]], tuple[str, ...]]:
        rows = [
            [str(i + 1), number(m, 8), vector_text(axis), number(k)]
            for i, (m, axis, k) in enumerate(zip(self.moments, self.axes, self.radii_of_gyration))
        ]
        title = f"principal moments and axes about {vector_text(self.about)}"
        return title, rows, ("axis", "moment", "direction (body axes)", "radius of gyration")


@dataclass(frozen=True)
class Part(TableRepr):
    """One part of a body, in file order (spec units, body frame).

    Attributes:
        name: the part's ``name`` (``parts[i]`` when it has none).
        shape: the part's shape (``cylinder``, ``mesh`` ... or ``point_cloud``).
        hole: True for a part removed from the body (``subtract: true``).
        mass: the part's mass (negative for a hole).
        center_of_mass: (3,) the part's centre of mass.
        inertia_about_com: (3, 3) the part's inertia about its own centre of mass, body axes.
        volume: the solid's volume (length³; negative for a hole, as its mass, so the parts'
            volumes add up to the body's), or None when it has none (points, custom parts).
        principal_moments: (3,) ascending, about the part's own centre of mass (negative for a
            hole), mass·length².
        inertia_share: the part's share of the trace of the body's inertia about the body's
            centre of mass (the shares add up to 1; a hole's is negative).
        integration_error: for a STEP part, the relative error estimate of its exact-geometry
            integration; else None.
    """

    name: str
    shape: str
    hole: bool
    mass: float
    center_of_mass: np.ndarray
    inertia_about_com: np.ndarray
    volume: float | None
    principal_moments: np.ndarray
    inertia_share: float
    integration_error: float | None = None

    def _table(self) -> tuple[str, list[tuple[str, str, str]], tuple[str, ...]]:
        rows = [
            ("shape", "", self.shape + (" (hole)" if self.hole else "")),
            ("mass", "", number(self.mass, 8)),
            ("centre of mass", "", vector_text(self.center_of_mass)),
            *(
                (f"inertia about its CoM, row {i + 1}", "", vector_text(row))
                for i, row in enumerate(self.inertia_about_com)
            ),
            ("volume", "", number(self.volume, 8)),
        ]
        return f"part {self.name}", rows, QUANTITY_COLUMNS


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


@dataclass(frozen=True)
class Dynamics:
    """Newton–Euler at one instant, about a point (spec units, body axes), as `Body.dynamics`
    gives it.

    Attributes:
        mode: ``"inverse"`` (loads from the motion) or ``"forward"`` (motion from the loads).
        about: (3,) the reference point o, length unit.
        omega: (3,) angular velocity, rad/s.
        alpha: (3,) angular acceleration, rad/s².
        point_acceleration: (3,) acceleration of o, length/s².
        force: (3,) the force on the body, mass·length/s² (``held``: the force holding o).
        torque: (3,) the torque about o, mass·length²/s².
        held: o was held (a pivot): forward dynamics without a force about a point other than
            the centre of mass.
    """

    mode: str
    about: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray
    point_acceleration: np.ndarray
    force: np.ndarray
    torque: np.ndarray
    held: bool


class Body(TableRepr):
    """A validated rigid body, as `load` returns it (not constructed directly).

    All numbers are in the spec's own units (`units`) and the body frame (the spec's
    coordinates). A Body does not change; every method returns new arrays.
    """

    def __init__(self, loaded: Any, raw: Any = None, spec_bytes: bytes | None = None) -> None:
        self._loaded = loaded
        self._raw = raw
        self._spec_bytes = spec_bytes  # the spec file's bytes as read (None: text, a dict, stdin)
        self.warnings: list[str] = list(loaded.warnings)
        """Warnings about the spec (units that look wrong for a spec without ``units:``: one
        line naming the part and the ``units:`` that would fit), the lines the CLI prints on
        stderr and puts in JSON as ``"warnings"``."""

    @property
    def path(self) -> str:
        """Where the spec came from: its path, or ``<stdin>``, ``<string>``, ``<dict>``."""
        return self._loaded.path

    @property
    def files_read(self) -> list[str]:
        """The files the body was read from, which no output of a run on it may replace: the
        spec's path (unless it came from text, a dict or standard input), then each file the
        spec names (meshes, STEP files, the point cloud) as an absolute path."""
        spec = [] if self.path in SPEC_TEXT_LABELS else [self.path]
        return [*spec, *self._loaded.files]

    @property
    def name(self) -> str | None:
        """The spec's ``name``, or None."""
        return self._loaded.name

    @property
    def units(self) -> dict[str, str]:
        """The spec's units: ``{"length": ..., "mass": ...}``, e.g. ``{"length": "m", "mass": "kg"}``."""
        return dict(self._loaded.units)

    @property
    def unit_labels(self) -> dict[str, str]:
        """The printed unit of each quantity in the spec's units: ``length``, ``mass``,
        ``inertia`` (``kg·m²``), ``angular_momentum``, ``energy`` (``J`` in SI), ``density``,
        ``velocity``, ``omega``."""
        return dict(self._loaded.labels)

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
        # not at top level: `rbi inertia` would load rbi.runs.run too
        from rbi.runs.run import body_spin_axis

        return body_spin_axis(self._loaded)

    def point(self, about: Point = "com") -> np.ndarray:
        """The reference point ``about`` as (3,) body coordinates, length unit.

        ``"com"``: the centre of mass; ``"origin"``: (0, 0, 0); ``"pivot"``: the spec's pivot
        (ValueError when there is none); or a point (x, y, z)."""

        key = reference_name(about) if isinstance(about, str) else vector_value(about, "about")
        if key is None:
            raise ArgumentError("about", f"expected {reference_choices('(x, y, z)')}, got {literal(about)}")
        point = self._loaded.point(key)
        if point is None:
            raise ArgumentError("about", NO_PIVOT, file=self.path)
        return np.array(point, dtype=float)

    def _refuse_non_finite(self, **results: Any) -> None:
        """ValueError (an `ArgumentError` naming the file) when a result overflowed: inputs of
        absurd size (``about=(1e200, 0, 0)``, ``omega=(1e200, 0, 0)``) give inf or NaN, which no
        caller can use (the CLI prints the message as bad input, exit 2)."""
        bad = [
            name for name, value in results.items() if value is not None and not np.all(np.isfinite(value))
        ]
        if bad:
            raise ArgumentError(
                (),
                f"result{'s' if len(bad) > 1 else ''} {', '.join(bad)} {'are' if len(bad) > 1 else 'is'} not "
                "finite: the input values are too large for double precision",
                file=self.path,
            )

    def inertia(
        self, about: Point = "com", axes: Sequence[tuple[str, float]] | np.ndarray | None = None
    ) -> np.ndarray:
        """The (3, 3) inertia matrix about a point, mass·length² (tensor sign: ``I_xy = -∫xy dm``).

        Args:
            about: the reference point (see `point`): ``"com"`` (default), ``"origin"``,
                ``"pivot"`` or (x, y, z) in body coordinates.
            axes: None for body axes; or turns of the body about world axes, applied in
                order — a sequence of ``("x"|"y"|"z", degrees)`` pairs; or a (3, 3) rotation
                matrix R, body → world. The matrix is then given in world axes: ``R I Rᵀ``.
        """

        rotation = None if axes is None else _rotation(axes)
        with np.errstate(over="ignore", invalid="ignore"):
            matrix = self._loaded.props.inertia_about(self.point(about))
            if rotation is not None:
                matrix = re_express(matrix, rotation)
        if not isinstance(about, str) and not np.all(np.isfinite(matrix)):
            raise ArgumentError(
                "about",
                "the point is too far from the body: the inertia about it overflows double precision "
                f"(got {literal(np.asarray(about).tolist())})",
                file=self.path,
            )
        self._refuse_non_finite(inertia=matrix)
        return matrix

    def principal(self, about: Point = "com") -> Principal:
        """Principal moments (ascending) and axes (rows, body frame, right-handed) about a point
        (default the centre of mass), as ``rbi principal`` prints them."""

        point = self.point(about)
        moments, axes = principal_axes(self.inertia(about))
        # + 0.0: no -0.0 components (the CLI prints 0 there too)
        return Principal(
            moments=np.asarray(moments) + 0.0,
            axes=np.asarray(axes) + 0.0,
            radii_of_gyration=np.asarray(radii_of_gyration(list(moments), self.mass)),
            about=point,
        )

    def parts(self) -> list[Part]:
        """Each part's mass properties, in file order (see `Part`)."""
        # not at top level: `rbi audit` would load rbi.spec.translate and rbi.spec.volumes too
        from rbi.spec.translate import integration_errors
        from rbi.spec.volumes import part_volume

        loaded = self._loaded
        spec_parts = list(loaded.spec.parts) if loaded.spec is not None else []
        shares = inertia_shares(loaded.elements, loaded.props)
        errors = integration_errors(loaded.spec) or []
        # volumes are computed in the spec's units: a body in other units (`in_units`) scales them
        cube = (
            1.0
            if not spec_parts
            else LENGTH_UNITS[loaded.spec.units.length] / LENGTH_UNITS[loaded.length_unit]
        )
        out = []
        for i, element in enumerate(loaded.elements):
            part = spec_parts[i] if i < len(spec_parts) else None
            volume = None if part is None else part_volume(part)
            if volume is not None and getattr(part, "subtract", False):
                volume = -volume  # a hole takes its volume away, as its mass
            out.append(
                Part(
                    name=loaded.part_names[i] or f"parts[{i}]",
                    shape=part.shape if part is not None else "point_cloud",
                    hole=bool(getattr(part, "subtract", False)),
                    mass=float(element.mass),
                    center_of_mass=np.array(element.center_of_mass, dtype=float),
                    inertia_about_com=np.array(element.inertia_about_com, dtype=float),
                    volume=volume if volume is None or cube == 1.0 else volume * cube**3,
                    principal_moments=principal_axes(element.inertia_about_com)[0],
                    inertia_share=float(shares[i]),
                    integration_error=errors[i] if i < len(errors) else None,
                )
            )
        return out

    def momentum(
        self, omega: Sequence[float], about: Point = "com", velocity: Sequence[float] | None = None
    ) -> Momentum:
        """Angular momentum about a point and kinetic energy, for angular velocity ``omega``
        (body axes, rad/s).

        Args:
            omega: (3,) angular velocity, rad/s, body axes.
            about: the reference point (see `point`).
            velocity: (3,) velocity of the centre of mass, length/s, body axes. None: the
                ``about`` point is fixed and the body turns about it (``v = ω × r``).
        """

        w = np.array(vector_value(omega, "omega"))
        point = self.point(about)
        props = self._loaded.props
        com_from_point = props.center_of_mass - point
        v_com = (
            np.cross(w, com_from_point) if velocity is None else np.array(vector_value(velocity, "velocity"))
        )
        with np.errstate(over="ignore", invalid="ignore"):
            h = angular_momentum_about_point(props.inertia_about_com, props.mass, com_from_point, w, v_com)
            energy = float(kinetic_energy(props.inertia_about_com, w, props.mass, v_com))
        self._refuse_non_finite(com_velocity=v_com, angular_momentum=h, kinetic_energy=energy)
        return Momentum(
            omega=w,
            about=point,
            com_velocity=v_com,
            angular_momentum=np.asarray(h),
            angle_deg=angle_between_deg(h, w),
            kinetic_energy=energy,
        )

    @property
    def mass_properties(self) -> MassProperties:
        """The body's mass properties as one immutable value: ``mass``, ``center_of_mass`` (3,),
        ``inertia_about_com`` (3, 3, body axes) and ``frame`` (``"body"``), spec units;
        ``.inertia_about(point)`` shifts it by the parallel-axis theorem."""
        return self._loaded.props

    def in_units(self, length: str, mass: str) -> Body:
        """The same body with every number in other units: lengths in ``length`` (a key of
        `LENGTH_UNITS`, e.g. ``"mm"``), masses in ``mass`` (a key of `MASS_UNITS`, e.g.
        ``"g"``), inertias in mass·length²; the pivot and each part follow."""

        for parameter, value, known in (("length", length, LENGTH_UNITS), ("mass", mass, MASS_UNITS)):
            if value not in known:
                raise ArgumentError(parameter, f"expected one of {', '.join(known)}, got {literal(value)}")
        return Body(convert_body(self._loaded, length, mass), self._raw, self._spec_bytes)

    def moment_about_axis(
        self, axis: Sequence[float], about: Point = "com", axes: Sequence[tuple[str, float]] | None = None
    ) -> float:
        """The scalar moment of inertia ``nᵀ I n`` (mass·length²) about the line through
        ``about`` along ``axis`` (any non-zero length), with ``axis`` in the axes of
        ``inertia(about, axes)``: body axes, or world axes after ``axes``."""

        matrix = self.inertia(about, axes)
        try:
            with np.errstate(over="ignore", invalid="ignore"):
                moment = moment_about_axis(matrix, axis)
        except ValueError:
            raise ArgumentError(
                "axis", f"must be a non-zero finite direction (x, y, z), got {literal(axis)}"
            ) from None
        self._refuse_non_finite(moment=moment)
        return moment

    def check(self) -> list[Check]:
        """Each expectation of the spec's ``expect:`` block (see docs/check.md) against the
        body, as ``rbi check`` compares them (see `Check`), in the spec's units. SpecError when
        the spec has none."""

        loaded, spec = self._loaded, self._loaded.spec
        if spec is not None and (spec.units.length, spec.units.mass) != (
            loaded.length_unit,
            loaded.mass_unit,
        ):
            loaded = convert_body(loaded, spec.units.length, spec.units.mass)
        return run_checks(loaded)

    def dynamics(
        self,
        omega: Sequence[float],
        *,
        about: Point = "com",
        alpha: Sequence[float] | None = None,
        point_acceleration: Sequence[float] | None = None,
        force: Sequence[float] | None = None,
        torque: Sequence[float] | None = None,
    ) -> Dynamics:
        """Newton–Euler at one instant, about the point ``about`` (see `point`), every vector
        in body axes and spec units: inverse with ``alpha`` (the force and the torque about
        ``about`` that angular acceleration needs), else forward with ``force``/``torque`` (the
        accelerations they give). Without ``force``, a point other than ``"com"`` is held (a
        pivot: its acceleration is ``point_acceleration``) and the force holding it is found.

        Args:
            omega: (3,) angular velocity, rad/s.
            alpha: (3,) angular acceleration, rad/s².
            point_acceleration: (3,) acceleration of ``about``, length/s² (default 0).
            force: (3,) force on the body, mass·length/s².
            torque: (3,) torque about ``about``, mass·length²/s².
        """

        if (alpha is None) == (force is None and torque is None):
            raise ArgumentError(("alpha", "force"), "give either alpha (inverse) or force/torque (forward)")
        name = reference_name(about)  # None for a point (x, y, z)
        about_com = name == "com"
        point = self.point(about)
        props = self._loaded.props
        inertia = self.inertia(about)
        if alpha is None and np.linalg.matrix_rank(inertia) < 3:
            where = name or f"point {literal(point.tolist())}"
            raise ArgumentError(
                (),
                f"the inertia about the {where} is singular: the body cannot be given an angular acceleration",
                file=self.path,
            )
        given = dict(alpha=alpha, point_acceleration=point_acceleration, force=force, torque=torque)
        vectors = {k: None if v is None else np.array(vector_value(v, k)) for k, v in given.items()}
        w = np.array(vector_value(omega, "omega"))
        with np.errstate(over="ignore", invalid="ignore"):
            (linear, angular), (f, t), held = newton_euler_about(
                props, inertia, props.center_of_mass - point, w, about_com=about_com, **vectors
            )
        self._refuse_non_finite(linear_acceleration=linear, angular_acceleration=angular, force=f, torque=t)
        mode = "inverse" if alpha is not None else "forward"
        return Dynamics(mode, point, w, angular, linear, f, t, held)

    def inertial_xml(
        self, to: str, *, name: str | None = None, document: bool = False, diagonal: bool = False
    ) -> str:
        """The ``<inertial>`` element for a robot description, as ``rbi export`` prints it: SI
        units (kg, m, kg·m²), inertia about the centre of mass in body axes, a comment first.

        Args:
            to: ``"urdf"``, ``"mjcf"`` or ``"sdf"``.
            name: the link's (body's) name in a document; default the spec's name, else the
                file's stem (``body`` for a spec read from text).
            document: a whole minimal document (robot/link, mujoco/worldbody/body,
                sdf/model/link) instead of the bare element.
            diagonal: MJCF only: principal moments (``diaginertia``) and the principal frame
                (``quat``) instead of ``fullinertia``.
        """

        # not at top level: `rbi inertia` would load rbi.formats.inertial_xml too
        from rbi.formats.inertial_xml import FORMATS, export_xml

        if to not in FORMATS:
            raise ArgumentError("to", f"expected one of {', '.join(FORMATS)}, got {literal(to)}")
        if diagonal and to != "mjcf":
            raise ArgumentError("diagonal", "only for to='mjcf' (URDF and SDF take the full matrix)")
        length, mass = self.units["length"], self.units["mass"]
        spec_units = "" if (length, mass) == ("m", "kg") else f"; spec units were {length}, {mass}"
        comment = (
            f"rbi export of {Path(self.path).name}: SI units (kg, m, kg·m²); "
            f"inertia about the centre of mass, body axes{spec_units}"
        )
        if name is None:
            text = self.path in SPEC_TEXT_LABELS
            name = self.name or ("body" if text else Path(self.path).stem)
        si = self.in_units("m", "kg").mass_properties
        return export_xml(to, si, name=name, document=document, diagonal=diagonal, comment=comment)

    def export_warnings(self) -> list[str]:
        """The warnings that go with `inertial_xml`, as ``rbi export`` prints them on stderr and
        puts in JSON as ``"warnings"``: the body's `warnings`, then, when its inertia about the
        centre of mass has a zero principal moment (point masses only, a thin rod), one line
        naming the file: simulators such as MuJoCo refuse a moving body without rotational
        inertia."""

        moments = self.mass_properties.moments  # ascending; the test is a ratio, so any units
        if moments[0] > 1e-12 * max(moments[-1], 0.0):
            return list(self.warnings)
        return [
            *self.warnings,
            f"{self.path}: the inertia has a zero principal moment (a point mass or thin rod); "
            "simulators such as MuJoCo refuse a moving body without rotational inertia",
        ]

    def __repr__(self) -> str:
        units = self.units
        return (
            f"<rbi.Body {self.name or self.path!r}: mass {number(self.mass)} {units['mass']}, "
            f"{len(self._loaded.elements)} parts, {'pivot' if self._loaded.pivot is not None else 'free'}>"
        )

    def _table(self) -> tuple[str, list[tuple[str, str, str]], tuple[str, ...]]:
        units = self.units
        inertia_unit = f"{units['mass']}·{units['length']}²"
        principal = self.principal()
        rows = [
            ("mass", units["mass"], number(self.mass, 8)),
            ("centre of mass", units["length"], vector_text(self.center_of_mass)),
        ]
        if self._loaded.pivot is not None:
            rows.append(("pivot", units["length"], vector_text(self.pivot)))
        rows.append(("principal moments about CoM", inertia_unit, vector_text(principal.moments)))
        for i, axis in enumerate(principal.axes, start=1):
            rows.append((f"principal axis {i}", "", vector_text(axis)))
        rows.append(("parts", "", str(len(self._loaded.elements))))
        return f"{self.name or self.path}", rows, QUANTITY_COLUMNS


def _rotation(axes: Any) -> np.ndarray:
    """A body → world rotation matrix from ``axes`` (see `Body.inertia`): a (3, 3) rotation
    matrix, or (axis, degrees) pairs applied in order about world axes."""

    if isinstance(axes, str):
        raise ArgumentError(
            "axes", f"expected a 3x3 rotation matrix or (axis, degrees) pairs, got {literal(axes)}"
        )
    if np.shape(axes) == (3, 3) and not isinstance(np.asarray(axes, dtype=object)[0, 0], str):
        R = np.asarray(axes, dtype=float)
        orthonormal = np.all(np.isfinite(R)) and np.allclose(R @ R.T, np.eye(3), atol=1e-9)
        if not (orthonormal and np.linalg.det(R) > 0):
            raise ArgumentError("axes", "a 3x3 matrix must be a rotation (orthonormal, determinant +1)")
        return R
    turns = []
    for turn in axes:
        try:
            axis, degrees = turn
            axis, degrees = str(axis).strip().lower(), float(degrees)
        except (TypeError, ValueError, OverflowError):
            axis, degrees = "", float("nan")
        if axis not in ("x", "y", "z") or not np.isfinite(degrees):
            raise ArgumentError(
                "axes",
                f"expected (axis, degrees) pairs with axis 'x', 'y' or 'z', e.g. [('y', 30)], got {literal(turn)}",
            )
        if not angle_is_kept(degrees):
            raise ArgumentError("axes", turn_lost_to_rounding(literal(degrees)))
        turns.append((axis, np.radians(degrees)))
    return compose_world_rotations(turns)


@dataclass(frozen=True, repr=False)
class Trajectory(TableRepr):
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
    body: Body | None = field(default=None, compare=False)
    """The simulated `Body` (None for a trajectory made by hand)."""

    def plot(self, path: Destination) -> None:
        """Draw the run at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib), as ``rbi
        simulate --plot`` does: the path of the tip of the spin axis seen from above (world
        frame), its tilt against time (a free body: each principal axis's angle to the angular
        momentum), degrees; ω in body axes, rad/s; the energy's drift. The file is replaced
        atomically."""
        from rbi.viz.plots import plot_simulation  # matplotlib loads only to draw

        body = self.body
        if body is None:
            raise ArgumentError("body", "plot needs the Body of the run: a Trajectory from rbi.simulate")
        free = (
            {"principal_axes": body.principal().axes, "inertia": body.inertia()} if body.pivot is None else {}
        )
        plot_simulation(
            self.columns(),
            _output(path, ("png", "svg", "pdf"), body),
            name=body.name or body.path,
            omega0=self.summary["initial"]["omega"],
            nudge_deg=self.summary["initial"]["nudge_deg"],
            energy_unit=body.unit_labels["energy"],
            spin_axis=self.summary["spin_axis"],
            **free,
        )

    def to_csv(self) -> str:
        """The trajectory as the CSV ``rbi simulate --out`` writes (columns t, qw, qx, qy, qz, wx,
        wy, wz, tilt_deg, precession_deg, energy; full precision)."""
        # not at top level: `rbi inertia` would load rbi.runs.run too
        from rbi.runs.run import trajectory_csv

        return trajectory_csv(self.columns())

    def columns(self) -> dict[str, np.ndarray]:
        """The CSV's columns by name (``t``, ``qw`` … ``energy``), each (N,)."""
        # not at top level: `rbi inertia` would load rbi.sim.summary too
        from rbi.sim.summary import columns_of

        return columns_of(self.t, self.q, self.omega, self.tilt_deg, self.precession_deg, self.energy)

    def __repr__(self) -> str:
        return (
            f"<rbi.Trajectory {self.t.size} samples over {number(self.t[-1])} s, "
            f"{self.summary.get('method', '')}>"
        )

    def _table(self) -> tuple[str, list[tuple[str, str, str]], tuple[str, ...]]:
        s = self.summary
        final = s.get("final", {})
        rows = [
            ("scene", "", str(s.get("scene", ""))),
            ("method", "", str(s.get("method", ""))),
            ("duration", "s", number(self.t[-1])),
            ("samples", "", str(self.t.size)),
            ("final q [w, x, y, z]", "", vector_text(self.q[-1])),
            ("final ω (body axes)", "rad/s", vector_text(self.omega[-1])),
            (f"final tilt of {_axis_name(s.get('spin_axis'))}", "deg", number(self.tilt_deg[-1])),
            ("tilt min … max", "deg", f"{number(np.min(self.tilt_deg))} … {number(np.max(self.tilt_deg))}"),
        ]
        if final and "energy" in s.get("conserved", {}):
            rows.append(("energy drift", "", number(s["conserved"]["energy"]["drift"], 2)))
        return f"{s.get('name') or 'trajectory'} — simulate", rows, QUANTITY_COLUMNS


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
    about its centre of mass — the run ``rbi simulate`` makes with the same settings. Returns
    the `Trajectory`.

    Args:
        body: the `Body`.
        spin, omega: initial spin about the spin axis, rad/s; or the initial angular velocity
            (3,), body axes, rad/s.
        tilt_deg, tilt_axis: the nudge: the body turned at t = 0 by this angle (degrees) about
            the world axis ``"x"`` or ``"y"``. The tilt reported is the spin axis's from the vertical.
        duration, samples: simulated time, s; samples, equally spaced from t = 0 (1: only the end).
        gravity: m/s² (SI whatever the spec's units); 0 switches it off; None is 9.81.
        method: ``"default"`` (compiled adaptive DOP853), ``"rk45"``, ``"dop853"`` (scipy) or
            ``"exact"`` (closed forms, where they apply).
        rtol: integrator tolerance (None: 1e-12 for default, 1e-8 for the scipy methods).
        max_steps, check_budget: most integration steps (None: rbi's `DEFAULT_MAX_STEPS`);
            refuse a run estimated past them before it starts (they stop it in any case).
        error_estimate: estimate the error with a second run 1000× tighter.
        progress: called now and then with the fraction done (0…1).
        spin_axis: the body-frame axis of ``spin`` and of the reported tilt and precession:
            ``"x"``, ``"y"``, ``"z"`` (``"-y"``: reversed) or a direction (3,); None for the
            spec's ``spin_axis``, else `Body.spin_axis`'s default.

    Raises:
        ValueError: a setting is out of range, named as this function's parameter
            (``duration: must be ...``), or the run is estimated to exceed ``max_steps``.
        SpecError: the run cannot be made (no mass, too many steps, overflow).
    """
    # not at top level: `rbi inertia` would load rbi.runs.run too
    from rbi.runs.run import prepare_run
    from rbi.sim.api import check_samples

    samples = check_samples(samples)
    run: dict[str, Any] = dict(
        spin=spin, omega=omega, tilt_deg=tilt_deg, tilt_axis=tilt_axis, gravity=gravity
    )
    run |= dict(duration=duration, method=method, rtol=rtol, max_steps=max_steps, check_budget=check_budget)
    prepared = prepare_run(_loaded(body, "body"), spin_axis=spin_axis, **run)
    return _trajectory(prepared.simulate(samples, error_estimate=error_estimate, progress=progress), body)


def _trajectory(run: Any, body: Body) -> Trajectory:
    """The `Trajectory` of a finished run (:class:`rbi.runs.run.SimulationRun`) of ``body``."""
    columns = run.columns
    return Trajectory(
        t=columns["t"],
        q=run.trajectory.q,
        omega=run.trajectory.omega,
        tilt_deg=columns["tilt_deg"],
        precession_deg=columns["precession_deg"],
        energy=columns["energy"],
        summary=run.summary,
        body=body,
    )


def _axis_name(axis: Any) -> str:
    """``body y`` for a coordinate axis of the body frame, else ``the spin axis [x, y, z]``."""
    if axis is None:
        return "the spin axis"
    axis = np.asarray(axis, dtype=float)
    for index, name in enumerate("xyz"):
        if axis[index] == 1.0:
            return f"body {name}"
    return f"the spin axis {vector_text(axis)}"


def _loaded(body: Any, parameter: str) -> Any:
    """The loaded body behind a `Body`; TypeError naming ``parameter`` for anything else."""
    if not isinstance(body, Body):
        raise TypeError(f"{parameter}: expected a Body from rbi.load (got {type(body).__name__})")
    return body._loaded


class SweepTable(TableRepr):
    """The rows of a sweep, one per run in run order: ``len(table)`` runs, each column by name
    as a numpy array (``table["max_tilt_deg"]``; float columns hold NaN where a failed run has
    no value, ``status`` holds text), ``table.columns`` their names, ``table.records()`` the
    rows as dicts (as ``rbi sweep --format json`` prints ``runs``), ``table.to_pandas()``.

    Attributes:
        columns: the column names: ``run``, the swept values (``spin``, ``tilt_deg``, each
            varied path), then the results.
        count: the runs of the sweep; held: whether the table holds their rows (a sweep of
            more than 100,000 runs keeps them in its ``out`` file only).
        name, units, warnings: of the nominal body.
        failed: how many runs failed (their ``status`` says why).
        spread: with ``mass_properties``, each quantity's percentiles (``p0``, ``p50``,
            ``p100``...) and standard deviation over the ok runs; else None.
    """

    def __init__(self, study: Any, rows: Sequence[Sequence[Any]] | None, body: Body) -> None:
        nominal = study.nominal
        self._body = body  # the swept Body: no map replaces a file it was read from
        self.columns: list[str] = list(study.columns)
        self.count: int = study.plan.size
        self.held = rows is not None
        self._rows = [list(row) for row in rows or []]
        self._study = study
        self.name: str | None = nominal.name
        self.units: dict[str, str] = dict(nominal.units)
        self.warnings: list[str] = list(nominal.warnings)
        mass_properties = study.settings.mass_properties and self.held
        self.spread: dict[str, dict[str, float]] | None = (
            study.spread(self._rows) if mass_properties else None
        )
        self.failed = sum(1 for row in self._rows if row[-1] != "ok")

    def plot(self, path: Destination) -> None:
        """Draw the stability map at ``path`` (``.png``, ``.svg`` or ``.pdf``; needs matplotlib),
        as ``rbi sweep --plot`` does: the largest tilt (degrees) over the first one or two
        swept axes, and the nominal top's sleeping threshold (rad/s) when the first is the spin.
        ValueError for a sweep of mass properties, with nothing swept, or whose rows are not held."""
        from rbi.viz.plots import plot_map  # matplotlib loads only to draw

        if not self.held:
            raise ArgumentError("plot", "the map is drawn from the rows, and this table does not hold them")
        plot_map(self._study.stability_map(self._rows), _output(path, ("png", "svg", "pdf"), self._body))

    def __len__(self) -> int:
        return len(self._rows)

    def __iter__(self) -> Iterator[str]:
        return iter(self.columns)

    def keys(self) -> list[str]:
        """The column names (so ``dict(table)`` maps each to its array)."""
        return list(self.columns)

    def __getitem__(self, column: str) -> np.ndarray:
        if column not in self.columns:
            raise KeyError(f"{column!r}: no such column (columns: {', '.join(self.columns)})")
        i = self.columns.index(column)
        values = [row[i] for row in self._rows]
        if any(isinstance(v, str) for v in values):
            return np.array(values, dtype=object)
        if column in ("run", "steps") and None not in values:
            return np.array(values, dtype=np.int64)
        return np.array([np.nan if v is None else v for v in values], dtype=float)

    def records(self) -> list[dict[str, Any]]:
        """One dict per run, column name → value (None where a failed run has none)."""
        return [dict(zip(self.columns, row)) for row in self._rows]

    def to_pandas(self) -> Any:
        """The table as a :class:`pandas.DataFrame`, one row per run, the columns in order."""
        try:
            # not at top level: importing pandas takes ~0.3 s, and only this method needs it
            import pandas
        except ImportError:
            raise ImportError(
                "SweepTable.to_pandas needs pandas, which is not installed: pip install pandas"
            ) from None
        return pandas.DataFrame(self.records(), columns=self.columns)

    def __repr__(self) -> str:
        return f"<rbi.SweepTable {len(self)} runs × {len(self.columns)} columns, {self.failed} failed>"

    def _table(self) -> tuple[str, list[list[str]], list[str]]:
        shown: list[list[Any] | None] = list(self._rows)
        if len(shown) > 20:
            shown = shown[:10] + [None] + shown[-10:]
        rows = [
            ["…"] * len(self.columns)
            if row is None
            else [v if isinstance(v, str) else number(v) for v in row]
            for row in shown
        ]
        return f"{self.name or 'sweep'} — {len(self)} runs, {self.failed} failed", rows, self.columns


if TYPE_CHECKING:
    AxisValues = float | Sequence[float] | np.ndarray | Grid | Normal | Uniform
    """A sweep axis: one value, the grid's values, or a draw per run."""


def sweep(
    body: Body | str | os.PathLike[str],
    *,
    spin: AxisValues = 0.0,
    tilt_deg: AxisValues = 0.0,
    vary: Mapping[str, AxisValues] | None = None,
    runs: int = 1,
    seed: int = 0,
    duration: float = 4.0,
    samples: int = 481,
    rtol: float = 1e-12,
    gravity: float | None = None,
    tilt_axis: str = "y",
    max_steps: int | None = None,
    spin_axis: str | Sequence[float] | None = None,
    workers: int | None = None,
    dask: str | None = None,
    mass_properties: bool = False,
    check_budget: bool = True,
    out: Destination | None = None,
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> SweepTable:
    """Many simulations of one body — a grid over spin, tilt and numbers of the spec, or Monte
    Carlo draws — as ``rbi sweep`` runs them (on every core). A failed run never stops the
    others: its row says why in ``status``. Returns a `SweepTable`.

    Args:
        body: the `Body`, or its spec file's path (the spec is varied; files it names are read beside it).
        spin: initial spin about the spin axis, rad/s: one number, the grid's values (numbers,
            or ``Grid(start, stop, count)``), or a draw per run: ``Normal(mean, sd)``, ``Uniform(low, high)``.
        tilt_deg: the nudge at t = 0, degrees, given the same way.
        vary: numbers of the spec, path → values given as ``spin``'s:
            ``{"parts.bolt.mass": [0.01, 0.02]}``, ``{"parts.bolt.position[0]": Normal(0.04, 0.001)}``.
        runs, seed: Monte Carlo draws of every `Normal`/`Uniform` per grid point; their seed.
        duration, samples, rtol, gravity, tilt_axis, max_steps, spin_axis: as `simulate`'s (per
            run; one spin axis for every run, the nominal body's unless given).
        workers, dask: cores to use (None: all); or a Dask scheduler's address, or ``"local"``.
        mass_properties: simulate nothing: each row gives the mass properties at the varied values.
        check_budget: refuse a sweep estimated past rbi's step budget (about four core-hours).
        out, resume, progress: stream the rows to a ``.csv`` or ``.parquet`` file as runs end
            (past 100,000 runs, only there; never a file the body is read from); continue the
            sweep already in it; called with (runs done, runs).

    Raises:
        ValueError, TypeError: a setting or a variation is invalid (named as this function's
            parameter), or the sweep has more than 100,000 runs and no ``out``.
    """
    # not at top level: `rbi inertia` would load rbi.sweeps.study too
    from rbi.sweeps.study import Study, SweepSettings, check_settings

    grid = (spin, tilt_deg, _variations(vary), runs, seed, duration, samples, rtol, gravity, tilt_axis)
    settings = SweepSettings(*grid, max_steps, workers, dask, mass_properties, check_budget, spin_axis)
    check_settings(settings)
    path, raw, spec_bytes = _spec_source(body)
    read = body if isinstance(body, Body) else path  # a Body: every file it was read from
    target = None if out is None else _output(out, ("csv", "parquet"), read, "out")
    study = Study(path, raw, settings, rows_printed=out is None, spec_bytes=spec_bytes)
    swept, target = _swept(body, study, out, target)
    return SweepTable(study, study.run(target, resume, progress), swept)


def _swept(
    body: Any, study: Any, out: Destination | None, target: OutputTarget | None
) -> tuple[Body, OutputTarget | None]:
    """`sweep`'s `Body` and ``out``'s target. For a spec path, the nominal body the study has
    just translated, whose files are known only now: ``out`` is checked again against each
    file it was read from (`Body.files_read`), before any run."""
    if isinstance(body, Body):
        return body, target
    nominal = Body(study.nominal, study.raw, study.spec_bytes)
    return nominal, None if out is None else _output(out, ("csv", "parquet"), nominal, "out")


def _variations(vary: Any) -> tuple[tuple[str, Any], ...]:
    """`sweep`'s ``vary`` as (path, values) pairs."""
    if vary is not None and not isinstance(vary, Mapping):
        raise TypeError(f"vary: expected a mapping of spec paths to values, got {type(vary).__name__}")
    return tuple((str(path), value) for path, value in (vary or {}).items())


def _spec_source(body: Any) -> tuple[str, Any, bytes | None]:
    """`sweep`'s ``body`` as (path, parsed spec, the bytes of its file as read: None for text, a
    dict or standard input): a `Body`'s, or a spec file read once (a sweep validates each varied
    spec, not the file as it stands, and hashes those bytes for ``resume``)."""
    if isinstance(body, (str, os.PathLike)):
        # not at top level: `rbi audit` would load rbi.spec.load too
        from rbi.spec.load import read_spec

        path = os.fsdecode(os.fspath(body))
        return (path, *read_spec(path))
    return _loaded(body, "body").path, body._raw, body._spec_bytes


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
    out: Destination | None = None,
    allow_outside_paths: bool | None = None,
    mesh_repair: bool = False,
) -> AuditReport:
    """Audit a robot file (URDF ``.urdf``, SDF ``.sdf``, MJCF ``.xml``, or ``.xacro`` with the
    ``xacro`` extra) as ``rbi audit`` does: each link's declared mass properties against its own
    geometry, with flags, and the whole robot's totals. SI units; vectors and matrices in each
    link's frame (totals: the root link's frame for URDF/SDF, the world for MJCF). Returns an
    `AuditReport`: ``.links`` (each with ``.declared``, ``.geometry``, ``.ratios``, ``.flags``),
    ``.total``, ``.notes``, ``.exit_code`` (1 when a link has an error-level flag, else 0) and
    ``.as_dict()`` (what ``rbi audit --format json`` prints).

    Args:
        robot_file: the file's path.
        package_paths: ``{NAME: DIR}`` or ``["NAME=DIR", ...]`` for ``package://NAME/`` meshes
            (``ROS_PACKAGE_PATH`` is searched too).
        geometry: ``"collision"`` or ``"visual"``: which geometry gives a link's volume (a link
            without it falls back to the other); ``"none"``: the declared inertials and totals only.
        density, material: kg/m³, or a built-in material name, for links that declare no mass.
        mesh_inertia: ``"auto"`` (exact where a mesh is closed, else its convex hull, flagged
            ``mesh``), ``"exact"``, ``"convex"`` (its hull) or ``"shell"`` (mass on the surface).
        joints: ``{NAME: VALUE}`` or ``["NAME=VALUE", ...]``: radians for revolute/hinge joints,
            metres for prismatic/slide; the others at zero (MJCF: ``qpos0``).
        fix, out: also plan the fixed copy (``report.fix.content``, bytes; ``.changes``,
            ``.unfixable``); and write it at ``out`` (``.urdf``, ``.sdf`` or ``.xml``; never a
            file the robot reads), replaced atomically.
        allow_outside_paths: let the file name meshes and includes outside its folder; None:
            as an enclosing `outside_paths_allowed` block says (not allowed outside one).
        mesh_repair: close meshes' holes of three or four edges first (listed in ``report.notes``).

    Raises:
        SpecError: the file cannot be read, is malformed, names a mesh that cannot be found or
            read, or repeats a link name; ``out`` cannot be written.
    """
    # not at top level: `rbi inertia` would load rbi.robot.audit too
    from rbi.robot import audit as run_audit

    if out is not None and not fix:
        raise ArgumentError("out", "writes the fixed copy, so it needs {fix=True}")
    target = None if out is None else _output(out, ("urdf", "sdf", "xml"), _path(robot_file), "out")
    allowed = outside_paths_are_allowed() if allow_outside_paths is None else allow_outside_paths
    settings: dict[str, Any] = dict(package_paths=package_paths, geometry=geometry, material=material)
    settings |= dict(density=density, mesh_inertia=mesh_inertia, joints=joints, mesh_repair=mesh_repair)
    report = run_audit(_path(robot_file), fix=fix, allow_outside_paths=allowed, **settings)
    if target is not None:
        from rbi.robot.fix import check_out_not_read  # the files the robot reads

        check_out_not_read(target.path, report.model)  # an include, a mesh or the robot file itself
        write_output(target, report.fix.content)
    return report


@dataclass(frozen=True)
class ImportedLink:
    """One link of a robot file with mass properties, as ``rbi import`` turns it into a spec
    (SI units: kg, m, kg·m²; the link's own frame).

    Attributes:
        name: the link's name (None for an unnamed MJCF body); ``label``: how messages name it.
        index: its place among the file's links.
        mass: kg. center_of_mass: (3,) m, link frame.
        inertia: (3, 3) kg·m² about the centre of mass, in the link's axes.
        inertial_quaternion: (4,) [w, x, y, z], the inertial frame's orientation in the link frame.
        problems: why the declared values are not physical, one line each (empty when fine).
        yaml: the link's spec (one custom part) as YAML text under a comment header.
    """

    name: str | None
    label: str
    index: int
    mass: float
    center_of_mass: np.ndarray
    inertia: np.ndarray
    inertial_quaternion: np.ndarray
    problems: list[str]
    yaml: str


@dataclass(frozen=True)
class RobotImport:
    """A robot file read as ``rbi import`` reads it: ``path``; ``format`` (``"urdf"``, ``"sdf"``,
    ``"mjcf"``); ``name`` (the model's); ``link_word`` (``"link"``, or ``"body"`` for MJCF);
    ``links``, the `ImportedLink` s asked for; ``skipped``, ``(label, reason)`` of each link
    without mass properties; ``robot_yaml()``, the whole robot as one spec."""

    path: str
    format: str
    name: str | None
    link_word: str
    links: list[ImportedLink]
    skipped: list[tuple[str, str]]
    model: Any = field(default=None, repr=False)
    """The file as rbi reads it (its links, with their geometry)."""

    def robot_yaml(self) -> str:
        """The whole robot as one spec (YAML text under a comment header): one custom part per
        link with mass, placed at the zero configuration (MJCF: ``qpos0``), SI units."""
        # not at top level: `rbi inertia` would load rbi.robot.specs and rbi.spec.yaml_writer too
        from rbi.robot.specs import robot_spec
        from rbi.spec.yaml_writer import comment, dump

        model = self.model
        spec, left_out = robot_spec(model)
        frame = (
            "the world frame at qpos0"
            if model.format == "mjcf"
            else "the root link's frame, every joint at zero"
        )
        lines = [
            f"rbi import of {os.path.basename(model.path)}: the whole robot, one custom part per "
            f"{model.link_word} with mass,",
            f"placed in {frame}; SI units.",
            "One link alone, in its own frame: --link NAME; one spec per link: --out DIR/.",
        ]
        if left_out:
            lines.append(f"Without mass (left out): {', '.join(left_out)}.")
        return comment(*lines) + dump(spec)


def _path(value: object, name: str = "robot_file") -> str:
    """``value`` as a str path; TypeError naming the parameter ``name`` for anything but a path."""
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{name}: expected a path (str or os.PathLike), got {type(value).__name__}")
    return os.fsdecode(os.fspath(value))


def import_robot(
    robot_file: str | os.PathLike[str],
    *,
    links: Sequence[str] | None = None,
    package_paths: dict[str, str] | Sequence[str] | None = None,
) -> RobotImport:
    """Read the links of a robot file (URDF, SDF, MJCF) that have mass properties, as ``rbi
    import`` does: each one's mass, centre of mass and inertia (SI, link frame) and its spec.

    Args:
        robot_file: the file's path.
        links: the names of the links to import (MJCF: bodies), in order; None: every one.
        package_paths: as `audit`'s, for ``package://NAME/`` paths.

    Raises:
        SpecError: the file cannot be read or is malformed; no link has mass properties.
        ValueError: a name in ``links`` names no link with an ``<inertial>``.
    """
    # not at top level: `rbi inertia` would load rbi.formats.robot_files and rbi.formats.robot_paths too
    from rbi.formats.robot_files import link_problems, read_robot
    from rbi.formats.robot_paths import parse_package_paths

    packages = parse_package_paths(package_paths)
    robot = read_robot(_path(robot_file), packages)
    chosen = _chosen_links(robot, _link_names(links))
    if not chosen:
        raise SpecError(f"{robot.path}: no {robot.link_word} with an <inertial> element to import")
    imported = [
        ImportedLink(
            link.name,
            link.label,
            link.index,
            float(link.inertial.mass),
            np.asarray(link.inertial.properties.center_of_mass),
            np.asarray(link.inertial.properties.inertia_about_com),
            _inertial_quaternion(link.inertial),
            link_problems(robot, link),
            _link_yaml(robot, link),
        )
        for link in chosen
    ]
    return RobotImport(robot.path, robot.format, robot.name, robot.link_word, imported, robot.skipped, robot)


def _inertial_quaternion(inertial: Any) -> np.ndarray:
    """``[w, x, y, z]`` of the inertial frame: the file's own quaternion, else the identity or the
    rotation's."""

    if inertial.quaternion is not None and inertial.rpy is None:
        return np.asarray(inertial.quaternion)
    R = inertial.rotation
    return np.array([1.0, 0.0, 0.0, 0.0]) if R is None else matrix_to_quaternion(R)


def _link_yaml(robot: Any, link: Any) -> str:
    """One link's spec: a comment header, then the spec written by the YAML dumper. Names from
    the file are data: escaped in the comment, quoted and escaped by the dumper where they hold
    anything but visible characters (:mod:`rbi.spec.yaml_writer`)."""
    # not at top level: `rbi inertia` would load rbi.formats.robot_files and rbi.spec.yaml_writer too
    from rbi.formats.robot_files import link_spec
    from rbi.spec.yaml_writer import comment, dump

    source = {"urdf": "URDF", "sdf": "SDF", "mjcf": "MJCF"}[robot.format]
    header = comment(
        f"rbi import of {os.path.basename(robot.path)}, {link.label}, from its {source} <inertial>:",
        "SI units, link frame; the inertia is about the centre of mass in the inertial frame's axes,",
        "turned into link axes by `rotation`.",
    )
    return header + dump(link_spec(robot, link))


def _link_names(links: Any) -> list[str]:
    """``links`` of :func:`import_robot` as a list of names (one name given as text is that
    name); ArgumentError naming ``links`` for anything else."""
    if links is None or isinstance(links, str):
        return [] if links is None else [links]
    names = list(links) if isinstance(links, Iterable) else None
    if names is None or not all(isinstance(name, str) for name in names):
        raise ArgumentError("links", f"expected link names (str), got {literal(links)}")
    return names


def _chosen_links(robot: Any, names: list[str]) -> list[Any]:
    """The links named in ``names`` (every one when empty), each once, in the order named."""
    if not names:
        return robot.inertial_links
    by_name = {each.name: each for each in robot.inertial_links}
    missing = [name for name in names if name not in by_name]
    if missing:
        hint = difflib.get_close_matches(missing[0], [n for n in by_name if n], n=1)
        raise ArgumentError(
            "links",
            f"{robot.path} has no {robot.link_word} named {literal(missing[0])} with an <inertial>"
            + (f" (did you mean {literal(hint[0])}?)" if hint else ""),
        )
    return [by_name[name] for name in dict.fromkeys(names)]


Destination = str | os.PathLike[str] | OutputTarget
"""Where a picture or a file of rows goes: a path (its extension gives the format), or a target
`output_target` has already checked (a caller's own messages then name it)."""


def _output(
    path: Destination,
    formats: tuple[str, ...],
    read: str | os.PathLike[str] | Body,
    name: str = "path",
) -> OutputTarget:
    """``path`` checked as an output of one of ``formats`` (its extension) by rbi's one checked
    writer (:mod:`rbi.files.output`): never the file ``read`` (a spec, a robot file), nor for a
    `Body` any file it was read from (`Body.files_read`: a target checked before the body was
    loaded is checked against them now, its refusal naming its option). ArgumentError naming
    the parameter ``name`` when it may not be written there."""
    reads = read.files_read if isinstance(read, Body) else [os.fsdecode(os.fspath(read))]
    if isinstance(path, OutputTarget):
        if isinstance(read, Body) and not path.is_stdout:
            output_target(path.given, path.option, (path.format,), inputs=reads)
        return path
    given = _path(path, name)
    try:
        return output_target(given, name, formats, inputs=reads)
    except ArgumentError:
        raise
    except SpecError as exc:
        raise ArgumentError(name, literal(str(exc).removeprefix(f"{name}: "), quoted=False)) from None


def show(body: Body, path: Destination, *, title: str | None = None) -> int:
    """Draw the body as specified at ``path``, as ``rbi show`` does: every part in place (holes
    red and translucent), the centre of mass, the principal axes about it (lengths in
    proportion to their moments, labelled with them) and the pivot, in the body frame with
    lengths in the spec's unit. ``.png`` or ``.svg`` (needs matplotlib), or ``.html`` (a 3D
    page that opens offline). The file is replaced atomically; ``title`` defaults to the
    spec's name, else its path. Returns the number of parts drawn.

    Raises:
        SpecError: ``path`` cannot be written, or its extension is none of those."""
    from rbi.viz.still import draw_body  # matplotlib and the page's template load only to draw

    loaded = _loaded(body, "body")
    return draw_body(loaded, _output(path, ("png", "svg", "html"), body), title)


@dataclass(frozen=True)
class Animation:
    """What `animate` wrote: ``path``; ``frames``, the pictures in it (a page's keyframes, a
    GIF's frames); ``max_tilt_deg``, the largest tilt of the spin axis from the upward
    vertical over the run, degrees."""

    path: str
    frames: int
    max_tilt_deg: float


def animate(
    body: Body,
    path: Destination,
    *,
    speed: float = 1.0,
    fps: int = 25,
    progress: Callable[[int, int], None] | None = None,
    **run: Any,
) -> Animation:
    """Animate the body's motion, simulated as `simulate` does, at ``path`` as ``rbi animate``
    does: ``.html``, a self-contained 3D page (parts as solids, pivot, ground, the path of the
    tip of the spin axis) that plays in real time, or ``.gif`` (needs matplotlib and pillow).

    Args:
        body, path: the `Body`; the file to write (replaced atomically).
        speed: playback speed the page starts at, 0.1 to 2 (1: real time).
        fps: frames per second of a GIF, 1 to 60.
        progress: called with (frames drawn, frames) as a GIF is drawn.
        run: `simulate`'s settings: ``spin``, ``omega``, ``tilt_deg``, ``tilt_axis``,
            ``gravity``, ``duration``, ``rtol``, ``max_steps``, ``check_budget``, ``spin_axis``.

    Raises:
        ValueError: a setting is out of range (named as this function's parameter), or the
            motion needs more keyframes (or GIF frames) than a file may hold.
        SpecError: ``path`` cannot be written; the run cannot be made."""
    from rbi.runs.animation import write_animation  # the integrator loads only to simulate

    # not at top level: `rbi inertia` would load rbi.runs.run too
    from rbi.runs.run import prepare_run

    loaded = _loaded(body, "body")
    target = _output(path, ("html", "gif"), body)
    prepared = prepare_run(loaded, **run)
    frames, tilt = write_animation(prepared, target, speed=speed, fps=fps, progress=progress)
    return Animation(target.given, frames, tilt)


def __getattr__(name: str) -> Any:
    # imported on first use: `rbi inertia` loads neither the audit's modules nor the sweep's
    if name == "AuditReport":
        # not at top level: `rbi inertia` would load rbi.robot.audit too
        from rbi.robot.audit import AuditReport

        return AuditReport
    if name == "import_step":  # read a STEP file as `rbi import FILE.step` does
        # not at top level: `rbi inertia` would load rbi.spec.from_step too
        from rbi.spec.from_step import import_step

        return import_step
    if name in ("Grid", "Normal", "Uniform"):
        # not at top level: `rbi inertia` would load rbi.sweeps.plan too
        from rbi.sweeps import plan

        return getattr(plan, name)
    if name == "DEFAULT_MAX_STEPS":  # most integration steps of a run unless max_steps says otherwise
        # not at top level: `rbi inertia` would load rbi.sim.budget too
        from rbi.sim.budget import DEFAULT_MAX_STEPS

        return DEFAULT_MAX_STEPS
    if name == "MAX_ROWS_SHOWN":  # most runs a sweep holds in memory (more: in its out file only)
        # looked up per call: tests replace it
        from rbi.sweeps.study import MAX_ROWS_SHOWN

        return MAX_ROWS_SHOWN
    if name == "available_cores":  # the cores this process may use: sweep's default workers
        # looked up per call: tests replace it
        from rbi.sweeps.execute import available_cores

        return available_cores
    raise AttributeError(f"module 'rbi.api' has no attribute {name!r}")
