"""``rbi audit``: each link's declared mass properties against its own geometry, the flags that
say what is wrong, and the whole robot's totals.

Per link (all in the link frame, SI): ``declared``, the inertial element (MJCF: what MuJoCo's
compiler gives the body); ``geometry``, the link's collision geometry (else visual;
``--geometry visual`` the other way round) as a solid at the declared mass, or at the given
density when the link declares no mass; ``ratios``, each declared moment about the geometry's
principal axes over the geometry's; ``com_offset``, the distance between the two centres of mass
over the geometry's size (its bounding box's diagonal). The flags (``unphysical``,
``placeholder``, ``mismatch``, ``density``, ``massless``, ``mesh``), their levels and limits
(:data:`ERROR_RATIO`, :data:`WARNING_RATIO`, :data:`SOLID_DENSITY_RANGE`, :data:`COM_MARGIN`)
are tabled in docs/audit.md ("What it checks").

Every model is audited one way, on arrays of its links (:class:`~rbi.formats.robot.LinkColumns`:
a URDF's reader gives them as columns, the SDF and MJCF readers' links are laid into them):
screens on stacks clear the links with nothing to flag, and only the others are audited one by one.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from rbi.core.inertia import symmetric_eigen
from rbi.core.mass import MassProperties
from rbi.core.validity import declared_inertia_problem, finite
from rbi.errors import ArgumentError, InputError, literal
from rbi.formats.robot import SOLID_KINDS, Link, LinkColumns, RobotModel, stacked
from rbi.formats.robot_files import inertia_problem_text
from rbi.formats.robot_geometry import MESH_INERTIA_MODES, distribution, half_extent, primitive
from rbi.reprs import Result, Rows, json_ready, plain
from rbi.robot.tree import placement, stack_apply, totals
from rbi.text import number, vector_text

ERROR_RATIO = 10.0
"""A declared moment beyond this factor of the geometry's (either way) is an error."""

USABLE_MOMENT = 1e-9
"""A geometry's principal moment below this fraction of its largest gives no ratio (``-``,
null): a rod's moment about its own axis is nothing to divide by."""

WARNING_RATIO = 2.0
"""A declared moment beyond this factor of the geometry's (either way) is a warning."""

SOLID_DENSITY_RANGE = (50.0, 25000.0)
"""Densities (kg/m³) a link's material can have: from rigid foam to above osmium (22,590)."""

GEOMETRY_CHOICES = ("collision", "visual", "none")
"""Which geometry gives a link's volume; ``none`` reads none (the declared inertials alone)."""

COM_MARGIN = 0.01
"""A declared centre of mass may lie this fraction of the geometry's size outside its bounds."""


@dataclass
class Flag:
    """``code`` (unphysical, placeholder, mismatch, density, massless), ``level`` (error,
    warning), ``message`` (what is wrong, with the numbers) and ``summary`` (a few words)."""

    code: str
    level: str
    message: str
    summary: str = ""

    def as_dict(self) -> dict[str, str]:
        return {"code": self.code, "level": self.level, "message": self.message}


@dataclass(frozen=True)
class GeometryProps:
    """What the link's geometry gives it: ``properties`` (its mass properties in the link frame
    at the declared mass, else at the given density; None when the link declares no mass and no
    density was given: a shape with no mass), ``centroid`` (m, link frame), ``volume`` (m³; None
    when it is all shells), ``implied_density`` (kg/m³), its bounds ``low``/``high`` (m, link
    frame) and ``source`` (``collision`` or ``visual``)."""

    properties: MassProperties | None
    centroid: np.ndarray
    volume: float | None
    implied_density: float | None
    low: np.ndarray
    high: np.ndarray
    source: str = "collision"

    @classmethod
    def of(cls, properties, centroid, volume, implied_density, low, high, source) -> GeometryProps:
        """``GeometryProps(...)`` without the frozen dataclass's checks per field (an audit of
        100,000 links makes one per link)."""
        value = object.__new__(cls)
        vars(value).update(
            properties=properties,
            centroid=centroid,
            volume=volume,
            implied_density=implied_density,
            low=low,
            high=high,
            source=source,
        )
        return value

    @property
    def mass(self) -> float | None:
        return None if self.properties is None else self.properties.mass

    @property
    def center_of_mass(self) -> np.ndarray:
        """The geometry's centre of mass (its centroid when it has no mass), m, link frame."""
        return self.centroid if self.properties is None else self.properties.center_of_mass

    @property
    def inertia_about_com(self) -> np.ndarray | None:
        return None if self.properties is None else self.properties.inertia_about_com

    @property
    def moments(self) -> np.ndarray | None:
        """Principal moments (kg·m², ascending), or None when the mass is unknown."""
        return None if self.properties is None else self.properties.moments


@dataclass
class LinkAudit:
    link: Link
    declared: MassProperties | None
    geometry: GeometryProps | None
    ratios: np.ndarray | None = None
    com_offset: float | None = None
    flags: list[Flag] = field(default_factory=list)

    @property
    def name(self) -> str | None:
        return self.link.name

    @property
    def has_error(self) -> bool:
        return any(flag.level == "error" for flag in self.flags)

    @property
    def worst_ratio(self) -> float | None:
        """The ratio of a declared moment to the geometry's farthest from 1 (by factor), or None
        when there is none (no geometry, no declared inertia)."""
        return None if self.ratios is None else _worst_ratio(self.ratios)

    @property
    def given_ratios(self) -> list[float | None] | None:
        """:attr:`ratios` as JSON and CSV hold them: a ratio the geometry cannot give (NaN,
        ``-`` in the table) or one past the largest double (``>1.8e+308``) is None."""
        return None if self.ratios is None else _given(self.ratios)

    @property
    def worst_ratio_text(self) -> str:
        """:attr:`worst_ratio` as the table shows it (:func:`ratio_text`; ``-`` for none)."""
        worst = self.worst_ratio
        return "-" if worst is None else ratio_text(worst)


def ratio_text(ratio: float) -> str:
    """A moment ratio for people: 3 significant digits, ``-`` for one the geometry cannot give
    (NaN), ``>1.8e+308`` for one past the largest double (the declared moment is finite, the
    geometry's too small to divide it by)."""
    if math.isnan(ratio):
        return "-"
    return f">{sys.float_info.max:.2g}" if math.isinf(ratio) else f"{ratio:.3g}"


@dataclass(repr=False)
class AuditReport(Result):
    """What ``rbi audit`` found: the model read, one :class:`LinkAudit` per link, the totals,
    ``notes`` (what was read but not checked, inertials MuJoCo ignores) and the options used.
    :meth:`as_dict` is the JSON the CLI prints."""

    model: RobotModel
    _links: list[LinkAudit] | None
    total: Any
    notes: list[str]
    settings: dict[str, Any]
    fix: Any = None
    joints: list = field(default_factory=list)
    """Each joint coordinate's holding torque (:class:`rbi.robot.statics.JointTorque`)."""
    columns: _ColumnAudit | None = None
    """The audit on the links' arrays, whose :attr:`links` are made when first asked for."""
    left_out: list[str] = field(default_factory=list)
    """The links whose declared moments the total does not count: mass 0 with moments (each
    flagged ``unphysical``), by name (an unnamed MJCF body as ``body[i]``)."""

    @property
    def links(self) -> list[LinkAudit]:
        """One :class:`LinkAudit` per link, in file order."""
        if self._links is None:
            self._links = [] if self.columns is None else self.columns.links()
        return self._links

    @property
    def path(self) -> str:
        return self.model.path

    @property
    def total_moments(self) -> np.ndarray:
        """The whole robot's principal moments about its centre of mass, kg·m², ascending (the
        table's and the JSON's ``total.moments``)."""
        return np.array(_stack_moments(self.total.inertia_about_com[None])[0])

    @property
    def has_error(self) -> bool:
        if self._links is None and self.columns is not None:
            return self.columns.has_error or bool(self.model.unchecked)
        return any(link.has_error for link in self.links) or bool(self.model.unchecked)

    @property
    def exit_code(self) -> int:
        """1 when a link has an error-level flag (a fixed copy written: when a flagged link
        could not be fixed or the file holds what was not checked), else 0."""
        if self.fix is not None and self.fix.out is not None:
            return 1 if self.fix.unfixable or self.model.unchecked else 0
        return 1 if self.has_error else 0

    def __repr__(self) -> str:
        """One line (the dataclass's own repr would print the whole robot file's text)."""
        errors = sum(1 for link in self.links if link.has_error)
        warnings = sum(1 for link in self.links if link.flags and not link.has_error)
        return (
            f"<rbi.AuditReport {self.model.path!r} ({self.model.format}): {len(self.links)} links, "
            f"{len(self.joints)} joints, {errors} with errors, {warnings} with warnings>"
        )

    def rows(self) -> list[Rows]:
        """The links (the CLI's table: mass, implied density, worst ratio, CoM offset, flags),
        the totals, and the joints' holding torques when there are any."""
        word = self.model.link_word
        plural = "bodies" if word == "body" else word + "s"
        links = Rows(
            f"{self.path}: {len(self.links)} {plural} (ratio: the declared moment farthest from the "
            "geometry's, as a multiple of it)",
            (word, "mass kg", "ρ kg/m³", "ratio", "CoM off ÷ size", "flags"),
            [_link_cells(each) for each in self.links],
        )
        total = self.total
        quantities = [
            ("mass", "kg", number(total.mass, 6)),
            ("centre of mass", "m", vector_text(_without_noise(total.center_of_mass), 6)),
            ("principal moments", "kg·m²", vector_text(_without_noise(self.total_moments), 6)[1:-1]),
        ]
        if self.left_out:
            quantities.append(("left out (mass 0)", "", ", ".join(self.left_out)))
        tables = [links, Rows.quantities(f"total ({total.frame})", quantities)]
        if self.joints:
            tables.append(
                Rows(
                    "joints: torque that holds the pose (N·m; N for prismatic)",
                    ("joint", "type", "torque", "limit", "margin", "flags"),
                    _joint_cells(self.joints),
                    left=2,
                )
            )
        return tables

    @json_ready
    def to_dict(self) -> dict[str, Any]:
        """What ``rbi audit --format json`` prints, less ``"file"`` (with ``"fix"`` when the fixed
        copy was planned): JSON-ready, built so (no numpy value, no -0.0) without walking the
        links' millions of numbers again."""
        total = self.total
        found = {
            "robot": self.model.name,
            "format": self.model.format,
            "units": {"length": "m", "mass": "kg"},
            "links": [] if self.columns is None else self.columns.link_dicts(),
            "total": plain(
                {
                    "mass": total.mass,
                    "center_of_mass": total.center_of_mass,
                    "inertia_about_com": total.inertia_about_com,
                    "moments": self.total_moments,
                    "frame": total.frame,
                    "left_out": list(self.left_out),
                }
            ),
            "joints": [
                {
                    "name": each.name,
                    "type": each.type,
                    "torque": float(each.torque) + 0.0,
                    "effort_limit": None if each.effort_limit is None else float(each.effort_limit) + 0.0,
                    "flags": list(each.flags),
                }
                for each in self.joints
            ],
            "notes": list(self.notes),
            "warnings": list(self.notes),
        }
        if self.fix is not None:
            found["fix"] = self.fix.to_dict()
        return found

    def as_dict(self) -> dict[str, Any]:
        """:meth:`to_dict` with ``"file"`` first: what ``rbi audit --format json`` prints."""
        return {"file": self.model.path, **self.to_dict()}

    def csv_rows(self) -> list[dict[str, Any]]:
        """One row a link (``rbi audit --format csv``)."""
        return [_csv_row(each) for each in self.links]


def _without_noise(values: np.ndarray) -> np.ndarray:
    """``values`` with each entry below 1e-12 of the largest (finite) one set to 0: rounding
    noise (2.8e-18 m in a symmetric robot's centre of mass) printed as 0."""
    values = np.array(values, dtype=float)
    finite = np.abs(values[np.isfinite(values)])
    values[np.abs(values) < 1e-12 * (float(finite.max()) if finite.size else 0.0)] = 0.0
    return values


def _link_cells(each: LinkAudit) -> tuple[str, ...]:
    declared, geo = each.declared, each.geometry
    return (
        each.link.name if each.link.name is not None else each.link.label,
        "-" if declared is None else number(declared.mass, 6),
        "-" if geo is None or geo.implied_density is None else number(geo.implied_density, 4),
        each.worst_ratio_text,
        "-" if each.com_offset is None else number(each.com_offset, 2),
        " ".join(f.code + ("!" if f.level == "error" else "") for f in each.flags) or "ok",
    )


def _joint_cells(joints: list) -> list[tuple[str, ...]]:
    """Each joint's row: a torque below 1e-12 of the largest is rounding noise (7e-14 N·m beside
    0.013 N·m), shown as 0."""
    torques = [float(each.torque) for each in joints]
    largest = max((abs(t) for t in torques if math.isfinite(t)), default=0.0)
    return [
        (
            "-" if each.name is None else each.name,
            each.type,
            number(0.0 if abs(torque) < 1e-12 * largest else torque, 6),
            "-" if each.effort_limit is None else number(each.effort_limit, 6),
            "-" if each.margin is None else number(each.margin, 6),
            " ".join(flag["code"] for flag in each.flags) or "ok",
        )
        for each, torque in zip(joints, torques)
    ]


def _csv_row(each: LinkAudit) -> dict[str, Any]:
    declared, geo, ratios = each.declared, each.geometry, each.given_ratios
    return {
        "link": each.link.name or each.link.label,
        "mass": declared.mass if declared else None,
        "geometry_volume": geo.volume if geo else None,
        "implied_density": geo.implied_density if geo else None,
        **{f"ratio_{i + 1}": None if ratios is None else ratios[i] for i in range(3)},
        "com_offset": each.com_offset,
        "flags": " ".join(f"{f.code}:{f.level}" for f in each.flags),
    }


def _link_dict(each: LinkAudit, declared_moments, geometry_moments) -> dict[str, Any]:
    """One link's JSON (``declared_moments``/``geometry_moments``: the principal moments of its
    declared and geometry inertias, kg·m², from :func:`_stack_moments`)."""
    declared = geometry = None
    if each.declared is not None:
        declared = {
            "mass": each.declared.mass,
            "center_of_mass": each.declared.center_of_mass,
            "inertia_about_com": each.declared.inertia_about_com,
            "moments": declared_moments,
        }
    if each.geometry is not None:
        g = each.geometry
        geometry = {
            "volume": g.volume,
            "mass": g.mass,
            "center_of_mass": g.center_of_mass,
            "inertia_about_com": g.inertia_about_com,
            "moments": geometry_moments,
            "implied_density": g.implied_density,
            "source": g.source,
        }
    return {
        "name": each.link.name,
        "index": each.link.index,
        "declared": declared,
        "geometry": geometry,
        "moment_ratios": each.given_ratios,
        "com_offset": each.com_offset,
        "flags": [flag.as_dict() for flag in each.flags],
    }


_OFF_DIAGONAL = ~np.eye(3, dtype=bool)


def _stack_moments(stack: np.ndarray) -> list[list[float]]:
    """The principal moments (ascending, kg·m²) of each inertia of a (k, 3, 3) stack, as lists,
    without the axes: an inertia with no products has its diagonal as moments, sorted on the
    stack at once (a million-link report asks for two per link); the others'
    :func:`rbi.core.inertia.symmetric_eigen` eigenvalues."""
    diagonal = np.diagonal(stack, axis1=1, axis2=2)
    sortable = ~np.any(stack[:, _OFF_DIAGONAL], axis=1) & np.all(np.abs(diagonal) < 1e300, axis=1)
    ordered = np.take_along_axis(diagonal, np.argsort(diagonal, axis=1, kind="stable"), axis=1)
    ordered = (ordered + 0.0).tolist()  # + 0.0: no -0.0
    for k in np.flatnonzero(~sortable).tolist():
        ordered[k] = (symmetric_eigen(stack[k])[0] + 0.0).tolist()
    return ordered


def _moments_of(properties: MassProperties | None) -> list[float] | None:
    return None if properties is None else _stack_moments(properties.inertia_about_com[None])[0]


def material_density(material: str | None, density: float | None) -> float | None:
    """kg/m³ from ``density`` or ``material`` (``--density``, ``--material``); ArgumentError
    (naming the parameters) for both, a bad number or an unknown material."""
    if material is not None and density is not None:
        raise ArgumentError(("density", "material"), "give one of them")
    if density is not None:
        value = _number(density)
        if not (value is not None and np.isfinite(value) and value > 0):
            raise ArgumentError(
                "density", f"{literal(density)}: must be a finite number greater than 0 (kg/m³)"
            )
        return value
    if material is not None:
        # not at top level: `rbi audit` would load rbi.spec.materials too
        from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name, unknown_material_message

        name = canonical_name(material) if isinstance(material, str) else None
        if name is None:
            message = unknown_material_message(str(material), numbers_too=False)
            raise ArgumentError("material", literal(message, quoted=False) + " (or {density} in kg/m³)")
        return MATERIAL_DENSITIES_SI[name]
    return None


def _number(value) -> float | None:
    """``value`` as a float, or None when it is not a real number (a str, a bool, None, ...)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        return None
    return float(value) if finite(value) else math.nan


def check_choices(geometry, mesh_inertia) -> None:
    """ArgumentError naming ``geometry`` or ``mesh_inertia`` (``--geometry``, ``--mesh-inertia``)
    when it is not one of the audit's choices."""
    if geometry not in GEOMETRY_CHOICES:
        raise ArgumentError("geometry", f"{literal(geometry)}: must be collision, visual or none")
    if mesh_inertia not in MESH_INERTIA_MODES:
        choices = ", ".join(MESH_INERTIA_MODES)
        raise ArgumentError("mesh_inertia", f"{literal(mesh_inertia)}: must be one of {choices}")


def audit_model(
    model: RobotModel,
    *,
    geometry: str = "collision",
    density: float | None = None,
    mesh_inertia: str = "auto",
    joints: dict[str, float] | None = None,
    mesh_repair: bool = False,
) -> AuditReport:
    """Audit a model already read (see :func:`rbi.formats.robot_files.read_robot`)."""
    # not at top level: `rbi import` would load rbi.robot.statics too
    from rbi.robot.statics import joint_torques

    check_choices(geometry, mesh_inertia)
    repairs: list[str] = []
    columns = model.link_columns()
    audited = _ColumnAudit(model, columns)
    audited.audit(geometry, density, mesh_inertia, mesh_repair, repairs)
    _refuse_overflow(model, audited.audited.values())
    notes = list(model.unchecked) + list(model.notes) + list(dict.fromkeys(repairs))
    placed = placement(model, joints, columns)
    return AuditReport(
        model,
        None,
        totals(model, joints, placed),
        notes,
        {
            "geometry": geometry,
            "density": density,
            "mesh_inertia": mesh_inertia,
            "joints": dict(joints or {}),
            "mesh_repair": mesh_repair,
        },
        joints=joint_torques(model, joints, placed),
        columns=audited,
        left_out=_left_out(model, columns),
    )


def _refuse_overflow(model: RobotModel, audited) -> None:
    """InputError naming the file and the link when a number its audit gives overflows a
    double (a centre of mass 1e155 m from a 0.1 m geometry: the offset's square): refused
    here, once, for every output form and the API. Only links not cleared by the screens can
    hold one (a cleared link's numbers are finite)."""
    for each in audited:
        geo = each.geometry
        found = {"its centre of mass's offset from its geometry": each.com_offset}
        if geo is not None:
            found["its geometry's implied density"] = geo.implied_density
            found["its geometry's inertia"] = (
                None if geo.properties is None else np.max(np.abs(geo.inertia_about_com))
            )
        for what, value in found.items():
            if value is not None and not math.isfinite(value):
                raise InputError(
                    f"{model.path}: {each.link.label}: {what} overflows a double; give lengths in "
                    "metres, masses in kg and moments in kg·m²"
                )


def _left_out(model: RobotModel, columns: LinkColumns) -> list[str]:
    """The names of the links of mass 0 that declare moments (the total counts no moment without
    a mass: :func:`rbi.robot.tree.heavy_links`); an unnamed one as ``body[i]``."""
    inertials = columns.inertials
    rows = (
        columns.declared & (inertials.mass == 0.0) & np.any(inertials.inertia_about_com != 0.0, axis=(1, 2))
    )
    names = columns.names
    word = model.link_word
    return [f"{word}[{row}]" if names[row] is None else names[row] for row in np.flatnonzero(rows).tolist()]


class _ColumnAudit:
    """The audit of a model's links on their :class:`~rbi.formats.robot.LinkColumns`: the links
    the bulk screens clear (no flag, their numbers worked out on stacks) are kept as rows and
    made into :class:`LinkAudit` values when asked for (:meth:`links`); the others (``audited``:
    row → LinkAudit) are made now and audited one by one (:func:`_measured_link`, :func:`_flags`)."""

    def __init__(self, model: RobotModel, columns: LinkColumns):
        self.model, self.columns = model, columns
        self.audited: dict[int, LinkAudit] = {}
        self.measured: _Measured | None = None
        self.compared: dict[int, tuple] = {}  # row → (ratios, com_offset)

    @property
    def has_error(self) -> bool:
        return any(each.has_error for each in self.audited.values())

    def audit(self, geometry, density, mesh_inertia, mesh_repair, repairs) -> None:
        """Each link screened on the arrays; those not cleared audited one by one."""
        model, columns = self.model, self.columns
        n = len(columns)
        heavy = columns.declared & (columns.inertials.mass > 0)
        carried = _carried(columns)
        moving = np.zeros(n, dtype=bool)  # links a joint moves
        kinds = zip(columns.joint_rows, columns.joint_kinds)
        moving[[row for row, kind in kinds if kind != "fixed" and columns.parents[row] != n]] = True
        measured = self.measured = _primitives_in_bulk(model, geometry, density, columns)
        shaped = np.zeros(n, dtype=bool)  # links with geometry to measure
        if geometry != "none":
            for column in columns.geoms:
                shaped[column.rows] = True
        fine = np.zeros(n, dtype=bool)
        if measured is not None:
            fine[np.asarray(measured.rows)[measured.fine]] = True
        declared = np.flatnonzero(columns.declared).tolist()
        inertias = columns.inertials.inertia_about_com[declared]
        physical, maybe = _screens(n, declared, inertias, columns.written[declared])
        clean = self._compare(heavy & fine)
        simple = heavy & physical & ~maybe & (~shaped | clean)
        simple |= ~columns.declared & ~moving & (~shaped | fine)
        for row in np.flatnonzero(~simple).tolist():
            link = columns.link(row)
            if fine[row]:
                declared_props = None if link.inertial is None else link.inertial.properties
                result = LinkAudit(link, declared_props, measured.props(measured.at[row]))
            else:
                result = _measured_link(model, link, geometry, density, mesh_inertia, mesh_repair, repairs)
            result.flags += _flags(model, link, result, carried[row])
            self.audited[row] = result

    def _compare(self, chosen: np.ndarray) -> np.ndarray:
        """(n,) which of the ``chosen`` links (declared mass, geometry measured) :func:`_compared`
        finds clean; their ratios and centre-of-mass offsets into :attr:`compared`."""
        clean = np.zeros(len(chosen), dtype=bool)
        measured, columns = self.measured, self.columns
        if measured is None or not np.any(chosen):
            return clean
        at = np.array([measured.at[row] for row in np.flatnonzero(chosen).tolist()], dtype=int)
        at = at[np.all(np.isfinite(measured.scaled[at]), axis=(1, 2))]
        found = np.asarray(measured.rows)[at]
        moments, axes = np.linalg.eigh(measured.scaled[at])
        low_density, high_density = SOLID_DENSITY_RANGE
        implied = measured.implied[at]
        ratios, offsets, inside, near = _compared(
            moments,
            axes,
            columns.inertials.inertia_about_com[found],
            columns.inertials.center_of_mass[found],
            measured.low[at],
            measured.high[at],
            measured.com[at],
        )
        clean[found] = near & inside & (implied >= low_density) & (implied <= high_density)
        self.compared = dict(zip(found.tolist(), zip(ratios, offsets)))
        return clean

    def links(self) -> list[LinkAudit]:
        """Every link's :class:`LinkAudit`, in file order."""
        return [self.link_audit(row, link) for row, link in enumerate(self.columns.links())]

    def link_audit(self, row: int, link: Link | None = None) -> LinkAudit:
        """The :class:`LinkAudit` of ``row``: audited one by one, or made from the arrays."""
        result = self.audited.get(row)
        if result is not None:
            return result
        link = self.columns.link(row) if link is None else link
        measured, geometry = self.measured, None
        if measured is not None and row in measured.at and measured.fine[measured.at[row]]:
            geometry = measured.props(measured.at[row])
        declared = None if link.inertial is None else link.inertial.properties
        return LinkAudit(link, declared, geometry, *self.compared.get(row, (None, None)))

    def link_dicts(self) -> list[dict[str, Any]]:
        """Each link's JSON object (:func:`_link_dict`), in file order, JSON-ready: a link the
        screens cleared (no flag) straight from the arrays, the same numbers its
        :class:`LinkAudit` holds (a 100,000-link report makes no object per link); the others
        (audited one by one, or with a turned inertial frame) from their LinkAudit."""
        columns, measured, compared = self.columns, self.measured, self.compared
        own = set(self.audited) | set(columns.turned)
        inertials = columns.inertials
        declared, masses = columns.declared.tolist(), (inertials.mass + 0.0).tolist()  # + 0.0: no -0.0
        coms = (inertials.center_of_mass + 0.0).tolist()
        inertias = (inertials.inertia_about_com + 0.0).tolist()
        moments = [None] * len(masses)
        rows = np.flatnonzero(columns.declared)
        for row, each in zip(rows.tolist(), _stack_moments(inertials.inertia_about_com[rows])):
            moments[row] = each
        shapes = _geometry_dicts(measured) if measured is not None else {}
        found = []
        for row, name in enumerate(columns.names):
            if row in own:
                each = self.link_audit(row)
                geo = None if each.geometry is None else each.geometry.properties
                found.append(plain(_link_dict(each, _moments_of(each.declared), _moments_of(geo))))
                continue
            ratios, offset = compared.get(row, (None, None))
            found.append(
                {
                    "name": name,
                    "index": row,
                    "declared": {
                        "mass": masses[row],
                        "center_of_mass": coms[row],
                        "inertia_about_com": inertias[row],
                        "moments": moments[row],
                    }
                    if declared[row]
                    else None,
                    "geometry": shapes.get(row),
                    "moment_ratios": None if ratios is None else _given(ratios),
                    "com_offset": None if offset is None else offset + 0.0,
                    "flags": [],
                }
            )
        return found


def _geometry_dicts(measured: _Measured) -> dict[int, dict[str, Any]]:
    """Row → the JSON object of its measured geometry (``fine`` rows): what
    :meth:`_Measured.props` gives, from the arrays."""
    fine = np.flatnonzero(measured.fine)
    heavy = fine[measured.has_mass[fine]]
    moments = dict(zip(heavy.tolist(), _stack_moments(measured.scaled[heavy])))
    volume, mass = (measured.measure + 0.0).tolist(), (measured.mass + 0.0).tolist()  # + 0.0: no -0.0
    implied, com = (measured.implied + 0.0).tolist(), (measured.com + 0.0).tolist()
    scaled, has_mass = (measured.scaled + 0.0).tolist(), measured.has_mass.tolist()
    return {
        measured.rows[k]: {
            "volume": volume[k],
            "mass": mass[k] if has_mass[k] else None,
            "center_of_mass": com[k],
            "inertia_about_com": scaled[k] if has_mass[k] else None,
            "moments": moments.get(k),
            "implied_density": implied[k] if has_mass[k] else None,
            "source": measured.sources[k],
        }
        for k in fine.tolist()
    }


def _given(ratios: np.ndarray) -> list[float | None]:
    """Moment ratios as JSON and CSV hold them: NaN (none) and inf (past a double) as None."""
    return [float(r) + 0.0 if math.isfinite(r) else None for r in ratios]


def _carried(columns: LinkColumns) -> list[bool]:
    """For each link (by row): does any link below it in the tree have mass?"""
    parents, heavy = columns.parents, (columns.declared & (columns.inertials.mass > 0)).tolist()
    below = [False] * (len(parents) + 1)
    for row in reversed(columns.order):  # every child before its parent
        if below[row] or heavy[row]:
            below[parents[row]] = True
    return below[: len(parents)]


def chosen_geoms(link: Link, geometry: str) -> tuple[list, str]:
    """(geoms, source) a link's geometry is measured from: its ``geometry`` ("collision" or
    "visual") elements, or the other kind when it has none of those."""
    first, second = (
        (link.collisions, link.visuals) if geometry == "collision" else (link.visuals, link.collisions)
    )
    if first:
        return first, geometry
    return second, "visual" if geometry == "collision" else "collision"


def link_geometry(
    model: RobotModel,
    link: Link,
    geometry: str,
    mesh_inertia: str,
    mesh_repair: bool = False,
    notes: list[str] | None = None,
    fallbacks: list | None = None,
):
    """(source, pieces) for the link: each piece (distribution, mass or None); MJCF geoms carry
    their own mass or density. ``fallbacks`` collects the meshes ``auto`` could not integrate
    exactly."""
    if geometry == "none":
        return None, []
    geoms, source = chosen_geoms(link, geometry)
    where = f"{model.path}: {link.label}: "
    pieces = []
    for geom in geoms:
        found = distribution(geom, mesh_inertia, where, mesh_repair, notes, fallbacks)
        if found is None or not found.measure > 0:
            continue
        own_mass = None
        if model.format == "mjcf":
            own_mass = geom.mass if geom.mass is not None else geom.density * found.measure
        pieces.append((found, own_mass))
    return source, pieces


def _measured_link(model, link, geometry, density, mesh_inertia, mesh_repair, notes) -> LinkAudit:
    """The link's declared and geometry mass properties, and the ``mesh`` flags of meshes ``auto``
    could not integrate exactly (the other flags come from :func:`_flags`)."""
    inertial = link.inertial
    declared = None if inertial is None else inertial.properties
    fallbacks: list = []
    source, pieces = link_geometry(model, link, geometry, mesh_inertia, mesh_repair, notes, fallbacks)
    geo = _geometry_props(model, pieces, source, declared, density)
    result = LinkAudit(link, declared, geo)
    result.flags = [Flag("mesh", "warning", each.message(), "mesh not closed") for each in fallbacks]
    return result


class _Shapes(NamedTuple):
    """The links whose geometry (as :func:`link_geometry` chooses it) is one solid primitive:
    their ``rows``, each one's shape (``distinct[which[k]]``: kind and size in m), pose in the
    link frame (``R`` (k, 3, 3), ``p`` (k, 3)) and ``sources`` (collision or visual)."""

    rows: list[int]
    distinct: list[tuple[str, tuple]]
    which: np.ndarray
    R: np.ndarray
    p: np.ndarray
    sources: list[str]


def _one_primitive(model: RobotModel, geometry: str, links: LinkColumns) -> _Shapes | None:
    """The :class:`_Shapes` of a URDF or SDF model (None: none, or MJCF): each link's ``geometry``
    elements, or the other kind's when it has none of those (as :func:`chosen_geoms` chooses),
    when they are one solid primitive; what :func:`_primitives_in_bulk` measures."""
    if geometry == "none" or model.format == "mjcf":
        return None
    other = "visual" if geometry == "collision" else "collision"
    counts = {tag: np.zeros(len(links.declared), dtype=int) for tag in (geometry, other)}
    for column in links.geoms:
        np.add.at(counts[column.tag], column.rows, 1)
    chosen = {geometry: counts[geometry] == 1, other: (counts[geometry] == 0) & (counts[other] == 1)}
    rows, distinct, which, R, p, sources = [], {}, [], [], [], []  # type: ignore[var-annotated]
    for column in links.geoms:
        if column.kind not in SOLID_KINDS or column.sizes is None:
            continue
        at = np.flatnonzero(chosen[column.tag][column.rows])
        if not len(at):
            continue
        sizes = column.sizes[at]
        if np.all(sizes == sizes[0]):  # one size throughout
            keys, inverse = [tuple(sizes[0].tolist())], np.zeros(len(at), dtype=int)
        else:
            found = {key: k for k, key in enumerate(dict.fromkeys(map(tuple, sizes.tolist())))}
            keys, inverse = list(found), np.array([found[key] for key in map(tuple, sizes.tolist())])
        codes = [distinct.setdefault((column.kind, key), len(distinct)) for key in keys]
        which.append(np.array(codes, dtype=int)[inverse])
        rows += np.asarray(column.rows)[at].tolist()
        R.append(column.rotations[at])
        p.append(column.translations[at])
        sources += [column.tag] * len(at)
    if not rows:
        return None
    return _Shapes(rows, list(distinct), np.concatenate(which), np.concatenate(R), np.concatenate(p), sources)


def _primitives_in_bulk(
    model: RobotModel, geometry: str, density: float | None, links: LinkColumns
) -> _Measured | None:
    """The geometry of the links :func:`_one_primitive` finds, measured on (n, 3, 3) stacks with
    the operations :func:`distribution`, :func:`_sum` and :func:`_geometry_props` make on one
    link, element by element (so the same numbers). A link whose numbers would take another
    branch there (no volume, overflow, an unusual sum) is left to them (not ``fine``)."""
    shapes = _one_primitive(model, geometry, links)
    if shapes is None:
        return None
    known = []
    for key in shapes.distinct:
        try:
            known.append((*primitive(*key), half_extent(*key)))
        except ValueError:
            known.append((np.nan, np.full(3, np.nan), np.full(3, np.nan)))
    measure = np.array([found[0] for found in known], dtype=float)[shapes.which]
    moments = stacked([found[1] for found in known], (3,))[shapes.which]
    half = stacked([found[2] for found in known], (3,))[shapes.which]
    R, p = shapes.R, shapes.p
    turned = np.matmul(R * moments[:, None, :], np.swapaxes(R, 1, 2))
    inertia = 0.5 * (turned + np.swapaxes(turned, 1, 2))
    corners = stack_apply(np.abs(R), half)
    with np.errstate(all="ignore"):
        fine = (measure > 0) & np.isfinite(measure) & np.all(np.isfinite(turned), axis=(1, 2))
        fine &= np.all(np.isfinite(p), axis=1) & np.all(np.abs(inertia) < 1e300, axis=(1, 2))
    declared = np.where(links.declared, links.inertials.mass, 0.0)[shapes.rows]
    return _Measured.of(
        shapes, fine, measure, inertia + 0.0, p + 0.0, p - corners, p + corners, declared, density
    )


class _Measured:
    """The geometry of :class:`_Shapes` measured: of each ``fine`` row, a piece of ``measure``
    (m³) with its inertia at density 1 (kg·m²), centroid ``com`` and bounds ``low``/``high``
    (m, link frame), and its mass (the declared one when positive, else ``density`` times the
    volume), implied density and scaled inertia (``scaled``), worked out on the arrays (the
    same IEEE operations as :func:`_geometry_props`, element by element). ``has_mass``: the rows
    whose geometry has mass properties. :meth:`props` gives one row's :class:`GeometryProps`."""

    @classmethod
    def of(cls, shapes, fine, measure, inertia, com, low, high, declared, density) -> _Measured:
        value = cls()
        given = declared > 0
        with np.errstate(all="ignore"):
            mass = np.where(given, declared, np.nan if density is None else density * measure)
            implied = mass / measure
            scaled = inertia * implied[:, None, None]
        given |= density is not None
        value.rows, value.sources, value.fine = shapes.rows, shapes.sources, fine
        value.measure, value.com, value.low, value.high = measure, com, low, high
        value.mass, value.implied, value.scaled = mass, implied, scaled
        value.has_mass = fine & given
        value.at = dict(zip(shapes.rows, range(len(shapes.rows))))
        return value

    def props(self, k: int) -> GeometryProps:
        """The :class:`GeometryProps` of the k-th row (a ``fine`` one)."""
        properties = None
        if self.has_mass[k]:
            properties = MassProperties(self.mass[k], self.com[k], self.scaled[k], "link")
        return GeometryProps.of(
            properties,
            self.com[k],
            float(self.measure[k]),
            None if properties is None else float(self.implied[k]),
            self.low[k],
            self.high[k],
            self.sources[k],
        )


def _screens(n: int, declared: list[int], inertias: np.ndarray, written: np.ndarray) -> tuple:
    """(physical, maybe_placeholder), (n,) each, for n links of which the ``declared`` rows
    declare ``inertias`` (about the centre of mass, link axes) as ``written`` (k, 3, 3):
    :func:`_certainly_physical` and :func:`_maybe_placeholder` (False and True for the others)."""
    physical = np.zeros(n, dtype=bool)
    maybe_placeholder = np.ones(n, dtype=bool)
    if declared:
        physical[declared] = _certainly_physical(inertias)
        maybe_placeholder[declared] = _maybe_placeholder(written)
    return physical, maybe_placeholder


def _compared(moments, axes, inertia, com, low, high, geometry_com) -> tuple:
    """The declared mass properties against the geometry's for k links on stacks (one link:
    k = 1, :func:`_geometry_flags`): each link's geometry's principal ``moments`` (k, 3) and
    ``axes`` (k, 3, 3), the declared ``inertia`` (k, 3, 3, kg·m²) and ``com`` (k, 3, m), the
    geometry's bounds and centre of mass (k, 3, m), all in the link frame. Returns (ratios
    (k, 3): each declared moment about the geometry's principal axes over the geometry's, NaN
    where the geometry's is too small to divide by; com offsets (None where the geometry has
    no size); inside (k,): the declared centre of mass within the bounds (with the margin);
    near (k,): every ratio within the warning range)."""
    along = np.einsum("nji,njk,nki->ni", axes, inertia, axes)
    usable = moments > USABLE_MOMENT * np.max(moments, axis=1)[:, None]
    with np.errstate(all="ignore"):
        ratios = np.where(usable, along / moments, np.nan)
    size = _norms(high - low)
    offset = _norms(com - geometry_com)
    with np.errstate(all="ignore"):
        offset = offset / size
    margin = (COM_MARGIN * size)[:, None]
    inside = ~(np.any(com < low - margin, axis=1) | np.any(com > high + margin, axis=1))
    near = np.all(np.isnan(ratios) | ((ratios >= 1 / WARNING_RATIO) & (ratios <= WARNING_RATIO)), axis=1)
    offsets = [value if sized else None for value, sized in zip(offset.tolist(), (size > 0).tolist())]
    return ratios, offsets, inside, near


def _norms(rows: np.ndarray) -> np.ndarray:
    """``np.linalg.norm`` of each row of a (k, 3) array: the square root of the row's dot product
    with itself, as a stack of one-row products (the same call as for one vector)."""
    return np.sqrt(np.matmul(rows[:, None, :], rows[:, :, None])[:, 0, 0])


def _certainly_physical(stack: np.ndarray) -> np.ndarray:
    """Each inertia of the (N, 3, 3) stack that certainly passes :func:`declared_inertia_problem`:
    entries below 1e300 (no sum of them overflows), exactly symmetric, principal moments not
    negative and meeting the triangle inequality with no tolerance at all (the function forgives
    a tolerance, never less)."""
    ok = np.all(np.abs(stack) < 1e300, axis=(1, 2)) & np.all(stack == np.swapaxes(stack, 1, 2), axis=(1, 2))
    if np.any(ok):
        chosen = stack[ok]
        moments = np.linalg.eigvalsh(0.5 * chosen + 0.5 * np.swapaxes(chosen, 1, 2))
        ok[ok] = (moments[:, 0] >= 0) & (moments[:, 0] + moments[:, 1] >= moments[:, 2])
    return ok


def _maybe_placeholder(written: np.ndarray) -> np.ndarray:
    """Each written inertia of the (N, 3, 3) stack :func:`_placeholder` might call a placeholder:
    no products, and three equal moments or moments within 1e-6 (in log10) of round values (the
    test itself allows 1e-12)."""
    diagonal = np.diagonal(written, axis1=1, axis2=2)
    no_products = np.all(written[:, _OFF_DIAGONAL] == 0, axis=1)
    equal = np.all(diagonal == diagonal[:, :1], axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = np.log10(np.abs(diagonal))
        round_ = (diagonal == 0) | (np.abs(exponent - np.round(exponent)) < 1e-6)
    return no_products & (equal | np.all(round_, axis=1))


def _geometry_props(
    model, pieces, source, declared: MassProperties | None, density: float | None
) -> GeometryProps | None:
    if not pieces:
        return None
    solid = [d for d, _ in pieces if not d.shell]
    volume = float(sum(d.measure for d in solid)) if solid else None
    low = np.min([d.low for d, _ in pieces], axis=0)
    high = np.max([d.high for d, _ in pieces], axis=0)
    if model.format == "mjcf":  # each geom at its own mass
        parts = [d.unit.with_mass(m) for d, m in pieces]
    else:  # at density 1
        parts = [d.unit for d, _ in pieces]
    try:
        unit = _sum(parts)
    except ValueError:  # no mass in the geometry
        return None
    if declared is not None and declared.mass > 0:
        mass = declared.mass
    elif density is not None and model.format != "mjcf":
        mass = density * unit.mass
    elif model.format == "mjcf":
        mass = unit.mass
    else:
        mass = None
    implied = mass / volume if mass is not None and volume and len(solid) == len(pieces) else None
    return GeometryProps(
        None if mass is None else unit.with_mass(mass),
        unit.center_of_mass,
        volume,
        implied,
        low,
        high,
        source,
    )


def _sum(parts: list[MassProperties]) -> MassProperties:
    """``MassProperties.sum(parts)``; for one part of positive mass, the value that sum gives
    without its arithmetic: the part with each -0.0 made 0.0 (the sum adds a zero offset to the
    centre of mass and a zero parallel-axis term to the inertia, then averages the inertia with
    its transpose, which leaves a symmetric one as it is)."""
    if len(parts) == 1:
        (part,) = parts
        inertia = part.inertia_about_com
        finite = np.isfinite(part.mass) and np.all(np.isfinite(part.center_of_mass))
        if (
            finite
            and part.mass > 0
            and np.all(np.abs(inertia) < 1e300)
            and np.array_equal(inertia, inertia.T)
        ):
            return MassProperties(part.mass, part.center_of_mass + 0.0, inertia + 0.0, part.frame)
    return MassProperties.sum(parts)


def _flags(model: RobotModel, link: Link, result: LinkAudit, carries_mass: bool) -> list[Flag]:
    """The link's flags (other than ``mesh``), one link at a time."""
    declared, geo = result.declared, result.geometry
    if declared is None or declared.mass == 0.0:
        return _zero_mass_flags(link, declared, carries_mass)
    flags: list[Flag] = []
    I = declared.inertia_about_com
    if declared.mass < 0:
        flags.append(Flag("unphysical", "error", f"mass {declared.mass:.6g} kg is negative", "negative mass"))
    problem = declared_inertia_problem(declared.mass, I)
    if problem is not None:
        flags.append(Flag("unphysical", "error", inertia_problem_text(problem, I), problem.kind))
    has_geometry = geo is not None and geo.inertia_about_com is not None and geo.mass
    if link.inertial is not None and link.inertial.source == "default":
        if has_geometry:
            _geometry_flags(result, None)  # the ratios only: the default is not the file's claim
        return flags + [Flag("placeholder", "warning", _DEFAULT_TEXT, "SDFormat's default inertial")]
    placeholder = _placeholder(model, link)
    if has_geometry:
        flags += _geometry_flags(result, placeholder)
    elif placeholder:
        flags.append(Flag("placeholder", "warning", f"{placeholder} (no geometry to compare with)"))
    return flags


_DEFAULT_TEXT = (
    "no <inertial>: SDFormat, Gazebo and Drake give the link mass 1 kg and a unit inertia "
    "(1 kg·m² about each axis) at its origin; declare its own"
)


def _zero_mass_flags(link: Link, declared: MassProperties | None, carries_mass: bool) -> list[Flag]:
    """A link without mass: ``unphysical`` when it declares moments anyway; ``massless`` when a
    joint moves it (an error when nothing it carries has mass either)."""
    flags = []
    if declared is not None and np.any(declared.inertia_about_com != 0):
        moments = ", ".join(f"{m:.4g}" for m in np.linalg.eigvalsh(declared.inertia_about_com))
        flags.append(
            Flag(
                "unphysical",
                "error",
                f"mass 0 with principal moments {moments} kg·m²: no body without mass has a moment "
                "of inertia (simulators disagree on what it means)",
                "mass 0 with moments",
            )
        )
    if not link.moves:
        return flags
    what = "no <inertial>" if declared is None else "mass 0"
    if carries_mass:
        text = f"moved by a joint but has {what}; the links it carries have mass, so the joint still moves a mass"
        flags.append(Flag("massless", "warning", text))
    else:
        text = (
            f"moved by a joint but has {what}, and nothing it carries has mass: a simulator cannot "
            "integrate that joint"
        )
        flags.append(Flag("massless", "error", text))
    return flags


def _geometry_flags(result: LinkAudit, placeholder: str | None) -> list[Flag]:
    """``placeholder``/``mismatch`` from the moment ratios, ``mismatch`` for a centre of mass
    outside the geometry, ``density`` for an implausible implied density; sets the link's
    ``ratios`` and ``com_offset``."""
    declared, geo = result.declared, result.geometry
    flags: list[Flag] = []
    moments, axes = np.linalg.eigh(geo.inertia_about_com)
    found = _compared(
        *(value[None] for value in (moments, axes, declared.inertia_about_com, declared.center_of_mass)),
        *(value[None] for value in (geo.low, geo.high, geo.center_of_mass)),
    )
    (ratios,), (result.com_offset,), (inside,), _ = found
    result.ratios = ratios
    worst = _worst_ratio(ratios)
    level = None
    if worst is not None and (worst > ERROR_RATIO or worst < 1 / ERROR_RATIO):
        level = "error"
    elif (worst is not None and (worst > WARNING_RATIO or worst < 1 / WARNING_RATIO)) or (
        placeholder and _spread(moments) > 1.5
    ):
        level = "warning"
    if level is not None:
        code = "placeholder" if placeholder else "mismatch"
        texts = ", ".join(ratio_text(r) for r in ratios)
        detail = f"declared moments about the geometry's principal axes are {texts} × the {geo.source} geometry's at the same mass"
        if placeholder:
            detail = f"{placeholder}; {detail}"
        summary = "" if worst is None else f"a moment {ratio_text(worst)} × the {geo.source} geometry's"
        flags.append(Flag(code, level, detail, summary))
    if not inside:
        text = (
            "the declared centre of mass lies outside the geometry's bounds (offset "
            f"{result.com_offset:.3g} of the geometry's size from its centre of mass)"
        )
        flags.append(Flag("mismatch", "warning", text))
    low, high = SOLID_DENSITY_RANGE
    if geo.implied_density is not None and not low <= geo.implied_density <= high:
        text = (
            f"implied density {geo.implied_density:.4g} kg/m³ (mass {declared.mass:.6g} kg / {geo.source} "
            f"volume {geo.volume:.4g} m³) is outside what a solid material has ({low:g} to {high:g} kg/m³)"
        )
        flags.append(Flag("density", "warning", text))
    return flags


def _spread(moments) -> float:
    moments = np.asarray(moments, dtype=float)
    return float(moments.max() / moments.min()) if moments.min() > 0 else float("inf")


def _worst_ratio(ratios) -> float | None:
    """The ratio farthest from 1 (by factor; one past the largest double is inf), or None when
    there is none."""
    given = ratios[~np.isnan(ratios)]
    if given.size == 0:
        return None
    extreme = [float(given.max()), float(given.min())]
    return max(extreme, key=lambda r: abs(np.log(r)) if r > 0 else np.inf)


def _round(value: float) -> bool:
    if value == 0:
        return True
    exponent = np.log10(abs(value))
    return abs(exponent - round(exponent)) < 1e-12


def _placeholder(model: RobotModel, link: Link) -> str | None:
    """Words for a placeholder-looking inertia, or None."""
    inertial = link.inertial
    I = inertial.written_inertia
    if np.any(I[~np.eye(3, dtype=bool)] != 0):
        return None
    diagonal = np.diag(I)
    if model.format == "mjcf" and inertial.source == "geoms":
        return None
    if np.all(diagonal == diagonal[0]) and diagonal[0] > 0:
        return f"three equal moments ({diagonal[0]:.6g} kg·m²) with no products, as exporters write a placeholder"
    if all(_round(v) for v in diagonal):
        return (
            f"moments of round values ({', '.join(f'{v:g}' for v in diagonal)} kg·m²) with no products, as "
            "exporters write a placeholder"
        )
    return None
