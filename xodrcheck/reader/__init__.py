"""Read any OpenDRIVE file into the typed model of :mod:`xodrcheck.model`, with what was found on the way.

``read(path_or_bytes)`` never raises for bad content: a file that is not well-formed, not OpenDRIVE, or full of invalid
values gives findings (the reader rules of :mod:`xodrcheck.rules.xml`) and as much of the model as could be built.
Only input that cannot be opened at all (a missing file, a directory, more bytes than the configured limit) raises
:class:`~xodrcheck.findings.ReadError`.

Gzip-compressed files (``.xodrz``, the standard's compressed form) are decompressed first, within the same size limit.

The document is built by :mod:`.document` (the root), :mod:`.header`, :mod:`.roads` (with :mod:`.road_records`),
:mod:`.lanes` (with :mod:`.lane_records`), :mod:`.objects`, :mod:`.signals` and :mod:`.junctions`; :mod:`.elements`
tables every element for reports that point into the file, and :mod:`.context` holds what the builders share.
"""

from __future__ import annotations

import io
import os
import stat
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from xodrcheck.config import Tolerances
from xodrcheck.findings import Finding, ReadError, Severity
from xodrcheck.model import Document
from xodrcheck.reader.context import Context
from xodrcheck.reader.document import KNOWN_VERSIONS, build_document
from xodrcheck.reader.xmlsafe import parse
from xodrcheck.rules import xml as R

if TYPE_CHECKING:  # pragma: no cover
    from lxml import etree

__all__ = ["KNOWN_VERSIONS", "ReadResult", "parse", "parse_tree", "read", "read_keeping_tree"]

_GZIP_MAGIC = b"\x1f\x8b"
#: Reader findings after which the file counts as not read whole (see :meth:`ReadResult.not_whole`).
_NOT_WHOLE = frozenset({R.NOT_WELL_FORMED.code, R.DOCTYPE.code, R.WRONG_ROOT.code})


@dataclass(frozen=True)
class ReadResult:
    """The model (``None`` when nothing could be built), the reader's findings in the order found, and the path read."""

    document: Document | None
    findings: tuple[Finding, ...]
    path: str | None

    def not_whole(self) -> str | None:
        """Why the file could not be read whole (``None`` when it was): it is not well-formed XML (``X101``: nothing,
        or only what a recovering parser kept, was read), its root is not ``<OpenDRIVE>`` (``X201``), or entity
        references were left out (``X102`` at error level). The commands that turn a map into data (``info``,
        ``sample``, ``mesh``, ``metrics``, ``snapshot``, ``diff``, ``junctionart render``) refuse such a file rather
        than give data about part of it; ``check`` reports these findings like any other."""
        for f in self.findings:
            if f.code in _NOT_WHOLE and f.severity >= Severity.ERROR:
                return f"{f.code} {f.name}: {f.message}"
        if self.document is None:
            return "no OpenDRIVE document could be read"
        return None


def _size(n: int) -> str:
    return f"{n / 2**20:.1f} MiB" if n >= 2**20 else f"{n} bytes"


def _too_large(n: int, limit: int, path: str | None) -> ReadError:
    return ReadError(
        f"it is larger than the limit of {_size(limit)} (tolerance max_file_bytes); raise it to read it", path
    )


def _load(path: str, limit: int) -> bytes:
    try:
        info = os.stat(path)
    except FileNotFoundError:
        raise ReadError("no such file", path) from None
    except OSError as exc:
        raise ReadError(exc.strerror or str(exc), path) from None
    if stat.S_ISDIR(info.st_mode):
        raise ReadError("it is a directory, not a file", path)
    if info.st_size > limit:
        raise _too_large(info.st_size, limit, path)
    # A regular file is read at its size (asking for limit + 1 bytes makes Python allocate that much first: 512 MiB by
    # default, several ms a file); one byte more shows a file that grew since the stat. Anything else (a pipe) is read
    # up to the limit, which still holds.
    want = info.st_size + 1 if stat.S_ISREG(info.st_mode) else limit + 1
    try:
        with open(path, "rb") as stream:
            data = stream.read(want)
            if len(data) == want and want <= limit:  # grew since the stat: read on, within the limit
                data += stream.read(limit + 1 - want)
    except OSError as exc:
        raise ReadError(exc.strerror or str(exc), path) from None
    if len(data) > limit:
        raise _too_large(len(data), limit, path)
    return data


def _gunzip(data: bytes, limit: int, findings: list[Finding], path: str | None) -> bytes | None:
    try:
        import gzip  # here: only compressed files need it

        with gzip.GzipFile(fileobj=io.BytesIO(data)) as stream:
            out = stream.read(limit + 1)
    except (OSError, EOFError, zlib.error) as exc:
        findings.append(
            R.NOT_WELL_FORMED.finding(
                f"the file is gzip-compressed (.xodrz) but cannot be decompressed ({exc}); nothing could be read",
                line=None,
            )
        )
        return None
    if len(out) > limit:
        raise ReadError(f"decompressed, it is larger than the limit of {_size(limit)} (tolerance max_file_bytes)", path)
    return out


def read(source: str | os.PathLike[str] | bytes, *, max_bytes: int | None = None) -> ReadResult:
    """Read an OpenDRIVE file (a path, or the file's bytes).

    ``max_bytes`` defaults to :attr:`Tolerances.max_file_bytes`. Raises :class:`ReadError` only when the input cannot
    be opened or is over that limit.
    """
    return _read(source, max_bytes, keep_tree=False)[0]


def read_keeping_tree(
    source: str | os.PathLike[str] | bytes, *, max_bytes: int | None = None
) -> tuple[ReadResult, etree._ElementTree | None]:
    """:func:`read`, and the parse tree the model was built from when it is the tree schema validation reads
    (:func:`parse_tree`'s: well-formed, no namespace to strip), else ``None``. The checker
    parses a file once this way instead of twice (a big map's tree is many times the file's size)."""
    return _read(source, max_bytes, keep_tree=True)


def parse_tree(data: bytes) -> etree._ElementTree | None:
    """The file's XML tree as schema validation reads it: parsed safely (:func:`parse`), without recovering from
    errors, namespaces and tags as written; ``None`` when it is not well-formed."""
    from lxml import etree

    root, _ = parse(data, recover=False, strip_namespaces=False)
    return None if root is None else etree.ElementTree(root)


def _read(
    source: str | os.PathLike[str] | bytes, max_bytes: int | None, *, keep_tree: bool
) -> tuple[ReadResult, etree._ElementTree | None]:
    """:func:`read_keeping_tree`; without ``keep_tree`` no tree is returned, and the parse leaves out the whitespace
    between elements, which only schema validation's tree needs (the model is the same:
    tests/xodrcheck/test_reader.py)."""
    limit = Tolerances().max_file_bytes if max_bytes is None else max_bytes
    if isinstance(source, (bytes, bytearray, memoryview)):
        data = bytes(source)
        path = None
        if len(data) > limit:
            raise _too_large(len(data), limit, None)
    else:
        path = str(Path(source))
        data = _load(path, limit)
    findings: list[Finding] = []
    if data.startswith(_GZIP_MAGIC):
        unpacked = _gunzip(data, limit, findings, path)
        if unpacked is None:
            return ReadResult(None, tuple(findings), path), None
        data = unpacked
    root, parse_findings = parse(data, keep_blank_text=keep_tree)
    del data  # the bytes (a decompressed copy, say) are not needed past the parse
    findings.extend(parse_findings)
    document = None
    tree = None
    if root is not None:
        from lxml import etree

        # the tree of schema validation: parsed without recovering (no X101), its tags as written (no default
        # namespace on the root, which the reader strips from every tag)
        shared = None not in root.nsmap and not any(f.code == R.NOT_WELL_FORMED.code for f in parse_findings)
        document = build_document(Context(findings), root, path)
        if keep_tree and shared and document is not None:
            tree = etree.ElementTree(root)
    return ReadResult(document, tuple(findings), path), tree
