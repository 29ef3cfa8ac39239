"""Bytes to an lxml element tree, safely, with findings instead of exceptions.

Before lxml sees the bytes:

* UTF-16/UTF-32 input is decoded and re-encoded as UTF-8 (the declaration's ``encoding`` rewritten to match);
* anything before the XML declaration is dropped, keeping line numbers: the declaration moves to the top and the
  dropped lines become empty lines;
* a DOCTYPE is replaced by empty lines, so the parser never sees an entity declaration: no expansion bomb, no external
  entity, whatever the libxml2 version does with them.

lxml then parses without loading DTDs, without resolving entities and without network access; ``huge_tree`` lets maps
of hundreds of MB through. A file that is not well-formed is parsed again in recover mode to keep what can be kept.
"""

from __future__ import annotations

import contextlib
import dataclasses
import re

from lxml import etree

from xodrcheck.findings import Finding, Severity
from xodrcheck.rules import xml as R

_UTF8_BOM = b"\xef\xbb\xbf"
#: Byte-order marks, longest first (a UTF-32-LE BOM starts with the UTF-16-LE one).
_BOMS = (
    (b"\x00\x00\xfe\xff", "utf-32-be"),
    (b"\xff\xfe\x00\x00", "utf-32-le"),
    (b"\xfe\xff", "utf-16-be"),
    (b"\xff\xfe", "utf-16-le"),
)
#: How ``<`` or ``<?`` looks in wide encodings without a byte-order mark.
_WIDE_STARTS = (
    (b"\x00\x00\x00<", "utf-32-be"),
    (b"<\x00\x00\x00", "utf-32-le"),
    (b"\x00<\x00", "utf-16-be"),
    (b"<\x00", "utf-16-le"),
)
_UTF8_NAMES = frozenset({"utf-8", "utf8", "us-ascii", "ascii"})

_ENCODING_ATTR = re.compile(rb"""(\bencoding\s*=\s*)(["'])([^"']*)\2""")
_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)
_ELEMENT_START = re.compile(rb"<[A-Za-z_:]")
#: Whitespace, comments and processing instructions (the XML declaration included) at the start of the prolog.
_PROLOG_SKIP = re.compile(rb"(?:\s+|<!--.*?-->|<\?.*?\?>)*", re.DOTALL)
_DOCTYPE_TOKEN = re.compile(rb""""[^"]*"|'[^']*'|<!--.*?-->|[\[\]>]|[^"'\[\]<>]+|<""", re.DOTALL)
_ENTITY_DECL = re.compile(rb"<!ENTITY\s+(%\s+)?([^\s\"'>]+)")
#: libxml2 advice that does not apply (huge_tree is already on).
_PARSER_HINT = re.compile(r",?\s*use XML_PARSE_HUGE option")
#: From this line on libxml2 keeps an element's line number through the text nodes beside it (XML_PARSE_BIG_LINES).
_BIG_LINES = 65535
#: Files this long have their lines counted before the parse to know whether the text nodes must be kept; shorter ones
#: (whose 65,535th line would mean fewer than 16 bytes a line) are parsed without them and parsed again with them if
#: the last element's line shows it was needed: counting costs about 2 % of a read.
COUNT_LINES_FROM = 1 << 20
_SHOW = 60  # characters of a raw value or of parser text shown in a message


def _parser(recover: bool, keep_blank_text: bool = True) -> etree.XMLParser:
    return etree.XMLParser(
        remove_blank_text=not keep_blank_text,
        resolve_entities=False,
        no_network=True,
        load_dtd=False,
        dtd_validation=False,
        huge_tree=True,
        recover=recover,
        remove_comments=True,
        remove_pis=True,
        collect_ids=False,
    )


def _line_at(data: bytes, pos: int) -> int:
    return data.count(b"\n", 0, pos) + 1


def _declaration(data: bytes) -> tuple[int, int]:
    """Start and end of the XML declaration (``<?xml`` followed by a blank), or ``(-1, -1)``."""
    pos = data.find(b"<?xml")
    while pos >= 0:
        if data[pos + 5 : pos + 6] in (b" ", b"\t", b"\r", b"\n"):
            end = data.find(b"?>", pos)
            return (pos, end + 2) if end >= 0 else (-1, -1)
        pos = data.find(b"<?xml", pos + 5)
    return -1, -1


def _decode_wide(data: bytes, findings: list[Finding]) -> bytes | None:
    """UTF-16/32 bytes as UTF-8 (declaration rewritten), the input itself when it is not wide, ``None`` when broken."""
    codec: str | None = None
    bom = b""
    for mark, name in _BOMS:
        if data.startswith(mark):
            codec, bom = name, mark
            break
    else:
        for prefix, name in _WIDE_STARTS:
            if data.startswith(prefix):
                codec, bom = name, b""
                break
    if codec is None:
        return data
    try:
        text = data[len(bom) :].decode(codec)
    except UnicodeDecodeError as exc:
        findings.append(
            R.NOT_WELL_FORMED.finding(
                f"the file starts like {codec.upper()} text but byte {exc.start + len(bom)} is not valid "
                f"{codec.upper()}; nothing could be read",
                line=1,
            )
        )
        return None
    how = "with a byte-order mark" if bom else "without a byte-order mark"
    findings.append(
        R.ENCODING.finding(
            f"the file is encoded in {codec.upper()} ({how}), not UTF-8; it was read, but tools that expect UTF-8 "
            "will misread or reject it",
            line=1,
        )
    )
    out = text.encode("utf-8")
    start, end = _declaration(out)
    if start >= 0:
        decl = _ENCODING_ATTR.sub(rb"\1\2UTF-8\2", out[start:end], count=1)
        out = out[:start] + decl + out[end:]
    return out


def _drop_prefix(data: bytes, findings: list[Finding]) -> bytes:
    """Move a misplaced XML declaration to the top, dropping what came before it (same line numbers)."""
    if data.startswith(b"<?xml"):
        return data
    start, end = _declaration(data)
    if start <= 0:
        return data
    prefix = data[:start]
    rest = _COMMENT.sub(b"", prefix)
    if _ELEMENT_START.search(rest):  # the declaration is inside the document: the parser will say so
        return data
    parts = []
    if len(rest) != len(prefix):
        parts.append("a comment")
    if b"<!--" in rest:
        parts.append(f"an unterminated comment ({rest.strip()[:_SHOW].decode('utf-8', 'replace')!r})")
    elif rest.strip():
        parts.append(f"text ({rest.strip()[:_SHOW].decode('utf-8', 'replace')!r})")
    if not parts:
        parts.append("blank space")
    line = _line_at(data, start)
    findings.append(
        R.CONTENT_BEFORE_DECLARATION.finding(
            f"{' and '.join(parts)} before the XML declaration at line {line}; CARLA and libOpenDRIVE accept this but "
            "SUMO, pyxodr and strict XML parsers reject the file (the declaration must come first); xodrcheck ignored "
            "what precedes it",
            line=1,
        )
    )
    return data[start:end] + b"\n" * prefix.count(b"\n") + data[end:]


def _check_declared_encoding(data: bytes, findings: list[Finding]) -> None:
    start, end = _declaration(data[:4096])
    if start != 0:
        return
    match = _ENCODING_ATTR.search(data, start, end)
    if match is None:
        return
    name = match.group(3).decode("ascii", "replace")
    if name.lower() not in _UTF8_NAMES and not data.isascii():
        findings.append(
            R.ENCODING.finding(
                f'the XML declaration says encoding="{name}" and the file uses characters outside ASCII; it was read '
                "as declared, but tools that expect UTF-8 will misread those characters",
                line=1,
            )
        )


def _drop_doctype(data: bytes, findings: list[Finding]) -> tuple[bytes | None, frozenset[str]]:
    """Replace a DOCTYPE in the prolog by as many newlines (``None`` when it never ends); also the names of the
    entities it declared."""
    prolog = _PROLOG_SKIP.match(data)  # always matches (possibly the empty string)
    pos = prolog.end() if prolog else 0
    if not data.startswith(b"<!DOCTYPE", pos):
        return data, frozenset()
    in_subset = False
    end = -1
    for token in _DOCTYPE_TOKEN.finditer(data, pos + 9):
        t = token.group()
        if t == b"[":
            in_subset = True
        elif t == b"]":
            in_subset = False
        elif t == b">" and not in_subset:
            end = token.end()
            break
    line = _line_at(data, pos)
    if end < 0:
        findings.append(
            R.NOT_WELL_FORMED.finding(f"the DOCTYPE at line {line} never ends; nothing could be read", line=line)
        )
        return None, frozenset()
    doctype = data[pos:end]
    entities = [m.group(2).decode("utf-8", "replace") for m in _ENTITY_DECL.finditer(doctype)]
    external = b"SYSTEM" in doctype or b"PUBLIC" in doctype
    if entities:
        shown = ", ".join(entities[:5]) + (f" and {len(entities) - 5} more" if len(entities) > 5 else "")
        message = (
            f"the DOCTYPE at line {line} declares {len(entities)} entit{'y' if len(entities) == 1 else 'ies'} "
            f"({shown}); xodrcheck never expands entities nor opens files or URLs named in a DOCTYPE, so every "
            "reference to them is left out. OpenDRIVE needs no DOCTYPE: remove it and write the values out"
        )
        severity = None
    else:
        what = "refers to an external DTD, which was not loaded" if external else "has no use in OpenDRIVE"
        message = f"the DOCTYPE at line {line} {what}; it was ignored"
        severity = Severity.WARNING
    findings.append(R.DOCTYPE.finding(message, severity=severity, line=line))
    return data[:pos] + b"\n" * doctype.count(b"\n") + data[end:], frozenset(entities)


def _syntax_message(error: etree._LogEntry | None, data: bytes) -> tuple[str, int | None]:
    if not data.strip():
        return ("the file is empty" if not data else "the file contains only blank space"), 1
    if b"\x00" in data[:1024]:
        return "the file contains binary data (NUL bytes), not XML text", 1
    if error is None:
        return "the parser gave no reason", None
    text = _PARSER_HINT.sub("", " ".join(error.message.split()))
    if len(text) > 2 * _SHOW:
        text = text[: 2 * _SHOW] + "..."
    return text, error.line or None


def _strip_namespaces(root: etree._Element) -> None:
    """OpenDRIVE 1.1/1.2 files may use a default namespace: read tags by their local names."""
    for el in root.iter():
        tag = el.tag
        if isinstance(tag, str) and tag[0] == "{":
            el.tag = tag.split("}", 1)[1]


def parse(
    data: bytes, *, recover: bool = True, strip_namespaces: bool = True, keep_blank_text: bool = True
) -> tuple[etree._Element | None, list[Finding]]:
    """Parse ``data`` safely. Returns the root element (``None`` when nothing could be built) and the findings.

    ``recover=False`` gives no root for a file that is not well-formed (instead of what a recovering parser keeps);
    ``strip_namespaces=False`` keeps a default namespace on the tags (schema validation of 1.1/1.2 needs it).
    ``keep_blank_text=False`` leaves out the whitespace between elements (the indentation: about half of a typical
    file's nodes, so the tree is made and freed faster) for a caller that reads only elements, attributes and text
    and lines: it is kept anyway in a file of 65,535 lines or more, whose elements' line numbers past that libxml2
    finds through the text nodes beside them.
    """
    findings: list[Finding] = []
    data = data.removeprefix(_UTF8_BOM)
    wide = _decode_wide(data, findings)
    if wide is None:
        return None, findings
    if wide is data:
        data = _drop_prefix(data, findings)
        _check_declared_encoding(data, findings)
    else:
        data = _drop_prefix(wide, findings)
    stripped, declared = _drop_doctype(data, findings)
    if stripped is None:
        return None, findings
    data = stripped

    if not keep_blank_text and len(data) >= COUNT_LINES_FROM:
        keep_blank_text = data.count(b"\n") >= _BIG_LINES
    # the parse adds to (and may reword) the findings so far: a copy, in case it is done again
    root, found = _parse(data, list(findings), recover, strip_namespaces, keep_blank_text, declared)
    if not keep_blank_text and root is not None and _past_big_lines(root):
        del root  # the tree without text nodes, freed before the parse that keeps them
        root, found = _parse(data, findings, recover, strip_namespaces, True, declared)
    return root, found


def _past_big_lines(root: etree._Element) -> bool:
    """Whether the last element of the tree (the one starting last) starts at line 65535 or later, or at a line
    libxml2 does not know: the elements past that line have their lines only through the text nodes beside them."""
    el = root
    while len(el):
        el = el[-1]
    line = el.sourceline
    return line is None or line >= _BIG_LINES


def _parse(
    data: bytes,
    findings: list[Finding],
    recover: bool,
    strip_namespaces: bool,
    keep_blank_text: bool,
    declared: frozenset[str],
) -> tuple[etree._Element | None, list[Finding]]:
    """:func:`parse` once the bytes are ready for lxml."""
    parser = _parser(recover=False, keep_blank_text=keep_blank_text)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError:
        errors = [e for e in parser.error_log if e.level >= etree.ErrorLevels.ERROR]
        references = [e for e in errors if _declared_entity(e, declared)]
        errors = [e for e in errors if not _declared_entity(e, declared)]
        root = None
        if (recover or not errors) and data.strip():
            with contextlib.suppress(etree.XMLSyntaxError):
                root = etree.fromstring(data, _parser(recover=True, keep_blank_text=keep_blank_text))
        if references:
            _count_references(findings, references)
        if not errors and root is not None:  # only references to the DOCTYPE's entities, which X102 reports
            return _finish(root, strip_namespaces), findings
        message, line = _syntax_message(errors[0] if errors else None, data)
        where = f" at line {line}" if line else ""
        then = (
            "xodrcheck read what a recovering parser could build, so parts of the map may be missing"
            if root is not None
            else "nothing could be read"
        )
        findings.append(R.NOT_WELL_FORMED.finding(f"not well-formed XML{where}: {message}; {then}", line=line))
    return _finish(root, strip_namespaces), findings


def _finish(root: etree._Element | None, strip_namespaces: bool) -> etree._Element | None:
    if root is not None and strip_namespaces:
        tag = root.tag
        if isinstance(tag, str) and tag[0] == "{":
            _strip_namespaces(root)
    return root


_UNDECLARED = re.compile(r"Entity '([^']+)' not defined")


def _declared_entity(error: etree._LogEntry, declared: frozenset[str]) -> bool:
    """Whether ``error`` is a reference to an entity the dropped DOCTYPE declared (X102 covers it, not X101)."""
    found = _UNDECLARED.search(error.message or "")
    return found is not None and found.group(1) in declared


def _count_references(findings: list[Finding], references: list[etree._LogEntry]) -> None:
    """Say in the X102 finding how many references were left out and where the first is."""
    for k, f in enumerate(findings):
        if f.code == R.DOCTYPE.code:
            n = len(references)
            first = f", the first at line {references[0].line}" if references[0].line else ""
            message = f.message.replace(
                "so every reference to them is left out",
                f"so the {n} reference{'' if n == 1 else 's'} to them{first}, {'was' if n == 1 else 'were'} left out",
            )
            findings[k] = dataclasses.replace(f, message=message)
            return
