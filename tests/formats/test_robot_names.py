"""Names from a robot file in messages: letters shown as they are written (``ünï``, not
``\\xfcn\\xef``), hidden characters escaped by the one terminal escaper (a right-to-left
override cannot reorder the line), in every output form."""

from __future__ import annotations

import pytest

from tests.conftest import one_line_exit_2, run_rbi_inprocess

DUPLICATE = '<robot name="r"><link name="ünï\u202e"/><link name="ünï\u202e"/></robot>'


@pytest.mark.parametrize("form", ["table", "json", "csv"])
def test_a_duplicate_link_name_is_shown_as_written_with_hidden_characters_escaped(tmp_path, form):
    path = tmp_path / "dup.urdf"
    path.write_text(DUPLICATE, encoding="utf-8")
    proc = run_rbi_inprocess("audit", path, "--format", form)
    one_line_exit_2(proc, "dup.urdf", "link[1] (ünï\\u202e)", "duplicate link name")
    assert "\\xfc" not in proc.stderr and "\u202e" not in proc.stderr
