"""XML documents for ``rbi export``: the ``<inertial>`` element of URDF, MJCF and SDF (written by
:mod:`rbi.formats.inertial_xml`, the one writer ``rbi audit --fix`` uses too), alone or in a
minimal document, with a comment first.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable

from rbi.formats.inertial_xml import (  # noqa: F401 - the writers, named here for export's callers
    FORMATS,
    inertial_element,
    mjcf_inertial,
    sdf_inertial,
    urdf_inertial,
    xml_comment,
    xml_number,
)


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
    element = inertial_element(to, mass, com, inertia, diagonal=diagonal)
    if document:
        element = DOCUMENTS[to](xml_safe(name), element)
    ET.indent(element, space="  ")
    text = ET.tostring(element, encoding="unicode")
    if comment:
        text = f"{xml_comment(xml_safe(comment))}\n{text}"
    return text + "\n"


def xml_safe(text: str) -> str:
    """``text`` with control characters written as visible escapes: XML 1.0 cannot hold them,
    and a name from a spec must not reach the terminal raw when the XML is printed."""
    from rbi.cli.terminal import terminal_safe

    return terminal_safe(text)
