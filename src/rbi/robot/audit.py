"""``rbi audit``: each link's declared mass properties against its own geometry, the flags that
say what is wrong, and the whole robot's totals.

Per link (all in the link frame, SI): ``declared``, the inertial element (MJCF: what MuJoCo's
compiler gives the body); ``geometry``, the link's collision geometry (else visual;
``--geometry visual`` the other way round) as a solid at the declared mass, or at the given
density when the link declares no mass; ``ratios``, each declared moment about the geometry's
principal axes over the geometry's; ``com_offset``, the distance between the two centres of mass
over the geometry's size (its bounding box's diagonal). The flags (``unphysical``,
``placeholder``, ``mismatch``, ``density``, ``massless``, ``mesh``), their levels and limits
(:mod:`rbi.robot.flags`) are tabled in docs/audit.md ("What it checks").

Every model is audited one way, on arrays of its links (:class:`~rbi.formats.robot.LinkColumns`:
a URDF's reader gives them as columns, the SDF and MJCF readers' links are laid into them), into
one table (:class:`AuditedLinks`): the geometry measured one geom a row (the solid primitives on
stacks, the others one by one) and summed per link, compared with the declared inertials on
stacks, and flagged where screens on those stacks leave something to say. One link's audit is a
row of that table (:class:`LinkAudit`).
"""

from __future__ import annotations

import math
from dataclasses import InitVar, dataclass, field
from typing import Any

import numpy as np

from rbi.core.inertia import OFF_DIAGONAL, symmetric_eigen
from rbi.core.mass import MassProperties
from rbi.core.validity import finite, require_flags
from rbi.errors import ArgumentError, InputError, literal
from rbi.formats.robot import SOLID_KINDS, Link, LinkColumns, RobotModel, stacked
from rbi.formats.robot_geometry import MESH_INERTIA_MODES, distribution, half_extent, primitive
from rbi.formats.robot_paths import parse_package_paths
from rbi.memory import collector_paused
from rbi.reprs import Result, Rows, json_ready, plain
from rbi.robot.flags import (
    SOLID_DENSITY_RANGE,
    Flag,
    certainly_physical,
    comparison,
    link_flags,
    maybe_placeholder,
    ratio_text,
    worst_ratio,
)
from rbi.robot.statics import joint_torques
from rbi.robot.tree import parse_joint_values, placement, stack_apply, totals
from rbi.spec.materials import MATERIAL_DENSITIES_SI, canonical_name, unknown_material_message
from rbi.text import number, vector_text

GEOMETRY_CHOICES = ("collision", "visual", "none")
"""Which geometry gives a link's volume; ``none`` reads none (the declared inertials alone)."""


@dataclass(frozen=True)
class AuditSettings:
    """How a robot file is audited, made of :func:`rbi.audit`'s keywords (less ``out``), checked
    once when made and passed down; ArgumentError naming the keyword of a bad one.
    ``package_paths`` (given as ``{NAME: DIR}`` or ``NAME=DIR`` texts; kept as NAME → folders,
    for ``package://NAME/``), ``geometry`` (one of :data:`GEOMETRY_CHOICES`), ``density``
    (kg/m³ for the links that declare no mass: the one given, or that of ``material``, a built-in
    material, given in its place), ``mesh_inertia`` (auto, exact, convex or shell), ``joints``
    (given as ``{NAME: VALUE}`` or ``NAME=VALUE`` texts; kept as name → coordinate, rad or m,
    for the totals), ``fix`` (plan the fixed copy), ``allow_outside_paths`` and ``mesh_repair``."""

    package_paths: Any = None
    geometry: str = "collision"
    density: float | None = None
    material: InitVar[str | None] = None
    mesh_inertia: str = "auto"
    joints: Any = None
    fix: bool = False
    allow_outside_paths: bool = False
    mesh_repair: bool = False

    def __post_init__(self, material: str | None) -> None:
        require_flags(fix=self.fix, mesh_repair=self.mesh_repair)
        if self.geometry not in GEOMETRY_CHOICES:
            raise ArgumentError("geometry", f"{literal(self.geometry)}: must be collision, visual or none")
        if self.mesh_inertia not in MESH_INERTIA_MODES:
            choices = ", ".join(MESH_INERTIA_MODES)
            raise ArgumentError("mesh_inertia", f"{literal(self.mesh_inertia)}: must be one of {choices}")
        packages, values = parse_package_paths(self.package_paths), parse_joint_values(self.joints)
        object.__setattr__(self, "package_paths", packages)
        object.__setattr__(self, "joints", values)
        object.__setattr__(self, "density", material_density(material, self.density))


@dataclass
class LinkAudit:
    """One link's audit, a row of :class:`AuditedLinks`: the ``link``; its ``declared`` mass
    properties (None: no inertial); its ``geometry``'s at the declared mass, else at the given
    density (None: no geometry, or no mass to give it); where the geometry came from,
    ``source`` (``collision`` or ``visual``; None: no geometry measured); its ``volume`` (m³;
    None when it is all shells) and ``implied_density`` (kg/m³, or None); the moment
    ``ratios``, the ``com_offset`` and the ``flags``."""

    link: Link
    declared: MassProperties | None
    geometry: MassProperties | None
    source: str | None = None
    volume: float | None = None
    implied_density: float | None = None
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
        return None if self.ratios is None else worst_ratio(self.ratios)


@dataclass(repr=False)
class AuditReport(Result):
    """What ``rbi audit`` found: the model read, its links' audit (:class:`AuditedLinks`, one
    :class:`LinkAudit` a link in :attr:`links`), the totals, ``notes`` (what was read but not
    checked, inertials MuJoCo ignores) and the settings used. :meth:`as_dict` is the JSON the
    CLI prints."""

    model: RobotModel
    audited: AuditedLinks
    total: MassProperties
    notes: list[str]
    settings: AuditSettings
    fix: Any = None
    joints: list = field(default_factory=list)
    """Each joint coordinate's holding torque (:class:`rbi.robot.statics.JointTorque`)."""
    left_out: list[str] = field(default_factory=list)
    """The links whose declared moments the total does not count: mass 0 with moments (each
    flagged ``unphysical``), by name (an unnamed MJCF body as ``body[i]``)."""
    _links: list[LinkAudit] | None = None

    @property
    def links(self) -> list[LinkAudit]:
        """One :class:`LinkAudit` per link, in file order (made when first asked for)."""
        if self._links is None:
            with collector_paused():  # a large robot's rows are millions of new objects
                self._links = self.audited.rows()
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
        return self.audited.has_error or bool(self.model.unchecked)

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
        with collector_paused():  # a large robot's rows are millions of new objects
            cells = [_link_cells(each) for each in self.links]
        links = Rows(
            f"{self.path}: {len(self.links)} {plural} (ratio: the declared moment farthest from the "
            "geometry's, as a multiple of it)",
            (word, "mass kg", "ρ kg/m³", "ratio", "CoM off ÷ size", "flags"),
            cells,
            kind="parts",  # names and flags fold, numbers never wrap
            text_last=True,
        )
        total = self.total
        quantities = [
            ("mass", "kg", number(total.mass, 6)),
            ("centre of mass", "m", vector_text(total.center_of_mass, 6, scale=0)),
            ("principal moments", "kg·m²", vector_text(self.total_moments, 6, scale=0)[1:-1]),
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
                    text_last=True,
                )
            )
        return tables

    @json_ready
    def to_dict(self) -> dict[str, Any]:
        """What ``rbi audit --format json`` prints, less ``"file"`` (with ``"fix"`` when the fixed
        copy was planned): JSON-ready, built so (no numpy value, no -0.0) without walking the
        links' millions of numbers again."""
        total = self.total
        more = {"moments": self.total_moments, "frame": total.frame, "left_out": list(self.left_out)}
        with collector_paused():  # a large robot's JSON is millions of new objects
            links, joints = self.audited.to_dicts(), _joint_dicts(self.joints)
        found = {
            "robot": self.model.name,
            "format": self.model.format,
            "units": {"length": "m", "mass": "kg"},
            "links": links,
            "total": plain(total.to_dict() | more),
            "joints": joints,
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


def _link_cells(each: LinkAudit) -> tuple[str, ...]:
    declared, implied = each.declared, each.implied_density
    return (
        each.link.name if each.link.name is not None else each.link.label,
        "-" if declared is None else number(declared.mass, 6),
        "-" if implied is None else number(implied, 4),
        ratio_text(each.worst_ratio),
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
            " ".join(flag.code for flag in each.flags) or "ok",
        )
        for each, torque in zip(joints, torques)
    ]


def _joint_dicts(joints: list) -> list[dict[str, Any]]:
    """Each joint's JSON object: its :class:`~rbi.robot.statics.JointTorque` fields in order
    (name, type, torque, effort_limit, flags), JSON-ready (no -0.0)."""
    return [plain(vars(each) | {"flags": [flag.as_dict() for flag in each.flags]}) for each in joints]


def _csv_row(each: LinkAudit) -> dict[str, Any]:
    declared, ratios = each.declared, None if each.ratios is None else _given(each.ratios)
    return {
        "link": each.link.name or each.link.label,
        "mass": declared.mass if declared else None,
        "geometry_volume": each.volume,
        "implied_density": each.implied_density,
        **{f"ratio_{i + 1}": None if ratios is None else ratios[i] for i in range(3)},
        "com_offset": each.com_offset,
        "flags": " ".join(f"{f.code}:{f.level}" for f in each.flags),
    }


def _stack_moments(stack: np.ndarray) -> list[list[float]]:
    """The principal moments (ascending, kg·m²) of each inertia of a (k, 3, 3) stack, as lists,
    without the axes: an inertia with no products has its diagonal as moments, sorted on the
    stack at once (a million-link report asks for two per link); the others'
    :func:`rbi.core.inertia.symmetric_eigen` eigenvalues."""
    diagonal = np.diagonal(stack, axis1=1, axis2=2)
    sortable = ~np.any(stack[:, OFF_DIAGONAL], axis=1) & np.all(np.abs(diagonal) < 1e300, axis=1)
    ordered = np.take_along_axis(diagonal, np.argsort(diagonal, axis=1, kind="stable"), axis=1)
    ordered = (ordered + 0.0).tolist()  # + 0.0: no -0.0
    for k in np.flatnonzero(~sortable).tolist():
        ordered[k] = (symmetric_eigen(stack[k])[0] + 0.0).tolist()
    return ordered


def material_density(material: str | None, density: float | None) -> float | None:
    """kg/m³ from ``density`` or ``material`` (``--density``, ``--material``); ArgumentError
    (naming the parameters) for both, a bad number or an unknown material."""
    if material is not None and density is not None:
        raise ArgumentError(("density", "material"), "give one of them")
    if density is not None:
        real = isinstance(density, (int, float, np.integer, np.floating))  # a bool is none: finite
        if not (real and finite(density) and density > 0):
            raise ArgumentError(
                "density", f"{literal(density)}: must be a finite number greater than 0 (kg/m³)"
            )
        return float(density)
    if material is not None:
        name = canonical_name(material) if isinstance(material, str) else None
        if name is None:
            message = unknown_material_message(str(material), numbers_too=False)
            raise ArgumentError("material", literal(message, quoted=False) + " (or {density} in kg/m³)")
        return MATERIAL_DENSITIES_SI[name]
    return None


def audit_model(model: RobotModel, settings: AuditSettings | None = None, **options: Any) -> AuditReport:
    """Audit a model already read (see :func:`rbi.formats.robot_files.read_robot`) as
    ``settings`` say, or the keywords of :class:`AuditSettings`."""
    settings = AuditSettings(**options) if settings is None else settings
    repairs: list[str] = []
    columns = model.link_columns()
    audited = AuditedLinks(model, columns, settings, repairs)
    notes = list(model.unchecked) + list(model.notes) + list(dict.fromkeys(repairs))
    placed = placement(model, settings.joints, columns)
    return AuditReport(
        model,
        audited,
        totals(model, settings.joints, placed),
        notes,
        settings,
        joints=joint_torques(model, placed),
        left_out=_left_out(model, columns),
    )


def _left_out(model: RobotModel, columns: LinkColumns) -> list[str]:
    """The names of the links of mass 0 that declare moments (the total counts no moment without
    a mass: :attr:`rbi.robot.tree.Placement.heavy`); an unnamed one as ``body[i]``."""
    rows = (
        columns.declared
        & (columns.inertials.mass == 0.0)
        & np.any(columns.inertials.inertia_about_com != 0.0, axis=(1, 2))
    )
    names, word = columns.names, model.link_word
    return [f"{word}[{row}]" if names[row] is None else names[row] for row in np.flatnonzero(rows).tolist()]


class AuditedLinks:
    """Every link's audit as arrays, one row a link in file order (the rows of its
    :class:`~rbi.formats.robot.LinkColumns`). The geometry: ``measured`` (n,), the links with
    some; ``has_mass`` (n,), those whose geometry has a mass (the declared one, else the given
    density's; MJCF: its geoms'); its ``mass`` (n,), centre of mass ``com`` (n, 3; the centroid
    when it has no mass) and ``inertia`` (n, 3, 3) about it, kg·m², NaN where it has no mass;
    ``volume`` (n,) m³, NaN when all shells; ``implied`` density (n,), NaN where none; bounds
    ``low``/``high`` (n, 3) and ``sources``. The comparison, on the ``compared`` rows (a declared
    mass other than 0 and a geometry with mass): ``ratios`` (n, 3; NaN where none), ``offsets``
    (None where none), the geometry's principal ``moments`` and whether the declared centre of
    mass lies ``inside`` its bounds. ``flags``: row → the link's flags (none when not there).
    :meth:`row` gives one row as a :class:`LinkAudit`."""

    def __init__(self, model: RobotModel, columns: LinkColumns, settings: AuditSettings, notes: list[str]):
        self.model, self.columns = model, columns
        n = len(columns)
        self.measured, self.has_mass = np.zeros(n, dtype=bool), np.zeros(n, dtype=bool)
        self.mass, self.volume, self.implied = np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan)
        self.com, self.low, self.high = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3))
        self.inertia = np.full((n, 3, 3), np.nan)
        self.sources: list[str | None] = [None] * n
        self.flags: dict[int, list[Flag]] = {}
        if settings.geometry != "none":
            self._measure(settings, notes)
        self._compare()
        self._flag()
        self._refuse_overflow()

    @property
    def has_error(self) -> bool:
        return any(flag.level == "error" for flags in self.flags.values() for flag in flags)

    @property
    def geometry(self) -> MassProperties:
        """The geometry's mass properties, a stack of one a link (NaN where it has none)."""
        return MassProperties(self.mass, self.com, self.inertia, "link")

    def _measure(self, settings: AuditSettings, notes: list[str]) -> None:
        """Each link's geometry: its pieces (:meth:`_pieces`) summed as :meth:`MassProperties.sum`
        sums them (a link's only piece, when the sum would give it back as it is: that piece, on
        the stacks), then at the declared mass where there is one, else at the given density
        (MJCF: at its geoms' own masses), the inertia scaled as :meth:`MassProperties.with_mass`
        scales it; its volume that of its solid pieces, its implied density where none is a shell."""
        n = len(self.columns)
        first, rows, measure, mass, com, inertia, low, high, shell = self._pieces(settings, notes)
        kept = measure > 0
        single = _alone(n, rows, kept, mass, com, inertia)
        unit_mass, unit_inertia = np.full(n, np.nan), np.full((n, 3, 3), np.nan)
        solid = np.zeros(n, dtype=bool)
        at = rows[single]
        self.measured[at], unit_mass[at], unit_inertia[at] = True, mass[single], inertia[single] + 0.0
        self.com[at], self.low[at], self.high[at] = com[single] + 0.0, low[single], high[single]
        self.volume[at], solid[at] = np.where(shell[single], np.nan, measure[single]), ~shell[single]
        grouped: dict[int, list[int]] = {}
        for g in np.flatnonzero(kept & ~single).tolist():  # each link's pieces in file order
            grouped.setdefault(int(rows[g]), []).append(g)
        for row, each in grouped.items():
            try:
                unit = MassProperties(mass[each], com[each], inertia[each], "link").sum()
            except ValueError:  # no mass in the geometry
                continue
            volumes = measure[each][~shell[each]].tolist()
            self.measured[row], unit_mass[row], unit_inertia[row] = True, unit.mass, unit.inertia_about_com
            self.com[row], solid[row] = unit.center_of_mass, len(volumes) == len(each)
            self.low[row], self.high[row] = np.min(low[each], axis=0), np.max(high[each], axis=0)
            if volumes:
                self.volume[row] = float(sum(volumes))
        kind, other = settings.geometry, "visual" if settings.geometry == "collision" else "collision"
        pairs = zip(self.measured.tolist(), first.tolist())  # (measured, from settings.geometry) a link
        self.sources = [(kind if at else other) if measured else None for measured, at in pairs]
        declared = np.where(self.columns.declared, self.columns.inertials.mass, 0.0)
        given = self.measured & (declared > 0)
        mjcf, density = self.model.format == "mjcf", settings.density
        heavy = self.measured if mjcf or density is not None else given
        with np.errstate(all="ignore"):
            otherwise = unit_mass if mjcf else (np.nan if density is None else density) * unit_mass
            found = np.where(given, declared, otherwise)
            scaled = unit_inertia * (found / unit_mass)[:, None, None]
            implied = np.where(solid, found / self.volume, np.nan)
        self.has_mass[heavy], self.mass[heavy], self.inertia[heavy] = True, found[heavy], scaled[heavy]
        self.implied[heavy] = implied[heavy]

    def _pieces(self, settings: AuditSettings, notes: list[str]) -> tuple:
        """Every geom a link's geometry is measured from (its ``settings.geometry`` elements, or
        the other kind's when it has none of those), as :func:`distribution` measures it:
        ``first`` (n,), the links measured from ``settings.geometry``; then one entry a geom, in
        the order of ``columns.geoms``: its link's row, its volume (m³; m² for a shell; NaN:
        none), its mass at density 1 (MJCF: at its own mass or density), its centre of mass
        and inertia at that mass, its bounds and whether it is a shell. The solid primitives
        are measured on stacks (:func:`_on_stacks`); the other geoms, and a primitive whose
        numbers take another branch there, one at a time, links in file order (a ``mesh``
        flag for each mesh ``auto`` could not integrate exactly)."""
        model, columns, geometry = self.model, self.columns, settings.geometry
        other = "visual" if geometry == "collision" else "collision"
        counts = {tag: np.zeros(len(columns), dtype=int) for tag in (geometry, other)}
        for column in columns.geoms:
            counts[column.tag] += np.bincount(column.rows, minlength=len(columns))
        first = counts[geometry] > 0
        chosen = {geometry: first, other: ~first & (counts[other] > 0)}
        picked = [(column, np.flatnonzero(chosen[column.tag][column.rows])) for column in columns.geoms]
        rows = np.concatenate([np.zeros(0, dtype=int), *(np.asarray(c.rows)[at] for c, at in picked)])
        size = len(rows)
        measure, shell = np.full(size, np.nan), np.zeros(size, dtype=bool)
        com, low, high = np.zeros((size, 3)), np.zeros((size, 3)), np.zeros((size, 3))
        inertia = np.full((size, 3, 3), np.nan)
        one_by_one, start = [], 0
        for column, at in picked:
            span, start = np.arange(start, start + len(at)), start + len(at)
            fine = np.zeros(len(at), dtype=bool)
            if column.kind in SOLID_KINDS and column.sizes is not None and len(at):
                fine, *found = _on_stacks(column, at)
                put = span[fine]
                measure[put], com[put], inertia[put], low[put], high[put] = found
            one_by_one += [(int(rows[g]), int(g), column, k) for g, k in zip(span[~fine], at[~fine])]
        mode, repair = settings.mesh_inertia, settings.mesh_repair
        for row, g, column, k in sorted(one_by_one, key=lambda each: each[:2]):
            fallbacks: list = []
            where = f"{model.path}: {columns.link(row).label}: "
            found = distribution(column.geom(k), mode, where, repair, notes, fallbacks)
            if fallbacks:
                why = [Flag("mesh", "warning", each.message(), "mesh not closed") for each in fallbacks]
                self.flags[row] = self.flags.get(row, []) + why
            if found is not None:
                measure[g], shell[g], low[g], high[g] = found.measure, found.shell, found.low, found.high
                com[g], inertia[g] = found.unit.center_of_mass, found.unit.inertia_about_com
        mass = measure.copy()
        if model.format == "mjcf":  # each geom at its own mass
            geoms = [column.geom(k) for column, at in picked for k in at.tolist()]
            mass[:] = [g.density * v if g.mass is None else g.mass for g, v in zip(geoms, measure.tolist())]
            with np.errstate(all="ignore"):
                inertia = inertia * (mass / measure)[:, None, None]
        return first, rows, measure, mass, com, inertia, low, high, shell

    def _compare(self) -> None:
        """The declared mass properties against the geometry's, on stacks (:func:`compared`),
        of the links that declare a mass other than 0 and whose geometry has mass (and a finite
        inertia: one that overflows is refused by :meth:`_refuse_overflow`)."""
        columns, n = self.columns, len(self.columns)
        finite = np.all(np.isfinite(self.inertia), axis=(1, 2))
        self.compared = (
            columns.declared & (columns.inertials.mass != 0) & self.has_mass & (self.mass != 0) & finite
        )
        rows = np.flatnonzero(self.compared)
        self.ratios, self.moments = np.full((n, 3), np.nan), np.full((n, 3), np.nan)
        self.inside, self.clean = np.zeros(n, dtype=bool), np.zeros(n, dtype=bool)
        self.offsets: list[float | None] = [None] * n
        moments, axes = np.linalg.eigh(self.inertia[rows])
        ratios, offsets, inside, near = comparison(
            moments,
            axes,
            columns.inertials.inertia_about_com[rows],
            columns.inertials.center_of_mass[rows],
            self.low[rows],
            self.high[rows],
            self.com[rows],
        )
        self.ratios[rows], self.moments[rows], self.inside[rows] = ratios, moments, inside
        for row, offset in zip(rows.tolist(), offsets):
            self.offsets[row] = offset
        low_density, high_density = SOLID_DENSITY_RANGE
        implied = self.implied[rows]
        self.clean[rows] = near & inside & (implied >= low_density) & (implied <= high_density)

    def _flag(self) -> None:
        """Each link's flags (:func:`link_flags`), asked of the links the screens on the stacks do
        not clear: a declared inertial certainly physical, no placeholder, a clean comparison
        (or none); no inertial on a link no joint moves."""
        columns, n = self.columns, len(self.columns)
        heavy = columns.declared & (columns.inertials.mass > 0)
        moving = np.zeros(n, dtype=bool)  # links a joint moves
        kinds = zip(columns.joint_rows, columns.joint_kinds)
        moving[[row for row, kind in kinds if kind != "fixed" and columns.parents[row] != n]] = True
        physical = certainly_physical(columns.inertials.inertia_about_com)  # (zero where none is declared)
        clear = heavy & physical & ~maybe_placeholder(columns.written) & (~self.compared | self.clean)
        clear |= ~columns.declared & ~moving
        carried = _carried(columns)
        for row in np.flatnonzero(~clear).tolist():
            found = link_flags(self.model, self.row(row), carried[row], self.moments[row], self.inside[row])
            if found:
                self.flags[row] = self.flags.get(row, []) + found

    def _refuse_overflow(self) -> None:
        """InputError naming the file and the link when a number its audit gives overflows a
        double (a centre of mass 1e155 m from a 0.1 m geometry: the offset's square): refused
        here, once, for every output form and the API."""
        offsets = np.array([0.0 if offset is None else offset for offset in self.offsets])
        with np.errstate(invalid="ignore"):
            largest = np.where(self.has_mass, np.max(np.abs(self.inertia), axis=(1, 2)), 0.0)
        found = {
            "its centre of mass's offset from its geometry": ~np.isfinite(offsets),
            "its geometry's implied density": np.isinf(self.implied),
            "its geometry's inertia": ~np.isfinite(largest),
        }
        bad = np.flatnonzero(np.any(list(found.values()), axis=0))
        if bad.size:
            row = int(bad[0])
            what = next(what for what, rows in found.items() if rows[row])
            raise InputError(
                f"{self.model.path}: {self.columns.link(row).label}: {what} overflows a double; give "
                "lengths in metres, masses in kg and moments in kg·m²"
            )

    def row(self, row: int, link: Link | None = None) -> LinkAudit:
        """The :class:`LinkAudit` of ``row``."""
        link = self.columns.link(row) if link is None else link
        geometry = None
        if self.has_mass[row]:
            geometry = MassProperties(self.mass[row], self.com[row], self.inertia[row], "link")
        volume, implied = float(self.volume[row]), float(self.implied[row])
        return LinkAudit(
            link,
            None if link.inertial is None else link.inertial.properties,
            geometry,
            self.sources[row],
            None if math.isnan(volume) else volume,
            None if math.isnan(implied) else implied,
            self.ratios[row].copy() if self.compared[row] else None,
            self.offsets[row],
            self.flags.get(row, []),
        )

    def rows(self) -> list[LinkAudit]:
        """Every link's :class:`LinkAudit`, in file order."""
        return [self.row(row, link) for row, link in enumerate(self.columns.links())]

    def to_dicts(self) -> list[dict[str, Any]]:
        """Each link's JSON object, in file order, JSON-ready, made from the arrays (a
        100,000-link report makes no object per link but these): the declared and the
        geometry's mass properties as their stacks' ``to_dict()``."""
        columns = self.columns
        declared, geometry = [None] * len(columns), [None] * len(columns)
        rows = np.flatnonzero(columns.declared)
        stack = columns.inertials[rows]
        found = _unsigned(stack).to_dict() | {"moments": _stack_moments(stack.inertia_about_com)}
        for row, each in zip(rows.tolist(), _each(found)):
            declared[row] = each
        rows = np.flatnonzero(self.measured)
        heavy = self.has_mass[rows].tolist()
        moments = iter(_stack_moments(self.inertia[rows[self.has_mass[rows]]]))
        found = {"volume": _nan_none(self.volume[rows] + 0.0)} | _unsigned(self.geometry[rows]).to_dict()
        found["mass"] = [m if h else None for m, h in zip(found["mass"], heavy)]
        found["inertia_about_com"] = [m if h else None for m, h in zip(found["inertia_about_com"], heavy)]
        found["moments"] = [next(moments) if h else None for h in heavy]
        found["implied_density"] = _nan_none(self.implied[rows] + 0.0)
        found["source"] = [self.sources[row] for row in rows.tolist()]
        for row, each in zip(rows.tolist(), _each(found)):
            geometry[row] = each
        ratios, offsets, flags = self.ratios, self.offsets, self.flags
        compared = self.compared.tolist()
        return [
            {
                "name": name,
                "index": row,
                "declared": declared[row],
                "geometry": geometry[row],
                "moment_ratios": _given(ratios[row]) if compared[row] else None,
                "com_offset": None if offsets[row] is None else offsets[row] + 0.0,
                "flags": [flag.as_dict() for flag in flags.get(row, ())],
            }
            for row, name in enumerate(columns.names)
        ]


def _nan_none(values: np.ndarray) -> list[float | None]:
    """``values`` as a list, each NaN (no value) as None."""
    return [None if value != value else value for value in values.tolist()]


def _unsigned(stack: MassProperties) -> MassProperties:
    """``stack`` with each -0.0 as 0.0 (JSON's numbers)."""
    return MassProperties(
        stack.mass + 0.0, stack.center_of_mass + 0.0, stack.inertia_about_com + 0.0, stack.frame
    )


def _each(columns: dict[str, list]) -> list[dict[str, Any]]:
    """One dict a body of a stack's columns (key → one value a body, a stack's ``to_dict()``)."""
    return [dict(zip(columns, values)) for values in zip(*columns.values())]


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


def _alone(n: int, rows: np.ndarray, kept: np.ndarray, mass, com, inertia) -> np.ndarray:
    """The pieces kept (``kept``) alone in their link (``rows``, of ``n``) that
    :meth:`MassProperties.sum` gives back as they are (each -0.0 as 0.0): a finite positive
    mass, a finite centre of mass and an inertia whose symmetrizing cannot overflow."""
    with np.errstate(all="ignore"):
        alone = kept & (np.bincount(rows[kept], minlength=n)[rows] == 1) & (mass > 0) & np.isfinite(mass)
        return alone & np.all(np.isfinite(com), axis=1) & np.all(np.abs(inertia) < 1e300, axis=(1, 2))


def _on_stacks(column, at: np.ndarray) -> tuple:
    """The geoms ``at`` of a column of one solid primitive, measured on stacks with the
    operations :func:`distribution` makes on one, element by element (so the same numbers):
    ``fine`` (k,), those :func:`distribution` measures so (their size not refused, their
    numbers finite), and their volume, centre of mass, inertia at density 1 and bounds
    (:func:`primitive` and :func:`half_extent` once for each size)."""
    sizes = column.sizes[at]
    if np.all(sizes == sizes[0]):  # one size throughout
        keys, inverse = [tuple(sizes[0].tolist())], np.zeros(len(at), dtype=int)
    else:
        found = {key: k for k, key in enumerate(dict.fromkeys(map(tuple, sizes.tolist())))}
        keys, inverse = list(found), np.array([found[key] for key in map(tuple, sizes.tolist())])
    known = []
    for key in keys:
        try:
            known.append((*primitive(column.kind, key), half_extent(column.kind, key)))
        except ValueError:  # refused here, refused there
            known.append((np.nan, np.full(3, np.nan), np.full(3, np.nan)))
    measure = np.array([each[0] for each in known], dtype=float)[inverse]
    moments, half = (stacked([each[k] for each in known], (3,))[inverse] for k in (1, 2))
    R, p = column.rotations[at], column.translations[at]
    turned = np.matmul(R * moments[:, None, :], np.swapaxes(R, 1, 2))
    corners = stack_apply(np.abs(R), half)
    with np.errstate(all="ignore"):
        fine = np.isfinite(measure) & np.all(np.isfinite(turned), axis=(1, 2))
    inertia = 0.5 * (turned + np.swapaxes(turned, 1, 2))
    return fine, measure[fine], p[fine], inertia[fine], (p - corners)[fine], (p + corners)[fine]
