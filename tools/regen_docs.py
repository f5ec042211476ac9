"""Re-run every command example of README.md and docs/*.md and rewrite the output shown under
it from the real run (the convention: tools/docs_examples.py, docs/README.md).

    .venv/bin/python tools/regen_docs.py                 # every page
    .venv/bin/python tools/regen_docs.py docs/inertia.md # some pages
    .venv/bin/python tools/regen_docs.py --check         # change nothing; exit 1 if a page would change

Lines shown as ``...`` stay; a command whose output has ``...`` and changed is listed, so
that you can check the wildcards still sit where they should.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import docs_examples  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "pages", nargs="*", type=Path, help="pages to rewrite (default: README.md and docs/*.md)"
    )
    parser.add_argument("--check", action="store_true", help="only report pages that would change")
    args = parser.parse_args(argv)
    pages = [p.resolve() for p in args.pages] or docs_examples.PAGES
    changed_any = False
    for page in pages:
        with tempfile.TemporaryDirectory() as folder:
            text, changed = docs_examples.rewrite_page(page, Path(folder))
        if not changed:
            continue
        changed_any = True
        name = page.relative_to(docs_examples.ROOT)
        for line in changed:
            print(f"{name}: $ {line}")
        if not args.check:
            page.write_text(text)
    return 1 if (args.check and changed_any) else 0


if __name__ == "__main__":
    sys.exit(main())
