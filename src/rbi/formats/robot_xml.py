"""Hardened XML reading for robot description files: a small element tree that remembers where
each element starts and ends in the file, so that a fixed copy can edit the original text at
those spans and keep every other byte.

What is refused, as :class:`InputError` (one line naming the file): files over
:data:`MAX_FILE_BYTES`; entity declarations and external references (a robot file has no use
for them and they are the door to entity-expansion and file-disclosure attacks); nesting deeper
than :data:`MAX_DEPTH`; text in an encoding other than UTF-8, UTF-16, ASCII, ISO-8859-1 or
Windows-1252 (named in the message, with the fix: save it as UTF-8); text that does not decode in
the encoding it declares.

What is accepted because files in the wild have it and pybullet, Pinocchio and MuJoCo load them:
a byte-order mark, blank lines or spaces before ``<?xml``, and NULs or blank lines after the
last element.

The document is handed to expat in chunks of :data:`PARSE_CHUNK_BYTES` (expat re-scans an
unfinished token on every feed, so a 63 MiB attribute fed 16 KiB at a time takes minutes; fed in
large chunks, a second).
"""

from __future__ import annotations

import codecs
import re
from collections.abc import Iterator
from dataclasses import dataclass, field

from rbi.errors import InputError
from rbi.files.safe import InputFileRefused, read_input_file
from rbi.memory import collector_paused
from rbi.text import visible

MAX_FILE_BYTES = 64 * 1024 * 1024
"""Largest robot file read (64 MiB): far above any real description, whose meshes live in
other files."""

MAX_DEPTH = 500
"""Deepest element nesting read; an MJCF chain of 500 bodies is already far beyond any robot."""

TOKEN_BLOCK_BYTES = 1024 * 1024
"""A file with a block of this many bytes holding no space, angle bracket or quote is refused:
it holds one name, number or text run at least this long, which no robot needs and which
expat reads in time that grows with the square of its length (60 MiB: over a minute)."""

PARSE_CHUNK_BYTES = 64 * 1024 * 1024
"""Bytes handed to expat per call: the whole of any file rbi reads, in one feed."""

ENCODINGS = {
    "utf-8": "utf-8",
    "utf8": "utf-8",
    "utf-16": "utf-16",
    "utf16": "utf-16",
    "us-ascii": "ascii",
    "ascii": "ascii",
    "iso-8859-1": "latin-1",
    "iso8859-1": "latin-1",
    "latin-1": "latin-1",
    "latin1": "latin-1",
    "windows-1252": "cp1252",
    "cp1252": "cp1252",
}
"""Declared encodings read (lower case) and Python's codec for each."""

_DECLARATION = re.compile(rb"^<\?xml[^>]*?encoding\s*=\s*([\"'])([^\"']*)\1", re.S)
_BOMS = ((codecs.BOM_UTF8, "utf-8"), (codecs.BOM_UTF16_LE, "utf-16-le"), (codecs.BOM_UTF16_BE, "utf-16-be"))


_NO_CHILDREN: list = []  # the children of every element that has none (never appended to)


class XmlElement:
    """One element: ``tag`` without namespace, ``pairs`` its attributes as written (name, value,
    name, value, ...; ``attrib`` as a dict, :meth:`get` one), ``text`` the character data directly inside it (stripped), ``children`` in order, and its span ``start:end`` in
    :attr:`XmlDocument.text` (UTF-8 bytes) from ``<`` to the closing ``>``; ``line`` is 1-based.
    ``end`` and ``text`` are worked out when first asked for (a robot file has a million elements
    and most are never asked). An element holds no link to its parent, so a tree has no reference
    cycle and is freed as soon as it is dropped (a cycle per element left a 100,000-link file's
    tree to the cycle collector: seconds of CPU when a process drops it or exits)."""

    __slots__ = (
        "tag",
        "pairs",
        "line",
        "start",
        "children",
        "source",
        "_pieces",
        "_close",
        "_bytes",
    )

    def __init__(self, tag: str, attributes: list[str], line: int, start: int, text: bytes = b""):
        self.tag, self.line, self.start = tag, line, start
        self.pairs = attributes  # name, value, name, value, ... as written (half a dict's memory)
        self.children: list[XmlElement] = _NO_CHILDREN  # replaced by a list at the first child
        self.source: str | None = None
        self._pieces: list[str] | None = None  # character data directly inside, as expat gave it
        self._close = -1  # byte index of the end tag (or of the empty element's one tag)
        self._bytes = text  # the document text the indices are in

    @property
    def text(self) -> str:
        return "".join(self._pieces).strip() if self._pieces else ""

    @property
    def end(self) -> int:
        """Index just past the element's last ``>`` in the document text."""
        opening_end = _tag_end(self._bytes, self.start)
        if self._bytes[opening_end - 2 : opening_end] == b"/>":
            return opening_end  # <tag .../>: its one tag is the whole element
        return _tag_end(self._bytes, self._close)

    @property
    def attrib(self) -> dict[str, str]:
        """The attributes as written, name → value (a new dict each time)."""
        pairs = self.pairs
        return dict(zip(pairs[::2], pairs[1::2]))

    def get(self, key: str, default: str | None = None) -> str | None:
        pairs = self.pairs
        if key not in pairs:  # (a scan in C; index's ValueError costs more where an attribute is absent)
            return default
        at = pairs.index(key)
        if at % 2 == 0:
            return pairs[at + 1]
        return self.attrib.get(key, default)  # the name was first found as a value

    def child(self, tag: str) -> XmlElement | None:
        for each in self.children:
            if each.tag == tag:
                return each
        return None

    def all(self, tag: str) -> list[XmlElement]:
        return [each for each in self.children if each.tag == tag]

    def iter(self, tag: str | None = None) -> Iterator[XmlElement]:
        """This element and every element below it, document order."""
        stack = [self]
        while stack:
            element = stack.pop()
            if tag is None or element.tag == tag:
                yield element
            stack.extend(reversed(element.children))

    def __repr__(self) -> str:
        return f"XmlElement({self.tag!r}, line {self.line})"


@dataclass
class XmlDocument:
    """A parsed file: ``root``; ``text`` the document as UTF-8 bytes (the spans index it);
    ``prefix``/``suffix`` the original bytes before and after it (BOM, blank lines, NULs);
    ``encoding`` the Python codec of the original file."""

    path: str
    root: XmlElement | None
    """The root element (None until parsed: :func:`decoded`)."""
    text: bytes
    prefix: bytes
    suffix: bytes
    encoding: str
    includes: list[str] = field(default_factory=list)
    """Other files the robot reads (xacro and MJCF includes, MJCF mesh assets), resolved."""

    def original_bytes(self, text: bytes) -> bytes:
        """``text`` (UTF-8, this document's text edited) in the file's own encoding, with the
        original bytes before and after it."""
        body = text if self.encoding == "utf-8" else text.decode("utf-8").encode(self.encoding)
        return self.prefix + body + self.suffix


def read_xml(path: str, data: bytes | None = None) -> XmlDocument:
    """Read and parse ``path`` (or the bytes ``data`` named by it); InputError for anything
    refused or malformed."""
    document = decoded(path, data)
    document.root = parse(path, document.text)
    return document


def decoded(path: str, data: bytes | None = None) -> XmlDocument:
    """The document of ``path`` (or of the bytes ``data`` named by it) as UTF-8 text, not yet
    parsed (``root`` None): InputError for a file too large, an encoding not read, text that
    does not decode, or a token too long to parse."""
    if data is None:
        try:
            data = read_input_file(path, MAX_FILE_BYTES, "robot file")
        except InputFileRefused as exc:
            raise InputError(f"{path}: {exc}") from None
    prefix, body, suffix, encoding = _split(path, data)
    utf8 = body  # UTF-8 as it is, or decoded from UTF-16 already (_split)
    if encoding == "utf-8":
        try:
            utf8.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise InputError(
                f"{path}: not valid UTF-8 at byte {len(prefix) + exc.start} (the file declares UTF-8 "
                "or no encoding); save it as UTF-8"
            ) from None
    elif encoding not in ("utf-16-le", "utf-16-be"):
        utf8 = _as_utf8(path, body, encoding, "the encoding it declares")
    _refuse_huge_tokens(path, utf8)
    return XmlDocument(path, None, utf8, prefix, suffix, encoding)


def _split(path: str, data: bytes) -> tuple[bytes, bytes, bytes, str]:
    """(prefix, document, suffix, codec): the BOM and blank space before the document, and the
    blank space and NULs after it, set aside; the codec from the BOM or the declaration."""
    data_prefix, decoded_from = b"", None
    for bom, codec in _BOMS:
        if data.startswith(bom):
            data_prefix, data = bom, data[len(bom) :]
            if codec != "utf-8":
                data, decoded_from = _as_utf8(path, data, codec, "its byte-order mark says so"), codec
            break
    stripped = data.lstrip(b" \t\r\n")
    end = len(stripped.rstrip(b" \t\r\n\x00"))
    lead, body, suffix = data[: len(data) - len(stripped)], stripped[:end], stripped[end:]
    if decoded_from is not None:  # the blank space around it in the file's own encoding
        lead, suffix = lead.decode().encode(decoded_from), suffix.decode().encode(decoded_from)
        return data_prefix + lead, body, suffix, decoded_from
    prefix = data_prefix + lead
    if not body:
        raise InputError(f"{path}: not well-formed XML (line 1, column 0): the file is empty")
    match = _DECLARATION.match(body[:512])
    codec = "utf-8"
    if match is not None:
        declared = match.group(2).decode("ascii", "replace").strip()
        codec = ENCODINGS.get(declared.lower())
        if codec is None:
            shown = visible(declared)[:40]
            raise InputError(
                f"{path}: encoding {shown!r}: not an encoding rbi reads robot files in "
                "(UTF-8, UTF-16, ASCII, ISO-8859-1, Windows-1252); save the file as UTF-8"
            )
        if codec == "utf-16":
            raise InputError(f"{path}: declares UTF-16 but has no byte-order mark; save it as UTF-8")
    return prefix, body, suffix, codec


def _as_utf8(path: str, data: bytes, codec: str, because: str) -> bytes:
    """``data`` decoded as ``codec`` and written as UTF-8; InputError, saying ``because`` (why
    that codec), when it does not decode."""
    try:
        return data.decode(codec).encode("utf-8")
    except UnicodeError:
        raise InputError(
            f"{path}: the text does not decode as {codec} ({because}); save it as UTF-8"
        ) from None


def _refuse_huge_tokens(path: str, text: bytes) -> None:
    """InputError when a :data:`TOKEN_BLOCK_BYTES` block of ``text`` holds no delimiter (linear
    time: each block is searched for a few bytes; every run of twice the block is caught)."""
    for start in range(0, len(text), TOKEN_BLOCK_BYTES):
        block = text[start : start + TOKEN_BLOCK_BYTES]
        if len(block) == TOKEN_BLOCK_BYTES and not any(
            d in block for d in (b" ", b"<", b">", b'"', b"'", b"\n")
        ):
            raise InputError(
                f"{path}: refused: more than {TOKEN_BLOCK_BYTES // 2**20} MiB without a space, tag or quote "
                f"(from byte {start:,}): no name, number or text in a robot file is that long"
            )


def parse(path: str, text: bytes) -> XmlElement:
    """The element tree of ``text`` (UTF-8); InputError for malformed or refused XML."""
    # not at top level: `rbi validate` would load xml.parsers.expat too
    from xml.parsers import expat

    parser = expat.ParserCreate(encoding="utf-8")
    parser.buffer_text = True
    parser.ordered_attributes = True
    parser.buffer_size = 1 << 20
    builder = _TreeBuilder(path, text, parser)
    try:
        with collector_paused():  # a million new elements, none of them garbage
            for offset in range(0, max(len(text), 1), PARSE_CHUNK_BYTES):
                parser.Parse(text[offset : offset + PARSE_CHUNK_BYTES], False)
            parser.Parse(b"", True)
    except expat.ExpatError as exc:
        raise InputError(
            f"{path}: not well-formed XML (line {exc.lineno}, column {exc.offset}): "
            f"{expat.ErrorString(exc.code)}"
        ) from None
    except RecursionError:
        raise InputError(f"{path}: elements nested too deeply") from None
    if builder.root is None:
        raise InputError(f"{path}: empty XML document")
    return builder.root


class _TreeBuilder:
    """expat's handlers, set on ``parser``: build the :class:`XmlElement` tree of one document,
    refusing what :func:`read_xml` refuses (deep nesting, entities, DTD attribute defaults)."""

    def __init__(self, path: str, text: bytes, parser):
        self.path, self.text, self.parser = path, text, parser
        self.stack: list[XmlElement] = []
        self.root: XmlElement | None = None
        parser.AttlistDeclHandler = self.attribute_default
        parser.StartElementHandler = self._start_handler()
        parser.EndElementHandler = self._end_handler()
        parser.CharacterDataHandler = self.characters
        parser.EntityDeclHandler = self.refuse
        parser.UnparsedEntityDeclHandler = self.refuse
        parser.ExternalEntityRefHandler = self.refuse

    def _start_handler(self):
        """expat's start handler: one new :class:`XmlElement` per element, appended to its
        parent's children (a closure over the stack, parser and text: a file has a million
        elements, and each attribute lookup on ``self`` is paid a million times)."""
        stack, parser, text, builder = self.stack, self.parser, self.text, self

        def start(tag: str, attributes: list[str]) -> None:
            if len(stack) >= MAX_DEPTH:
                raise InputError(
                    f"{builder.path}: elements nested deeper than {MAX_DEPTH} levels; refused as not a "
                    "plausible robot description"
                )
            if "}" in tag:
                tag = tag.rsplit("}", 1)[-1]
            element = XmlElement(tag, attributes, parser.CurrentLineNumber, parser.CurrentByteIndex, text)
            if stack:
                parent = stack[-1]
                if parent.children is _NO_CHILDREN:
                    parent.children = [element]
                else:
                    parent.children.append(element)
            elif builder.root is None:
                builder.root = element
            stack.append(element)

        return start

    def _end_handler(self):
        """expat's end handler: the element's end tag's byte index recorded (its span's end)."""
        pop, parser = self.stack.pop, self.parser

        def end(_tag: str) -> None:
            pop()._close = parser.CurrentByteIndex

        return end

    def characters(self, data: str) -> None:
        if self.stack:
            element = self.stack[-1]
            if element._pieces is None:
                if data.isspace():
                    return  # blank before any text: stripped from the text in any case
                element._pieces = [data]
            else:
                element._pieces.append(data)

    def refuse(self, *_args) -> None:
        raise InputError(
            f"{self.path}: refused: the file declares XML entities or external references; rbi does "
            "not expand them"
        )

    def attribute_default(self, element_name, attribute, _type, default, _required) -> None:
        if default is not None:
            raise InputError(
                f"{self.path}: refused: the document type declaration gives <{element_name}> a default "
                f"{attribute}={default[:40]!r}; pybullet and urdfdom do not apply it, so the file means "
                "different things to different readers: write the attribute where it is used"
            )


_TAG_PIECE = re.compile(rb'"[^"]*"|\'[^\']*\'|>')


def _tag_end(text: bytes, at: int) -> int:
    """Index just past the ``>`` that ends the tag starting at ``at`` (an end tag, or an empty
    element's only tag), skipping ``>`` inside quoted attribute values."""
    for match in _TAG_PIECE.finditer(text, at):
        if match.group() == b">":
            return match.end()
    return len(text)
