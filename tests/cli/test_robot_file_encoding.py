"""A robot file that declares an encoding rbi does not read: the message shows the declared name
as every value from a robot file is shown (rbi.text.visible)."""

from __future__ import annotations

from tests.conftest import one_line_exit_2, run_rbi_inprocess


def test_an_unknown_encoding_is_named_escaped_once(tmp_path, monkeypatch):
    # the name was escaped by its own rule (unicode_escape): 'lat\\ufffd\\ufffdn\\\\\\x1b', the
    # replacement characters spelled out and the backslash doubled before repr doubled it again
    monkeypatch.chdir(tmp_path)
    (tmp_path / "r.urdf").write_bytes(
        b'<?xml version="1.0" encoding="lat\xc3\xa9n\\\x1b"?>\n<robot name="r"><link name="a"/></robot>\n'
    )
    for command in ("audit", "import"):
        proc = run_rbi_inprocess(command, "r.urdf")
        one_line_exit_2(proc)
        assert proc.stderr == (
            "rbi: r.urdf: encoding 'lat\ufffd\ufffdn\\\\\\\\x1b': not an encoding rbi reads robot files in "
            "(UTF-8, UTF-16, ASCII, ISO-8859-1, Windows-1252); save the file as UTF-8\n"
        )
