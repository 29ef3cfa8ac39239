"""Edits of a file's bytes: replace ``data[start:end]`` by ``text``. Insertions, deletions and attribute replacements
are all that. Edits of one pass never overlap; they are applied from the end of the file backwards, so every offset
refers to the bytes as they were.

The builders here make the edits fixes need from located elements (:mod:`xodrcheck.fix.xmltext`), keeping the
file's own layout: a removed element takes its line with it when it stood alone on it, an inserted child is indented
as its siblings are, a new attribute is quoted as the element's others.
"""

from __future__ import annotations

import bisect
import itertools
from collections.abc import Iterable
from dataclasses import dataclass

from xodrcheck.findings import XodrError
from xodrcheck.fix.xmltext import Element, XmlText, encode_value

__all__ = [
    "Edit",
    "LineMap",
    "OverlapError",
    "apply",
    "insert_child",
    "overlaps",
    "remove_attribute",
    "remove_element",
    "set_attribute",
]


class OverlapError(XodrError, ValueError):
    """Two edits of one pass touch the same bytes."""


@dataclass(frozen=True, slots=True)
class Edit:
    """Replace the bytes ``[start, end)`` by ``text`` (``start == end``: insert; empty ``text``: delete)."""

    start: int
    end: int
    text: bytes = b""


def overlaps(a: Edit, b: Edit) -> bool:
    """Whether two edits touch the same bytes (two insertions at one offset count: their order would be a guess)."""
    if a.start == b.start:
        return True
    first, second = (a, b) if a.start < b.start else (b, a)
    return first.end > second.start


def apply(data: bytes, edits: Iterable[Edit]) -> bytes:
    """``data`` with every edit made; raises :class:`OverlapError` when two of them overlap. (Joined in one pass over
    the offsets of ``data``: the same as making them from the end of the file backwards.)"""
    ordered = sorted(edits, key=lambda e: (e.start, e.end))
    for a, b in itertools.pairwise(ordered):
        if overlaps(a, b):
            raise OverlapError(f"edits at bytes {a.start}-{a.end} and {b.start}-{b.end} overlap")
    parts: list[bytes] = []
    at = 0
    for edit in ordered:
        parts += (data[at : edit.start], edit.text)
        at = edit.end
    parts.append(data[at:])
    return b"".join(parts)


class LineMap:
    """Maps a line of the edited file to the line it came from, so that findings before and after can be compared:
    the line holding what follows an edit maps to the old line of the edit's end, a line the edit wrote to its
    first line."""

    def __init__(self, old: XmlText, edits: Iterable[Edit]) -> None:
        data = old.data
        self._spans: list[tuple[int, int, int, int]] = []  # new first line, new last line, old first line, old span
        delta = 0
        for edit in sorted(edits, key=lambda e: e.start):
            first = old.line_of(edit.start)
            removed = _breaks(data[edit.start : edit.end])
            added = _breaks(edit.text)
            new_first = first + delta
            self._spans.append((new_first, new_first + added, first, removed))
            delta += added - removed
        self._starts = [span[0] for span in self._spans]
        self._delta = delta

    def old_line(self, line: int | None) -> int | None:
        if line is None or not self._spans:
            return line
        k = bisect.bisect_right(self._starts, line) - 1
        if k < 0:
            return line
        _new_first, new_last, old_first, removed = self._spans[k]
        if line == new_last:  # the line holding what follows the edit
            return old_first + removed
        if line < new_last:  # a line the edit wrote: the edit's own
            return old_first
        shift = new_last - (old_first + removed)  # new minus old, just past this edit
        return line - shift


def _breaks(text: bytes) -> int:
    return text.count(b"\n")


# ------------------------------------------------------------------------------------------------------ builders
def _own_lines(text: XmlText, start: int, end: int) -> tuple[int, int] | None:
    """``[start, end)`` widened to whole lines when nothing but whitespace shares its first and last line."""
    data = text.data
    head = text.line_start(start)
    if data[head:start].strip():
        return None
    stop = end
    while stop < len(data) and data[stop : stop + 1] in (b" ", b"\t"):
        stop += 1
    if stop < len(data) and data[stop : stop + 1] not in (b"\n", b"\r"):
        return None
    if data[stop : stop + 2] == b"\r\n":
        stop += 2
    elif stop < len(data):
        stop += 1
    return head, stop


def remove_element(text: XmlText, element: Element) -> Edit:
    """Delete ``element``; with its line when it stood alone on it."""
    span = _own_lines(text, element.start, element.end)
    start, end = span if span is not None else (element.start, element.end)
    return Edit(start, end)


def set_attribute(text: XmlText, element: Element, name: str, value: str) -> Edit:
    """Give ``element`` the attribute ``name="value"``: its value replaced where it is given, else added after the
    last attribute, quoted as that one is."""
    attribute = element.attributes.get(name)
    if attribute is not None:
        return Edit(attribute.start, attribute.end, encode_value(value, text.encoding, attribute.quote))
    quotes = [a.quote for a in element.attributes.values()]
    quote = quotes[-1] if quotes else b'"'
    raw = b" " + name.encode("ascii") + b"=" + quote + encode_value(value, text.encoding, quote) + quote
    return Edit(element.attributes_end, element.attributes_end, raw)


def remove_attribute(text: XmlText, element: Element, name: str) -> Edit | None:
    """Delete attribute ``name`` of ``element`` with the whitespace before it; ``None`` when it has none."""
    attribute = element.attributes.get(name)
    if attribute is None:
        return None
    start = attribute.name_start
    while start > element.start and text.data[start - 1 : start] in (b" ", b"\t", b"\n", b"\r"):
        start -= 1
    return Edit(start, attribute.end + 1)


def child_indent(text: XmlText, parent: Element) -> bytes | None:
    """How ``parent``'s children are indented: as its first child on a line of its own, else one step further than
    the parent as its own parent indents it (``None``: the file is not laid out in lines there)."""
    for child in parent.children:
        indent = text.indent_of(child)
        if indent is not None:
            return indent
    mine = text.indent_of(parent)
    if mine is None:
        return None
    up = parent.parent
    outer = text.indent_of(up) if up is not None else None
    step = mine[len(outer) :] if outer is not None and mine.startswith(outer) and len(mine) > len(outer) else b"  "
    return mine + step


def insert_child(text: XmlText, parent: Element, markup: bytes, first: bool = False) -> Edit:
    """Insert ``markup`` (one element) as ``parent``'s last child (``first``: its first), on a line of its own
    indented as its siblings when the file is laid out in lines. A self-closing parent is opened and closed."""
    indent = child_indent(text, parent)
    nl = text.newline
    if parent.self_closing:  # <link/> -> <link>...</link>, from the end of its attributes on
        name = _qualified(text, parent)
        mine = text.indent_of(parent)
        inner = markup if indent is None or mine is None else nl + indent + markup + nl + mine
        return Edit(parent.attributes_end, parent.end, b">" + inner + b"</" + name + b">")
    siblings = parent.children
    if indent is None:
        at = siblings[0].start if first and siblings else parent.head_end if first else parent.inner_end
        return Edit(at, at, markup)
    if first or not siblings:
        anchor = siblings[0] if siblings else None
        if anchor is not None and text.indent_of(anchor) is not None:
            at = text.line_start(anchor.start)
            return Edit(at, at, indent + markup + nl)
        return Edit(parent.head_end, parent.head_end, nl + indent + markup)
    last = siblings[-1]
    return Edit(last.end, last.end, nl + indent + markup)


def _qualified(text: XmlText, element: Element) -> bytes:
    """The element's name as written in its start tag (with any prefix)."""
    data = text.data
    stop = element.start + 1
    while stop < element.head_end and data[stop : stop + 1] not in (b" ", b"\t", b"\n", b"\r", b"/", b">"):
        stop += 1
    return data[element.start + 1 : stop]
