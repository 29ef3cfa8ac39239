"""The elements of an XML file as byte spans: where each start tag, attribute value and end tag lies.

Fixes edit a file's bytes, never a re-serialised tree, so that everything they do not touch (comments, ``<userData>``,
unknown elements, attribute order and quoting, whitespace, number spellings) stays byte for byte. This module finds
what they edit: a small scanner of XML text that skips comments, CDATA sections, processing instructions and a
DOCTYPE, reads quoted attribute values that may hold ``>``, and builds a tree of :class:`Element` spans, each with
the line libxml2 gives it (that of its start tag's ``>``; lines end at ``\\n``, as libxml2 counts them: a lone ``\\r``
ends none).

It reads ASCII-compatible encodings (UTF-8, the ISO-8859 family, ...); anything else, or text that is not
well-formed, raises :class:`ScanError` (nothing is fixed in such a file).
"""

from __future__ import annotations

import bisect
import codecs
import re
from dataclasses import dataclass, field

from xodrcheck.findings import XodrError

__all__ = ["Attribute", "Element", "ScanError", "XmlText", "decode_value", "encode_value", "scan"]


class ScanError(XodrError, ValueError):
    """The bytes are not XML text this scanner can edit safely; the message says why."""


@dataclass(frozen=True, slots=True)
class Attribute:
    """One attribute: its decoded ``value``, and the byte span of the value between its quotes."""

    name: str
    value: str
    start: int  # first byte of the value (after the opening quote)
    end: int  # the closing quote
    name_start: int  # first byte of the name
    quote: bytes


@dataclass(eq=False, slots=True)
class Element:
    """One element: ``tag`` is its local name (any prefix dropped). ``start`` is its ``<``; ``head_end`` the byte after
    its start tag's ``>``; ``inner_end`` the ``<`` of its end tag (``head_end`` when self-closing); ``end`` the byte
    after the element. ``line`` is the line of the start tag's ``>``, as libxml2 (and so the reader) numbers an
    element. :attr:`attributes` are read from the start tag when first asked for."""

    tag: str
    start: int
    head_end: int
    inner_end: int
    end: int
    parent: Element | None
    text: XmlText
    #: The attributes' text in the start tag (from the whitespace after the name to the last closing quote).
    attributes_start: int
    attributes_end: int
    children: list[Element] = field(default_factory=list)
    line: int = 0
    _attributes: dict[str, Attribute] | None = None

    @property
    def attributes(self) -> dict[str, Attribute]:
        if self._attributes is None:
            self._attributes = _attributes(self.text, self.attributes_start, self.attributes_end)
        return self._attributes

    @property
    def self_closing(self) -> bool:
        return self.inner_end == self.head_end and self.end == self.head_end

    def get(self, name: str) -> str | None:
        attribute = self.attributes.get(name)
        return None if attribute is None else attribute.value

    def find(self, tag: str) -> Element | None:
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[Element]:
        return [c for c in self.children if c.tag == tag]


_NAME = rb"[^\s=/>!?<\"']+"
#: One token of markup: a comment, CDATA section, processing instruction or DOCTYPE (skipped), an end tag, a start
#: tag (name, attributes, ``/``), or a ``<`` that starts none of these (not well-formed).
_TOKEN = re.compile(
    rb"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>"
    rb"|<!DOCTYPE(?:[^\[>\"']|\"[^\"]*\"|'[^']*'|\[(?:[^\]\"']|\"[^\"]*\"|'[^']*')*\])*>"
    rb"|</(" + _NAME + rb")\s*>"
    rb"|<(" + _NAME + rb")((?:\s+" + _NAME + rb"\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)\s*(/?)>"
    rb"|<",
    re.S,
)
_ATTRIBUTE = re.compile(rb"(" + _NAME + rb")\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")
_LINE_BREAK = re.compile(rb"\n")
_DECLARED = re.compile(rb"^(?:\xef\xbb\xbf)?<\?xml[^>]*?encoding\s*=\s*[\"']([A-Za-z0-9._-]+)[\"']")
_ENTITY = re.compile(r"&(#x[0-9A-Fa-f]+|#[0-9]+|lt|gt|amp|quot|apos);")
_NAMED = {"lt": "<", "gt": ">", "amp": "&", "quot": '"', "apos": "'"}


def _encoding(data: bytes) -> str:
    if data.startswith((b"\xff\xfe", b"\xfe\xff", b"\x00<", b"<\x00")):
        raise ScanError("the file is UTF-16 or UTF-32 encoded; only ASCII-compatible encodings are edited")
    found = _DECLARED.match(data)
    name = found.group(1).decode("ascii") if found else "utf-8"
    try:
        info = codecs.lookup(name)
    except LookupError:
        raise ScanError(f"unknown encoding {name!r} declared") from None
    if "\x3c".encode(info.name, "ignore") != b"<" or info.name.startswith(("utf-16", "utf-32")):
        raise ScanError(f"the encoding {name} is not ASCII-compatible; it is not edited")
    return info.name


def decode_value(raw: bytes, encoding: str) -> str:
    """An attribute value as a parser reads it: decoded, character and predefined entity references replaced."""
    text = raw.decode(encoding, "replace")
    if "&" not in text:
        return text

    def one(m: re.Match[str]) -> str:
        ref = m.group(1)
        if ref.startswith("#x"):
            return chr(int(ref[2:], 16))
        if ref.startswith("#"):
            return chr(int(ref[1:]))
        return _NAMED[ref]

    try:
        return _ENTITY.sub(one, text)
    except (ValueError, OverflowError):
        return text


def encode_value(value: str, encoding: str, quote: bytes = b'"') -> bytes:
    """``value`` written inside ``quote`` in the file's encoding (``&``, ``<`` and the quote escaped)."""
    text = value.replace("&", "&amp;").replace("<", "&lt;")
    text = text.replace('"', "&quot;") if quote == b'"' else text.replace("'", "&apos;")
    return text.encode(encoding, "xmlcharrefreplace")


class XmlText:
    """A file's bytes with its elements located: :attr:`root`, every element by start line (:meth:`at_line`), the
    line of any offset (:meth:`line_of`), the newline the file uses (:attr:`newline`)."""

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.encoding = _encoding(data)
        self._breaks = [m.end() for m in _LINE_BREAK.finditer(data)]
        self.newline = b"\r\n" if b"\r\n" in data[:65536] else b"\n"
        self.root, self.elements = _build(self)
        self._by_line: dict[int, list[Element]] | None = None

    def line_of(self, offset: int) -> int:
        """The 1-based line of the byte at ``offset``."""
        return bisect.bisect_right(self._breaks, offset) + 1

    def line_start(self, offset: int) -> int:
        """Offset of the first byte of the line holding ``offset``."""
        k = bisect.bisect_right(self._breaks, offset)
        return self._breaks[k - 1] if k else 0

    def at_line(self, line: int, tag: str | None = None) -> list[Element]:
        """The elements whose start tag begins on ``line`` (of one tag, if given), in file order."""
        if self._by_line is None:
            self._by_line = {}
            for e in self.elements:
                self._by_line.setdefault(e.line, []).append(e)
        found = self._by_line.get(line, [])
        return [e for e in found if tag is None or e.tag == tag]

    def indent_of(self, element: Element) -> bytes | None:
        """The whitespace before ``element`` on its line, when nothing else precedes it there."""
        head = self.data[self.line_start(element.start) : element.start]
        return head if not head.strip() else None


def _local(name: bytes) -> str:
    return name.rpartition(b":")[2].decode("ascii", "replace")


def _attributes(text: XmlText, start: int, end: int) -> dict[str, Attribute]:
    out: dict[str, Attribute] = {}
    for m in _ATTRIBUTE.finditer(text.data, start, end):
        group = 2 if m.group(2) is not None else 3
        name = m.group(1).decode("ascii", "replace")
        if name in out:
            raise ScanError(f"attribute {name} repeated at line {text.line_of(m.start())}")
        out[name] = Attribute(
            name,
            decode_value(m.group(group), text.encoding),
            m.start(group),
            m.end(group),
            m.start(),
            text.data[m.start(group) - 1 : m.start(group)],
        )
    return out


def _build(text: XmlText) -> tuple[Element, list[Element]]:
    elements: list[Element] = []
    stack: list[Element] = []
    root: Element | None = None
    for m in _TOKEN.finditer(text.data):
        end_name, name = m.group(1), m.group(2)
        if end_name is not None:
            if not stack or _local(end_name) != stack[-1].tag:
                raise ScanError(f"unexpected end tag at line {text.line_of(m.start())}")
            element = stack.pop()
            element.inner_end, element.end = m.start(), m.end()
        elif name is not None:
            if root is not None and not stack:
                raise ScanError(f"a second root element at line {text.line_of(m.start())}")
            parent = stack[-1] if stack else None
            element = Element(_local(name), m.start(), m.end(), m.end(), m.end(), parent, text, m.start(3), m.end(3))
            elements.append(element)
            if parent is None:
                root = element
            else:
                parent.children.append(element)
            if not m.group(4):
                stack.append(element)
        elif m.end() - m.start() == 1:
            raise ScanError(f"unreadable markup at line {text.line_of(m.start())}")
    if stack or root is None:
        raise ScanError("the document ends before its elements do" if stack else "no element in the file")
    _number_lines(text, elements)
    return root, elements


def _number_lines(text: XmlText, elements: list[Element]) -> None:
    breaks, k = text._breaks, 0
    for element in elements:  # in file order: one walk over the line breaks
        while k < len(breaks) and breaks[k] < element.head_end:
            k += 1
        element.line = k + 1


def scan(data: bytes) -> XmlText:
    """Locate every element of ``data`` (raises :class:`ScanError` when it cannot be done safely)."""
    return XmlText(data)
