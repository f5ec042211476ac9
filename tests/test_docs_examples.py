"""Every command shown with its output in README.md and docs/*.md is run, and what it prints
is compared with what the page shows.

How to write an example (the whole convention: tools/docs_examples.py and docs/README.md):

    ```console
    $ rbi inertia bodies/top.yaml --format json
    {"name": "spinning-top", ...}
    $ echo $?
    0
    ```

* A fenced block whose first line starts with ``$ `` is an example; each ``$ `` line is run
  (``rbi ...``, ``echo $?``, ``python SCRIPT``), the lines after it are its stdout and stderr
  as a terminal shows them at ``COLUMNS=80``.
* A page's commands run in order in one temporary folder with ``bodies/``, ``docs/``,
  ``tools/`` linked in; a block starting ``# file: NAME`` (or ``<!-- file: NAME -->``) is
  written there first, so a page can show the file its command reads.
* ``...`` alone on a line: any lines; inside a line: any text (wall times and the like).
* After changing output, rewrite every example from real runs:
  ``.venv/bin/python tools/regen_docs.py`` (then read the diff).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))

import docs_examples  # noqa: E402

PAGES_WITH_EXAMPLES = [
    p for p in docs_examples.PAGES if any(b.commands for b in docs_examples.blocks(p.read_text()))
]


@pytest.mark.parametrize("page", PAGES_WITH_EXAMPLES, ids=lambda p: p.name)
def test_every_example_prints_what_the_page_shows(page, tmp_path):
    wrong = []
    for _, command, printed in docs_examples.run_page(page, tmp_path):
        assert not any("internal error" in line or "Traceback" in line for line in printed), (
            command.line,
            printed,
        )
        if not docs_examples.output_matches(command.shown, printed):
            wrong.append(f"$ {command.line}\n{docs_examples.difference(command.shown, printed)}")
    assert not wrong, (
        f"{page.name}: output differs (tools/regen_docs.py rewrites it from real runs):\n\n"
        + "\n\n".join(wrong)
    )


def test_the_pages_show_commands_with_their_output():
    shown = {p.name for p in PAGES_WITH_EXAMPLES}
    for name in (
        "README.md",
        "inertia.md",
        "principal.md",
        "parts.md",
        "momentum.md",
        "simulate.md",
        "sweep.md",
        "export.md",
        "import.md",
        "check.md",
        "schema.md",
        "dynamics.md",
        "spec.md",
    ):
        assert name in shown, name


def test_wildcards_match_as_documented():
    match = docs_examples.output_matches
    assert match(["a", "...", "d"], ["a", "b", "c", "d"]) and match(["a", "...", "b"], ["a", "b"])
    assert not match(["a", "b"], ["a", "b", "c"])
    assert match([" wall time   s   ..."], [" wall time   s   0.00181"])
    assert match([" time ... s"], [" time 12.5 s"]) and not match([" time ... s"], [" time 12.5 s extra"])
    assert match(["x  "], ["x", ""])  # trailing spaces and empty lines do not count


def test_rewriting_keeps_the_wildcards_and_takes_the_rest_from_the_run():
    rewrite = docs_examples.rewritten_output
    assert rewrite(["a", "...", "tilt 31.7", "wall ... s"], ["a", "b", "tilt 31.8", "wall 0.4 s"]) == [
        "a",
        "...",
        "tilt 31.8",
        "wall ... s",
    ]
    assert rewrite(["old"], ["new", "lines"]) == ["new", "lines"]
    assert rewrite([], ["first", "output"]) == ["first", "output"]


# --- the number-by-number comparison (tools/docs_examples.numbers_match) -------------------


def test_zero_on_the_page_matches_rounding_noise_of_its_vector():
    match = docs_examples.line_matches
    shown = '<inertial pos="0.0 0.0 0.0" mass="0.8118070195620548" />'
    assert match(
        shown, '<inertial pos="1.750521290499351e-20 3.143046496895522e-20 0.0" mass="0.8118070195620548" />'
    )
    row = " x                  2.641641          0   -0.06153846"
    assert match(row, " x                  2.641641   1.2e-17   -0.06153846")
    # an all-zero vector takes its scale from the output it is in
    assert docs_examples.output_matches(
        ['pos="0.0 0.0 0.0"', 'mass="0.81"'], ['pos="1e-20 3e-20 0.0"', 'mass="0.81"']
    )


def test_full_precision_numbers_match_to_the_last_ulps():
    shown = "<pose>0.21973855418517876 0.0003930733668116799 0.009249805029743147 0.0</pose>"
    printed = "<pose>0.21973855418517876 0.00039307336681167996 0.009249805029743149 0.0</pose>"
    assert docs_examples.line_matches(shown, printed)
    assert docs_examples.numbers_match("0.52", "0.5200000000000001", 1.0)


def test_a_real_drift_still_fails():
    match = docs_examples.line_matches
    assert not match(
        "<pose>0.21973855418517876 0.0003930</pose>", "<pose>0.21973855418517876 0.0003931</pose>"
    )
    assert not match("mass 0.0003930733668116799", "mass 0.0003930733668126799")  # 2.5e-12 relative
    assert not match(" x   2.641641   0   -0.06153846", " x   2.641642   0   -0.06153846")  # last shown digit
    assert not match(" x   2.641641   0   -0.06153846", " x   2.641641   1.2e-05   -0.06153846")  # not noise
    assert not match("mass 0.52 kg", "mass 0.52 g")  # the text around numbers is compared as text
    assert not match("wall ... s, 3 steps", "wall 12 s, 4 steps")
    assert match("wall ... s, 3 steps", "wall 12 s, 3 steps")
    assert not docs_examples.output_matches(["pos 0 0 0"], ["pos 1e-20 0 0"])  # no scale: exact


def test_the_examples_run_with_the_readme_first_command_install_set_only():
    """rbi 4's README installed `.` alone, and its --plot example and `rbi validate bodies/*.yaml`
    (flange.yaml, a STEP part) needed more; the test ran them with every test extra installed."""
    installed = docs_examples.readme_install_set()
    assert {"matplotlib", "cadquery-ocp-novtk", "numpy", "typer"} <= installed
    assert not {"dask", "pyarrow", "xacro", "pytest", "mpmath"} & installed
    with docs_examples.only_the_readme_install():
        with pytest.raises(ImportError):
            import dask  # noqa: F401
    import dask  # noqa: F401, E402  (back after)


def test_every_install_hint_is_the_readme_s_form():
    """Hints disagreed: `pip install '.[plot]'` here, `pip install 'rbi[cad]'` there (rbi is
    installed from its source folder)."""
    texts = {p: p.read_text() for p in [*docs_examples.PAGES, *(ROOT / "src").rglob("*.py")]}
    assert [p.name for p, text in texts.items() if "install 'rbi[" in text] == []
    assert (
        "pip install '.[plot,cad]'" in (ROOT / "README.md").read_text().split("```")[3]
    )  # the first command
