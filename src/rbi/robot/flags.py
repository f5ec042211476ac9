"""What ``rbi audit`` says of a link: its flags (:class:`Flag`; ``unphysical``, ``placeholder``,
``mismatch``, ``density``, ``massless``; ``mesh`` comes with the geometry), their limits
(:data:`ERROR_RATIO`, :data:`WARNING_RATIO`, :data:`SOLID_DENSITY_RANGE`, :data:`COM_MARGIN`) and
wording, and the comparisons on stacks that decide them: the declared mass properties against the
geometry's (:func:`comparison`) and the screens that clear a link without asking it more
(:func:`certainly_physical`, :func:`maybe_placeholder`). :func:`link_flags` words one link's
flags from its row of the audit."""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbi.core.inertia import OFF_DIAGONAL
from rbi.core.mass import MassProperties
from rbi.core.validity import declared_inertia_problem
from rbi.formats.robot import Link, RobotModel
from rbi.formats.robot_files import inertia_problem_text
from rbi.robot.tree import dot_rows

ERROR_RATIO = 10.0
"""A declared moment beyond this factor of the geometry's (either way) is an error."""


USABLE_MOMENT = 1e-9
"""A geometry's principal moment below this fraction of its largest gives no ratio (``-``,
null): a rod's moment about its own axis is nothing to divide by."""


WARNING_RATIO = 2.0
"""A declared moment beyond this factor of the geometry's (either way) is a warning."""


SOLID_DENSITY_RANGE = (50.0, 25000.0)
"""Densities (kg/m³) a link's material can have: from rigid foam to above osmium (22,590)."""


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


def ratio_text(ratio: float | None) -> str:
    """A moment ratio for people: 3 significant digits, ``-`` for one the geometry cannot give
    (NaN), ``>1.8e+308`` for one past the largest double (the declared moment is finite, the
    geometry's too small to divide it by; None: no ratio)."""
    if ratio is None or math.isnan(ratio):
        return "-"
    return f">{sys.float_info.max:.2g}" if math.isinf(ratio) else f"{ratio:.3g}"


def comparison(moments, axes, inertia, com, low, high, geometry_com) -> tuple:
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
    size, offset = (np.sqrt(dot_rows(v, v)) for v in (high - low, com - geometry_com))  # their norms
    with np.errstate(all="ignore"):
        offset = offset / size
    margin = (COM_MARGIN * size)[:, None]
    inside = ~(np.any(com < low - margin, axis=1) | np.any(com > high + margin, axis=1))
    near = np.all(np.isnan(ratios) | ((ratios >= 1 / WARNING_RATIO) & (ratios <= WARNING_RATIO)), axis=1)
    offsets = [value if sized else None for value, sized in zip(offset.tolist(), (size > 0).tolist())]
    return ratios, offsets, inside, near


def certainly_physical(stack: np.ndarray) -> np.ndarray:
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


def maybe_placeholder(written: np.ndarray) -> np.ndarray:
    """Each written inertia of the (N, 3, 3) stack :func:`_placeholder` might call a placeholder:
    no products, and three equal moments or moments within 1e-6 (in log10) of round values (the
    test itself allows 1e-12)."""
    diagonal = np.diagonal(written, axis1=1, axis2=2)
    no_products = np.all(written[:, OFF_DIAGONAL] == 0, axis=1)
    equal = np.all(diagonal == diagonal[:, :1], axis=1)
    return no_products & (equal | np.all(_round(diagonal, 1e-6), axis=1))


def _round(values: np.ndarray, tolerance: float) -> np.ndarray:
    """Whether each of ``values`` is 0 or a power of ten (within ``tolerance`` in log10)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = np.log10(np.abs(values))
        return (values == 0) | (np.abs(exponent - np.round(exponent)) < tolerance)


def link_flags(model: RobotModel, each: Any, carries_mass: bool, moments, inside) -> list[Flag]:
    """The link's flags (other than ``mesh``) from its row of the audit (``each``, a
    :class:`rbi.robot.audit.LinkAudit`; ``moments``: its geometry's principal moments;
    ``inside``: its declared centre of mass within the geometry's bounds)."""
    declared, link = each.declared, each.link
    if declared is None or declared.mass == 0.0:
        return _zero_mass_flags(link, declared, carries_mass)
    flags: list[Flag] = []
    I = declared.inertia_about_com
    if declared.mass < 0:
        flags.append(Flag("unphysical", "error", f"mass {declared.mass:.6g} kg is negative", "negative mass"))
    problem = declared_inertia_problem(declared.mass, I)
    if problem is not None:
        flags.append(Flag("unphysical", "error", inertia_problem_text(problem, I), problem.kind))
    if link.inertial is not None and link.inertial.source == "default":
        return flags + [Flag("placeholder", "warning", _DEFAULT_TEXT, "SDFormat's default inertial")]
    placeholder = _placeholder(model, link)
    if each.ratios is not None:
        flags += _geometry_flags(each, placeholder, moments, inside)
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


def _geometry_flags(each: Any, placeholder: str | None, moments, inside) -> list[Flag]:
    """``placeholder``/``mismatch`` from the moment ratios, ``mismatch`` for a centre of mass
    outside the geometry, ``density`` for an implausible implied density."""
    flags: list[Flag] = []
    ratios, source, implied = each.ratios, each.source, each.implied_density
    worst = worst_ratio(ratios)
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
        detail = f"declared moments about the geometry's principal axes are {texts} × the {source} geometry's at the same mass"
        if placeholder:
            detail = f"{placeholder}; {detail}"
        summary = "" if worst is None else f"a moment {ratio_text(worst)} × the {source} geometry's"
        flags.append(Flag(code, level, detail, summary))
    if not inside:
        text = (
            "the declared centre of mass lies outside the geometry's bounds (offset "
            f"{each.com_offset:.3g} of the geometry's size from its centre of mass)"
        )
        flags.append(Flag("mismatch", "warning", text))
    low, high = SOLID_DENSITY_RANGE
    if implied is not None and not low <= implied <= high:
        text = (
            f"implied density {implied:.4g} kg/m³ (mass {each.declared.mass:.6g} kg / {source} "
            f"volume {each.volume:.4g} m³) is outside what a solid material has ({low:g} to {high:g} kg/m³)"
        )
        flags.append(Flag("density", "warning", text))
    return flags


def _spread(moments) -> float:
    moments = np.asarray(moments, dtype=float)
    return float(moments.max() / moments.min()) if moments.min() > 0 else float("inf")


def worst_ratio(ratios) -> float | None:
    """The ratio farthest from 1 (by factor; one past the largest double is inf), or None when
    there is none."""
    given = ratios[~np.isnan(ratios)]
    if given.size == 0:
        return None
    extreme = [float(given.max()), float(given.min())]
    return max(extreme, key=lambda r: abs(np.log(r)) if r > 0 else np.inf)


def _placeholder(model: RobotModel, link: Link) -> str | None:
    """Words for a placeholder-looking inertia, or None."""
    inertial = link.inertial
    I = inertial.written_inertia
    if np.any(I[OFF_DIAGONAL] != 0):
        return None
    diagonal = np.diag(I)
    if model.format == "mjcf" and inertial.source == "geoms":
        return None
    if np.all(diagonal == diagonal[0]) and diagonal[0] > 0:
        return f"three equal moments ({diagonal[0]:.6g} kg·m²) with no products, as exporters write a placeholder"
    if np.all(_round(diagonal, 1e-12)):
        return (
            f"moments of round values ({', '.join(f'{v:g}' for v in diagonal)} kg·m²) with no products, as "
            "exporters write a placeholder"
        )
    return None
