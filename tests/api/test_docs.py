"""The documentation site builds with warnings as errors, and every Python example of
docs/python-api.md runs and prints exactly the output the page shows below it."""

from __future__ import annotations

import contextlib
import inspect
import io
import re
import subprocess
import sys
from pathlib import Path

import pytest

import rbi

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "python-api.md"
sys.path.insert(0, str(ROOT / "tools"))

import docs_examples  # noqa: E402  (the examples run with the README's install set only)


def examples() -> list[tuple[str, str | None]]:
    """Each ```python block of the page with the ```text block right after it (None if none)."""
    blocks = re.findall(r"^```(\w*)\n(.*?)^```\n", PAGE.read_text(), re.S | re.M)
    out = []
    for i, (lang, code) in enumerate(blocks):
        if lang == "python":
            shown = blocks[i + 1][1] if i + 1 < len(blocks) and blocks[i + 1][0] == "text" else None
            out.append((code, shown))
    return out


def test_the_page_has_the_walk_through():
    text = PAGE.read_text()
    for step in ("rbi.load(", ".principal()", "rbi.simulate(", "matplotlib", "rbi.SpecError"):
        assert step in text, step
    assert len(examples()) >= 5


@pytest.mark.parametrize("index", range(len(examples())))
def test_every_python_example_runs_and_prints_what_the_page_shows(index, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    code, shown = examples()[index]
    (tmp_path / "bodies").symlink_to(ROOT / "bodies")
    monkeypatch.chdir(tmp_path)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed), docs_examples.only_the_readme_install():
        exec(compile(code, f"{PAGE.name} example {index + 1}", "exec"), {"__name__": "__main__"})
    if shown is not None:
        assert printed.getvalue() == shown


def test_the_site_builds_strictly(tmp_path):
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "mkdocs",
            "build",
            "--strict",
            "-f",
            str(ROOT / "mkdocs.yml"),
            "-d",
            str(tmp_path / "site"),
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    # not --quiet: it hid the 25 warnings (grouped parameters, names in __all__) strict counts
    assert proc.returncode == 0 and "WARNING" not in proc.stderr, proc.stderr
    reference = (tmp_path / "site" / "api" / "index.html").read_text()
    rows = re.findall(r'<tr class="doc-section-item">(.*?)</tr>', reference, re.S)
    marked = {re.search(r"<code>([^<]+)</code>", row)[1] for row in rows if "<em>required</em>" in row}
    callables = [getattr(rbi, name) for name in rbi.__all__ if callable(getattr(rbi, name, None))]
    callables += [f for f in vars(rbi.Body).values() if inspect.isfunction(f)]
    required = {
        name
        for function in callables
        for name, parameter in inspect.signature(function).parameters.items()
        if parameter.default is inspect.Parameter.empty
    }
    assert marked and marked <= required, marked - required  # no defaulted parameter marked required
    documented = set(re.findall(r'id="rbi\.[\w.]*?\.(\w+)"', reference))
    assert {name for name in rbi.__all__ if name != "__version__"} <= documented  # every public name
    assert 'id="rbi.api.Body.principal"' in reference
    assert (tmp_path / "site" / "python-api" / "index.html").exists()


def test_the_reference_page_lists_every_public_name():
    """docs/api.md names the members it documents; they are ``rbi.__all__`` (AuditReport has a
    section of its own, ``__version__`` is no member), in its order."""
    members = re.findall(r"^        - (\w+)$", (ROOT / "docs" / "api.md").read_text(), re.M)
    assert members == [name for name in rbi.__all__ if name not in ("AuditReport", "__version__")]
