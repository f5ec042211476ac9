"""Varying spec fields by path: resolution, errors that name the path, and re-derivation
through the ordinary translation (a varied radius changes a density part's mass)."""

from __future__ import annotations

import json
import math

import pytest

from rbi.errors import ArgumentError
from rbi.spec.errors import InputError
from rbi.spec.load import read_yaml, spec_from_raw
from rbi.spec.translate import body_from_spec
from rbi.spec.variations import current_values, resolve, with_values

SPEC = """
name: rotor
pivot: [0, 0, 0]
parts:
  - {name: disc, shape: cylinder, density: 7800, radius: 0.1, start: [0, 0, 0], end: [0, 0, 0.02]}
  - {name: bolt, shape: point, mass: 0.02, position: [0.05, 0, 0.01]}
  - {shape: sphere, mass: 1, center: [0, 0, 0.3], radius: 0.01}
"""


@pytest.fixture
def raw(write_spec):
    return read_yaml(write_spec(SPEC))


def test_paths_reach_numbers_by_part_name_index_and_component(raw):
    assert resolve(raw, "parts.bolt.position[0]").steps == ("parts", 1, "position", 0)
    assert resolve(raw, "parts.2.mass").steps == ("parts", 2, "mass")
    assert resolve(raw, "pivot[2]").steps == ("pivot", 2)
    assert current_values(raw, [resolve(raw, "parts.disc.radius"), resolve(raw, "parts.bolt.mass")]) == [
        0.1,
        0.02,
    ]
    components = [resolve(raw, f"parts.bolt.position[{k}]") for k in range(3)]
    assert current_values(raw, components) == [0.05, 0.0, 0.01]


@pytest.mark.parametrize(
    "path, words",
    [
        ("parts.nut.mass", ["parts has no entry 'nut'", "disc, bolt"]),
        ("parts.bolt.masss", ["parts.bolt.masss: no such field", "mass, name, position, shape"]),
        ("parts.bolt.position[3]", ["parts.bolt.position has no entry 3"]),
        ("parts.bolt.position", ["must name a number", "list"]),
        ("parts.bolt.shape", ["must name a number", "'point'"]),
        ("name", ["must name a number"]),
        ("parts..mass", ["cannot read"]),
        ("", ["field path"]),
    ],
)
def test_bad_paths_name_the_path_and_what_is_there(raw, path, words):
    with pytest.raises(InputError) as info:
        resolve(raw, path)
    assert str(info.value).startswith(f"vary[{path!r}]: ")
    for word in words:
        assert word in str(info.value), str(info.value)


def test_a_varied_radius_changes_the_mass_of_a_density_part_and_the_original_is_untouched(raw):
    path = resolve(raw, "parts.disc.radius")
    changed = with_values(raw, [path], [0.2])
    body = body_from_spec(spec_from_raw("rotor.yaml", changed), "rotor.yaml")
    disc_mass = 7800 * math.pi * 0.2**2 * 0.02
    assert body.props.mass == pytest.approx(disc_mass + 0.02 + 1, rel=1e-12)
    assert raw["parts"][0]["radius"] == 0.1


NAMED = """
name: named
parts:
  - {name: cone, shape: cone, mass: 0.4, radius: 0.04, apex: [0, 0, 0], base: [0, 0, 0.06]}
  - {name: bolt.1, shape: point, mass: 0.02, position: [0.04, 0, 0.06]}
  - {name: bolt, shape: point, mass: 0.05, position: [-0.04, 0, 0.06]}
  - {name: "a=b", shape: point, mass: 0.03, position: [0, 0.04, 0.06]}
"""


def test_a_part_named_with_dots_is_reached_by_its_name(write_spec):
    """`parts.bolt.1.mass` is the part named 'bolt.1' (a name the spec allows), not 'bolt'; the
    shorter name still reaches its own part."""
    raw = read_yaml(write_spec(NAMED))
    assert resolve(raw, "parts.bolt.1.mass").steps == ("parts", 1, "mass")
    assert resolve(raw, "parts.bolt.1.position[0]").steps == ("parts", 1, "position", 0)
    assert resolve(raw, "parts.bolt.mass").steps == ("parts", 2, "mass")
    assert current_values(raw, [resolve(raw, "parts.bolt.1.mass"), resolve(raw, "parts.a=b.mass")]) == [
        0.02,
        0.03,
    ]


@pytest.mark.parametrize("path, other", [("parts.bolt.1.mass", 0.05 + 0.03), ("parts.a=b.mass", 0.02 + 0.05)])
def test_sweep_varies_parts_named_with_dots_and_equals_signs(write_spec, path, other):
    """The command line splits PATH=RANGE at the last '=' (a range has none): the body's mass
    is the cone's 0.4 plus the varied part plus the other two points, run by run."""
    from tests.conftest import run_rbi

    spec = write_spec(NAMED)
    done = run_rbi("sweep", spec, "--mass-properties", "--vary", f"{path}=0.01:0.03:2", "--format", "csv")
    assert done.returncode == 0, done.stderr
    rows = list(__import__("csv").DictReader(__import__("io").StringIO(done.stdout)))
    assert [float(r[path]) for r in rows] == [0.01, 0.03]
    assert [float(r["mass"]) for r in rows] == pytest.approx(
        [0.4 + 0.01 + other, 0.4 + 0.03 + other], rel=1e-14
    )


def test_a_sub_assembly_s_measured_mass_may_be_swept_where_the_spec_leaves_it_out(write_spec):
    """Issue 39: ``--vary parts.panel.mass`` on a sub-assembly written without ``mass``: the
    sweep sets the measured mass (per copy of a pattern); the nominal keeps the parts' own."""
    from tests.conftest import run_rbi_inprocess

    write_spec("parts:\n  - {name: w, shape: point, mass: 0.5, position: [0.1, 0, 0]}\n", "weight.yaml")
    spec = write_spec(
        "parts:\n  - {name: hub, shape: point, mass: 1, position: [0, 0, 0]}\n"
        "  - {name: panel, shape: assembly, file: weight.yaml,\n"
        "     pattern: {count: 2, axis: [0, 0, 1], through: [0, 0, 0]}}\n"
    )
    raw = read_yaml(spec)
    path = resolve(raw, "parts.panel.mass")
    assert current_values(raw, [path]) == [None]
    assert with_values(raw, [path], [None]) == raw
    assert with_values(raw, [path], [2.0])["parts"][1]["mass"] == 2.0
    proc = run_rbi_inprocess(
        "sweep", spec, "--mass-properties", "--vary", "parts.panel.mass=0.25:1:2", "--format", "json"
    )
    assert proc.returncode == 0, proc.stderr
    masses = [run["mass"] for run in json.loads(proc.stdout)["runs"]]
    assert masses == [pytest.approx(1 + 2 * 0.25), pytest.approx(1 + 2 * 1.0)]  # mass is per copy
    with pytest.raises(ArgumentError, match="no such field"):
        resolve(raw, "parts.hub.radius")
