"""Issue 18, principle 9: an error says what is wrong with the value given and what would be
right. Each case: the spec, words naming the value given, words saying what would be right."""

from __future__ import annotations

import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess

CASES = {
    "torus axis zero": (
        "{shape: torus, mass: 1, major_radius: 1, minor_radius: 0.2, center: [0, 0, 0], axis: [0, 0, 0]}",
        ["axis", "[0, 0, 0]"],
        ["ring's axis", "e.g. [0, 0, 1]"],
    ),
    "hemisphere axis zero": (
        "{shape: hemisphere, mass: 1, radius: 1, center: [0, 0, 0], axis: [0, 0, 0]}",
        ["axis", "[0, 0, 0]"],
        ["flat face into the dome", "e.g. [0, 0, 1]"],
    ),
    "pattern axis zero": (
        "{shape: point, mass: 1, position: [1, 0, 0], pattern: {count: 3, axis: [0, 0, 0]}}",
        ["pattern: axis", "[0, 0, 0]"],
        ["copies turn about", "e.g. [0, 0, 1]"],
    ),
    "rotation axis zero": (
        "{shape: box, mass: 1, size: [1, 1, 1], center: [0, 0, 0], rotation: {axis: [0, 0, 0], angle_deg: 3}}",
        ["rotation: axis", "[0, 0, 0]"],
        ["direction to turn about", "e.g. [0, 0, 1]"],
    ),
    "quaternion zero": (
        "{shape: box, mass: 1, size: [1, 1, 1], center: [0, 0, 0], rotation: {quaternion: [0, 0, 0, 0]}}",
        ["quaternion", "[0, 0, 0, 0]"],
        ["identity", "[1, 0, 0, 0]"],
    ),
    "custom triangle": (
        "{shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1, iyy: 1, izz: 3}}",
        ["1 + 1 = 2 < 3"],
        ["at most the sum of the other two", "about one point and in one unit"],
    ),
    "custom negative": (
        "{shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1, iyy: 1, izz: 1, ixy: 2}}",
        ["I1 = -1 < 0"],
        ["no real body has a negative moment", "−∫xy dm"],
    ),
    "custom asymmetric": (
        "{shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}",
        ["[0][1] = 0.5 but [1][0] = 0"],
        ["give both the same value"],
    ),
    "custom about too far": (
        "{shape: custom, mass: 2, center_of_mass: [1, 0, 0], about: [0, 0, 0], "
        "inertia: {ixx: 1, iyy: 1, izz: 1}}",
        ["about the centre of mass", "mass × offset² = 2"],
        ["is `about` the point it was taken about"],
    ),
    "pattern count not whole": (
        "{shape: point, mass: 1, position: [1, 0, 0], pattern: {count: 2.5, axis: [0, 0, 1]}}",
        ["pattern.count", "got 2.5"],
        ["must be a whole number"],
    ),
    "pattern count too many": (
        "{shape: point, mass: 1, position: [1, 0, 0], pattern: {count: 1000000000, axis: [0, 0, 1]}}",
        ["pattern.count", "got 1000000000"],
        ["must be at most 100000"],
    ),
    "pattern count zero": (
        "{shape: point, mass: 1, position: [1, 0, 0], pattern: {count: 0, axis: [0, 0, 1]}}",
        ["pattern.count", "got 0"],
        ["must be at least 1"],
    ),
    "assembly file empty": ("{shape: assembly, file: ''}", ["file", "(got '')"], ["a file name, not empty"]),
    "mesh file empty": ("{shape: mesh, file: '', mass: 1}", ["file", "(got '')"], ["a file name, not empty"]),
    "custom too large": (
        "{shape: custom, mass: 1, center_of_mass: [0, 0, 0], inertia: {ixx: 1.0e+308, iyy: 1.0e+308, izz: 1.0e+308}}",
        ["too large", "1e+308"],
        ["unit"],
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_message_names_the_value_and_what_would_be_right(write_spec, case):
    part, given, right = CASES[case]
    proc = run_rbi_inprocess("inertia", write_spec(f"parts:\n  - {part}\n"))
    one_line_exit_2(proc, "parts[0]", *given, *right)


def test_duplicate_name_says_which_part_has_it_and_offers_a_free_one(write_spec):
    spec = write_spec(
        "parts:\n  - {name: a, shape: point, mass: 1, position: [0, 0, 0]}\n"
        "  - {name: a-2, shape: point, mass: 1, position: [2, 0, 0]}\n"
        "  - {name: a, shape: point, mass: 1, position: [1, 0, 0]}\n"
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec), "parts[2] (a)", "'a' is also the name of parts[0]", "e.g. 'a-3'"
    )


def test_names_that_look_the_same_are_duplicates(write_spec):
    """Found: 'é' written as one code point and as e + combining accent were two parts with
    names no table or --vary path could tell apart."""
    spec = write_spec(
        'parts:\n  - {name: "\\u00e9", shape: point, mass: 1, position: [0, 0, 0]}\n'
        '  - {name: "e\\u0301", shape: point, mass: 1, position: [1, 0, 0]}\n'
    )
    one_line_exit_2(
        run_rbi_inprocess("inertia", spec), "parts[1]", "looking the same as the name of parts[0]"
    )


def test_a_huge_axis_option_is_a_direction(bodies):
    """Found: --axis 1e200,0,1e200 was refused as 'must be a non-zero direction'."""
    import json

    big = json.loads(
        run_rbi_inprocess(
            "inertia", bodies / "top.yaml", "--axis", "1e200,0,1e200", "--format", "json"
        ).stdout
    )
    unit = json.loads(
        run_rbi_inprocess("inertia", bodies / "top.yaml", "--axis", "1,0,1", "--format", "json").stdout
    )
    assert big["moment_about_axis"] == pytest.approx(unit["moment_about_axis"], rel=1e-14)
