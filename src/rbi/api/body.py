"""Bodies: `load` and `loads` a spec, a `Body`'s mass properties (`Principal`, `Part`, `Momentum`,
`Dynamics`, `Check`) and its export."""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from rbi.api.checks import Checks, Validation
from rbi.api.results import (
    PRODUCT_SIGN_TITLES,
    About,
    Dynamics,
    Export,
    Inertia,
    Momentum,
    Part,
    Parts,
    Principal,
)
from rbi.api.uncertainty import UncertaintyBudget
from rbi.core.dynamics import (
    angle_between_deg,
    angular_momentum_about_point,
    kinetic_energy,
    newton_euler_about,
)
from rbi.core.inertia import (
    OFF_DIAGONAL,
    moment_about_axis,
    principal_axes,
    radii_of_gyration,
    re_express,
    symmetric_eigen,
    unit_axis,
)
from rbi.core.mass import MassProperties, inertia_shares
from rbi.core.rotation import angle_is_kept, compose_world_rotations, turn_lost_to_rounding
from rbi.core.validity import require_flags
from rbi.errors import ArgumentError, SpecError, literal, one_of
from rbi.formats.inertial_xml import FORMATS, export_xml
from rbi.formats.paths import outside_paths_allowed, outside_paths_setting
from rbi.formats.robot_paths import parse_package_paths
from rbi.reprs import Result, Rows
from rbi.runs.values import vector_value
from rbi.spec import load as spec_load
from rbi.spec.assembly import expanded
from rbi.spec.checks import run_checks
from rbi.spec.load import file_problems
from rbi.spec.models import StepPart, body_spec_json_schema
from rbi.spec.points import NO_PIVOT, REFERENCE_POINTS, reference_choices, reference_name
from rbi.spec.uncertain import StandardUncertainty, budget, linear, momentum_uncertainty, part_uncertainties
from rbi.spec.units import LENGTH_UNITS_IN_M as LENGTH_UNITS
from rbi.spec.units import MASS_UNITS_IN_KG as MASS_UNITS
from rbi.spec.units import convert_body
from rbi.spec.volumes import part_volume
from rbi.text import number, vector_text

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
        ValueError: ``source`` is spec text, not a path (it holds a newline or starts with
            ``{`` or ``[``, and no such file exists): read text with `loads`.
    """
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
    path = os.fsdecode(os.fspath(source))  # a PathLike may give bytes
    if ("\n" in path or path.lstrip()[:1] in ("{", "[")) and not os.path.lexists(path):
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

    allowed = outside_paths_setting(allow_outside_paths)
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
) -> Validation:
    """Check spec files without computing anything, as ``rbi validate`` does: for each path,
    the list of its problems, one line each (empty when the file is valid), as a `Validation`
    (its ``to_dict()`` is the command's JSON). A robot file (URDF,
    SDF, MJCF) gives every link whose inertia is not physical; ``package_paths`` (``{NAME:
    DIR}`` or ``["NAME=DIR", ...]``) finds its ``package://`` meshes. SpecError for a bad
    ``package_paths``."""
    packages = parse_package_paths(package_paths)
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    if not isinstance(paths, Sequence) or not all(isinstance(p, (str, os.PathLike)) for p in paths):
        raise TypeError(f"paths: expected a path (str or os.PathLike) or a list of them, got {paths!r:.80}")
    files = [spec_load.spec_label(os.fspath(path)) for path in paths]
    return Validation(files, [file_problems(os.fspath(path), packages) for path in paths])


def spec_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a body spec, as ``rbi schema`` prints it (for
    editors: see docs/schema.md)."""
    return body_spec_json_schema()


def unit_vector(direction: Sequence[float] | np.ndarray) -> np.ndarray:
    """``direction / |direction|`` as (3,), for any finite non-zero vector however large or
    small its components (1e-300 and 1e300 alike); ArgumentError naming ``direction`` else."""
    return _unit(direction, "direction")


def _unit(value: Sequence[float] | np.ndarray, parameter: str) -> np.ndarray:
    """`unit_vector` of ``value``, the argument ``parameter`` of a public function or method."""
    try:
        return unit_axis(value)
    except (ValueError, TypeError):
        raise ArgumentError(
            parameter, f"must be a non-zero finite vector (x, y, z), got {literal(value)}"
        ) from None


class Body(Result):
    """A validated rigid body, as `load` returns it (not constructed directly).

    All numbers are in the spec's own units (`units`) and the body frame (the spec's
    coordinates). A Body does not change; every method returns new arrays.
    """

    length_units: ClassVar[tuple[str, ...]] = tuple(LENGTH_UNITS)
    """The length units `in_units` takes: ``m``, ``cm``, ``mm``, ``in``, ..."""
    mass_units: ClassVar[tuple[str, ...]] = tuple(MASS_UNITS)
    """The mass units `in_units` takes: ``kg``, ``g``, ``lb``, ..."""
    reference_points: ClassVar[tuple[str, ...]] = REFERENCE_POINTS
    """The points `point` knows by name (any case, spaces around): ``com``, ``origin``, ``pivot``."""

    def __init__(self, loaded: Any, raw: Any = None, spec_bytes: bytes | None = None) -> None:
        self._loaded = loaded
        self._raw = raw
        self._spec_bytes = spec_bytes  # the spec file's bytes as read (None: text, a dict, stdin)
        self._file_length: str = loaded.length_unit  # the spec's length unit (before `in_units`)
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
        from rbi.runs.run import body_spin_axis  # not at top level: `rbi inertia` would load the integrator

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

    def _place(self, about: Point) -> About:
        """The point ``about`` as a result names it (`About`: ``com``, ``origin``, ``pivot`` or
        ``point``) and its body coordinates (`point`)."""
        return About(self, reference_name(about) or "point", self.point(about))

    def _refuse_non_finite(self, where: str = "", **results: Any) -> None:
        """ValueError (an `ArgumentError` naming the file, then ``where``: a part) when a result
        overflowed: inputs of absurd size (``about=(1e200, 0, 0)``, ``omega=(1e200, 0, 0)``,
        units that scale 1e305 past a double) give inf or NaN, which no caller can use (the CLI
        prints the message as bad input, exit 2, in every output form)."""
        bad = [
            name for name, value in results.items() if value is not None and not np.all(np.isfinite(value))
        ]
        if bad:
            raise ArgumentError(
                (),
                f"{literal(where, quoted=False)}result{'s' if len(bad) > 1 else ''} {', '.join(bad)} "
                f"{'are' if len(bad) > 1 else 'is'} not finite: the input values are too large for double precision",
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

        place = self._place(about)
        moments, axes = principal_axes(self.inertia(about))
        with np.errstate(over="ignore", invalid="ignore"):
            radii = np.asarray(radii_of_gyration(list(moments), self.mass))
        self._refuse_non_finite(radii_of_gyration=radii)
        spread = self.standard_uncertainty(about)
        # + 0.0: no -0.0 components (the CLI prints 0 there too)
        return Principal(
            moments=np.asarray(moments) + 0.0,
            axes=np.asarray(axes) + 0.0,
            radii_of_gyration=radii,
            about=place.point,
            place=place,
            uncertainty=None if spread is None else spread.only("moments", "axes_deg"),
        )

    def inertia_report(
        self,
        about: Point = "com",
        axes: Sequence[tuple[str, float]] | None = None,
        *,
        products: str = "tensor",
        axis: Sequence[float] | None = None,
    ) -> Inertia:
        """The inertia about a point as ``rbi inertia`` gives it (`Inertia`: ``to_dict()``,
        its tables): `inertia` ``(about, axes)`` with the products' sign ``products``
        (``"tensor"``, ``I_xy = −∫xy dm``, or ``"cad"``, ``+∫xy dm``), and with ``axis`` the
        moment about the line through ``about`` along it (`moment_about_axis`)."""

        one_of("products", products, PRODUCT_SIGN_TITLES)
        matrix = self.inertia(about, axes)  # a new array: its products may change sign; axes checked
        turns = list(axes or [])
        if products == "cad":
            matrix[OFF_DIAGONAL] = 0.0 - matrix[OFF_DIAGONAL]  # 0.0 - 0.0 is +0.0, no '-0' printed
        direction = None if axis is None else _unit(axis, "axis")
        spread = self.standard_uncertainty(about, turns or None)
        return Inertia(
            self._place(about),
            matrix,
            "world (rotated)" if turns else "body",
            tuple(f"{a}:{np.degrees(np.radians(float(d))):g}" for a, d in turns),
            products,
            direction,
            None if direction is None else self.moment_about_axis(direction, about, turns or None),
            None if spread is None else spread.only("inertia"),
        )

    def to_dict(self) -> dict[str, Any]:
        """What ``rbi inertia`` prints with ``--format json`` (about the centre of mass, body
        axes), less ``"file"``: see `inertia_report`."""
        return self.inertia_report().to_dict()

    def parts(self, expand: bool = False) -> Parts:
        """Each part's mass properties, in file order: the `Parts` table (a sequence of `Part`,
        with the body's totals), as ``rbi parts`` lists them; ``expand``: each
        sub-assembly (``shape: assembly``) listed as its own parts, named ``ASSEMBLY/PART``
        (``ASSEMBLY[i]/PART`` for the copies of a pattern), placed in the body."""
        loaded = self._loaded
        require_flags(expand=expand)
        rows = expanded(loaded, expand)
        shares = inertia_shares(list(rows.elements), loaded.props)
        spreads = part_uncertainties(loaded, expand) if self._uncertain else [None] * len(rows.names)
        out = []
        for name, part, element, length, share, spread in zip(
            rows.names, rows.parts, rows.elements, rows.lengths, shares, spreads
        ):
            hole = bool(getattr(part, "subtract", False))
            volume = None if part is None else part_volume(part)
            if volume is not None:  # a hole takes its volume away, as its mass
                volume = (-volume if hole else volume) * length**3
            out.append(
                Part(
                    name=name,
                    shape=part.shape if part is not None else "point_cloud",
                    hole=hole,
                    mass=float(element.mass),
                    center_of_mass=np.array(element.center_of_mass, dtype=float),
                    inertia_about_com=np.array(element.inertia_about_com, dtype=float),
                    volume=volume,
                    principal_moments=symmetric_eigen(np.asarray(element.inertia_about_com, dtype=float))[0],
                    inertia_share=float(share),
                    integration_error=part._integration_error if isinstance(part, StepPart) else None,
                    uncertainty=spread,
                )
            )
        return Parts(self, out)

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
        place = self._place(about)
        point = place.point
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
            place=place,
            uncertainty=momentum_uncertainty(self._loaded, point, w, None if velocity is None else v_com)
            if self._uncertain
            else None,
        )

    @property
    def _uncertain(self) -> bool:
        return self._loaded.spec is not None and bool(self._loaded.spec._uncertain)

    def uncertainty(
        self,
        of: str | Sequence[str] | None = None,
        method: str = "linear",
        samples: int = 100_000,
        seed: int | None = None,
        coverage: float = 0.95,
    ) -> UncertaintyBudget:
        """The uncertainty budget of the numbers the spec writes with ± (``rbi uncertainty``).

        Args:
            of: the quantities, as JSON paths of ``rbi inertia`` / ``rbi principal``
                (``"mass"``, ``"center_of_mass[0]"``, ``"inertia[0][2]"``, ``"moments[1]"``);
                None: mass, centre of mass, the inertia about it and the principal moments.
            method: ``"linear"`` (the law of propagation, JCGM 100) or ``"monte-carlo"``
                (JCGM 101: ``samples`` draws of every input, reproducible with ``seed``; 2 to
                10,000,000, and no more than 2 GiB holds of the draws and their 16 quantities:
                an `ArgumentError` of ``samples`` says how many the body allows).
            coverage: the coverage probability of each interval.
        """
        return UncertaintyBudget(budget(self._loaded, of, method, samples, seed, coverage))

    def standard_uncertainty(
        self, about: Point = "com", axes: Sequence[tuple[str, float]] | np.ndarray | None = None
    ) -> StandardUncertainty | None:
        """The combined standard uncertainty (GUM 5.1.2, first order) of ``mass``,
        ``center_of_mass``, ``inertia`` (about ``about``, in ``axes`` as `inertia` takes them),
        ``moments`` (about ``about``) and ``axes_deg`` (each principal axis's angular
        uncertainty, degrees; None for an axis of a pair of moments closer than 3 combined
        uncertainties); None when the spec writes no number with ±."""
        if not self._uncertain:
            return None
        spread = linear(self._loaded, self.point(about)).standard(None if axes is None else _rotation(axes))
        self._refuse_non_finite(
            "uncertainty: ", mass=spread.mass, center_of_mass=spread.center_of_mass, inertia=spread.inertia
        )
        return spread

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

        one_of("length", length, LENGTH_UNITS)
        one_of("mass", mass, MASS_UNITS)
        with np.errstate(over="ignore", invalid="ignore"):
            body = Body(convert_body(self._loaded, length, mass), self._raw, self._spec_bytes)
        props, elements, names = body._loaded.props, body._loaded.elements, body._loaded.part_names
        if not all(np.all(np.isfinite(value)) for value in props.to_dict().values()):
            for i, element in enumerate(elements):  # the part to blame, when one is
                part = f"parts[{i}]" + (f" ({names[i]})" if i < len(names) and names[i] else "")
                body._refuse_non_finite(f"{part}: in {length} and {mass}, ", **element.to_dict())
            body._refuse_non_finite(f"in {length} and {mass}, ", **props.to_dict())
        body._file_length = self._file_length
        return body

    def from_spec_units(self, lengths: Point | None) -> Point | None:
        """A point or a velocity given in the spec file's length unit, in this body's (which
        `in_units` may have changed); None and a point's name (``"pivot"``) stay as they are."""
        if lengths is None or isinstance(lengths, str):
            return lengths
        factor = LENGTH_UNITS[self._file_length] / LENGTH_UNITS[self._loaded.length_unit]
        return [factor * x for x in vector_value(lengths, "lengths")]

    def moment_about_axis(
        self,
        axis: Sequence[float] | np.ndarray,
        about: Point = "com",
        axes: Sequence[tuple[str, float]] | None = None,
    ) -> float:
        """The scalar moment of inertia ``nᵀ I n`` (mass·length²) about the line through
        ``about`` along ``axis`` (any non-zero length), with ``axis`` in the axes of
        ``inertia(about, axes)``: body axes, or world axes after ``axes``."""

        matrix = self.inertia(about, axes)
        try:
            with np.errstate(over="ignore", invalid="ignore"):
                moment = moment_about_axis(matrix, axis)  # type: ignore[arg-type]  # an array is a sequence
        except ValueError:
            raise ArgumentError(
                "axis", f"must be a non-zero finite direction (x, y, z), got {literal(axis)}"
            ) from None
        self._refuse_non_finite(moment=moment)
        return moment

    def check(self) -> Checks:
        """Each expectation of the spec's ``expect:`` block (see docs/check.md) against the
        body, as ``rbi check`` compares them (see `Check`), in the spec's units. SpecError when
        the spec has none."""

        loaded, spec = self._loaded, self._loaded.spec
        if spec is not None:  # back in the spec's units after `in_units` (else the body as it is)
            loaded = convert_body(loaded, spec.units.length, spec.units.mass)
        return Checks(self, run_checks(loaded))

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
            raise ArgumentError(
                (),
                "dynamics: give either {alpha} (inverse: force and torque) or {force}/{torque} (forward: accelerations)",
            )
        place = self._place(about)
        point = place.point
        props = self._loaded.props
        inertia = self.inertia(about)
        if alpha is None and np.linalg.matrix_rank(inertia) < 3:
            where = f"point {literal(point.tolist())}" if place.label == "point" else place.label
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
                props, inertia, props.center_of_mass - point, w, about_com=place.label == "com", **vectors
            )
        self._refuse_non_finite(linear_acceleration=linear, angular_acceleration=angular, force=f, torque=t)
        mode = "inverse" if alpha is not None else "forward"
        return Dynamics(mode, point, w, angular, linear, f, t, held, place)

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

        return self.export(to, name=name, document=document, diagonal=diagonal).xml

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

    def export(
        self, to: str, *, name: str | None = None, document: bool = False, diagonal: bool = False
    ) -> Export:
        """The `Export` ``rbi export`` prints: `inertial_xml` (the same arguments), its
        `export_warnings` and the SI mass properties it holds."""

        one_of("to", to, FORMATS)
        require_flags(document=document, diagonal=diagonal)
        if diagonal and to != "mjcf":
            raise ArgumentError(
                "diagonal",
                "only for {to='mjcf'} (URDF and SDF take the full matrix about the centre of mass)",
            )
        length, mass = self.units["length"], self.units["mass"]
        spec_units = "" if (length, mass) == ("m", "kg") else f"; spec units were {length}, {mass}"
        comment = (
            f"rbi export of {Path(self.path).name}: SI units (kg, m, kg·m²); "
            f"inertia about the centre of mass, body axes{spec_units}"
        )
        if name is None:
            text = self.path in SPEC_TEXT_LABELS
            name = self.name or ("body" if text else Path(self.path).stem)
        elif not isinstance(name, str):  # not str(name): a list's repr as the link's name
            raise TypeError(f"name: must be text (got {type(name).__name__} {name!r:.60})")
        si = self.in_units("m", "kg")
        xml = export_xml(
            to, si.mass_properties, name=name, document=document, diagonal=diagonal, comment=comment
        )
        return Export(si.name, to, si.units, self.export_warnings(), si.mass_properties, xml)

    def __repr__(self) -> str:
        units = self.units
        return (
            f"<rbi.Body {self.name or self.path!r}: mass {number(self.mass)} {units['mass']}, "
            f"{len(self._loaded.elements)} parts, {'pivot' if self._loaded.pivot is not None else 'free'}>"
        )

    def rows(self) -> list[Rows]:
        labels = self.unit_labels
        principal = self.principal()
        rows = [
            ("mass", labels["mass"], number(self.mass, 8)),
            ("centre of mass", labels["length"], vector_text(self.center_of_mass)),
        ]
        if self._loaded.pivot is not None:
            rows.append(("pivot", labels["length"], vector_text(self.pivot)))
        rows.append(("principal moments about CoM", labels["inertia"], vector_text(principal.moments)))
        for i, axis in enumerate(principal.axes, start=1):
            rows.append((f"principal axis {i}", "", vector_text(axis)))
        rows.append(("parts", "", str(len(self._loaded.elements))))
        return [Rows.quantities(f"{self.name or self.path}", rows)]


def _rotation(axes: Any) -> np.ndarray:
    """A body → world rotation matrix from ``axes`` (see `Body.inertia`): a (3, 3) rotation
    matrix, or (axis, degrees) pairs applied in order about world axes."""

    if isinstance(axes, str) or not bool(np.iterable(axes)):  # bool: axes stays Any for mypy
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
            axis, given = turn
            axis, degrees = str(axis).strip().lower(), float(given)
        except (TypeError, ValueError, OverflowError):
            axis, degrees = "", float("nan")
        if axis not in ("x", "y", "z") or not np.isfinite(degrees):
            raise ArgumentError(
                "axes",
                f"expected (axis, degrees) pairs with axis 'x', 'y' or 'z', e.g. [('y', 30)], got {literal(turn)}",
            )
        if not angle_is_kept(degrees):
            # the angle as written when it is text (the CLI's --rotate y:1e300)
            raise ArgumentError(
                "axes", turn_lost_to_rounding(literal(given, quoted=not isinstance(given, str)))
            )
        turns.append((axis, np.radians(degrees)))
    return compose_world_rotations(turns)


def loaded_body(body: Any, parameter: str) -> Any:
    """The loaded body behind a `Body`; TypeError naming ``parameter`` for anything else."""
    if not isinstance(body, Body):
        raise TypeError(f"{parameter}: expected a Body from rbi.load (got {type(body).__name__})")
    return body._loaded
