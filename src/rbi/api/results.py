"""What a `Body` answers, as results that present themselves (:class:`rbi.reprs.Result`): the
inertia about a point (`Inertia`), `Principal`, `Momentum`, `Dynamics`, the `Parts` table, the
`Checks` of an ``expect:`` block and an `Export`. Each gives ``to_dict()`` (what its ``rbi``
command prints with ``--format json``, less ``"file"``), its CSV rows and its tables' rows, from
which ``print()``, the notebook's table and the CLI's tables are drawn.

Tables print a coordinate below 1e-12 of the body's size, and a matrix entry below 1e-12 of the
matrix's largest, as 0 (rounding noise); JSON and CSV keep every digit.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rbi.core.mass import MassProperties
from rbi.reprs import Result, Results, Rows
from rbi.spec.units import LENGTH_UNITS_IN_M, MASS_UNITS_IN_KG
from rbi.text import number, plus_minus, vector_text, without_noise

if TYPE_CHECKING:
    from rbi.spec.uncertain import StandardUncertainty

PRODUCT_SIGN_TITLES = {"tensor": "products −∫xy dm", "cad": "CAD products +∫xy dm"}
"""Signs of the off-diagonal entries: ``tensor`` (the matrix, ``I_xy = −∫xy dm``) or ``cad``
(the positive integrals ``+∫xy dm`` SolidWorks and CATIA print), with their tables' titles."""

MAX_TABLE_PARTS = 200
"""Most parts a table lists (then a row saying how many more): 10,000 rows took rich 25 s to lay
out, and a person reads the CSV or JSON of a body that large, which list every part."""


def matrix_digits(matrix: Any) -> tuple[float, str]:
    """A common power-of-ten scale for a matrix, so a table can print ``×10⁻⁶`` once."""
    peak = float(np.max(np.abs(matrix))) if np.size(matrix) else 0.0
    if peak == 0.0 or 1e-3 <= peak < 1e4 or not 1e-300 < peak < 1e300:  # 10.0**-324 is 0: print as is
        return 1.0, ""
    exponent = int(math.floor(math.log10(peak)))
    return 10.0**exponent, "×10" + str(exponent).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))


def shown(values: Any, scale: float = 0.0, digits: int = 6) -> str:
    """A vector for a table: ``[x, y, z]`` without rounding noise (see :func:`without_noise`)."""
    return vector_text(values, digits, scale=scale)


def body_size(props: MassProperties) -> float:
    """A body's size for telling a position from rounding noise: its radius of gyration about
    the centre of mass, √(trace I / 2m), length unit (0 without mass or inertia)."""
    try:
        size = math.sqrt(float(np.trace(props.inertia_about_com)) / (2.0 * float(props.mass)))
    except (ValueError, ZeroDivisionError, OverflowError):
        return 0.0
    return size if math.isfinite(size) else 0.0


def named(body: Any) -> dict[str, Any]:
    """The keys a result of a body's ``to_dict()`` starts with: its ``name``, ``units`` and
    ``warnings``."""
    return {"name": body.name, "units": body.units, "warnings": list(body.warnings)}


@dataclass(frozen=True, repr=False)
class About:
    """What every result about a point starts with: the body's name, units, mass, centre of
    mass and warnings, and the point (``label``: ``com``, ``origin``, ``pivot`` or ``point``)."""

    body: Any = field(compare=False)
    label: str
    point: np.ndarray

    def to_dict(self) -> dict[str, Any]:
        """The keys a result about the point starts its JSON with (not JSON-ready: a result's
        ``to_dict()`` makes it so)."""
        body = self.body
        return {
            "name": body.name,
            "units": body.units,
            "mass": body.mass,
            "center_of_mass": body.center_of_mass,
            "about": self.point,
            "about_label": self.label,
            "warnings": list(body.warnings),
        }

    def title(self, what: str) -> str:
        return f"{self.body.name or self.body.path} — {what}"

    def place_rows(self, spread: StandardUncertainty | None = None) -> list[tuple[str, str, str]]:
        """The mass, the centre of mass and the point (a coordinate below 1e-12 of the body's
        size printed 0); with ``spread`` (`Body.standard_uncertainty`), the mass and centre of
        mass ``± u``."""
        body, labels = self.body, self.body.unit_labels
        size = body_size(body.mass_properties)
        mass, com = number(body.mass, 8), shown(body.center_of_mass, size)
        if spread is not None:
            mass = plus_minus(body.mass, spread.mass)
            com = f"{com} ± {shown(spread.center_of_mass, 0.0, 2)}"
        return [
            ("mass", labels["mass"], mass),
            ("centre of mass", labels["length"], com),
            (f"about ({self.label})", labels["length"], shown(self.point, size)),
        ]


def _placed(result: Any) -> dict[str, Any]:
    """The JSON of a result about a point (`Principal`, `Momentum`): its place's header (only
    ``about`` without one), its declared fields (``json_keys``), then ``uncertainty`` for a
    spec with ±."""
    head = result.place.to_dict() if result.place else {"about": result.about}
    spread = {} if result.uncertainty is None else {"uncertainty": result.uncertainty.to_dict()}
    return head | result.json_fields() | spread


def matrix_rows(title: str, values: Any, unit: str) -> Rows:
    """A 3×3 matrix with a common power-of-ten scale written once in its header."""
    values = np.reshape(without_noise(np.ravel(values)), np.shape(values))
    scale, scale_text = matrix_digits(values)
    corner = f"[{unit}]" + (f" {scale_text}" if scale_text else "")
    cells = [(label, *(number(v / scale, 7) for v in row)) for label, row in zip("xyz", values)]
    return Rows(title, (corner, "x", "y", "z"), cells, kind="matrix")


@dataclass(frozen=True, repr=False)
class Inertia(Result):
    """The inertia matrix about a point, as ``rbi inertia`` gives it (spec units).

    Attributes:
        about: the point (`About`).
        matrix: (3, 3) in the axes ``frame`` names, products with ``products_sign``.
        frame: ``"body"``, or ``"world (rotated)"`` after ``rotations`` (``"y:30"``, in order).
        products_sign: ``"tensor"`` (``I_xy = −∫xy dm``) or ``"cad"`` (``+∫xy dm``).
        axis, moment_about_axis: a unit direction and the moment about the line along it
            through the point (None when no axis was asked for).
    """

    about: About
    matrix: np.ndarray
    frame: str = "body"
    rotations: tuple[str, ...] = ()
    products_sign: str = "tensor"
    axis: np.ndarray | None = None
    moment_about_axis: float | None = None
    uncertainty: StandardUncertainty | None = None
    """For a spec that writes numbers with ±: the standard uncertainty of ``mass``,
    ``center_of_mass`` and ``inertia`` (as `Body.standard_uncertainty` gives them); else None."""

    def to_dict(self) -> dict[str, Any]:
        out = self.about.to_dict() | {
            "frame": self.frame,
            "rotations": list(self.rotations),
            "products_sign": self.products_sign,
            "inertia": self.matrix,
        }
        if self.axis is not None:
            out |= {"axis": self.axis, "moment_about_axis": self.moment_about_axis}
        if self.uncertainty is not None:
            out["uncertainty"] = self.uncertainty.to_dict()
        return out

    def rows(self) -> list[Rows]:
        about, labels = self.about, self.about.body.unit_labels
        places = about.place_rows(self.uncertainty)
        if self.axis is not None:
            places += [
                ("axis (unit)", "", shown(self.axis)),
                ("moment about axis", labels["inertia"], number(self.moment_about_axis, 8)),
            ]
        frame = "world axes after " + ", then ".join(self.rotations) if self.rotations else "body axes"
        title = f"Inertia about {about.label}, {frame}; {PRODUCT_SIGN_TITLES[self.products_sign]}"
        tables = [
            Rows.quantities(about.title("inertia"), places),
            matrix_rows(title, self.matrix, labels["inertia"]),
        ]
        if self.uncertainty is not None:
            tables.append(
                matrix_rows("± its standard uncertainty", self.uncertainty.inertia, labels["inertia"])
            )
        return tables


@dataclass(frozen=True, repr=False)
class Principal(Result):
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
    place: About | None = field(default=None, compare=False)
    """The body and the point's name (None for principal axes made by hand)."""
    uncertainty: StandardUncertainty | None = field(default=None, compare=False)
    """For a spec that writes numbers with ±: the standard uncertainty of ``mass``,
    ``center_of_mass``, ``moments`` and ``axes_deg`` (each axis's, degrees; None for an axis
    not determined); else None."""

    def __repr__(self) -> str:
        return f"Principal(moments={self.moments!r}, axes={self.axes!r}, about={self.about!r})"

    json_keys = ("moments", "axes", "radii_of_gyration")

    def to_dict(self) -> dict[str, Any]:
        out = _placed(self)
        if self.uncertainty is not None:
            out["warnings"] = out.get("warnings", []) + [
                f"principal axis {i + 1} is not determined: its moment is within 3 standard uncertainties of another's"
                for i, deg in enumerate(self.uncertainty.axes_deg)
                if deg is None
            ]
        return out

    def csv_rows(self) -> list[dict[str, Any]]:
        # radii numbered like the moments they belong to (radii_of_gyration_1 ...), not _x, _y, _z
        row = {k: v for k, v in self.to_dict().items() if k != "radii_of_gyration"}
        return [row | {f"radii_of_gyration_{i}": k for i, k in enumerate(self.radii_of_gyration, start=1)}]

    def rows(self) -> list[Rows]:
        label = self.place.label if self.place else "point"
        labels = self.place.body.unit_labels if self.place else {"inertia": "", "length": ""}
        scale, scale_text = matrix_digits(self.moments)
        moment = f"moment [{labels['inertia']}]" + (f" {scale_text}" if scale_text else "")
        spread = self.uncertainty
        columns: tuple[str, ...] = ("#", moment, "axis x", "axis y", "axis z")
        columns += (f"radius of gyration [{labels['length']}]", *(() if spread is None else ("axis ±°",)))
        u = [None] * 3 if spread is None else [x / scale for x in spread.moments]
        degrees = [()] * 3 if spread is None else [(number(d, 2),) for d in spread.axes_deg]
        cells = [
            (f"I{i + 1}", _with_u(m / scale, u[i], 7), *(number(v, 7) for v in a), number(k, 7), *degrees[i])
            for i, (m, a, k) in enumerate(zip(self.moments, self.axes, self.radii_of_gyration))
        ]
        axes = Rows(f"Principal axes about {label} (body frame)", columns, cells)
        if self.place is None:
            return [axes]
        return [Rows.quantities(self.place.title("principal"), self.place.place_rows(spread)), axes]


@dataclass(frozen=True, repr=False)
class Momentum(Result):
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
    place: About | None = field(default=None, compare=False)
    """The body and the point's name."""
    uncertainty: StandardUncertainty | None = field(default=None, compare=False)
    """For a spec that writes numbers with ±: the standard uncertainty of ``mass``,
    ``center_of_mass``, ``angular_momentum`` and ``kinetic_energy``; else None."""

    def __repr__(self) -> str:
        return (
            f"Momentum(omega={self.omega!r}, angular_momentum={self.angular_momentum!r}, "
            f"kinetic_energy={self.kinetic_energy!r})"
        )

    json_keys = ("omega", "com_velocity", "angular_momentum", "angle_deg", "kinetic_energy")

    def to_dict(self) -> dict[str, Any]:
        return _placed(self)

    def rows(self) -> list[Rows]:
        place, u = self.place, self.uncertainty
        labels = place.body.unit_labels if place else {"velocity": "", "angular_momentum": "", "energy": ""}
        h_unit = labels["angular_momentum"]
        spread = [] if u is None else [("± its standard uncertainty", h_unit, shown(u.angular_momentum))]
        energy = _with_u(self.kinetic_energy, None if u is None else u.kinetic_energy, 8)
        cells = [
            *(place.place_rows(u) if place else []),
            ("ω (body axes)", "rad/s", shown(self.omega)),
            ("v of centre of mass", labels["velocity"], shown(self.com_velocity)),
            ("angular momentum h", h_unit, shown(self.angular_momentum)),
            *spread,
            ("angle between h and ω", "deg", number(self.angle_deg, 6)),
            ("kinetic energy", labels["energy"], energy),
        ]
        title = place.title(f"momentum about {place.label}") if place else "momentum"
        return [Rows.quantities(title, cells)]


@dataclass(frozen=True, repr=False)
class Dynamics(Result):
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
    place: About | None = field(default=None, compare=False)
    """The body and the point's name."""

    def __repr__(self) -> str:
        return f"Dynamics(mode={self.mode!r}, alpha={self.alpha!r}, force={self.force!r}, torque={self.torque!r})"

    json_keys = ("omega", "alpha", "point_acceleration", "force", "torque")

    def to_dict(self) -> dict[str, Any]:
        nowhere: dict[str, Any] = {"name": None, "units": {}, "mass": None, "center_of_mass": None}
        nowhere |= {"about": self.about, "about_label": "point", "warnings": []}  # made by hand: no body
        head = self.place.to_dict() if self.place else nowhere
        first = {key: head.pop(key) for key in ("name", "units", "warnings")}  # then the mode
        return first | {"mode": self.mode} | head | self.json_fields()

    def rows(self) -> list[Rows]:
        body = self.place.body if self.place else None
        labels = body.unit_labels if body else {"mass": "", "length": ""}
        label = self.place.label if self.place else "point"
        given, found = ("given", "result") if self.mode == "inverse" else ("result", "given")
        force_note = "needed to hold the point" if self.held else found
        acceleration = f"a of {label} ({'given' if self.held else given})"
        cells = [
            ("mass", labels["mass"], number(body.mass if body else None, 8)),
            (f"about ({label})", labels["length"], shown(self.about)),
            ("ω", "rad/s", shown(self.omega)),
            (f"α ({given})", "rad/s²", shown(self.alpha)),
            (acceleration, f"{labels['length']}/s²", shown(self.point_acceleration)),
            (f"force ({force_note})", _load_unit(body, 1), shown(self.force)),
            (f"torque about {label} ({found})", _load_unit(body, 2), shown(self.torque)),
        ]
        name = (body.name or body.path) if body else "dynamics"
        return [Rows.quantities(f"{name} — Newton–Euler about {label} ({self.mode})", cells)]


def _load_unit(body: Any, length_power: int) -> str:
    """Unit of a force (``length_power`` 1) or torque (2) in the body's units: N and N·m in SI,
    otherwise the body's unit with its value in N or N·m."""
    si = "N" if length_power == 1 else "N·m"
    if body is None:
        return si
    units = body.units
    length = units["length"] if length_power == 1 else f"{units['length']}²"
    factor = MASS_UNITS_IN_KG[units["mass"]] * LENGTH_UNITS_IN_M[units["length"]] ** length_power
    if factor == 1.0:
        return si
    return f"{units['mass']}·{length}/s² (= {factor:g} {si})"


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
    uncertainty: MassProperties | None = field(default=None, compare=False)
    """For a spec that writes numbers with ±: the standard uncertainty of the part's ``mass``,
    ``center_of_mass`` and ``inertia_about_com`` from its own inputs; else None."""


class Parts(Results[Part]):
    """A body's parts in file order, as ``rbi parts`` lists them: a sequence of `Part` (``len``,
    ``[i]``, iteration), with the body's totals: ``volume`` (the solids' volume, holes taken
    away; None when no part has one), ``mean_density`` (mass / volume; None unless every part
    has a volume) and ``principal_moments`` (the body's, about its centre of mass)."""

    def __init__(self, body: Any, parts: list[Part]) -> None:
        self._body = body
        self._items = parts
        volumes = [part.volume for part in parts]
        volume = sum(v for v in volumes if v is not None)  # a hole's is negative
        self.volume: float | None = volume if any(v is not None for v in volumes) else None
        body._refuse_non_finite(volume=self.volume)  # sizes whose volume overflows a double
        every = all(v is not None for v in volumes)
        self.mean_density: float | None = body.mass / volume if every and volume > 0 else None
        self.principal_moments: np.ndarray = body.principal().moments

    def __repr__(self) -> str:
        return f"<rbi.Parts {len(self)} parts of {self._body.name or self._body.path!r}>"

    def to_dict(self) -> dict[str, Any]:
        """The body's totals and ``parts``, one object a part: the rows of the CSV and of the
        tables too."""
        body = self._body
        units = body.units
        to_si = MASS_UNITS_IN_KG[units["mass"]] / LENGTH_UNITS_IN_M[units["length"]] ** 3
        rows, step = [], any(part.shape == "step" for part in self._items)
        for part in self._items:
            density = abs(part.mass / part.volume) if part.volume else None
            row = {
                "name": part.name,
                "shape": part.shape,
                "hole": part.hole,
                "mass": part.mass,
                "mass_share": part.mass / body.mass,
                "center_of_mass": part.center_of_mass,
                "inertia_about_com": part.inertia_about_com,
                "principal_moments": part.principal_moments,
                "inertia_share": part.inertia_share,
                "volume": part.volume,  # negative for a hole, as the mass: the parts add up
                "implied_density": density,
                "implied_density_si": None if density is None else density * to_si,
            }
            if part.uncertainty is not None:
                row["uncertainty"] = part.uncertainty.to_dict()
            if step:  # the error estimate of each STEP part
                row["integration_error"] = part.integration_error
            rows.append(row)
        return (
            named(body)
            | {
                "mass": body.mass,
                "center_of_mass": body.center_of_mass,
                "volume": self.volume,
                "mean_density": self.mean_density,
                "principal_moments": self.principal_moments,
                "parts": rows,
            }
            | self._uncertainty()
        )

    def _uncertainty(self) -> dict[str, Any]:
        """``{"uncertainty": the body's mass, centre of mass and principal moments'}`` for a spec
        with ±, else nothing."""
        spread = self._body.standard_uncertainty()
        if spread is None:
            return {}
        return {"uncertainty": spread.only().to_dict() | {"principal_moments": spread.moments}}

    def csv_rows(self) -> list[dict[str, Any]]:
        return self.to_dict()["parts"]

    def csv_summary(self) -> dict[str, Any]:
        return {k: v for k, v in self.to_dict().items() if k != "warnings"} | {"parts": len(self)}

    def rows(self) -> list[Rows]:
        """Three tables, each narrow enough for 80 columns: mass and volume; centre of mass and
        share of the inertia; principal moments. Each ends with the whole body's row."""
        body, data = self._body, self.to_dict()
        labels, units, name = body.unit_labels, body.units, body.name or body.path
        # the body's row read as a part's (its ``uncertainty``, with a ±, gives its ``± u``)
        whole = {"name": "total", "shape": "", "hole": False, "mass_share": 1.0, "inertia_share": 1.0}
        rows = [*data["parts"], data | whole | {"implied_density": self.mean_density}]
        l_unit, length, size = units["length"], labels["length"], body_size(body.mass_properties)
        scale, scale_text = matrix_digits([row["principal_moments"] for row in rows])
        unit = f"[{labels['inertia']}]" + (f" {scale_text}" if scale_text else "")
        return [
            _part_table(
                f"{name}: parts — mass and volume",
                rows,
                (
                    "shape",
                    f"mass\n[{labels['mass']}]",
                    "mass\nshare [%]",
                    f"volume\n[{l_unit}³]",
                    f"density\n[{units['mass']}/{l_unit}³]",
                ),
                lambda row, u: (
                    row["shape"] + (" (hole)" if row["hole"] else ""),
                    _with_u(row["mass"], u.get("mass")),
                    number(100 * row["mass_share"], 4),
                    number(row["volume"]),  # — for none
                    number(row["implied_density"], 4),
                ),
                left=2,
            ),
            _part_table(
                f"{name}: parts — centre of mass",
                rows,
                (f"centre of\nmass x [{length}]", f"\ny [{length}]", f"\nz [{length}]", "inertia\nshare [%]"),
                lambda row, u: (
                    *_place_cells(row["center_of_mass"], size, u),
                    number(100 * row["inertia_share"], 4),
                ),
            ),
            _part_table(
                f"{name}: parts — principal moments (own CoM)",
                rows,
                (f"I1\n{unit}", f"I2\n{unit}", f"I3\n{unit}"),
                lambda row, u: tuple(  # only the body's moments have a ± u
                    _with_u(m / scale, None if s is None else s / scale, 5)
                    for m, s in zip(row["principal_moments"], u.get("principal_moments", [None] * 3))
                ),
            ),
        ]


def _with_u(value: float, u: float | None, digits: int = 6) -> str:
    """A table cell: ``value ± u`` when the spec gives the value an uncertainty, else the value."""
    return number(value, digits) if u is None else plus_minus(value, u)


def _place_cells(point: Any, size: float, spread: dict[str, Any]) -> list[str]:
    """A centre of mass's three table cells, rounding noise as 0 (see :func:`without_noise`),
    each ``± u`` when ``spread`` (the ``"uncertainty"`` of the JSON) gives one."""
    return list(map(_with_u, without_noise(point, size), spread.get("center_of_mass", [None] * 3)))


def _part_table(
    title: str, rows: list[dict[str, Any]], headers: tuple[str, ...], cells: Callable, left: int = 1
) -> Rows:
    """A parts table of ``rows`` (each part's JSON object, then the body's), each row's cells
    ``cells(row, its "uncertainty" or {})``: at most :data:`MAX_TABLE_PARTS` parts (then how many
    more), the body's total after a rule."""

    def line(row: dict[str, Any]) -> tuple[str, ...]:
        return (row["name"], *cells(row, row.get("uncertainty", {})))

    *parts, total = rows
    shown = [line(row) for row in parts[:MAX_TABLE_PARTS]]
    if len(parts) > MAX_TABLE_PARTS:  # CSV and JSON list them all
        shown.append((f"… {len(parts) - MAX_TABLE_PARTS} more parts", *("",) * len(headers)))
    return Rows(title, ("part", *headers), shown, total=line(total), left=left, kind="parts")


@dataclass(frozen=True, repr=False)
class Export(Result):
    """A body's ``<inertial>`` element for a robot description, as ``rbi export`` prints it:
    ``xml``, ``to`` (``urdf``, ``mjcf``, ``sdf``), ``warnings``, and the SI mass properties
    it holds (``mass_properties``: kg, m, kg·m²; ``name`` and ``units`` of the body in SI)."""

    name: str | None
    to: str
    units: dict[str, str]
    warnings: list[str]
    mass_properties: MassProperties
    xml: str

    def __repr__(self) -> str:
        return f"<rbi.Export {self.to} of {self.name!r}>"

    def __str__(self) -> str:
        return self.xml

    def to_dict(self) -> dict[str, Any]:
        props = self.mass_properties
        return {
            "name": self.name,
            "to": self.to,
            "units": self.units,
            "warnings": self.warnings,
            "mass": props.mass,
            "center_of_mass": props.center_of_mass,
            "inertia": props.inertia_about_com,
            "xml": self.xml,
        }

    def csv_rows(self) -> list[dict[str, Any]]:
        return [{k: v for k, v in self.to_dict().items() if k != "xml"}]

    def rows(self) -> list[Rows]:
        props = self.mass_properties
        cells = [
            ("mass", "kg", number(props.mass, 8)),
            ("centre of mass", "m", shown(props.center_of_mass)),
            *(
                (f"inertia about CoM, row {i + 1}", "kg·m²", shown(r))
                for i, r in enumerate(props.inertia_about_com)
            ),
        ]
        return [Rows.quantities(f"{self.name or 'body'} — export to {self.to}", cells)]
