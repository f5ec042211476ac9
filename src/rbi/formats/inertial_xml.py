"""The one writer of ``<inertial>`` elements (URDF, SDF, MJCF), used by ``rbi export`` and by
``rbi audit --fix``.

Every writer takes SI numbers (kg, m, kg·m²): the mass, the centre of mass in the link (body)
frame and the inertia matrix about the centre of mass in link axes, whose off-diagonal entries
are the matrix entries (``ixy = I[0][1] = −∫xy dm``), the convention of all three formats.
Numbers are written with the shortest repr that round-trips, so nothing is lost.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rbi.core.inertia import principal_axes, symmetrize
from rbi.core.mass import MassProperties
from rbi.core.rotation import matrix_to_quaternion
from rbi.text import visible

if TYPE_CHECKING:  # imported where an element is made: `rbi inertia` loads no XML module (~2 ms)
    import xml.etree.ElementTree as ET

FORMATS = ("urdf", "mjcf", "sdf")

_MUJOCO_ORDER = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
"""MJCF's ``fullinertia`` order."""

_SIX = (("ixx", (0, 0)), ("ixy", (0, 1)), ("ixz", (0, 2)), ("iyy", (1, 1)), ("iyz", (1, 2)), ("izz", (2, 2)))


def xml_number(value: float) -> str:
    """Shortest round-tripping text of a float (``-0.0`` written as ``0.0``)."""
    return repr(float(value) + 0.0)


def _numbers(values) -> str:
    return " ".join(xml_number(v) for v in values)


def inertial_element(fmt: str, props: MassProperties, diagonal: bool = False) -> ET.Element:
    """The ``<inertial>`` element of format ``fmt`` (one of :data:`FORMATS`) for ``props`` (SI,
    link axes). URDF: ``<origin xyz rpy>`` places the inertial frame at the centre of mass, axes
    parallel to the link's; ``<inertia ixx ixy ixz iyy iyz izz>`` about it. SDF: ``<pose>x y z roll pitch yaw</pose>`` (the same frame),
    ``<mass>``, and ``<inertia>`` with child elements ixx ixy ixz iyy iyz izz. MJCF:
    ``<inertial pos mass fullinertia>`` with fullinertia in MuJoCo's order Ixx Iyy Izz Ixy Ixz
    Iyz; or, with ``diagonal``, the principal moments as ``diaginertia`` and ``quat`` (w x y z)
    turning the principal frame into the body frame."""
    import xml.etree.ElementTree as ET

    I = symmetrize(props.inertia_about_com)
    six = {name: xml_number(I[i, j]) for name, (i, j) in _SIX}
    if fmt == "mjcf":
        attributes = {"pos": _numbers(props.center_of_mass), "mass": xml_number(props.mass)}
        if diagonal:
            moments, axes = principal_axes(I)
            # the quaternion of the matrix whose columns are the principal axes in body axes
            attributes["quat"] = _numbers(matrix_to_quaternion(axes.T))
            attributes["diaginertia"] = _numbers(moments)
        else:
            attributes["fullinertia"] = " ".join(six[key] for key in _MUJOCO_ORDER)
        return ET.Element("inertial", attributes)
    inertial = ET.Element("inertial")
    if fmt == "urdf":
        ET.SubElement(inertial, "origin", xyz=_numbers(props.center_of_mass), rpy="0 0 0")
        ET.SubElement(inertial, "mass", value=xml_number(props.mass))
        ET.SubElement(inertial, "inertia", six)
        return inertial
    ET.SubElement(inertial, "pose").text = _numbers([*props.center_of_mass, 0.0, 0.0, 0.0])
    ET.SubElement(inertial, "mass").text = xml_number(props.mass)
    block = ET.SubElement(inertial, "inertia")
    for name, text in six.items():
        ET.SubElement(block, name).text = text
    return inertial


def element_text(element: ET.Element, indent: str = "", step: str = "  ") -> str:
    """``element`` as text, its children indented by ``step`` per level; every line after the
    first starts with ``indent`` (the first is placed by the caller)."""
    import xml.etree.ElementTree as ET

    ET.indent(element, space=step)
    text = ET.tostring(element, encoding="unicode")
    return ("\n" + indent).join(text.split("\n"))


def inertial_text(fmt: str, props: MassProperties, *, indent: str = "", step: str = "  ") -> str:
    """The ``<inertial>`` element of ``fmt`` as text, for a place in a file whose lines there
    start with ``indent`` and whose nesting steps by ``step``."""
    return element_text(inertial_element(fmt, props), indent, step)


def xml_comment(text: str) -> str:
    """``<!-- text -->`` on one line; an XML comment may not hold ``--`` nor end in ``-``, so
    runs of hyphens are shortened to one and a final one dropped."""
    text = " ".join(text.split("\n"))
    while "--" in text:
        text = text.replace("--", "-")
    return f"<!-- {text.rstrip('-')} -->"


# --- `rbi export`: the element alone or in a minimal document, a comment first ----------------


def _document(fmt: str, name: str, inertial: ET.Element) -> ET.Element:
    """A minimal document of ``fmt`` holding ``inertial``: robot/link, sdf/model/link or
    mujoco/worldbody/body (with a free joint)."""
    import xml.etree.ElementTree as ET

    if fmt == "urdf":
        root = link = ET.Element("robot", name=name)
    elif fmt == "sdf":
        root = ET.Element("sdf", version="1.7")
        link = ET.SubElement(root, "model", name=name)
    else:
        root = ET.Element("mujoco", model=name)
        body = ET.SubElement(ET.SubElement(root, "worldbody"), "body", name=name)
        ET.SubElement(body, "freejoint")
        body.append(inertial)
        return root
    ET.SubElement(link, "link", name=name).append(inertial)
    return root


def export_xml(
    to: str, props, *, name: str, document: bool = False, diagonal: bool = False, comment: str | None = None
) -> str:
    """The XML text for format ``to`` (``urdf``, ``mjcf`` or ``sdf``) of ``props`` (a
    :class:`~rbi.core.mass.MassProperties` in SI units): the inertial element, or a minimal
    document holding it; ``comment`` goes first as an XML comment. Control
    characters in ``name`` and ``comment`` are written as visible escapes (XML 1.0 cannot hold
    them, and the text may be printed on a terminal)."""
    element = inertial_element(to, props, diagonal)
    if document:
        element = _document(to, visible(name), element)
    text = element_text(element)
    if comment:
        text = f"{xml_comment(visible(comment))}\n{text}"
    return text + "\n"
