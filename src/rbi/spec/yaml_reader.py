"""A bounded YAML reader for spec files: libyaml's event stream built into plain Python values.

Why not ``yaml.load``: PyYAML's composer and constructor recurse once per nesting level (30 000
nested ``[`` crash the C composer, 1 000 raise RecursionError), they hand aliased values out
shared but never count how far they expand (a "billion laughs" document of a few hundred bytes
stands for 10¹⁰ values that validation or an error message would then walk), and they follow
YAML 1.1, where ``010`` is 8 and ``1:30`` is 90. This reader walks the parser's events with an
explicit stack and so:

- refuses nesting deeper than :data:`MAX_DEPTH` levels the moment it is reached;
- counts every value an alias stands for and refuses a document whose aliases add more than
  :data:`ALIAS_BUDGET` values (or as many as the file writes out, when that is more), before
  copying anything; each alias then gets its own copy, so the result is a tree (changing one
  part's list never changes another's);
- reads plain scalars by the YAML 1.2 core schema restricted to decimal numbers: ``null``/``~``,
  ``true``/``false``, decimal integers and floats (``1e-3`` included), ``.inf``/``.nan``; a
  number written in a form YAML 1.1 reads differently (leading zero, ``0x``/``0o``/``0b``,
  base 60 ``1:30``, ``1_000``) is refused with its field rather than guessed;
- supports merge keys (``<<: *defaults`` or ``<<: [*a, *b]``; keys written in the mapping win,
  then the first merged mapping) while refusing a key written twice in one mapping;
- refuses complex (collection) keys, tags other than the standard scalar/collection ones, and
  more than one document.

Every problem raises :class:`YamlProblem` with the line, column and field path; the caller adds
the file name. Only the offending scalar (cut to a few characters) is ever quoted.
"""

from __future__ import annotations

import re
from typing import Any

import yaml

MAX_DEPTH = 100
"""Deepest nesting of lists and mappings accepted (a spec uses about five)."""

ALIAS_BUDGET = 1_000_000
"""Values aliases may add to a document beyond those written out (more if the file itself
writes out more values than this)."""

MAX_INTEGER_DIGITS = 4300
"""Longest integer accepted (Python's own limit for converting text to int)."""

_YAML = "tag:yaml.org,2002:"
_DECIMAL = re.compile(r"[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?")
_FLOAT_CHARS = frozenset(".eE")
_WORDS: dict[str, Any] = {"": None, "~": None} | {
    word: value
    for words, value in (
        ("null Null NULL", None),
        ("true True TRUE", True),
        ("false False FALSE", False),
        (".inf .Inf .INF +.inf +.Inf +.INF", float("inf")),
        ("-.inf -.Inf -.INF", float("-inf")),
        (".nan .NaN .NAN", float("nan")),
    )
    for word in words.split()
}
_NUMBER_START = frozenset("-+.0123456789")
# YAML 1.1's own patterns (yaml.org/type/int.html and float.html; the float's digits after
# the point written [0-9_]* as every YAML 1.1 library reads them): a plain scalar matching one
# is a number in YAML 1.1, anything else is text there.
_YAML11_INT = re.compile(
    r"[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+"
    r"|[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+"
)
_YAML11_FLOAT = re.compile(
    r"[-+]?(?:[0-9][0-9_]*)?\.[0-9_]*(?:[eE][-+][0-9]+)?|[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*"
)
_SEPARATOR = "digit separator '_' (YAML 1.1 only); write the number without underscores"
_LEADING_ZERO = "leading zero (YAML 1.1 reads it as octal); write the decimal number without it"
_OR_QUOTE = ", or quote it if it is text"
# Plain scalars that are not YAML 1.2 decimals and that YAML 1.1 (or YAML 1.2's core schema)
# reads as a number: refused (what each is, then _OR_QUOTE), rbi would read them differently
# from some other reader.
_YAML11_NUMBERS = [
    (re.compile(r"[-+]?0x[0-9a-fA-F_]+"), "hexadecimal; write the number in decimal"),
    (re.compile(r"[-+]?0o[0-7]+"), "octal; write the number in decimal"),
    (re.compile(r"[-+]?0b[01_]+"), "binary; write the number in decimal"),
    (
        re.compile(r"[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+(?:\.[0-9_]*)?"),
        "base 60 (YAML 1.1 reads 1:30 as 90); write the number in decimal",
    ),
    (re.compile(r"[-+]?0[0-7_]+"), _LEADING_ZERO),
    (_YAML11_INT, _SEPARATOR),  # what is left: 1_000, 1__0
    (_YAML11_FLOAT, _SEPARATOR),
]


def yaml11_reads_as_number(value: str) -> bool:
    """Whether YAML 1.1 (PyYAML and most YAML libraries) reads the plain scalar ``value`` as
    an int or float (``010``, ``0x1F``, ``1_000``, ``.5``, ``1:30``); ``08``, ``1e3``, ``0o7``
    are text there."""
    return bool(_YAML11_INT.fullmatch(value) or _YAML11_FLOAT.fullmatch(value))


_SCALAR_TAGS = {_YAML + "str", _YAML + "int", _YAML + "float", _YAML + "bool", _YAML + "null", "!"}
_COLLECTION_TAGS = {_YAML + "seq", _YAML + "map", "!"}
_MERGE = object()


class YamlProblem(Exception):
    """A document rbi will not read: ``where`` is the field path (``parts[2].mass``, or empty),
    ``line``/``column`` 1-based."""

    def __init__(self, problem: str, line: int, column: int, where: tuple = ()):
        super().__init__(problem)
        self.problem, self.line, self.column, self.where = problem, line, column, where


def _parser(text: str):
    cparser = getattr(getattr(yaml, "cyaml", None), "CParser", None)
    if cparser is not None:
        return cparser(text)
    return yaml.loader.BaseLoader(text)  # the pure-Python parser: iterative as well


def _short(text: str) -> str:
    """A scalar from the document quoted for a message, cut to a few characters."""
    return repr(text if len(text) <= 24 else text[:21] + "...")


def _show_tag(tag: str) -> str:
    """A tag as written (``!!set``), cut to a few characters."""
    shown = "!!" + tag[len(_YAML) :] if tag.startswith(_YAML) else tag
    return shown if len(shown) <= 40 else shown[:37] + "..."


class _Frame:
    """One open list or mapping."""

    __slots__ = ("value", "is_map", "key", "anchor", "start_total", "height", "merges", "mark")

    def __init__(self, value, is_map, anchor, start_total, mark):
        self.value = value
        self.is_map = is_map
        self.anchor = anchor
        self.start_total = start_total
        self.mark = mark
        self.key = _NO_KEY
        self.height = 1
        self.merges = None


_NO_KEY = object()


def read_document(text: str) -> Any:
    """The single YAML document in ``text`` as dicts, lists, str, int, float, bool and None.

    Raises :class:`YamlProblem` for anything this module refuses and ``yaml.YAMLError`` (with a
    mark) for a syntax error found by the parser. Scalars (most of a document) are read inline
    here; collections, aliases and documents by :class:`_Reading`."""
    try:
        return _read_events(_parser(text).get_event)
    except yaml.MarkedYAMLError as exc:
        # libyaml as PyYAML 6.0.4's wheels bundle it has a nesting limit of its own (1000) that
        # its scanner can reach while looking ahead, before this reader sees the 101st level.
        if "maximum nesting depth" not in (exc.problem or "") or exc.problem_mark is None:
            raise
        mark = exc.problem_mark
        raise YamlProblem(
            f"nested more than {MAX_DEPTH} levels deep", mark.line + 1, mark.column + 1
        ) from None


def _read_events(get_event) -> Any:
    """The document built from the parser's events (see :func:`read_document`)."""
    ScalarEvent, AliasEvent, DocumentStartEvent = yaml.ScalarEvent, yaml.AliasEvent, yaml.DocumentStartEvent
    starts = (yaml.MappingStartEvent, yaml.SequenceStartEvent)
    ends = (yaml.MappingEndEvent, yaml.SequenceEndEvent)
    words, number_start = _WORDS, _NUMBER_START
    reading = _Reading()
    fail, anchors = reading.fail, reading.anchors
    top: _Frame | None = None  # the innermost open list or mapping
    total = 0  # values in the document so far, aliases expanded
    while True:
        event = get_event()
        kind = type(event)
        if kind is ScalarEvent:
            total += 1
            value = event.value
            if event.tag is None:
                if not event.style:  # plain: resolve by the core schema
                    if value in words:
                        value = words[value]
                    elif value[0] in number_start:
                        in_name = top is not None and top.is_map and top.key == "name"
                        value = _number(value, event.start_mark, fail, text_field=in_name)
                    elif value == "<<":
                        value = _MERGE
            elif event.tag != "!":
                value = _tagged_scalar(event, fail)
            if event.anchor is not None:
                anchors[event.anchor] = (value, 1, 0)
            if top is None:
                reading.result = "<<" if value is _MERGE else value
            elif value is _MERGE or top.key is _MERGE:
                _add(top, value, event.start_mark, fail)
            elif not top.is_map:  # the common cases inline: a list item, a new key, a value
                top.value.append(value)
            elif top.key is _NO_KEY:
                if value in top.value:
                    _add(top, value, event.start_mark, fail)
                top.key = value
            else:
                top.value[top.key] = value
                top.key = _NO_KEY
        elif kind in starts:
            total += 1
            top = reading.open(event, kind is starts[0], total)
        elif kind in ends:
            top = reading.close(event, total)
        elif kind is AliasEvent:
            total = reading.alias(event, total)
        elif kind is DocumentStartEvent:
            reading.document(event)
        elif kind is yaml.StreamEndEvent:
            return reading.result


class _Reading:
    """What :func:`read_document` keeps beside the innermost collection and the count of
    values: the open collections, the anchors (name → (value, values it stands for, height)),
    the values added through aliases, the documents seen and the result."""

    __slots__ = ("stack", "anchors", "through_aliases", "documents", "result")

    def __init__(self) -> None:
        self.stack: list[_Frame] = []
        self.anchors: dict[str, tuple[Any, int, int]] = {}
        self.through_aliases = 0
        self.documents = 0
        self.result: Any = None

    def fail(self, problem: str, mark, in_key: bool = False):
        raise YamlProblem(problem, mark.line + 1, mark.column + 1, _where(self.stack, in_key))

    def open(self, event, is_map: bool, total: int) -> _Frame:
        """A list or mapping starts (``total`` counts it): the new innermost collection."""
        stack = self.stack
        if event.tag is not None and event.tag not in _COLLECTION_TAGS:
            self.fail(
                f"tag {_show_tag(event.tag)} is not supported (only plain lists, mappings and scalars)",
                event.start_mark,
            )
        if len(stack) >= MAX_DEPTH:
            self.fail(f"nested more than {MAX_DEPTH} levels deep", event.start_mark)
        if stack and stack[-1].is_map and stack[-1].key is _NO_KEY:
            self.fail(_COMPLEX_KEY, event.start_mark, in_key=True)
        frame = _Frame({} if is_map else [], is_map, event.anchor, total - 1, event.start_mark)
        stack.append(frame)
        return frame

    def close(self, event, total: int) -> _Frame | None:
        """The innermost list or mapping ends: it goes into its parent (or is the result);
        the parent, now innermost, is returned."""
        frame = self.stack.pop()
        value = frame.value
        if frame.merges:
            _apply_merges(value, frame.merges)
        if frame.anchor is not None:
            self.anchors[frame.anchor] = (value, total - frame.start_total, frame.height)
        return self._put(value, frame.height, event.start_mark)

    def _put(self, value: Any, height: int, mark) -> _Frame | None:
        """``value`` (lists and mappings ``height`` levels deep) into the innermost open list or
        mapping, or the result when none is open; the innermost is returned."""
        if not self.stack:
            self.result = value
            return None
        parent = self.stack[-1]
        if height >= parent.height:
            parent.height = height + 1
        _add(parent, value, mark, self.fail)
        return parent

    def alias(self, event, total: int) -> int:
        """An alias: a fresh copy of its anchor's value goes in, counted against the budget;
        returns the new count of values."""
        found = self.anchors.get(event.anchor)
        if found is None:
            self.fail(
                f"alias *{_short(event.anchor)[1:-1]} names no anchor defined before it", event.start_mark
            )
        value, size, height = found
        total += size
        self.through_aliases += size
        budget = max(ALIAS_BUDGET, total - self.through_aliases)
        if self.through_aliases > budget:
            self.fail(f"aliases expand to more than {budget:,} values (an alias bomb?)", event.start_mark)
        if len(self.stack) + height > MAX_DEPTH:
            self.fail(f"nested more than {MAX_DEPTH} levels deep (through an alias)", event.start_mark)
        if height:
            value = _fresh_copy(value)  # a tree, not a graph: editing one place never edits another
        parent = self.stack[-1] if self.stack else None
        if parent is not None and parent.is_map and parent.key is _NO_KEY and isinstance(value, (dict, list)):
            self.fail(_COMPLEX_KEY, event.start_mark, in_key=True)
        self._put(value, height, event.start_mark)
        return total

    def document(self, event) -> None:
        self.documents += 1
        if self.documents > 1:
            self.fail("more than one YAML document in the file (a spec is one document)", event.start_mark)


_COMPLEX_KEY = "a key must be text or a number, not a list or mapping (complex keys are not supported)"


def _add(frame: _Frame, value: Any, mark, fail) -> None:
    """Put ``value`` into the open list or mapping ``frame`` (as a key or as a value)."""
    if not frame.is_map:
        frame.value.append("<<" if value is _MERGE else value)
    elif frame.key is _NO_KEY:
        if value is _MERGE:
            if frame.merges is not None:
                fail("'<<' given twice in one mapping (merge several with <<: [*a, *b])", mark, in_key=True)
        elif value in frame.value:
            fail(f"duplicate key {_short(str(value))}", mark, in_key=True)
        frame.key = value
    else:
        key, frame.key = frame.key, _NO_KEY
        if key is _MERGE:
            merged = value if isinstance(value, list) else [value]
            if not merged or not all(isinstance(m, dict) for m in merged):
                frame.key = _MERGE
                fail(
                    "'<<' (merge) needs a mapping or a list of mappings, usually aliases: <<: *defaults", mark
                )
            frame.merges = merged
        else:
            frame.value[key] = "<<" if value is _MERGE else value


def _fresh_copy(value: Any) -> Any:
    """``value`` with every list and mapping in it copied (at most :data:`MAX_DEPTH` deep)."""
    if isinstance(value, dict):
        return {key: _fresh_copy(item) for key, item in value.items()}
    if isinstance(value, list):
        return [_fresh_copy(item) for item in value]
    return value


def _apply_merges(mapping: dict, merges: list[dict]) -> None:
    """Keys of the merged mappings that ``mapping`` does not set itself; the first merged
    mapping wins over later ones."""
    for source in merges:
        for key, value in source.items():
            if key not in mapping:
                mapping[key] = value


def plain_is_text(value: str) -> bool:
    """Whether ``value`` written as a plain (unquoted) scalar reads back as this same text here:
    not a word (null, true, .inf, ...), nothing that starts like a number, not a merge key."""
    return bool(value) and value not in _WORDS and value[0] not in _NUMBER_START and value != "<<"


def _number(value: str, mark, fail, text_field: bool = False) -> Any:
    """A plain scalar starting like a number: int, float, or text when neither YAML 1.2 nor 1.1
    reads it as a number; refused when YAML 1.1 reads it as a number differently from 1.2.
    In a ``text_field`` (a name), what YAML 1.1 reads as text stays text (``08``, ``1e3``):
    a YAML 1.1 writer such as PyYAML leaves such a name unquoted."""
    if text_field and not yaml11_reads_as_number(value):
        return value
    if _DECIMAL.fullmatch(value):
        if not _FLOAT_CHARS.isdisjoint(value):
            return float(value)
        digits = value.lstrip("+-")
        if len(digits) > MAX_INTEGER_DIGITS:
            fail(f"integer of {len(digits)} digits is too long (at most {MAX_INTEGER_DIGITS})", mark)
        if len(digits) > 1 and digits[0] == "0":
            if _YAML11_INT.fullmatch(value):
                fail(f"{_short(value)} is not a decimal number: {_LEADING_ZERO}{_OR_QUOTE}", mark)
            fail(
                f"{_short(value)} is not a decimal number: leading zero (YAML 1.1 reads it as text, "
                f"YAML 1.2 as {int(value)}); write {int(value)}{_OR_QUOTE}",
                mark,
            )
        return int(value)
    for pattern, meaning in _YAML11_NUMBERS:
        if pattern.fullmatch(value):
            fail(f"{_short(value)} is not a decimal number: {meaning}{_OR_QUOTE}", mark)
    return value


def _tagged_scalar(event, fail) -> Any:
    """A scalar with an explicit standard tag (``!!str 010``, ``!!float 1``)."""
    tag, value = event.tag, event.value
    if tag not in _SCALAR_TAGS:
        fail(
            f"tag {_show_tag(tag)} is not supported (only plain lists, mappings and scalars)",
            event.start_mark,
        )
    if tag == _YAML + "str":
        return value
    resolved = (
        _WORDS[value] if value in _WORDS else _number(value, event.start_mark, fail) if value else value
    )
    expected = {"int": int, "float": (int, float), "bool": bool, "null": type(None)}[tag[len(_YAML) :]]
    if not isinstance(resolved, expected) or (isinstance(resolved, bool) and tag != _YAML + "bool"):
        fail(f"{_short(value)} is not a valid {tag[len(_YAML) :]}", event.start_mark)
    return float(resolved) if tag == _YAML + "float" else resolved


def _where(stack: list[_Frame], in_key: bool) -> tuple:
    """The field path of the value being read, from the open collections (a key being read
    ends the path at its mapping)."""
    path: list[Any] = []
    for frame in stack:
        if frame.is_map:
            if frame.key is _NO_KEY or frame.key is _MERGE:
                break
            path.append(frame.key if isinstance(frame.key, (str, int)) else str(frame.key))
        else:
            path.append(len(frame.value))
    return tuple(path)
