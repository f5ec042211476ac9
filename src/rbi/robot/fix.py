"""``rbi audit --fix``: a copy of the robot file in which each flagged link's inertial is the one
its geometry gives (at the declared mass, or at the given density for a link without mass).

The copy is the original text edited at the spans of the inertial elements (the parser records
where each element starts and ends): every other byte is kept — comments, order, formatting,
encoding. Each replaced element is preceded by an XML comment saying what it was and why it
changed. Links whose inertial is in another file (an MJCF ``<include>``), or that MuJoCo's
compiler fills from geoms, or that have no geometry, cannot be fixed; they are listed.
"""

from __future__ import annotations

import difflib
import os
from dataclasses import dataclass, field

import numpy as np

from rbi.core.mass import MassProperties
from rbi.errors import InputError
from rbi.files.safe import shown
from rbi.formats.inertial_xml import inertial_text, xml_comment
from rbi.formats.robot_xml import _tag_end
from rbi.formats.urdf import attach_elements
from rbi.robot.audit import AuditReport, LinkAudit
from rbi.robot.flags import ERROR_RATIO, USABLE_MOMENT

FIXED_CODES = ("unphysical", "placeholder", "mismatch", "massless")


@dataclass
class Change:
    """One replaced (or added) inertial: the link, what was there, what is written, and why."""

    link: str
    reason: str
    old_text: str
    new_text: str
    start: int
    end: int


@dataclass
class FixPlan:
    """The edits, the links that could not be fixed (label, why), and the fixed file's bytes."""

    changes: list[Change] = field(default_factory=list)
    unfixable: list[tuple[str, str]] = field(default_factory=list)
    content: bytes = b""

    def diff(self, path: str, out: str | None = None) -> str:
        """A unified diff between the original file and the fixed copy."""

        return "".join(
            difflib.unified_diff(
                self.original.decode("utf-8", "replace").splitlines(True),
                self.content.decode("utf-8", "replace").splitlines(True),
                fromfile=path,
                tofile=out or f"{path} (fixed)",
            )
        )

    original: bytes = b""
    out: str | None = None
    """Where the fixed copy was written (the path as given), or None (planned only)."""

    def to_dict(self) -> dict:
        """``"fix"`` of ``rbi audit --fix --format json``."""
        return {
            "out": self.out,
            "changes": [{"link": c.link, "reason": c.reason} for c in self.changes],
            "unfixable": [{"link": label, "reason": why} for label, why in self.unfixable],
        }


def plan_fix(report: AuditReport, density: float | None = None) -> FixPlan:
    """The fixed copy of the audited file: every link with an error-level flag that the
    geometry can fix gets the geometry's inertial."""
    attach_elements(report.model)  # a URDF's links (made from columns) get their elements now
    document = report.model.document
    plan = FixPlan()
    text = document.text
    for each in report.links:
        codes = {flag.code for flag in each.flags if flag.level == "error"}
        if not codes & set(FIXED_CODES):
            continue
        reason = "; ".join(
            f"{flag.code}: {flag.summary or flag.message}" for flag in each.flags if flag.level == "error"
        )
        why_not = _why_not(report, each, density)
        if why_not is not None:
            plan.unfixable.append((each.link.label, why_not))
            continue
        change = _change(report, each, density, reason, text)
        if change is None:
            plan.unfixable.append((each.link.label, "its element cannot be edited in place"))
            continue
        plan.changes.append(change)
    pieces, at = [], 0
    for change in sorted(plan.changes, key=lambda c: c.start):
        pieces += [text[at : change.start], change.new_text.encode("utf-8")]
        at = change.end
    pieces.append(text[at:])
    plan.original = document.original_bytes(text)
    plan.content = document.original_bytes(b"".join(pieces))
    return plan


def _why_not(report: AuditReport, each: LinkAudit, density: float | None) -> str | None:
    geo = each.geometry
    inertial = each.link.inertial
    if each.source is None:
        return "it has no geometry with a volume to take the mass properties from"
    if inertial is not None and inertial.element is None and inertial.source == "geoms":
        return "MuJoCo's compiler gives it its mass properties from its geoms; change the geoms instead"
    if inertial is not None and getattr(inertial.element, "source", None):
        return "its <inertial> is in an included file"
    if geo is None:
        return "it declares no mass; give --density or --material to fix it at a density"
    if inertial is None and each.link.element is None:
        return "its element cannot be edited"
    return _bounded(report, geo)


def _bounded(report: AuditReport, geo: MassProperties) -> str | None:
    """Why the geometry's inertial would still be an error once MuJoCo's compiler has raised
    its principal moments to ``<compiler boundinertia>`` (the audit reads them raised), or
    None. A moment the audit compares with none (below USABLE_MOMENT of the largest) is not
    asked."""
    bound = report.model.options.get("boundinertia", 0.0)
    moments = np.linalg.eigvalsh(geo.inertia_about_com)
    smallest = float(np.min(moments[moments > USABLE_MOMENT * moments[-1]], initial=np.inf))
    if not bound > ERROR_RATIO * smallest:
        return None
    return (
        f"MuJoCo's compiler raises its principal moments to boundinertia {bound:g} kg·m², more "
        f"than {ERROR_RATIO:g} × its geometry's smallest ({smallest:.4g} kg·m²); lower boundinertia"
    )


def _indent(text: bytes, start: int) -> str:
    line_start = text.rfind(b"\n", 0, start) + 1
    lead = text[line_start:start]
    return lead.decode("utf-8") if lead.strip() == b"" else ""


def _step(indent: str) -> str:
    return "\t" if "\t" in indent else "  "


def _change(
    report: AuditReport, each: LinkAudit, density: float | None, reason: str, text: bytes
) -> Change | None:

    geo = each.geometry
    inertial = each.link.inertial
    basis = (
        f"at the declared mass {geo.mass:.6g} kg"
        if each.declared is not None and each.declared.mass > 0
        else f"at density {density:g} kg/m³ ({geo.mass:.6g} kg)"
    )
    if inertial is not None and inertial.element is not None:
        start, end = inertial.element.start, inertial.element.end
        old = text[start:end].decode("utf-8")
        indent = _indent(text, start)
    else:
        start = end = _after_start_tag(text, each.link.element)
        if start is None:
            return None
        old = ""
        outer = _indent(text, each.link.element.start)
        indent = outer + _step(outer)
    was = (
        "no mass"
        if each.declared is None or each.declared.mass == 0
        else f"principal moments {', '.join(f'{m:.4g}' for m in each.declared.moments)} kg·m²"
    )
    comment = xml_comment(
        f"rbi audit fix: was {was} ({reason}); now its {each.source} geometry's mass properties {basis}"
    )
    body = inertial_text(report.model.format, geo, indent=indent, step=_step(indent))
    new = f"{comment}\n{indent}{body}" if old else f"\n{indent}{comment}\n{indent}{body}"
    new = _held(new, report.model.document.encoding)
    if text.count(b"\r\n") * 2 > text.count(b"\n"):  # a file with Windows line ends keeps them
        new = new.replace("\r\n", "\n").replace("\n", "\r\n")
    return Change(each.link.name or each.link.label, reason, old, new, start, end)


_SPELLED = str.maketrans({"·": "*", "²": "^2", "³": "^3", "×": "x"})


def _held(text: str, encoding: str) -> str:
    """``text`` with only characters ``encoding`` (the file's declared one) holds: the comment's
    ``kg·m²`` and ``×`` spelled in ASCII, anything else it cannot hold as ``?``."""
    try:
        text.encode(encoding)
        return text
    except UnicodeEncodeError:
        spelled = text.translate(_SPELLED)
        return spelled.encode(encoding, "replace").decode(encoding)


def _after_start_tag(text: bytes, element) -> int | None:
    """Just after the start tag of ``element``, when it has an end tag (not ``<link/>``)."""

    if element is None:
        return None
    stop = _tag_end(text, element.start)
    if text[stop - 2 : stop] == b"/>":
        return None
    return stop


def files_read(model) -> list[str]:
    """Every file the robot reads: the robot file, its includes (xacro, MJCF), its mesh
    assets and meshes, as real paths."""

    found = [model.path, *getattr(model.document, "includes", [])]
    for link in model.links:
        found.extend(str(geom.mesh_file) for geom in (*link.collisions, *link.visuals) if geom.mesh_file)
    return list(dict.fromkeys(os.path.realpath(each) for each in found))


def check_out_not_read(out: str, model) -> None:
    """InputError when ``out`` names a file the robot reads: writing there would replace an
    include or a mesh (or the robot file) with the fixed copy."""

    for each in files_read(model):
        try:
            same = os.path.samefile(out, each)
        except OSError:
            same = os.path.realpath(out) == each
        if same:
            what = (
                "the robot file itself" if each == os.path.realpath(model.path) else "a file the robot reads"
            )
            raise InputError(
                f"--out: {shown(out)}: is {what} ({shown(each)}); write the fixed copy to a new file"
            )
