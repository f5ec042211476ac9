"""Every option a command's --help lists is named on that command's docs page, so a reader of
the page learns every option there is (the page may say more than --help, never less)."""

from __future__ import annotations

import os
import re

import pytest

from rbi.cli.app import COMMANDS
from tests.conftest import ROOT, run_rbi_inprocess

PAGES = {
    "validate": ("schema.md", "import.md"),
    "bench": ("performance.md",),
    "import": ("import.md", "step.md"),
}
"""Commands without a page of their own name: the pages that describe them."""


def _options(command: str) -> set[str]:
    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "200"  # one line an option: its name is not split
    try:
        text = run_rbi_inprocess(command, "--help").stdout
    finally:
        if saved is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = saved
    options = text.split("Options:", 1)[1]
    declared = re.findall(r"^\s+(?:-\w, )?(--[a-z][a-z-]*)(?: / (--[a-z][a-z-]*))?", options, re.M)
    return {name for pair in declared for name in pair if name} - {"--help"}


@pytest.mark.parametrize("command", list(COMMANDS))
def test_every_option_of_the_help_is_on_the_commands_page(command):
    # docs/simulate.md never named --gravity, --max-steps or --yes; principal.md and momentum.md
    # not --units; sweep.md not --gravity; import.md not --package-path, --density, --material
    pages = PAGES.get(command, (f"{command}.md",))
    text = "".join((ROOT / "docs" / page).read_text(encoding="utf-8") for page in pages)
    missing = sorted(option for option in _options(command) if option not in text)
    assert not missing, f"docs/{pages[0]} does not name {missing} (rbi {command} --help lists them)"
