"""rbi.load takes a path (a str is always one; "-" is standard input) or a dict, rbi.loads
takes YAML or JSON text; bad input raises rbi.SpecError whose str() is the line the CLI
prints."""

from __future__ import annotations

import io
import json
import sys

import numpy as np
import pytest
import yaml

import rbi
from tests.conftest import BODIES
from tests.conftest import run_rbi_inprocess as run_rbi

TOP = BODIES / "top.yaml"


def same_body(a, b):
    assert a.mass == b.mass
    np.testing.assert_array_equal(a.center_of_mass, b.center_of_mass)
    np.testing.assert_array_equal(a.inertia(), b.inertia())


def test_path_text_dict_and_stdin_give_the_same_body(monkeypatch):
    from_path = rbi.load(TOP)
    text = TOP.read_text()
    from_text = rbi.loads(text)
    assert rbi.loads(text.encode()).mass == from_text.mass
    from_dict = rbi.load(yaml.safe_load(text))
    monkeypatch.setattr(sys, "stdin", io.StringIO(text))
    from_stdin = rbi.load("-")
    for body in (from_text, from_dict, from_stdin):
        same_body(body, from_path)
    assert from_path.path == str(TOP)
    assert (from_text.path, from_dict.path, from_stdin.path) == ("<string>", "<dict>", "<stdin>")
    assert rbi.load(str(TOP)).name == from_path.name


def test_json_text_is_a_spec_too():
    same_body(rbi.loads(json.dumps(yaml.safe_load(TOP.read_text()))), rbi.load(TOP))


def test_a_str_is_always_a_path():
    text = TOP.read_text()
    with pytest.raises(ValueError, match=r"^source: is text, not a path .* rbi.loads$"):
        rbi.load(text)
    with pytest.raises(rbi.SpecError, match="no such file"):
        rbi.load("top.yaml is not here.yaml")
    with pytest.raises(TypeError, match=r"^text: "):
        rbi.loads(TOP)


@pytest.mark.parametrize("text", [json.dumps(yaml.safe_load(TOP.read_text())), "{name: top, parts: []}"])
def test_one_line_spec_text_given_as_a_path_is_not_echoed(text):
    """rbi 4 echoed a one-line JSON spec (1,798 characters) in its 'no such file' error."""
    assert "\n" not in text
    with pytest.raises(ValueError, match=r"^source: is text, not a path .* rbi.loads$") as raised:
        rbi.load(text)
    assert len(str(raised.value)) <= 200


@pytest.mark.parametrize(
    "args, make",
    [
        (["nope.yaml"], lambda tmp: "nope.yaml"),
        (["{tmp}/bad.yaml"], lambda tmp: f"{tmp}/bad.yaml"),
        (["{tmp}/unknown.yaml"], lambda tmp: f"{tmp}/unknown.yaml"),
    ],
)
def test_spec_error_is_the_cli_error_line(tmp_path, args, make):
    (tmp_path / "bad.yaml").write_text("parts: [\n")
    (tmp_path / "unknown.yaml").write_text(
        "parts:\n  - name: a\n    shape: sphere\n    radius: 1\n    mas: 2\n"
    )
    path = make(tmp_path)
    with pytest.raises(rbi.SpecError) as caught:
        rbi.load(path)
    proc = run_rbi("inertia", path)
    assert proc.returncode == 2
    assert proc.stderr == f"rbi: {caught.value}\n"


def test_spec_error_names_file_part_and_field_of_text():
    text = "parts:\n  - name: cone\n    shape: cone\n    mass: 1\n    radius: -1\n    apex: [0, 0, 0]\n    base: [0, 0, 1]\n"
    with pytest.raises(rbi.SpecError) as caught:
        rbi.loads(text)
    message = str(caught.value)
    assert message.startswith("<string>: ") and "cone" in message and "radius" in message
    assert "\n" not in message
    error = caught.value
    assert (error.file, error.part, error.field) == ("<string>", "parts[0] (cone)", "radius")


def test_a_dict_that_is_not_a_spec():
    with pytest.raises(rbi.SpecError, match=r"^<dict>: "):
        rbi.load({"parts": "nothing"})
    with pytest.raises(TypeError, match=r"^source: expected a path"):
        rbi.load(42)


def test_files_a_spec_names_are_read_beside_it_or_beside_the_caller(monkeypatch, tmp_path):
    bracket = rbi.load(BODIES / "bracket.yaml")  # names the mesh bracket.stl beside it
    text = (BODIES / "bracket.yaml").read_text()
    monkeypatch.chdir(BODIES)
    assert rbi.loads(text).mass == bracket.mass  # text: files beside the current folder
    monkeypatch.chdir(tmp_path)
    with pytest.raises(
        rbi.SpecError, match=r"^<string>: parts\[0\] \(bracket\): file: bracket.stl: no such file$"
    ):
        rbi.loads(text)
    outside = text.replace("file: bracket.stl", f"file: {BODIES / 'bracket.stl'}")
    with pytest.raises(rbi.SpecError, match="leaves the spec's folder"):
        rbi.loads(outside)
    assert rbi.loads(outside, allow_outside_paths=True).mass == bracket.mass


def test_several_problems_in_text_or_a_dict_are_counted_without_a_command_to_run():
    """`rbi validate FILE` lists every problem of a file; a spec given as text or a dict has no
    file to give it, so the message only counts them."""
    with pytest.raises(rbi.SpecError) as caught:
        rbi.load({"parts": [{"shape": "cone", "mass": -1}]})
    message = str(caught.value)
    assert message.startswith("<dict>: parts[0]: ") and "more)" in message and "rbi validate" not in message


def _holding_itself():
    spec = {"parts": []}
    spec["parts"].append(spec)
    return spec


def _list_holding_itself():
    loop: list = [0.0, 0.0]
    loop.append(loop)
    return {"parts": [{"shape": "point", "mass": 1.0, "position": loop}]}


def _shared_doubling(levels=60):
    node: list = [0.0]
    for _ in range(levels):
        node = [node, node]  # 2**60 values once written out
    return {"parts": [{"shape": "point", "mass": 1.0, "position": node}]}


@pytest.mark.parametrize(
    "make, words",
    [
        (_holding_itself, "nests deeper than 100 levels or holds itself"),
        (_list_holding_itself, "nests deeper than 100 levels or holds itself"),
        (_shared_doubling, "more than 33,554,432 values"),
    ],
)
def test_a_dict_that_holds_itself_or_expands_without_bound_is_refused_at_once(make, words):
    """rbi.load of a dict that holds itself walked it until memory ran out (MemoryError under a
    2 GB limit; without one, the machine's memory): the lone-surrogate walk followed the loop for
    ever. A dict is held to what a spec file may be: at most 100 levels deep, and at most as many
    values, written out, as a 64 MiB file could hold (a shared list counts once per place)."""
    with pytest.raises(rbi.SpecError, match=f"^<dict>: .*{words}"):
        rbi.load(make())


def test_a_part_shared_by_many_places_is_read_as_written_out():
    part = {"shape": "point", "mass": 0.5, "position": [1.0, 0.0, 0.0]}
    body = rbi.load({"parts": [part] * 1000})
    assert body.mass == pytest.approx(500.0)
    np.testing.assert_allclose(body.center_of_mass, [1.0, 0.0, 0.0])
