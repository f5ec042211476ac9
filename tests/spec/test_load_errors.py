"""Every kind of bad input: exit status 2, one line on stderr naming the file, the part (name
or index) and the field, nothing on stdout, never a traceback.

Most cases run the CLI's ``main`` in-process (fast); a handful go through a real subprocess
to prove the same holds for the installed program."""

from __future__ import annotations

import pytest

from tests.conftest import run_rbi, run_rbi_inprocess

TOP = """\
name: bolted-top
parts:
  - name: cone
    shape: cone
    mass: 0.4
    radius: 0.04
    apex: [0, 0, 0]
    base: [0, 0, 0.06]
  - name: stem
    shape: cylinder
    mass: 0.1
    radius: 0.008
    start: [0, 0, 0.06]
    end: [0, 0, 0.10]
  - shape: point
    mass: 0.02
    position: [0.04, 0, 0.06]
"""


def edit(old: str, new: str, text: str = TOP) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


CONE, STEM, BOLT = "parts[0] (cone)", "parts[1] (stem)", "parts[2]"

# (id, spec text, fragments the one-line message must contain besides the file name)
SPEC_CASES = [
    ("missing-field", edit("    radius: 0.04\n", ""), [CONE, "radius", "missing"]),
    ("misspelt-field", edit("radius: 0.04", "raduis: 0.04"), [CONE, "raduis", "radius"]),
    (
        "unknown-field",
        edit("    radius: 0.008\n", "    radius: 0.008\n    colour: red\n"),
        [STEM, "colour", "unknown"],
    ),
    ("unknown-top-level-field", "colour: red\n" + TOP, ["colour", "unknown"]),
    (
        "field-on-wrong-shape",
        edit("    mass: 0.02\n", "    mass: 0.02\n    radius: 0.01\n"),
        [BOLT, "radius"],
    ),
    ("text-for-number", edit("radius: 0.04", "radius: big"), [CONE, "radius", "number"]),
    ("quoted-number", edit("radius: 0.04", 'radius: "0.04"'), [CONE, "radius", "number"]),
    ("bool-for-number", edit("mass: 0.1", "mass: true"), [STEM, "mass", "number"]),
    ("list-for-number", edit("mass: 0.1", "mass: [0.1]"), [STEM, "mass"]),
    ("text-in-vector", edit("apex: [0, 0, 0]", "apex: [0, 0, zero]"), [CONE, "apex"]),
    ("short-vector", edit("base: [0, 0, 0.06]", "base: [0, 0.06]"), [CONE, "base", "3"]),
    ("long-vector", edit("end: [0, 0, 0.10]", "end: [0, 0, 0.10, 1]"), [STEM, "end", "3"]),
    ("scalar-for-vector", edit("position: [0.04, 0, 0.06]", "position: 0.04"), [BOLT, "position"]),
    ("nan", edit("radius: 0.04", "radius: .nan"), [CONE, "radius", "finite"]),
    ("inf", edit("mass: 0.1", "mass: .inf"), [STEM, "mass", "finite"]),
    ("minus-inf-in-vector", edit("start: [0, 0, 0.06]", "start: [0, 0, -.inf]"), [STEM, "start", "finite"]),
    ("zero-mass", edit("mass: 0.4", "mass: 0"), [CONE, "mass", "greater than 0"]),
    ("negative-mass", edit("mass: 0.1", "mass: -0.1"), [STEM, "mass", "greater than 0"]),
    ("zero-point-mass", edit("mass: 0.02", "mass: 0.0"), [BOLT, "mass", "greater than 0"]),
    ("zero-density", edit("mass: 0.1", "density: 0"), [STEM, "density", "greater than 0"]),
    ("negative-density", edit("mass: 0.4", "density: -7800"), [CONE, "density", "greater than 0"]),
    ("zero-radius", edit("radius: 0.008", "radius: 0"), [STEM, "radius", "greater than 0"]),
    ("negative-radius", edit("radius: 0.04", "radius: -0.04"), [CONE, "radius", "greater than 0"]),
    ("zero-height-cone", edit("base: [0, 0, 0.06]", "base: [0, 0, 0]"), [CONE, "apex", "base"]),
    ("zero-length-cylinder", edit("end: [0, 0, 0.10]", "end: [0, 0, 0.06]"), [STEM, "start", "end"]),
    ("mass-and-density", edit("mass: 0.1", "mass: 0.1\n    density: 7800"), [STEM, "mass", "density"]),
    ("neither-mass-nor-density", edit("    mass: 0.4\n", ""), [CONE, "mass", "density"]),
    ("density-on-point", edit("mass: 0.02", "density: 3.0"), [BOLT, "density"]),
    ("duplicate-part-names", edit("name: stem", "name: cone"), ["parts[1] (cone)", "name", "duplicate"]),
    ("empty-parts", "name: x\nparts: []\n", ["parts"]),
    ("null-parts", "name: x\nparts:\n", ["parts"]),
    ("missing-parts", "name: x\n", ["parts"]),
    ("parts-not-a-list", "parts: {shape: point}\n", ["parts"]),
    ("part-not-a-mapping", "parts:\n  - 3\n", ["parts[0]"]),
    ("unknown-shape", edit("shape: cylinder", "shape: blob"), [STEM, "shape", "blob"]),
    ("missing-shape", edit("    shape: cylinder\n", ""), [STEM, "shape"]),
    ("unknown-length-unit", "units: {length: furlong}\n" + TOP, ["units", "length", "furlong"]),
    ("unknown-mass-unit", "units: {length: m, mass: stone}\n" + TOP, ["units", "mass", "stone"]),
    ("units-not-a-mapping", "units: mm\n" + TOP, ["units"]),
    ("name-not-text", edit("name: stem", "name: 12"), ["parts[1]", "name"]),
    ("bad-pivot", "pivot: [0, 0]\n" + TOP, ["pivot"]),
    ("yaml-syntax-error", edit("apex: [0, 0, 0]", "apex: [0, 0, 0"), ["line 8"]),
    ("yaml-tab-indent", edit("    mass: 0.1", "\tmass: 0.1"), ["line 11"]),
    (
        "duplicate-yaml-key",
        edit("    mass: 0.1\n", "    mass: 0.1\n    mass: 0.2\n"),
        ["duplicate", "mass", "line 12"],
    ),
    ("duplicate-top-level-key", TOP + "parts: []\n", ["duplicate", "parts"]),
    ("unsafe-yaml-tag", "parts: !!python/object/apply:os.system ['echo hi']\n", ["python/object"]),
    ("list-file", "- 1\n- 2\n", ["mapping"]),
    ("scalar-file", "just some words\n", ["mapping"]),
    ("empty-file", "", ["empty"]),
    ("comments-only-file", "# nothing here\n", []),
    ("too-large-part", edit("radius: 0.008", "radius: 1.0e+200"), [STEM, "too large"]),
]


def assert_one_line_error(proc, *fragments):
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    assert proc.stdout == ""
    assert "Traceback" not in proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1, proc.stderr
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])
    return lines[0]


@pytest.mark.parametrize("text, fragments", [c[1:] for c in SPEC_CASES], ids=[c[0] for c in SPEC_CASES])
def test_bad_spec_gives_one_clear_line(write_spec, text, fragments):
    path = write_spec(text, name="bad-body.yaml")
    assert_one_line_error(run_rbi_inprocess("inertia", path, "--format", "json"), str(path), *fragments)


def test_binary_file(tmp_path):
    path = tmp_path / "body.yaml"
    path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR")
    assert_one_line_error(run_rbi_inprocess("inertia", path), str(path))


def test_non_utf8_file(tmp_path):
    path = tmp_path / "body.yaml"
    path.write_bytes(b"name: caf\xe9\nparts: []\n")
    assert_one_line_error(run_rbi_inprocess("principal", path), str(path))


def test_directory_instead_of_file(tmp_path):
    assert_one_line_error(run_rbi_inprocess("inertia", tmp_path), str(tmp_path))


def test_every_problem_command_reports_the_same_way(write_spec):
    path = write_spec(edit("radius: 0.008", "radius: 0"))
    for args in (["inertia"], ["principal"], ["momentum", "--omega", "0,0,1"]):
        assert_one_line_error(run_rbi_inprocess(args[0], path, *args[1:]), str(path), STEM, "radius")


@pytest.mark.parametrize(
    "text, mass",
    [
        # YAML 1.1 would read 4e-2 and 1.0e-1 as text; users write them as numbers.
        (edit("radius: 0.04", "radius: 4e-2").replace("mass: 0.1", "mass: 1.0e-1"), 0.52),
        (
            "parts:\n  - {shape: point, mass: 2, position: [1, 0, 0]}\n"
            "  - {shape: point, mass: 2, position: [-1, 0, 0]}\n",
            4.0,
        ),
    ],
)
def test_exponents_and_integers_are_numbers(write_spec, text, mass):
    proc = run_rbi_inprocess("inertia", write_spec(text), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    assert f'"mass": {mass!r},' in proc.stdout


def test_body_whose_sums_overflow(write_spec):
    # Each part is finite, the body's inertia is not: refused, not printed as null.
    path = write_spec(
        "parts:\n  - {shape: point, mass: 1.0, position: [1.0e+200, 0, 0]}\n"
        "  - {shape: point, mass: 1.0, position: [-1.0e+200, 0, 0]}\n"
    )
    assert_one_line_error(run_rbi_inprocess("inertia", path, "--format", "json"), str(path), "too large")


OPTION_CASES = [
    ("momentum", "--omega", "1,2"),
    ("momentum", "--omega", "1,2,x"),
    ("momentum", "--omega", "1,2,nan"),
    ("inertia", "--rotate", "q:30"),
    ("inertia", "--rotate", "y30"),
    ("inertia", "--rotate", "y:abc"),
    ("inertia", "--about", "1,2"),
    ("principal", "--about", "somewhere"),
]


@pytest.mark.parametrize("command, option, value", OPTION_CASES)
def test_bad_option_value_names_the_option(bodies, command, option, value):
    extra = ["--omega", "0,0,1"] if command == "momentum" and option != "--omega" else []
    line = assert_one_line_error(run_rbi_inprocess(command, bodies / "top.yaml", option, value, *extra))
    assert option in line and value in line


def test_about_pivot_without_a_pivot(write_spec):
    path = write_spec(TOP)  # TOP has no pivot
    assert_one_line_error(run_rbi_inprocess("inertia", path, "--about", "pivot"), str(path), "pivot")


# --- the same through the real program ---------------------------------------------------------


@pytest.mark.parametrize("case", ["zero-radius", "yaml-syntax-error", "density-on-point", "too-large-part"])
def test_through_a_subprocess(write_spec, case):
    text, fragments = next(c[1:] for c in SPEC_CASES if c[0] == case)
    path = write_spec(text)
    assert_one_line_error(run_rbi("inertia", path, "--format", "json"), str(path), *fragments)


def test_missing_file_and_bad_option_through_a_subprocess(tmp_path, bodies):
    missing = tmp_path / "nowhere.yaml"
    assert_one_line_error(run_rbi("principal", missing), str(missing))
    line = assert_one_line_error(run_rbi("momentum", bodies / "top.yaml", "--omega", "1,2"))
    assert "--omega" in line
