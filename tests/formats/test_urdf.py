"""The URDF reader (rbi.formats.urdf): its groups taken from a plain text (plain_text) and
from the parsed element tree (read_urdf) give the same audit, number for number; a model's
columns audit as its links do; a refusal is worded for the first thing wrong in the file, in
the words urdfdom's readers know (the messages of rbi's reader of one element at a time)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rbi.errors import InputError
from rbi.formats import robot_xml
from rbi.formats.robot_files import read_robot
from rbi.formats.urdf import attach_elements, plain_text, read_urdf
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


def read_urdf_text(path: str, data: bytes):
    """The model read from the plain text of ``data`` (:func:`plain_text`); None when the text
    is not plain or the file is refused."""
    document = robot_xml.decoded(path, data)
    plain = plain_text(document)
    try:
        return None if plain is None else read_urdf(document, None, True, plain)
    except InputError:
        return None


def _careful(path: str, data: bytes):
    """The model read from the element tree, its links made (so the audit reads them, not the
    columns)."""
    model = read_urdf(robot_xml.read_xml(path, data), None, True)
    assert model.links
    return model


def _written(tmp_path, text: str) -> tuple[str, bytes]:
    """``text`` written as robot.urdf in ``tmp_path``: its path and its bytes."""
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    return str(path), path.read_bytes()


def _read_alike(tmp_path, text: str):
    """``text`` written as a URDF and read from its plain text, which must read it and audit it
    as the element tree's reading does: (path, bytes, the model read from the text)."""
    path, data = _written(tmp_path, text)
    bulk = read_urdf_text(path, data)
    assert bulk is not None
    assert _as_json(bulk) == _as_json(_careful(path, data))
    return path, data, bulk


JOINT_COLUMNS = ("joint_rows", "joint_names", "joint_kinds", "axes", "anchors", "efforts", "references")
"""The model's joints, as its columns hold them."""


def _as_json(model) -> str:
    def plain(value):
        if isinstance(value, np.ndarray):
            return value.tolist()
        return float(value)

    report = audit_model(model)
    return json.dumps(
        [report.as_dict(), [getattr(model.columns, key) for key in JOINT_COLUMNS]], default=plain
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
        _swap('ixx="0.101"', 'ixx="1e300"'),  # read, and checked alone: 9 such entries could overflow
    ],
)
def test_the_plain_text_reads_as_the_element_tree_reads(tmp_path, text):
    path, data, bulk = _read_alike(tmp_path, text)
    attach_elements(bulk)  # what --fix edits: the tree's elements
    elements = robot_xml.read_xml(path, data).root.all("link")
    for mine, theirs in zip(bulk.links, elements, strict=True):
        assert (mine.element.start, mine.element.end) == (theirs.start, theirs.end)
        if theirs.child("inertial") is not None:
            assert mine.inertial.element.start == theirs.child("inertial").start


REFUSALS_AND_ODDITIES = [
    (
        _swap('<link name="l2">', "<link>"),
        "link[2] (line 6): name: missing; every link needs a name (urdfdom and pybullet refuse it)",
    ),
    (
        _swap('<link name="l2">', '<link name="l1">'),
        "link[2] (l1): duplicate link name 'l1' (also link[1] (l1)); every link needs its own name",
    ),
    (_swap('<mass value="3"/>', ""), "link[2] (l2): inertial/mass: missing"),
    (
        _swap('<mass value="3"/>', '<mass value="nan"/>'),
        "link[2] (l2): inertial/mass: value: must be a finite number (got 'nan')",
    ),
    (
        _swap('<mass value="3"/>', '<mass value="1_0"/>'),
        "link[2] (l2): inertial/mass: value: must be a finite number (got '1_0')",
    ),
    (
        _swap('<mass value="3"/>', '<mass value="3 4"/>'),
        "link[2] (l2): inertial/mass: value: expected 1 number(s), got 2 ('3 4')",
    ),
    (
        _swap('<mass value="3"/>', '<mass value="1e-310"/>'),
        "link[2] (l2): inertial/mass: value: 1e-310 is subnormal (smaller than 2.23e-308, the smallest double with all its digits): the moments computed from it would lose their digits or vanish",
    ),
    (
        _swap('<mass value="3"/>', '<mass value="1e999"/>'),
        "link[2] (l2): inertial/mass: value: must be a finite number (got '1e999', too large)",
    ),
    (
        _swap('rpy="0.1 0.0 0"', 'rpy="0.1 1e10 0"'),
        "link[0] (l0): inertial rpy: pitch = 1e+10 rad is not an angle a double can hold to a microradian: give it within one turn (between -3.14159 and 3.14159)",
    ),
    (
        _swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2 -0.1 0.05"/>'),
        "link[0] (l0): collision[0]/geometry/box: size: must be zero or greater than 0 (got -0.1)",
    ),
    (
        _swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2 0.1"/>'),
        "link[0] (l0): collision[0]/geometry/box: size: expected 3 number(s), got 2 ('0.2 0.1')",
    ),
    (_swap('<box size="0.2 0.1 0.05"/>', '<box size="0.2&#9;0.1 0.05"/>'), None),
    (
        _swap('<box size="0.2 0.1 0.05"/>', '<mesh filename="missing.stl"/>'),
        "link[0] (l0): collision[0]/geometry/mesh: missing.stl: no such file",
    ),
    (
        _swap('<geometry><box size="0.2 0.1 0.05"/></geometry>', "<geometry/>"),
        "link[0] (l0): collision[0]/geometry: missing (give a box, cylinder, sphere, capsule or mesh)",
    ),
    (
        _swap('type="continuous"', 'type="hinge"'),
        "joint[0] (j1): type: 'hinge' is not a URDF joint type (revolute, continuous, prismatic, fixed, floating, planar)",
    ),
    (
        _swap('<parent link="l0"/><child link="l2"/>', '<parent link="l9"/><child link="l1"/>'),
        "joint[1] (j2): child: link 'l1' is already the child of link 'l0': two joints close a loop, and a URDF's links form a tree (model a closed chain in SDF or MJCF)",
    ),
    (
        _swap('<parent link="l0"/><child link="l2"/>', '<parent link="lx"/><child link="l2"/>'),
        "joint[1] (j2): parent: no link named 'lx'",
    ),
    (
        _swap('<parent link="l0"/><child link="l2"/>', '<child link="l2"/>'),
        "joint[1] (j2): needs <parent link=…/> and <child link=…/>",
    ),
    (
        _swap('name="j3"', 'name="j2"'),
        "link[3] (l3): duplicate joint name 'j2' (also a joint of link[2] (l2)); every joint needs its own name (urdfdom refuses the file)",
    ),
    (
        _swap('<axis xyz="1 1 0"/>', '<axis xyz="0 0 0"/>'),
        "joint[0] (j1): axis: xyz: must not be the zero vector",
    ),
    (
        _swap('<robot name="r">', '<!DOCTYPE robot [<!ENTITY e "1">]><robot name="r">'),
        "refused: the file declares XML entities or external references; rbi does not expand them",
    ),
    (_swap('<link name="l2">', "<link name='l2'>"), None),
    (_swap('<link name="l2">', '<link name="l2"><inertial/>'), "link[2] (l2): inertial/mass: missing"),
    (
        _swap('<link name="l2">', '<link name="l2"><collision/>'),
        "link[2] (l2): collision[0]/geometry: missing (give a box, cylinder, sphere, capsule or mesh)",
    ),
    (_swap('<link name="l2">', '<link name="l2">text'), None),
    (_swap('<link name="l2">', '<link name="l2&amp;">'), "joint[1] (j2): child: no link named 'l2'"),
    (_swap('<link name="l2">', '<link name="l2&#10;">'), "joint[1] (j2): child: no link named 'l2'"),
    (_swap('<link name="l2">', '<link name="l2\n">'), "joint[1] (j2): child: no link named 'l2'"),
    (_swap('<link name="l2">', '<link name="l\t2">'), "joint[1] (j2): child: no link named 'l2'"),
    (_swap('<link name="l2">', '<?pi x?><link name="l2">'), None),
    (_swap('<link name="l2">', '<link name="l2" note="a>b">'), None),
    (_swap('<link name="l2">', '<link name="l2"><![CDATA[x]]>'), None),
    (
        _swap('<link name="l2">', '<link name="l2"><a'),
        "not well-formed XML (line 6, column 18): not well-formed (invalid token)",
    ),
    (
        _urdf(joint={5: ""}),
        "2 root links ('l0', 'l5'): no joint joins them; a URDF has one root link that every other hangs from (urdfdom and pybullet refuse it)",
    ),
    (
        _urdf(link={i: "" for i in range(12)}, joint={i: "" for i in range(12)}),
        "no <link>: a URDF needs at least one (urdfdom and pybullet refuse it)",
    ),
]
"""A file the plain text's reading leaves to the element tree, and what reading it gives: the
message after the file's path, or None where it reads as it would written plainly."""


@pytest.mark.parametrize("text, message", REFUSALS_AND_ODDITIES)
def test_a_refusal_names_the_first_thing_wrong(tmp_path, text, message):
    """Each message as urdfdom's users have read it from rbi (the reader of one element at a
    time, whose words these are); where nothing is wrong, the model of the plain text."""
    path, data = _written(tmp_path, text)
    assert read_urdf_text(path, data) is None
    found = _outcome(lambda: read_robot(path))
    if message is None:
        assert found == _outcome(lambda: read_robot(_written(tmp_path, _urdf())[0]))
    else:
        assert found == f"error: {path}: {message}"


def test_a_refusal_in_a_generated_file_names_its_first_wrong_link(tmp_path):
    """Links alike are read as one group, a field at a time (the masses before the shapes), yet
    the message is for the first link that is wrong: link 10's shape, not link 40's mass."""
    from rbi.bench.robotaudit import urdf_text

    text = urdf_text(64)
    at, later = text.index('<link name="l10">'), text.index('<link name="l40">')
    text = (
        text[:at]
        + text[at:later].replace('size="0.2 0.1 0.05"', 'size="-1 0.1 0.05"', 1)
        + text[later:].replace('<mass value="1"/>', '<mass value="nan"/>', 1)
    )
    path, data = _written(tmp_path, text)
    assert read_urdf_text(path, data) is None
    assert _outcome(lambda: read_robot(path)) == (
        f"error: {path}: link[10] (l10): collision[0]/geometry/box: size: must be zero or greater than 0 "
        "(got -1.0)"
    )


def _outcome(read) -> str:
    """The audit's JSON of the model ``read`` gives, or the error it (or the audit) raises."""
    try:
        return _as_json(read())
    except InputError as exc:
        return f"error: {exc}"


@pytest.mark.parametrize("odd", [None, 'xyz="0.1 0 0" rpy="0 0 0.5"', 'xyz="0.1 0 0"  '])
def test_a_generated_file_of_alike_links_reads_as_the_element_tree_reads(tmp_path, odd):
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
def test_the_audit_of_a_model_in_columns_is_the_audit_of_its_links(tmp_path, options):
    """A model read in bulk is audited on its columns, its links made only when the report's
    rows are asked for: the exit code (asked first, before any row is made), the JSON and the
    joints are those of its links, for links without an inertial (moved and fixed), of mass
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
    bulk, careful = read_urdf_text(path, data), _careful(path, data)
    assert bulk is not None
    mine, theirs = audit_model(bulk, **options), audit_model(careful, **options)
    assert mine._links is None  # no row made yet: the exit code comes from the columns' audit
    assert mine.exit_code == theirs.exit_code == (0 if options.get("geometry") == "none" else 1)
    assert json.dumps(mine.as_dict(), default=np.ndarray.tolist) == json.dumps(
        theirs.as_dict(), default=np.ndarray.tolist
    )
    flagged = {link["name"]: [f["code"] for f in link["flags"]] for link in mine.as_dict()["links"]}
    assert flagged["l3"] == [] and flagged["l7"] == ["massless"] and "placeholder" in flagged["l9"]


@pytest.mark.parametrize(
    "swaps, message",
    [
        (
            [
                ('<link name="l2500">', '<mass value="1"/>', '<mass value="nan"/>'),
                ('<link name="l1500">', 'size="0.2 0.1 0.05"', 'size="0.2 -1 0.05"'),
            ],
            "link[1500] (l1500): collision[0]/geometry/box: size: must be zero or greater than 0 (got -1.0)",
        ),
        (
            [('<joint name="j2000"', 'child link="l2000"', 'child link="l5"')],
            "joint[1999] (j2000): child: link 'l5' is already the child of link 'l2': two joints close a "
            "loop, and a URDF's links form a tree (model a closed chain in SDF or MJCF)",
        ),
    ],
)
def test_a_refusal_in_a_large_element_tree_names_its_first_wrong_element(tmp_path, swaps, message):
    """A file that is not plain (one value in single quotes) is read from its element tree, its
    elements in chunks of groups: the message is for the first wrong element of the file, and a
    joint's link already taken is named with the parent an earlier chunk gave it."""
    from rbi.bench.robotaudit import urdf_text

    text = urdf_text(3000).replace('<robot name="large">', "<robot name='large'>")
    for start, old, new in swaps:
        at = text.index(start)
        text = text[:at] + text[at:].replace(old, new, 1)
    path, data = _written(tmp_path, text)
    assert read_urdf_text(path, data) is None
    assert _outcome(lambda: read_robot(path)) == f"error: {path}: {message}"
