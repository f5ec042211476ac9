"""rbi.files.safe on what can stand where rbi keeps a file: each check answers at once (no
read, no wait), names stay within 255 bytes, and writes never go through a link."""

from __future__ import annotations

import os
import time

import pytest

from rbi.errors import InputError
from rbi.files import safe


def plant(path, kind, tmp_path):
    victim = tmp_path / "victim"
    victim.write_text("precious\n")
    if kind == "symlink":
        path.symlink_to(victim)
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "devzero":
        path.symlink_to("/dev/zero")
    elif kind == "folder":
        path.mkdir()
    return victim


@pytest.mark.parametrize("kind", ["symlink", "fifo", "devzero", "folder"])
@pytest.mark.parametrize("check", ["existing", "read", "open", "replace"])
def test_anything_but_a_regular_file_is_refused_in_under_a_second(tmp_path, kind, check):
    path = tmp_path / ".x.rbi-sweep.json"
    victim = plant(path, kind, tmp_path)
    started = time.monotonic()
    with pytest.raises(InputError):
        if check == "existing":
            safe.existing_regular(path, "x")
        elif check == "read":
            safe.read_capped(path, 1 << 20, "x")
        elif check == "open":
            os.close(safe.open_regular(path, "x", os.O_RDWR))
        else:
            safe.replace_small(path, b"new", "x")
    assert time.monotonic() - started < 1.0
    assert victim.read_text() == "precious\n"


def test_a_read_is_capped_by_size_before_reading(tmp_path):
    path = tmp_path / "big"
    with open(path, "wb") as handle:
        handle.truncate(8 << 30)
    started = time.monotonic()
    with pytest.raises(InputError, match="larger than"):
        safe.read_capped(path, 1 << 20, "x")
    assert time.monotonic() - started < 1.0


def test_create_exclusive_never_writes_what_already_stands_there(tmp_path):
    path = tmp_path / "new"
    victim = plant(path, "symlink", tmp_path)
    with pytest.raises(InputError):
        safe.create_exclusive(path, "x")
    assert victim.read_text() == "precious\n"


def test_replace_small_leaves_no_temporary_file_and_replaces_atomically(tmp_path):
    path = tmp_path / "side.json"
    safe.replace_small(path, b"one", "x")
    safe.replace_small(path, b"two", "x")
    assert path.read_bytes() == b"two" and sorted(os.listdir(tmp_path)) == ["side.json"]


def test_a_long_name_is_shortened_with_a_hash_and_stays_apart():
    long = "a" * 250 + ".csv"
    one, two = safe.beside(long, ".rbi-sweep.json"), safe.beside("b" + long[1:], ".rbi-sweep.json")
    assert len(os.fsencode(one.name)) <= 255 and one != two and "~" in one.name
    assert safe.beside("map.csv", ".rbi-lock").name == ".map.csv.rbi-lock"


def test_a_path_with_a_nul_character_is_refused_as_unusable():
    """rbi.load('a\\x00.yaml') (and rbi.audit, rbi.validate, rbi.sweep of such a path) raised
    os.open's bare ValueError 'embedded null byte', naming neither the path nor a parameter."""
    import rbi

    with pytest.raises(safe.InputFileRefused, match="not a usable path"):
        safe.read_input_file("a\x00.yaml", 100, "spec")
    for call in (
        lambda: rbi.load("a\x00.yaml"),
        lambda: rbi.audit("a\x00.urdf"),
        lambda: rbi.sweep("a\x00.yaml"),
    ):
        with pytest.raises(rbi.SpecError, match="^a\x00.(yaml|urdf): not a usable path"):
            call()
    assert rbi.validate(["a\x00.yaml"]) == [["a\x00.yaml: not a usable path (it contains a NUL character)"]]
