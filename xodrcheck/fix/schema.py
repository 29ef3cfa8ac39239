"""Fixes of schema errors (``S001``) that have one plain cure: an empty element the schema forbids empty and lets be
left out, a ``<geoReference>`` written beside the header instead of in it, a header that declares an older version
than the features the file uses."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import insert_child, remove_element, set_attribute
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element

#: Elements that may be left out of their parent and say nothing when empty (absent, the standard's default holds:
#: no elevation is elevation 0, no lateral profile is a flat road, no objects, no signals).
OMITTABLE = frozenset({"elevationProfile", "lateralProfile", "objects", "signals"})

#: Versions a header may be raised to, oldest first (the schemas 1.1-1.7 validate fast; newer ones change more).
RAISES = ((1, 5), (1, 6), (1, 7))


def _empty(ws: Workspace, element: Element) -> bool:
    if element.children or element.attributes:
        return False
    return not ws.text.data[element.head_end : element.inner_end].strip()


@fixer("S001", "remove-empty-element", safe=True, bound="moves nothing")
def remove_empty_element(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes an empty ``<elevationProfile/>``, ``<lateralProfile/>``, ``<objects/>`` or ``<signals/>`` the schema
    rejects.

    The schema lets each be left out and requires content when present; left out, the standard's meaning is the same
    as the empty element's (no elevation records: elevation 0; no objects). Moves nothing.
    """
    by_line: dict[int, list[Finding]] = {}
    for finding in findings:
        if finding.line:
            by_line.setdefault(finding.line, []).append(finding)
    for line, group in by_line.items():
        empty = [e for e in ws.text.at_line(line) if e.tag in OMITTABLE and _empty(ws, e)]
        if len(empty) == 1:
            yield Repair(tuple(group), (remove_element(ws.text, empty[0]),), f"removed an empty <{empty[0].tag}>")


@fixer("S001", "move-georeference-into-header", safe=True, bound="moves nothing")
def move_georeference_into_header(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Moves a ``<geoReference>`` written beside the ``<header>`` into it, where the schema has it.

    Every version's schema places ``<geoReference>`` inside ``<header>``; a copy beside it is the same projection in
    the wrong place. Left alone when the header has one already. Moves nothing.
    """
    root = ws.text.root
    header = root.find("header")
    beside = root.findall("geoReference")
    for finding in findings:
        # lxml names the element's line; the XSD 1.1 validator (1.8, 1.9) its parent's, the root
        found = beside if finding.line == root.line else [e for e in beside if e.line == finding.line]
        if len(found) != 1 or header is None:
            continue
        if header.find("geoReference") is not None:
            yield Skip(finding, "the header has a <geoReference> already; which one holds is unclear")
            continue
        markup = ws.text.data[found[0].start : found[0].end]
        edits = (remove_element(ws.text, found[0]), insert_child(ws.text, header, markup, first=True))
        if edits[0].end > header.start and edits[0].start < header.end:
            continue
        yield Repair((finding,), edits, "moved the <geoReference> into the <header>")


@fixer("S001", "raise-header-version", safe=True, bound="moves nothing")
def raise_header_version(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Raises the header's ``revMinor`` to the oldest version (up to 1.7) whose schema accepts the features the file
    uses, where the declared version's schema rejects them (a 1.5 file with direct junctions, say).

    The file is checked against each newer schema; the version chosen removes the most schema errors and brings no
    new one (other rules judge the file again before the change is kept). Moves nothing.
    """
    from xodrcheck.check import check

    header = ws.text.root.find("header")
    version = ws.document.version
    if header is None or version is None or version[0] != 1 or header.get("revMinor") is None:
        return
    best: tuple[int, tuple[int, int], list[Finding]] | None = None
    before = {(f.line, f.message.split(":", 1)[-1]) for f in findings}
    for candidate in (v for v in RAISES if v > version):
        edit = set_attribute(ws.text, header, "revMinor", str(candidate[1]))
        data = ws.data[: edit.start] + edit.text + ws.data[edit.end :]
        left = [f for f in check(data, select=("S001",)).findings if f.code == "S001"]
        if any((f.line, f.message.split(":", 1)[-1]) not in before for f in left):
            continue
        if best is None or len(left) < best[0]:
            best = (len(left), candidate, left)
    if best is None or best[0] >= len(findings):
        return
    remaining = {f.line for f in best[2]}
    gone = tuple(f for f in findings if f.line not in remaining)
    edit = set_attribute(ws.text, header, "revMinor", str(best[1][1]))
    yield Repair(gone, (edit,), f"raised the header's version from 1.{version[1]} to 1.{best[1][1]}")
