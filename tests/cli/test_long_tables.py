"""Tables of thousands of rows (a robot of 10⁵ links: rich takes about a millisecond a row) are
laid out by rbi itself when they fit the terminal, and must print exactly what rich prints; the
audit of a large robot prints the same table either way."""

from __future__ import annotations

import contextlib
import io

import pytest
from rich import box

import rbi.cli.render as render
from rbi.bench.robotaudit import urdf_text
from rbi.cli.tables import SafeTable
from rbi.text import visible
from tests.conftest import run_rbi_inprocess


def _printed(table_of, rows: int, width: int, monkeypatch, laid_out_by_rbi: bool) -> str:
    monkeypatch.setenv("COLUMNS", str(width))
    monkeypatch.setattr(render, "LONG_TABLE_ROWS", 10 if laid_out_by_rbi else 10**9)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        render.print_table(table_of(rows))
    return out.getvalue()


def titled(title: str) -> SafeTable:
    """An empty table in rbi's style (as rbi.cli.tables.drawn makes them)."""
    return SafeTable(title=title, box=box.SIMPLE_HEAD, title_justify="left", show_edge=False)


def _links(rows: int):
    table = titled(f"robot.urdf: {rows} links (a title long enough to wrap at sixty columns of terminal)")
    table.add_column("link", overflow="fold")
    table.add_column("mass kg", justify="right", no_wrap=True)
    table.add_column("ρ kg/m³", justify="right", no_wrap=True)
    table.add_column("flags", overflow="fold")
    names = ["l0", "ρ÷·", "a_much_longer_link_name", "[b]bold?[/b]", "tab\\there", "x"]
    for i in range(rows):
        table.add_row(
            names[i % len(names)], f"{1.5 * i:.6g}", "-" if i % 3 else "1000", "ok" if i % 4 else "mass!"
        )
    return table


def _numbers_only(rows: int):
    table = titled("")
    for heading in ("joint", "torque", "limit"):
        table.add_column(heading, justify="left" if heading == "joint" else "right")
    for i in range(rows):
        table.add_row(f"j{i}", f"{-9.81 * i:.6g}", "-")
    return table


@pytest.mark.parametrize("table_of", [_links, _numbers_only])
@pytest.mark.parametrize("width", [60, 80, 200])
def test_a_long_table_prints_exactly_what_rich_prints(table_of, width, monkeypatch):
    rich_lines = _printed(table_of, 40, width, monkeypatch, laid_out_by_rbi=False)
    rbi_lines = _printed(table_of, 40, width, monkeypatch, laid_out_by_rbi=True)
    assert rbi_lines == rich_lines
    assert "─" * 20 in rbi_lines


def test_a_long_table_too_wide_for_the_terminal_is_left_to_rich(monkeypatch):
    monkeypatch.setenv("COLUMNS", "30")
    monkeypatch.setattr(render, "LONG_TABLE_ROWS", 10)
    table = _links(40)
    assert render._long_table_lines(table, render.rich_console()) is None


def test_the_audit_of_a_large_robot_prints_the_same_table_either_way(tmp_path, monkeypatch):
    path = tmp_path / "large.urdf"
    path.write_text(urdf_text(800))
    monkeypatch.setattr(render, "LONG_TABLE_ROWS", 10**9)
    by_rich = run_rbi_inprocess("audit", path)
    monkeypatch.setattr(render, "LONG_TABLE_ROWS", 500)
    by_rbi = run_rbi_inprocess("audit", path)
    assert by_rich.returncode == by_rbi.returncode == 0, by_rbi.stderr
    assert by_rbi.stdout == by_rich.stdout
    assert by_rbi.stdout.count(" ok ") >= 800 + 799  # every link and every joint listed


@pytest.mark.parametrize(
    "text", ["plain ASCII 0.25 kg", "a\x7fb", "tab\there", "é ρ", "\u202eevil", "a\u00a0b"]
)
def test_visible_escapes_the_same_characters_on_its_fast_path(text):
    slow = "".join(c if c == " " or not (c.isspace() or not c.isprintable()) else repr(c)[1:-1] for c in text)
    assert visible(text) == slow
