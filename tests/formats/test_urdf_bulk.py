"""The URDF reader in bulk (issue 25) against the careful one (rbi.formats.urdf over
rbi.formats.robot_xml's tree): the same audit, number for number, where it reads a file, and
no reading at all (None: the careful reader words the refusal) where that reader refuses one."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.robot_files import read_robot
from rbi.formats.urdf import read_urdf
from rbi.formats.urdf_bulk import attach_elements, read_urdf_bulk
from rbi.robot.audit import audit_model

LINK = (
    '<link name="{name}"><inertial><origin xyz="{com}" rpy="{rpy}"/><mass value="{mass}"/>'
    '<inertia ixx="{ixx}" ixy="{ixy}" ixz="0" iyy="0.2" iyz="-0.0" izz="0.3"/></inertial>'
    '<collision><origin xyz="0.1 0 0" rpy="{grpy}"/><geometry>{shape}</geometry></collision>'
    '<visual><geometry><sphere radius="0.05"/></geometry></visual></link>\n'
)
JOINT = (
    '<joint name="j{i}" type="{kind}"><parent link="l{parent}"/><child link="l{i}"/>'
    '<origin xyz="0 0 0.3" rpy="{rpy}"/>{axis}<limit effort="{effort}"/></joint>\n'
)
SHAPES = (
    '<box size="0.2 0.1 0.05"/>',
    '<cylinder radius="0.03" length="0.4"/>',
    '<capsule radius="0.02" length="0.1"/>',
    '<sphere radius="1e-2"/>',
    "<plane/>",
)
KINDS = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")


def _urdf(n: int = 12, link=None, joint=None, head: str = '<?xml version="1.0"?>\n') -> str:
    """A tree of ``n`` links with every shape, joint type and rotated frame; ``link`` and
    ``joint`` (index → text) replace one element's text."""
    parts = [head, '<robot name="r">\n<!-- a comment -->\n']
    for i in range(n):
        text = LINK.format(
            name=f"l{i}",
            com=f"{i * 0.01} -0.0 0.02",
            rpy="0 0 0" if i % 3 else f"0.1 {i * 0.1} 0",
            mass=1 + i,
            ixx=0.1 + i * 1e-3,
            ixy=f"{i * 1e-4}",
            grpy="0 0 0" if i % 2 else "0 0.5 0",
            shape=SHAPES[i % len(SHAPES)],
        )
        parts.append((link or {}).get(i, text))
    for i in range(1, n):
        axis = "" if i % 4 == 0 else f'<axis xyz="{i} 1 0"/>'
        text = JOINT.format(
            i=i, parent=(i - 1) // 2, kind=KINDS[i % len(KINDS)], rpy=f"0 0 {i * 0.2}", axis=axis, effort=-i
        )
        parts.append((joint or {}).get(i, text))
    parts.append("</robot>\n")
    return "".join(parts)


def _swap(old: str, new: str) -> str:
    text = _urdf()
    assert old in text
    return text.replace(old, new, 1)


def _careful(path: str, data: bytes):
    return read_urdf(robot_xml.read_xml(path, data), None, True)


def _written(tmp_path, text: str) -> tuple[str, bytes]:
    """``text`` written as robot.urdf in ``tmp_path``: its path and its bytes."""
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    return str(path), path.read_bytes()


def _read_alike(tmp_path, text: str):
    """``text`` written as a URDF and read in bulk, which must read it and audit it as the
    careful reader does: (path, bytes, the bulk reader's model)."""
    path, data = _written(tmp_path, text)
    bulk = read_urdf_bulk(path, data)
    assert bulk is not None
    assert _as_json(bulk) == _as_json(_careful(path, data))
    return path, data, bulk


def _as_json(model) -> str:
    def plain(value):
        if isinstance(value, np.ndarray):
            return value.tolist()
        return float(value)

    report = audit_model(model)
    return json.dumps(
        [report.as_dict(), [vars(m) for link in model.links for m in link.motions]], default=plain
    )


@pytest.mark.parametrize(
    "text",
    [
        _urdf(),
        _urdf(1),
        _urdf(head=""),
        _urdf(
            link={
                3: '<link name="l3"/>\n',
                4: '<link name="l4"><!-- x --><inertial><mass value="2"/>'
                '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>\n',
            }
        ),
        _urdf(
            joint={
                2: '<joint name="j2" type="revolute"><parent link="l0"/><child link="l2"/>'
                '<axis xyz="0 -0.0 2"/></joint>\n'
            }
        ),
        _swap('<robot name="r">', '<robot name="r" xmlns="http://example.com/urdf" xmlns:x="u">'),
        _swap('<robot name="r">', "<robot>"),
        _urdf().replace("\n", "\r\n"),
        _swap('<robot name="r">', '<robot version = "1" name =\n "r2">'),
        _swap('<link name="l2">', '<!-- <link name="l2"/> --><link name="l2"><!-- inside -->'),
        _swap('<link name="l2">', '<gazebo reference="l2"><link name="x"/></gazebo><link  name = "l2" >'),
        _swap('<link name="l2">', '<transmission name="t"><joint name="j1"/></transmission><link name="l2">'),
        _swap('<link name="l2">', '<link\n    name="l2"\n  >\n  '),
        _swap('<link name="l2">', '<link name="l2" x:y="z">'),
        _swap('<link name="l2">', '<x:link name="q"/><link name="l2">'),
        _swap(
            '<link name="l2">', '<link name="l2"><collision><geometry><plane a="b"/></geometry></collision>'
        ),
        _swap('"l1"', '"\u00e9l\u00e8ve"').replace('link="l1"', 'link="\u00e9l\u00e8ve"'),
    ],
)
def test_the_bulk_reader_reads_what_the_careful_one_reads(tmp_path, text):
    path, data, bulk = _read_alike(tmp_path, text)
    attach_elements(bulk)  # what --fix edits: the careful tree's elements
    careful = _careful(path, data)
    for mine, theirs in zip(bulk.links, careful.links):
        assert (mine.element.start, mine.element.end) == (theirs.element.start, theirs.element.end)
        if theirs.inertial is not None:
            assert mine.inertial.element.start == theirs.inertial.element.start


@pytest.mark.parametrize(
    "text",
    [
        _swap('<link name="l2">', "<link>"),
        _swap('<link name="l2">', '<link name="l1">'),
        _swap('<mass value="3"/>', ""),
        _swap('<mass value="3"/>', '<mass value="nan"/>'),
        _swap('<mass value="3"/>', '<mass value="1_0"/>'),
        _swap('<mass value="3"/>', '<mass value="3 4"/>'),
        _swap('<mass value="3"/>', '<mass value="1e-310"/>'),
        _swap('<mass value="3"/>', '<mass value="1e999"/>'),
        _swap('ixx="0.101"', 'ixx="1e308"'),
        _swap('rpy="0.1 0.0 0"', 'rpy="0.1 1e10 0"'),
        _swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2 -0.1 0.05"/>'),
        _swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2 0.1"/>'),
        _swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2&#9;0.1 0.05"/>'),
        _swap('<box size="0.2 0.1 0.05"/>', '<mesh filename="missing.stl"/>'),
        _swap('<geometry><box size="0.2 0.1 0.05"/></geometry>', "<geometry/>"),
        _swap('type="continuous"', 'type="hinge"'),
        _swap('<parent link="l0"/><child link="l2"/>', '<parent link="l9"/><child link="l1"/>'),
        _swap('<parent link="l0"/><child link="l2"/>', '<parent link="lx"/><child link="l2"/>'),
        _swap('<parent link="l0"/><child link="l2"/>', '<child link="l2"/>'),
        _swap('name="j3"', 'name="j2"'),
        _swap('<axis xyz="1 1 0"/>', '<axis xyz="0 0 0"/>'),
        _swap('<robot name="r">', '<!DOCTYPE robot [<!ENTITY e "1">]><robot name="r">'),
        _swap('<link name="l2">', "<link name='l2'>"),
        _swap('<link name="l2">', '<link name="l2"><inertial/>'),
        _swap('<link name="l2">', '<link name="l2"><collision/>'),
        _swap('<link name="l2">', '<link name="l2">text'),
        _swap('<link name="l2">', '<link name="l2&amp;">'),
        _swap('<link name="l2">', '<link name="l2&#10;">'),
        _swap('<link name="l2">', '<link name="l2\n">'),
        _swap('<link name="l2">', '<link name="l\t2">'),
        _swap('<link name="l2">', '<?pi x?><link name="l2">'),
        _swap('<link name="l2">', '<link name="l2" note="a>b">'),
        _swap('<link name="l2">', '<link name="l2"><![CDATA[x]]>'),
        _swap('<link name="l2">', '<link name="l2"><a'),
        _urdf(joint={5: ""}),
        _urdf(link={i: "" for i in range(12)}, joint={i: "" for i in range(12)}),
    ],
)
def test_the_careful_reader_words_every_refusal(tmp_path, text):
    """The bulk reader reads none of these (a refused file, or one it leaves to the careful
    reader), so what the user sees is the careful reader's: its model or its one-line error."""
    path, data = _written(tmp_path, text)
    assert read_urdf_bulk(path, data) is None
    assert _outcome(lambda: read_robot(path)) == _outcome(lambda: _careful(path, data))


def _outcome(read) -> str:
    """The audit's JSON of the model ``read`` gives, or the error it (or the audit) raises."""
    try:
        return _as_json(read())
    except InputError as exc:
        return f"error: {exc}"


@pytest.mark.parametrize("odd", [None, 'xyz="0.1 0 0" rpy="0 0 0.5"', 'xyz="0.1 0 0"  '])
def test_a_generated_file_of_alike_links_reads_as_the_careful_reader_reads_it(tmp_path, odd):
    """The bench's URDF (every link's text alike once its values are emptied, read as one
    group) and the same with one link's origin written otherwise (read link by link)."""
    from rbi.bench.robotaudit import urdf_text

    text = urdf_text(64)
    if odd is not None:
        at = text.index('<link name="l40">')
        text = text[:at] + text[at:].replace('xyz="0.1 0 0"', odd, 1)
    _read_alike(tmp_path, text)


@pytest.mark.parametrize(
    "options",
    [
        {},
        {"geometry": "visual"},
        {"geometry": "none"},
        {"density": 500.0},
        {"joints": {"j1": 0.3, "j2": -0.2}},
    ],
)
def test_the_audit_of_a_model_in_columns_is_the_audit_of_the_careful_readers_links(tmp_path, options):
    """A model read in bulk is audited on its columns, its links made only when the report's
    rows are asked for: the exit code (asked first, before any row is made), the JSON and the
    joints are the careful reader's, for links without an inertial (moved and fixed), of mass
    0, with a placeholder inertia and each option."""
    text = _urdf(
        20,
        link={
            3: '<link name="l3"/>\n',
            7: '<link name="l7"><collision><geometry><box size="1 1 1"/></geometry></collision></link>\n',
            8: '<link name="l8"><inertial><mass value="0"/>'
            '<inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>\n',
            9: '<link name="l9"><inertial><mass value="5"/>'
            '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
            '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>\n',
        },
    )
    path, data = _written(tmp_path, text)
    bulk, careful = read_urdf_bulk(path, data), _careful(path, data)
    assert bulk is not None and bulk.in_columns is not None
    mine, theirs = audit_model(bulk, **options), audit_model(careful, **options)
    assert mine._links is None  # no row made yet: the exit code comes from the columns' audit
    assert mine.exit_code == theirs.exit_code == (0 if options.get("geometry") == "none" else 1)
    assert json.dumps(mine.as_dict(), default=np.ndarray.tolist) == json.dumps(
        theirs.as_dict(), default=np.ndarray.tolist
    )
    flagged = {link["name"]: [f["code"] for f in link["flags"]] for link in mine.as_dict()["links"]}
    assert flagged["l3"] == [] and flagged["l7"] == ["massless"] and "placeholder" in flagged["l9"]
