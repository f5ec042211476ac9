"""Hostile and odd spec files: each is refused with exit 2 and one short line (or, for merge
keys and a byte-order mark, read as the user meant), fast and in bounded memory.

Cases that crashed, hung or ate memory before run in a subprocess with a memory limit and a
timeout, so a regression fails the test instead of taking the machine down."""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys

import numpy as np
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from rbi.spec.errors import InputError
from rbi.spec.load import MAX_SPEC_BYTES, load_body, read_yaml
from rbi.spec.yaml_reader import MAX_DEPTH, read_document
from tests.conftest import one_line_exit_2, run_rbi_inprocess

MEMORY_LIMIT = 1024**3  # bytes of address space a guarded subprocess may take beyond its start


def run_guarded(*args: str, timeout: float = 30.0) -> subprocess.CompletedProcess:
    """``python -m rbi ARGS`` with its address space capped and a timeout: a crash shows as a
    signal exit code, a runaway as TimeoutExpired, either failing the test."""

    def limit():
        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        base = 2 * MEMORY_LIMIT  # the interpreter, numpy and pydantic start in well under this
        if soft == resource.RLIM_INFINITY or soft > base:
            resource.setrlimit(resource.RLIMIT_AS, (base, resource.getrlimit(resource.RLIMIT_AS)[1]))

    return subprocess.run(
        [sys.executable, "-m", "rbi", *map(str, args)],
        capture_output=True,
        text=True,
        timeout=timeout,
        preexec_fn=limit,
    )


POINT = "{shape: point, mass: 1.0, position: [0, 0, 0]}"


# -- nesting -------------------------------------------------------------------------------


def test_thirty_thousand_nested_brackets_are_refused_not_a_crash(tmp_path):
    spec = tmp_path / "deep.yaml"
    spec.write_text("parts: " + "[" * 30_000 + "]" * 30_000 + "\n")
    proc = run_guarded("inertia", spec)
    one_line_exit_2(proc, str(spec), "nested more than 100 levels")


@pytest.mark.parametrize(
    "text",
    [
        "parts: " + "[" * 1000 + "]" * 1000 + "\n",
        "parts: " + "{a: " * 1000 + "1" + "}" * 1000 + "\n",
        "parts:\n" + "".join("  " * i + "- \n" for i in range(150)),
        "parts:\n  " + "- " * 2000 + "1\n",
        "parts:\n" + "".join(" " * i + f"k{i}:\n" for i in range(150)),
        '{"parts": ' + "[" * 5000 + "]" * 5000 + "}",  # JSON: the fast path must obey the limit too
        '{"parts": ' + "[" * 101 + "]" * 101 + "}",
    ],
    ids=[
        "flow-1000",
        "mapping-1000",
        "block-150",
        "compact-sequences-2000",
        "indented-keys-150",
        "json-5000",
        "json-101",
    ],
)
def test_deep_nesting_is_exit_2_naming_the_limit(write_spec, text):
    proc = run_rbi_inprocess("inertia", write_spec(text))
    one_line_exit_2(proc, "nested more than 100 levels")


def test_nesting_up_to_the_limit_is_read_as_written():
    for depth in (1, 50, MAX_DEPTH):
        value = read_document("[" * depth + "7" + "]" * depth)
        for _ in range(depth):
            assert isinstance(value, list) and len(value) == 1
            value = value[0]
        assert value == 7
    with pytest.raises(Exception, match="nested more than"):
        read_document("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1))


# -- aliases ---------------------------------------------------------------------------------

BILLION_LAUGHS = (
    "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
    + "".join(f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 10)}]\n" for i in range(9))
    + "parts: *j\n"
)


def test_billion_laughs_is_refused_fast_in_bounded_memory(tmp_path):
    spec = tmp_path / "laughs.yaml"
    spec.write_text(BILLION_LAUGHS)
    assert len(BILLION_LAUGHS) < 700  # a few hundred bytes standing for 10¹⁰ values
    proc = run_guarded("inertia", spec, timeout=20)
    one_line_exit_2(proc, str(spec), "aliases expand to more than")
    assert len(proc.stderr) < 300  # the expanded value is never printed


def test_aliases_within_the_budget_are_independent_copies():
    data = read_document("a: &v [1, 2, 3]\nb: *v\nc: [*v, *v]\nd: &m {p: *v}\ne: {<<: *m}\n")
    assert data == {
        "a": [1, 2, 3],
        "b": [1, 2, 3],
        "c": [[1, 2, 3], [1, 2, 3]],
        "d": {"p": [1, 2, 3]},
        "e": {"p": [1, 2, 3]},
    }
    data["b"][0] = 9
    data["e"]["p"][0] = 8  # merged from d: editing it (as rbi sweep --vary does) leaves d alone
    assert data["a"] == data["c"][0] == data["c"][1] == data["d"]["p"] == [1, 2, 3]


def test_an_alias_must_name_an_earlier_anchor(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec("parts: [*nowhere]\n"))
    one_line_exit_2(proc, "alias", "no anchor")


def test_aliases_cannot_build_nesting_past_the_limit(write_spec):
    # Each level nests the previous one 10 deep: 11 anchors reach 110 levels with no big bracket run.
    lines = ["l0: &l0 [1]"] + [f"l{i}: &l{i} " + "[" * 10 + f"*l{i - 1}" + "]" * 10 for i in range(1, 11)]
    proc = run_rbi_inprocess("inertia", write_spec("\n".join(lines) + "\nparts: [*l10]\n"))
    one_line_exit_2(proc, "nested more than 100 levels")


# -- merge keys ------------------------------------------------------------------------------

MERGED = """\
defaults: &steel {shape: cylinder, density: 7800, radius: 0.01}
top: &top {start: [0, 0, 0.1], end: [0, 0, 0.2], radius: 0.05}
parts:
  - <<: *steel
    name: shaft
    start: [0, 0, 0]
    end: [0, 0, 0.1]
  - <<: [*top, *steel]
    name: disc
"""

WRITTEN_OUT = """\
parts:
  - {name: shaft, shape: cylinder, density: 7800, radius: 0.01, start: [0, 0, 0], end: [0, 0, 0.1]}
  - {name: disc, shape: cylinder, density: 7800, radius: 0.05, start: [0, 0, 0.1], end: [0, 0, 0.2]}
"""


def test_merge_keys_share_part_defaults(tmp_path):
    # The spec model refuses unknown top-level keys, so the defaults live in the merged parts only:
    # read the document, then compare the parts with the written-out ones.
    merged = read_document(MERGED)
    assert merged["parts"] == yaml.safe_load(WRITTEN_OUT)["parts"]
    # Keys written in the mapping win over merged ones; the first merged mapping wins over later.
    assert merged["parts"][1]["radius"] == 0.05
    assert read_document("a: &a {x: 1}\nb: {<<: *a, x: 2}\n")["b"] == {"x": 2}
    assert read_document("a: &a {x: 1}\nb: &b {x: 3, y: 4}\nc: {<<: [*a, *b]}\n")["c"] == {"x": 1, "y": 4}


def test_a_spec_using_merge_keys_gives_the_written_out_body(tmp_path):
    merged = tmp_path / "merged.yaml"
    merged.write_text(
        "parts:\n  - &steel {shape: cylinder, density: 7800, radius: 0.01, name: shaft,"
        " start: [0, 0, 0], end: [0, 0, 0.1]}\n"
        "  - <<: *steel\n    name: disc\n    radius: 0.05\n    start: [0, 0, 0.1]\n    end: [0, 0, 0.2]\n"
    )
    written = tmp_path / "written.yaml"
    written.write_text(WRITTEN_OUT)
    a, b = load_body(merged).props, load_body(written).props
    assert a.mass == b.mass
    np.testing.assert_array_equal(a.inertia_about_com, b.inertia_about_com)
    # Independent figure: two steel cylinders, m = ρ π r² h.
    assert a.mass == pytest.approx(7800 * np.pi * (0.01**2 + 0.05**2) * 0.1, rel=1e-14)


@pytest.mark.parametrize(
    "text, words",
    [
        (
            "parts: [{shape: point, mass: 1, mass: 2, position: [0, 0, 0]}]\n",
            ["duplicate key 'mass'", "line 1"],
        ),
        (
            "d: &d {mass: 1}\nparts: [{<<: *d, shape: point, position: [0, 0, 0], position: [1, 1, 1]}]\n",
            ["duplicate key 'position'"],
        ),
        ("d: &d {mass: 1}\nparts: [{<<: *d, <<: *d, shape: point}]\n", ["'<<' given twice"]),
        ("parts: [{<<: 3, shape: point}]\n", ["merge", "mapping"]),
    ],
)
def test_duplicate_keys_stay_refused_with_merge_keys_supported(write_spec, text, words):
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), *words)


# -- numbers: YAML 1.2 decimals only -----------------------------------------------------------


@pytest.mark.parametrize(
    "written, reason",
    [
        ("010", "leading zero"),
        ("-07", "leading zero"),
        ("0x10", "hexadecimal"),
        ("0o7", "octal"),
        ("0b11", "binary"),
        ("1:30", "base 60"),
        ("1_000", "digit separator"),
    ],
)
def test_numbers_yaml_1_1_reads_differently_are_refused_naming_the_field(write_spec, written, reason):
    text = f"parts:\n  - name: bolt\n    shape: point\n    mass: {written}\n    position: [0, 0, 0]\n"
    proc = run_rbi_inprocess("inertia", write_spec(text))
    one_line_exit_2(proc, "parts[0]", "mass", "line 4", written, reason)


@pytest.mark.parametrize("written", ["2002-12-14", "yes", "1.2.3"])
def test_other_yaml_1_1_only_values_are_text_and_not_numbers(write_spec, written):
    text = f"parts:\n  - {{shape: point, mass: {written}, position: [0, 0, 0]}}\n"
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "parts[0]", "mass", "must be a number")


@pytest.mark.parametrize(
    "written, value",
    [
        ("10", 10),
        ("+3", 3),
        ("-0", 0),
        ("0", 0),
        ("1e-3", 1e-3),
        ("7.8e3", 7800.0),
        ("2.", 2.0),
        (".5", 0.5),
        ("-1.5E+2", -150.0),
        ("!!float 2", 2.0),
        ("!!int 12", 12),
        ("'010'", "010"),
        ("!!str 0x10", "0x10"),
        ("null", None),
        ("~", None),
        ("true", True),
        ("False", False),
        (".inf", float("inf")),
    ],
)
def test_decimal_numbers_and_core_schema_words_read_as_yaml_1_2_says(written, value):
    got = read_document(f"v: {written}\n")["v"]
    assert got == value and type(got) is type(value)


def test_a_set_and_other_tags_are_refused(write_spec):
    proc = run_rbi_inprocess("inertia", write_spec("parts: !!set {a, b}\n"))
    one_line_exit_2(proc, "!!set", "not supported")
    proc = run_rbi_inprocess(
        "inertia",
        write_spec("parts:\n  - {shape: point, mass: !!timestamp 2001-12-14, position: [0, 0, 0]}\n"),
    )
    one_line_exit_2(proc, "parts[0]", "mass", "!!timestamp")


def test_an_integer_too_long_for_python_is_exit_2(write_spec):
    digits = "9" * 5000
    for text in (
        f"parts: [{{shape: point, mass: {digits}, position: [0, 0, 0]}}]\n",
        f'{{"parts": [{{"shape": "point", "mass": {digits}, "position": [0, 0, 0]}}]}}',
    ):
        one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "parts[0]", "mass", "5000 digits")


# -- keys and documents --------------------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "? [a, b]\n: 1\nparts: [" + POINT + "]\n",
        "parts: [{[1, 2]: 3}]\n",
        "k: &k [1]\nparts: [{*k : 3}]\n",
    ],
)
def test_complex_keys_are_refused(write_spec, text):
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "complex keys")


def test_more_than_one_document_is_refused(write_spec):
    text = "parts: [" + POINT + "]\n---\nparts: [" + POINT + "]\n"
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "more than one YAML document", "line 2")


# -- the spec file itself ------------------------------------------------------------------------


def test_dev_zero_as_the_spec_is_refused_before_reading():
    proc = run_guarded("inertia", "/dev/zero", timeout=20)
    one_line_exit_2(proc, "/dev/zero", "not a regular file")


def test_a_fifo_as_the_spec_is_refused_without_waiting_for_a_writer(tmp_path):
    fifo = tmp_path / "spec.yaml"
    os.mkfifo(fifo)
    proc = run_guarded("inertia", fifo, timeout=20)
    one_line_exit_2(proc, "not a regular file")


def test_a_spec_larger_than_the_cap_is_refused_before_reading(tmp_path):
    huge = tmp_path / "huge.yaml"
    with open(huge, "wb") as stream:  # sparse: takes no disk space
        stream.truncate(MAX_SPEC_BYTES + 1)
    one_line_exit_2(run_rbi_inprocess("inertia", huge), "too large", f"{MAX_SPEC_BYTES:,}")


@pytest.mark.parametrize(
    "text",
    [
        "parts:\n  - " + POINT + "\n",
        json.dumps({"parts": [{"shape": "point", "mass": 1.0, "position": [0, 0, 0]}]}),
    ],
)
def test_a_byte_order_mark_is_skipped(tmp_path, text):
    spec = tmp_path / "bom.yaml"
    spec.write_bytes(b"\xef\xbb\xbf" + text.encode())
    assert read_yaml(spec) == {"parts": [{"shape": "point", "mass": 1.0, "position": [0, 0, 0]}]}
    assert load_body(spec).props.mass == 1.0


def test_errors_name_the_field_and_never_echo_a_long_value(write_spec):
    long_text = "x" * 10_000
    with pytest.raises(InputError) as error:
        load_body(write_spec(f"parts: [{{shape: point, mass: 0{long_text}1, position: [0, 0, 0]}}]\n"))
    assert len(str(error.value)) < 300


# -- properties ------------------------------------------------------------------------------------

scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**20), 10**20),
    st.floats(allow_nan=False, allow_infinity=True),
    st.text(alphabet="abcdefghijklmnopqrstuvwxyz XYZ", max_size=12),
)
documents = st.recursive(
    scalars,
    lambda children: st.one_of(
        st.lists(children, max_size=5),
        st.dictionaries(st.text(alphabet="abcdefgh", min_size=1, max_size=6), children, max_size=5),
    ),
    max_leaves=30,
)


@settings(max_examples=100, deadline=None, derandomize=True)
@given(documents, st.booleans())
def test_reads_what_pyyaml_writes_as_pyyaml_reads_it(document, flow):
    """For documents PyYAML writes (strings of letters, decimal numbers), this reader and
    PyYAML's safe loader agree: an independent YAML implementation as the reference."""
    text = yaml.safe_dump(document, default_flow_style=flow)
    assert read_document(text) == yaml.safe_load(text)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.integers(1, 3 * MAX_DEPTH), st.sampled_from(["[", "{a: "]))
def test_depth_is_refused_exactly_past_the_limit(depth, opener):
    closer = "]" if opener == "[" else "}"
    text = opener * depth + "1" + closer * depth
    if depth <= MAX_DEPTH:
        read_document(text)
    else:
        with pytest.raises(Exception, match=f"nested more than {MAX_DEPTH}"):
            read_document(text)


# -- names: only what YAML 1.1 really reads as a number is handled specially ------------------


@pytest.mark.parametrize(
    "written", ["08", "09", "+08", "0_8", "1e3", "1e-3", "0o7", "0X1F", "0:30", "1:70", "1.2.3"]
)
def test_a_name_yaml_1_1_reads_as_text_is_that_text(written):
    """Found by hypothesis: a part named ``08``, written unquoted by PyYAML (YAML 1.1 reads it as
    text), was refused as 'YAML 1.1 reads it as octal'."""
    import yaml

    assert yaml.safe_load(f"v: {written}\n")["v"] == written  # YAML 1.1 reads it as text
    assert read_document(f"name: {written}\nparts: [{{name: {written}}}]\n") == {
        "name": written,
        "parts": [{"name": written}],
    }


@pytest.mark.parametrize(
    "written, reason",
    [
        ("010", "octal"),
        ("0x1F", "hexadecimal"),
        ("1_000", "digit separator"),
        ("0b101", "binary"),
        ("1:30", "base 60"),
        ("190:20:30", "base 60"),
    ],
)
def test_a_name_yaml_1_1_reads_as_a_number_is_refused_saying_quote_it(write_spec, written, reason):
    text = f"parts:\n  - name: {written}\n    shape: point\n    mass: 1\n    position: [0, 0, 0]\n"
    one_line_exit_2(run_rbi_inprocess("inertia", write_spec(text)), "parts[0]", "name", reason, "quote it")


@pytest.mark.parametrize("written, value", [("12", 12), (".5", 0.5), ("1.5", 1.5)])
def test_a_name_yaml_1_1_reads_as_a_decimal_is_a_number(written, value):
    assert read_document(f"name: {written}\n")["name"] == value


def test_a_leading_zero_yaml_1_1_reads_as_text_is_not_called_octal(write_spec):
    text = "parts:\n  - {shape: point, mass: 08, position: [0, 0, 0]}\n"
    proc = run_rbi_inprocess("inertia", write_spec(text))
    one_line_exit_2(proc, "parts[0]", "mass", "'08'", "YAML 1.2 as 8", "write 8")
    assert "octal" not in proc.stderr
