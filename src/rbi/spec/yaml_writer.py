"""Writing specs as YAML text: every string is data, whatever it holds.

A name read from another file (a robot file's link, a mesh's object) can hold newlines, YAML
syntax, control characters, bidirectional overrides or Unicode's line separators (which YAML
takes as line breaks). Specs are therefore written only through PyYAML's dumper, never by
pasting strings: a string holding any character that is not plainly visible is written
double-quoted with escapes (``"arm\\npivot: [0, 0, 9]"``, ``"\\u202Eevil"``), so the text a
terminal shows is the text the file holds and reading it back gives the name exactly.
Comments (which the dumper cannot write) go through :func:`comment`, which escapes the same
characters and every line break, so nothing in a comment can end it.
"""

from __future__ import annotations

import unicodedata
from typing import Any

import yaml

from rbi.spec.yaml_reader import plain_is_text
from rbi.text import is_hidden, visible


def comment(*lines: str) -> str:
    """Each of ``lines`` as one YAML comment line (``# ...``), made :func:`visible`: a line
    break or any other character in it cannot end the comment."""
    return "".join(f"# {visible(line)}".rstrip() + "\n" for line in lines)


def dump(data: Any, *, width: int = 100) -> str:
    """``data`` (plain dicts, lists, numbers, strings) as block-style YAML with flow-style
    leaf lists, keys in the order given. Strings holding a hidden character are written
    double-quoted with escapes; other non-ASCII text (``名前``, ``ü``) stays as it is."""

    class Dumper(yaml.SafeDumper):
        pass

    def represent_str(dumper, value: str):
        # double quotes for hidden characters (escaped); single quotes where rbi's reader would
        # read the plain text as something else (1e3 is a number to it, though not to YAML 1.1)
        style = '"' if any(is_hidden(c) for c in value) else None if plain_is_text(value) else "'"
        return dumper.represent_scalar("tag:yaml.org,2002:str", value, style=style)

    Dumper.add_representer(str, represent_str)
    # PyYAML's double-quoted writer escapes controls, NEL, U+2028/9 and the BOM itself, but
    # with allow_unicode it keeps format characters (U+202E) raw: turn it off for such text.
    allow_unicode = not any(unicodedata.category(c) in ("Cf", "Co", "Cn") for s in _strings(data) for c in s)
    return yaml.dump(
        data,
        Dumper=Dumper,
        sort_keys=False,
        allow_unicode=allow_unicode,
        default_flow_style=None,
        width=width,
    )


def _strings(data: Any):
    if isinstance(data, str):
        yield data
    elif isinstance(data, (dict, list, tuple)):
        for item in data.items() if isinstance(data, dict) else data:  # a mapping's (key, value) pairs
            yield from _strings(item)
