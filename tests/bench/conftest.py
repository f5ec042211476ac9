"""One `rbi bench --quick` run, as CI would run it, shared by every test that reads its result
(the run takes most of a minute: its sections are the same whichever test reads them). The tests
that read it are all in test_bench_command.py, so that under pytest-xdist's `--dist loadfile`
(the README's test command) one worker runs them and the run is made once."""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_rbi


@pytest.fixture(scope="session")
def quick_proc(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bench")
    # the page's name holds an escape sequence: the line naming it must not reach the terminal raw
    doc, png = folder / "perf\x1b[31m.md", folder / "workprecision.png"
    proc = run_rbi("bench", "--quick", "--format", "json", "--write-docs", doc, "--plot", png)
    assert proc.returncode == 0, proc.stderr
    return proc, doc, png


@pytest.fixture(scope="session")
def quick_run(quick_proc):
    proc, doc, png = quick_proc
    return json.loads(proc.stdout), doc, png
