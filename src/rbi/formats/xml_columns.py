"""Columns of XML values: the elements of one *signature* (the same elements and attribute
names, their values at the same places) read field by field, each field one column of strings
checked and turned into numbers at once (:class:`Rows`), and a refusal worded for the first
wrong element in document order (:func:`in_order`). :mod:`rbi.formats.urdf` reads its links and
joints so.
"""

from __future__ import annotations

import re
from collections.abc import Callable

import numpy as np

from rbi.core.validity import SMALLEST_NORMAL
from rbi.errors import InputError
from rbi.formats.robot import Where
from rbi.formats.robot_xml import XmlElement


class Doubt(Exception):
    """The text is not plain (:func:`rbi.formats.urdf.plain_text`: its tree is read), or a
    column of values is not all plain decimals (read one value at a time)."""


_PLAIN = re.compile(rb"[0-9eE+\-. \n]*")
"""The characters of texts of plain decimals apart by spaces, one text a line: with them, a
token ``float`` reads is one :data:`rbi.formats.robot._NUMBER` matches (``float`` alone would
also take ``nan``, ``inf``, ``1_0`` and other digits than 0-9)."""

CHUNK = 1024
"""Elements read again together when a group of them is refused: a chunk with a wrong element
is read again element by element, in document order (about 0.3 s for 1,024 links)."""


def in_order(chunks: list, read: Callable[[Rows], None], state: list | None = None) -> None:
    """``read`` each group of each chunk, chunk by chunk; ``chunks``: (groups, a function giving
    the same elements as finer chunks, or None). A refusal in a chunk is worded for its first
    wrong element: its finer chunks are read in turn (``state`` restored first), down to chunks
    whose groups hold one element each, the first of which to be refused raises."""
    for groups, finer in chunks:
        saved = None if state is None or finer is None else state[:]
        try:
            for rows in groups:
                read(rows)
        except InputError:
            if finer is None:
                raise
            if state is not None:
                state[:] = saved
            in_order(finer(), read, state)
            raise


# --- columns of values --------------------------------------------------------------------------


class Values:
    """A document's attribute values, in document order: value k is ``codes[starts[k]:ends[k]]``."""

    def __init__(self, codes: np.ndarray, starts: np.ndarray, ends: np.ndarray):
        self.codes, self.starts, self.ends = codes, starts, ends

    def __len__(self) -> int:
        return len(self.starts)

    def one(self, k: int) -> bytes:
        return self.codes[self.starts[k] : self.ends[k]].tobytes()

    def texts(self, which: np.ndarray) -> list[bytes]:
        """The values of the indices ``which``."""
        found = self._rows(which)
        if found is None:
            return [b""] * len(which)
        return found.view(f"S{found.shape[1]}").reshape(-1).tolist()

    def distinct(self, which: np.ndarray) -> tuple[list[bytes], np.ndarray]:
        """The distinct values of the indices ``which`` (in order of first appearance) and where
        each index's value is among them."""
        found = self._rows(which)
        if found is None:
            return ([b""] if len(which) else []), np.zeros(len(which), dtype=int)
        if np.all(found == found[0]):  # one text throughout (a generated file's column)
            return [found[0].tobytes().rstrip(b"\0")], np.zeros(len(which), dtype=int)
        texts = found.view(f"S{found.shape[1]}").reshape(-1).tolist()
        places: dict[bytes, int] = {}
        inverse = np.array([places.setdefault(text, len(places)) for text in texts], dtype=int)
        return list(places), inverse

    def _rows(self, which: np.ndarray) -> np.ndarray | None:
        """The values of the indices ``which`` as rows of a (k, width) array of bytes, each
        padded with NULs (no value holds one: XML has none); None when all are empty."""
        starts, lengths = self.starts[which], self.ends[which] - self.starts[which]
        width = int(lengths.max()) if len(lengths) else 0
        if width == 0:
            return None
        first = int(starts.min())
        codes, starts = self.codes[first:], starts - first  # (a few values near the end: a short copy)
        if len(codes) < width + int(starts.max()):
            codes = np.concatenate([codes, np.zeros(width, dtype=np.uint8)])
        windows = np.lib.stride_tricks.as_strided(
            codes, shape=(len(codes) - width + 1, width), strides=(1, 1)
        )
        found = windows[starts]
        found[np.arange(width) >= lengths[:, None]] = 0
        return found


class Node:
    """One element of a signature: ``tag``, ``at`` (attribute name → place among the element's
    values) and its child elements."""

    __slots__ = ("tag", "at", "children")

    def __init__(self, tag: str, at: dict[str, int]):
        self.tag, self.at, self.children = tag, at, []

    @staticmethod
    def of(element, count: list[int]) -> Node:
        """The signature of an XML ``element``, its values counted from ``count[0]`` on (in
        document order: each element's attributes as written, then its children's)."""
        names = element.pairs[::2]
        node = Node(element.tag, {name: count[0] + k for k, name in enumerate(names)})
        count[0] += len(names)
        node.children = [Node.of(each, count) for each in element.children]
        return node

    child = XmlElement.child  # (the first child of that tag: the same walk over ``children``)


class Rows:
    """The elements of one signature (``top``): ``indices`` (each one's place among the links or
    joints), ``firsts`` (where each one's values start in ``values``), and :meth:`where` each
    row is in messages."""

    def __init__(self, top: Node, indices: list[int], firsts: np.ndarray, values: Values):
        self.top, self.indices, self.firsts, self.values = top, indices, firsts, values
        self.path, self.label = "", lambda k: None

    def __len__(self) -> int:
        return len(self.indices)

    def where(self, k: int) -> Where:
        """Where row ``k`` is, for messages (its label worked out only when shown)."""
        return Where(self.path, lambda: self.label(k))

    def column(self, place: int | None, default: bytes) -> list[bytes]:
        """The text at ``place`` of each element (``default`` where the attribute is not written)."""
        if place is None:
            return [default] * len(self)
        if len(self) == 1:  # (no arrays to set up for one)
            return [self.values.one(int(self.firsts[0]) + place)]
        return self.values.texts(self.firsts + place)

    def words(self, place: int | None) -> list[str]:
        """The text at ``place`` of each element as str (``""`` where the attribute is not written)."""
        texts = self.column(place, b"")
        joined = b"\n".join(texts)
        if joined.count(b"\n") == len(texts) - 1:  # (one decoding for all)
            return joined.decode().split("\n")
        return [text.decode() for text in texts]

    def distinct(self, place: int | None, default: bytes) -> tuple[list[bytes], np.ndarray]:
        """The distinct texts at ``place`` (``default`` where not written) and where each row's is."""
        if place is None:
            return [default], np.zeros(len(self), dtype=int)
        return self.values.distinct(self.firsts + place)

    def numbers(self, place: int | None, default: bytes | None, count, what: str) -> np.ndarray:
        """(k, 3 or ``count``) numbers at ``place`` (``default`` where not written; None: the
        attribute is needed), as :func:`rbi.formats.robot.numbers` reads each text (``count`` (1,
        3): one number stands for three); InputError, worded for the first wrong row."""
        if place is None and default is None:
            raise self.where(0).error(f"{what}: missing")
        if len(self) > 1:  # (one element, a file read again element by element: no arrays to set up)
            distinct, inverse = self.distinct(place, default)
            for each in (count,) if isinstance(count, int) else (3, 1):
                try:
                    found = plain_numbers(distinct, each)
                except Doubt:
                    continue
                return np.repeat(found, 3 // each if count == (1, 3) else 1, axis=1)[inverse]
        texts = self.column(place, default)
        return np.array([self._numbers(k, text.decode(), count, what) for k, text in enumerate(texts)])

    def _numbers(self, k: int, text: str, count, what: str) -> list[float]:
        found = self.where(k).numbers(text, what, count)
        return found * 3 if len(found) == 1 and not isinstance(count, int) else found


def plain_numbers(texts: list[bytes], count: int) -> np.ndarray:
    """(len(texts), count) floats of texts each of ``count`` plain finite decimals (what
    :func:`rbi.formats.robot.numbers` reads: signs, digits, a point and an exponent, apart by
    spaces), none subnormal; Doubt otherwise."""
    if not texts:
        return np.empty((0, count))
    joined = b"\n".join(texts)
    if _PLAIN.fullmatch(joined) is None:
        raise Doubt
    codes = np.frombuffer(joined, dtype=np.uint8)
    blank = (codes == 32) | (codes == 10)
    starts = ~blank
    starts[1:] &= blank[:-1]
    per_text = np.bincount(np.cumsum(codes == 10)[starts], minlength=len(texts))
    if len(per_text) != len(texts) or np.any(per_text != count):
        raise Doubt
    try:
        values = np.array(list(map(float, joined.split())), dtype=float).reshape(-1, count)
    except ValueError:  # "1-2", "1e": characters of numbers that make none
        raise Doubt from None
    if not np.all(np.isfinite(values)) or np.any((values != 0) & (np.abs(values) < SMALLEST_NORMAL)):
        raise Doubt
    return values
