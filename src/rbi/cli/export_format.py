"""XML writers for ``rbi export``: the ``<inertial>`` element of URDF, MJCF and SDF.

Every writer takes SI numbers (kg, m, kg·m²): the mass, the centre of mass in the body (link)
frame and the inertia matrix about the centre of mass in body axes, whose off-diagonal entries
are the matrix entries (``ixy = I[0][1] = −∫xy dm``), the convention of all three formats.
Numbers are written with the shortest repr that round-trips, so nothing is lost.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable

import numpy as np

from rbi.cli.render import plain

FORMATS = ("urdf", "mjcf", "sdf")


def xml_number(value: float) -> str:
    """Shortest round-tripping text of a float (``-0.0`` written as ``0.0``)."""
    return repr(plain(float(value)))


def _numbers(values) -> str:
    return " ".join(xml_number(v) for v in values)


def urdf_inertial(mass: float, com: np.ndarray, inertia: np.ndarray) -> ET.Element:
    """URDF: ``<origin xyz rpy>`` places the inertial frame at the centre of mass, axes
    parallel to the link's; ``<inertia ixx ixy ixz iyy iyz izz>`` about it."""
    I = np.asarray(inertia, dtype=float)
    inertial = ET.Element("inertial")
    ET.SubElement(inertial, "origin", xyz=_numbers(com), rpy="0 0 0")
    ET.SubElement(inertial, "mass", value=xml_number(mass))
    ET.SubElement(
        inertial,
        "inertia",
        {
            "ixx": xml_number(I[0, 0]),
            "ixy": xml_number(I[0, 1]),
            "ixz": xml_number(I[0, 2]),
            "iyy": xml_number(I[1, 1]),
            "iyz": xml_number(I[1, 2]),
            "izz": xml_number(I[2, 2]),
        },
    )
    return inertial


def sdf_inertial(mass: float, com: np.ndarray, inertia: np.ndarray) -> ET.Element:
    """SDF: ``<pose>x y z roll pitch yaw</pose>`` (the centre of mass, axes parallel to the
    link's), ``<mass>``, and ``<inertia>`` with child elements ixx ixy ixz iyy iyz izz."""
    I = np.asarray(inertia, dtype=float)
    inertial = ET.Element("inertial")
    ET.SubElement(inertial, "pose").text = _numbers(list(com) + [0.0, 0.0, 0.0])
    ET.SubElement(inertial, "mass").text = xml_number(mass)
    block = ET.SubElement(inertial, "inertia")
    for name, (i, j) in (
        ("ixx", (0, 0)),
        ("ixy", (0, 1)),
        ("ixz", (0, 2)),
        ("iyy", (1, 1)),
        ("iyz", (1, 2)),
        ("izz", (2, 2)),
    ):
        ET.SubElement(block, name).text = xml_number(I[i, j])
    return inertial


def mjcf_inertial(mass: float, com: np.ndarray, inertia: np.ndarray, diagonal: bool = False) -> ET.Element:
    """MJCF: ``<inertial pos mass fullinertia>`` with fullinertia in MuJoCo's order
    Ixx Iyy Izz Ixy Ixz Iyz; or, with ``diagonal``, the principal moments as ``diaginertia``
    and ``quat`` (w x y z) turning the principal frame into the body frame."""
    I = np.asarray(inertia, dtype=float)
    attributes = {"pos": _numbers(com), "mass": xml_number(mass)}
    if diagonal:
        from rbi.core.inertia import principal_axes
        from rbi.core.rotation import matrix_to_quaternion

        moments, axes = principal_axes(I)
        attributes["quat"] = _numbers(matrix_to_quaternion(axes.T))  # columns: principal axes in body axes
        attributes["diaginertia"] = _numbers(moments)
    else:
        attributes["fullinertia"] = _numbers([I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]])
    return ET.Element("inertial", attributes)


def urdf_document(name: str, inertial: ET.Element) -> ET.Element:
    robot = ET.Element("robot", name=name)
    ET.SubElement(robot, "link", name=name).append(inertial)
    return robot


def sdf_document(name: str, inertial: ET.Element) -> ET.Element:
    sdf = ET.Element("sdf", version="1.7")
    model = ET.SubElement(sdf, "model", name=name)
    ET.SubElement(model, "link", name=name).append(inertial)
    return sdf


def mjcf_document(name: str, inertial: ET.Element) -> ET.Element:
    mujoco = ET.Element("mujoco", model=name)
    body = ET.SubElement(ET.SubElement(mujoco, "worldbody"), "body", name=name)
    ET.SubElement(body, "freejoint")
    body.append(inertial)
    return mujoco


DOCUMENTS: dict[str, Callable[[str, ET.Element], ET.Element]] = {
    "urdf": urdf_document,
    "mjcf": mjcf_document,
    "sdf": sdf_document,
}


def export_xml(
    to: str,
    mass: float,
    com,
    inertia,
    *,
    name: str,
    document: bool = False,
    diagonal: bool = False,
    comment: str | None = None,
) -> str:
    """The XML text for format ``to`` (``urdf``, ``mjcf`` or ``sdf``): the inertial element,
    or a minimal document holding it; ``comment`` goes first as an XML comment."""
    if to == "urdf":
        element = urdf_inertial(mass, com, inertia)
    elif to == "sdf":
        element = sdf_inertial(mass, com, inertia)
    else:
        element = mjcf_inertial(mass, com, inertia, diagonal=diagonal)
    if document:
        element = DOCUMENTS[to](xml_safe(name), element)
    ET.indent(element, space="  ")
    text = ET.tostring(element, encoding="unicode")
    if comment:
        comment = xml_safe(comment)
        while "--" in comment:  # a comment may not hold "--"
            comment = comment.replace("--", "-")
        text = f"<!-- {comment} -->\n{text}"
    return text + "\n"


def xml_safe(text: str) -> str:
    """``text`` with control characters written as visible escapes: XML 1.0 cannot hold them,
    and a name from a spec must not reach the terminal raw when the XML is printed."""
    from rbi.cli.terminal import terminal_safe

    return terminal_safe(text)
