"""Issue 18, principle 4, the writing side of `rbi import`: text from a robot file is data,
never structure.

A link name (or the robot file's own name) reaches the YAML specs import writes, the comment
header above each, the file names under ``--out DIR/``, the listing (table, JSON, CSV) and
the terminal. Whatever the name holds (newlines, YAML syntax, C0/C1 controls, bidirectional
overrides, Unicode line separators, 100k characters), the spec written must hold exactly the
keys import writes, with the name as a value equal to the name read from the file, be readable
by rbi, and nothing unescaped may reach the terminal.
"""

from __future__ import annotations

import json
import re
from xml.sax.saxutils import quoteattr

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import run_rbi_inprocess

SPEC_KEYS = {"name", "units", "parts"}
PART_KEYS = {"name", "shape", "mass", "center_of_mass", "inertia", "rotation"}

UNSAFE_ON_A_TERMINAL = re.compile(
    "[\x00-\x09\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029]"
)
"""Characters that must never reach stdout raw: C0 controls but the newline, DEL, C1 controls
(CSI, NEL), bidirectional overrides and isolates, and Unicode's line and paragraph separators
(line breaks to YAML)."""


def xml_attribute(text: str) -> str:
    """``text`` as an XML attribute that a parser gives back exactly (newlines, tabs and CRs as
    character references, which XML does not normalise away)."""
    return quoteattr(text, {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"})


def urdf(names: list[str], robot: str = "r") -> str:
    links = "".join(
        f'<link name={xml_attribute(name)}><inertial><origin xyz="0 0 0" rpy="0 0 0.5"/><mass value="2"/>'
        f'<inertia ixx="1" iyy="2" izz="2.5" ixy="0" ixz="0" iyz="0"/></inertial></link>'
        for name in names
    )
    joints = "".join(  # one root link: the others fixed to the first
        f'<joint name="j{i}" type="fixed"><parent link={xml_attribute(names[0])}/><child link={xml_attribute(name)}/></joint>'
        for i, name in enumerate(names[1:])
    )
    return f"<robot name={xml_attribute(robot)}>{links}{joints}</robot>\n"


def read_names(path) -> list[str]:
    """The link names as the reader gives them (the reading side is not under test here)."""
    from rbi.formats.robot_files import read_robot

    return [link.name for link in read_robot(str(path)).inertial_links]


def check_specs(text: str, names: list[str]) -> list[dict]:
    """``text`` (what import printed or wrote) holds one spec per name, with exactly the keys
    import writes and the name as data; returns the specs."""
    specs = [doc for doc in yaml.safe_load_all(text) if doc is not None]
    assert len(specs) == len(names), text[:2000]
    for spec, name in zip(specs, names):
        assert set(spec) == SPEC_KEYS, (name, spec.keys())
        (part,) = spec["parts"]
        assert set(part) <= PART_KEYS, (name, part.keys())
        assert spec["name"] == name and part["name"] == name
        assert part["mass"] == 2.0
    return specs


def check_robot_spec(text: str, names: list[str]) -> dict:
    """``text`` (what import printed without --out) is one spec, the whole robot, with one
    custom part per link named as the link, the names as data."""
    (spec,) = [doc for doc in yaml.safe_load_all(text) if doc is not None]
    assert set(spec) == SPEC_KEYS, spec.keys()
    assert [part["name"] for part in spec["parts"]] == names
    for part in spec["parts"]:
        assert set(part) <= PART_KEYS and part["mass"] == 2.0
    return spec


def assert_terminal_safe(text: str) -> None:
    found = UNSAFE_ON_A_TERMINAL.search(text)
    assert found is None, (
        f"raw {found.group()!r} in output: {text[max(found.start() - 40, 0) : found.end() + 40]!r}"
    )


HOSTILE_NAMES = [
    "arm\npivot: [0, 0, 9]\nexpect:\n  mass: 5",  # the reported injection: live keys after a newline
    "arm\r\nparts: []",  # CR LF
    "arm\u2028pivot: [0, 0, 9]",  # YAML line separator, not a newline to Python's eye
    "arm\u2029units: {length: mm}",
    "arm\x85name: other",  # NEL: a line break in YAML 1.1
    "\u202eevil\u202c",  # right-to-left override
    "\x9d0;pwned\x9c\x9b2J",  # C1 OSC (set the title), CSI clear screen
    "\x9b31mred\x9b0m",  # C1 CSI
    "--- !!python/object:os.system",  # document separator and a tag
    "# not a comment",
    "&anchor *alias",
    "'quoted' \"double\" \\ back",
    "key: value",
    "tab\there",
    "\ufeffbom",
    "名前 ünïcödé 🚀",
    "yes",
    "null",
    "~",
    "1e3",
    "0x10",
    ".inf",
    "2024-01-01",
    "12:30:00",  # scalars YAML would read as non-strings
]


@pytest.mark.parametrize("name", HOSTILE_NAMES, ids=[repr(n)[:30] for n in HOSTILE_NAMES])
def test_a_hostile_link_name_is_data_in_the_printed_spec(tmp_path, name):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf([name, "plain"]))
    names = read_names(path)
    proc = run_rbi_inprocess("import", path)
    assert proc.returncode == 0, proc.stderr
    check_robot_spec(proc.stdout, names)
    assert_terminal_safe(proc.stdout)
    assert_terminal_safe(proc.stderr)


@pytest.mark.parametrize(
    "name",
    HOSTILE_NAMES[:8] + HOSTILE_NAMES[-8:],
    ids=[repr(n)[:30] for n in HOSTILE_NAMES[:8] + HOSTILE_NAMES[-8:]],
)
def test_a_hostile_link_name_is_data_in_the_written_spec_and_rbi_reads_it_back(tmp_path, name):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf([name]))
    (expected,) = read_names(path)
    out = tmp_path / "link.yaml"
    proc = run_rbi_inprocess("import", path, "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert_terminal_safe(proc.stdout)
    check_specs(out.read_text(encoding="utf-8"), [expected])
    back = run_rbi_inprocess("inertia", out, "--format", "json")
    assert back.returncode == 0, back.stderr
    assert json.loads(back.stdout)["mass"] == 2.0 and json.loads(back.stdout)["name"] == expected


def test_hostile_names_in_a_folder_of_specs(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf(HOSTILE_NAMES))
    names = read_names(path)
    folder = tmp_path / "specs"
    folder.mkdir()
    proc = run_rbi_inprocess("import", path, "--out", f"{folder}/")
    assert proc.returncode == 0, proc.stderr
    assert_terminal_safe(proc.stdout)
    written = sorted(folder.iterdir())
    assert len(written) == len(names)
    for file in written:
        assert re.fullmatch(r"[A-Za-z0-9._-]+\.yaml", file.name), file.name
    got = []
    for file in written:
        (spec,) = [doc for doc in yaml.safe_load_all(file.read_text(encoding="utf-8")) if doc is not None]
        check_specs(file.read_text(encoding="utf-8"), [spec["name"]])
        got.append(spec["name"])
    assert sorted(got) == sorted(names)


@pytest.mark.parametrize("robot_name", ["a\nb: c", "\x9b2J", "\u202erobot"])
def test_the_robot_and_file_names_in_the_header_are_escaped(tmp_path, robot_name):
    folder = tmp_path / "odd\u202edir"
    folder.mkdir()
    path = folder / "robo\x1bt\n.urdf"
    path.write_text(urdf(["link"], robot=robot_name))
    proc = run_rbi_inprocess("import", path)
    assert proc.returncode == 0, proc.stderr
    check_specs(proc.stdout, ["link"])
    assert_terminal_safe(proc.stdout)
    for line in proc.stdout.splitlines():
        assert line.startswith("#") or not line.startswith(" #"), line


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
def test_the_listing_escapes_names_for_the_terminal(tmp_path, fmt):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf(HOSTILE_NAMES))
    names = read_names(path)
    folder = tmp_path / "out"
    folder.mkdir()
    proc = run_rbi_inprocess("import", path, "--format", fmt, "--out", f"{folder}/")
    assert proc.returncode == 0, proc.stderr
    assert_terminal_safe(proc.stdout)
    if fmt == "json":
        assert [
            link["name"] for link in json.loads(proc.stdout)["links"]
        ] == names  # JSON keeps the data exact


def test_a_long_name_is_written_whole_and_quickly(tmp_path):
    name = "n" * 100_000 + "\nexpect: {mass: 1}"
    path = tmp_path / "robot.urdf"
    path.write_text(urdf([name]))
    proc = run_rbi_inprocess("import", path)
    assert proc.returncode == 0, proc.stderr
    check_specs(proc.stdout, read_names(path))


xml_text = (
    st.text(st.characters(blacklist_categories=("Cs",), blacklist_characters="\ufffe\uffff"), max_size=60)
    .map(lambda s: "".join(c for c in s if c in "\t\n\r" or ord(c) >= 0x20))
    .filter(lambda s: s.strip())
)


@given(st.lists(xml_text, min_size=1, max_size=3, unique=True), xml_text)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_any_names_give_specs_that_hold_them_as_data(tmp_path, names, robot):
    path = tmp_path / "robot.urdf"
    path.write_text(urdf(names, robot=robot), encoding="utf-8")
    expected = read_names(path)
    proc = run_rbi_inprocess("import", path)
    assert proc.returncode == 0, proc.stderr
    check_robot_spec(proc.stdout, expected)
    assert_terminal_safe(proc.stdout)
    assert_terminal_safe(proc.stderr)
