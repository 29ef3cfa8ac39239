"""The document carries what the junction rules and the id rules read, compared with the file's XML (issue 27, one
reader: those rules read the document only).

For every corpus map and every rule fixture, each ``<junction>`` element with an id is compared, attribute by attribute
and child by child, with its :class:`~xodrcheck.model.Junction` as the rules see it: the type and virtual-junction
attributes as written, connections (ids as written, lane links of both layers in file order, whether ``overlapZone``
is given, a virtual connection's ends), cross paths, priorities, controllers, road sections, boundary segments, the
elevation grid, the reference line, and the first line of each child tag ``J012`` names. The id table
(:class:`~xodrcheck.model.IdTable`) is compared with a search of the tree by path.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from tests.conftest import corpus_files
from tests.xodrcheck.treetext import integer, local, number, numbers
from xodrcheck.model import RECORDED, ContactPoint, Document, Junction
from xodrcheck.reader import parse_tree, read
from xodrcheck.rules.junction_usage import first_lines
from xodrcheck.rules.shared.context import describe_junction, written_id

HERE = Path(__file__).parent
FIXTURES = sorted((HERE / "rules" / "fixtures").rglob("*.xodr")) + sorted((HERE / "opendrive19").glob("*.xodr"))
_ENDS = {"start": "start", "begin": "start", "end": "end"}


def spelt(value: Any, record: Any, name: str) -> str | None:
    """A document value as the file spelt it: an enumeration's value, the text of an invalid one (``None``: absent)."""
    if value is None:
        return record.xml.text(name)
    return getattr(value, "value", value)


def place(text: str | None) -> Any:
    """A boundary segment's ``sStart``/``sEnd``/``contactPoint`` as written: a road end's name or a number."""
    if text is None:
        return None
    return _ENDS.get(text.strip(), number(text))


def _children(el: etree._Element, tag: str) -> list[etree._Element]:
    return list(el.iterchildren(f"{{*}}{tag}"))


def _connection(el: etree._Element, record: Any, where: str) -> None:
    assert (el.get("id"), el.sourceline) == (written_id(record), record.line), where
    written = [el.get(k) for k in ("incomingRoad", "connectingRoad", "linkedRoad", "type", "contactPoint")]
    read_ = [record.incoming_road, record.connecting_road, record.linked_road]
    read_ += [spelt(record.type, record, "type"), spelt(record.contact_point, record, "contactPoint")]
    assert written == read_, where
    links = [ll for ll in _children(el, "laneLink") if integer(ll.get("from")) is not None]
    links = [ll for ll in links if integer(ll.get("to")) is not None]  # the reader reports the others, unread
    assert [
        (int(ll.get("from")), int(ll.get("to")), number(ll.get("overlapZone")), ll.get("overlapZone") is not None)
        for ll in links
    ] == [(ll.from_lane, ll.to_lane, ll.overlap_zone, ll.xml.given("overlapZone")) for ll in record.all_lane_links]
    assert [ll.sourceline for ll in links] == [ll.line for ll in record.all_lane_links], where
    ends = [(local(e), e.get("elementType"), e.sourceline) for e in el if local(e) in ("predecessor", "successor")]
    records = [(tag, getattr(record, tag)) for tag in ("predecessor", "successor") if getattr(record, tag)]
    expected = [(tag, spelt(e.element_type, e, "elementType"), e.line) for tag, e in records]
    assert ends == sorted(expected, key=lambda end: end[2]), where


def _parts(el: etree._Element, record: Junction, where: str) -> None:
    assert [
        (c.get("id"), c.get("crossingRoad"), c.get("roadAtStart"), c.get("roadAtEnd"))
        for c in _children(el, "crossPath")
    ] == [(c.id, c.crossing_road, c.road_at_start, c.road_at_end) for c in record.cross_paths], where
    for c, cp in zip(_children(el, "crossPath"), record.cross_paths, strict=True):
        for tag, link in (("startLaneLink", cp.start), ("endLaneLink", cp.end)):
            found = next(iter(_children(c, tag)), None)
            written = None if found is None else (number(found.get("s")), integer(found.get("from")))
            written = None if found is None else (*written, integer(found.get("to")), found.sourceline)
            assert written == (None if link is None else (link.s, link.from_lane, link.to_lane, link.line)), where
    assert [(p.get("high"), p.get("low"), p.sourceline) for p in _children(el, "priority")] == [
        (p.high, p.low, p.line) for p in record.priorities
    ], where
    assert [(c.get("id"), c.sourceline) for c in _children(el, "controller")] == [
        (c.id, c.line) for c in record.controllers
    ], where
    assert [
        (r.get("id"), r.get("roadId"), number(r.get("sStart")), number(r.get("sEnd")), r.sourceline)
        for r in _children(el, "roadSection")
    ] == [(r.id, r.road, r.s_start, r.s_end, r.line) for r in record.road_sections], where


def _segment(seg: etree._Element) -> tuple:
    kind = seg.get("type")
    if kind == "lane":
        return (kind, seg.get("roadId"), integer(seg.get("boundaryLane")), place(seg.get("sStart")))
    if kind == "joint":
        lanes = integer(seg.get("jointLaneStart")), integer(seg.get("jointLaneEnd"))
        return (kind, seg.get("roadId"), place(seg.get("contactPoint")), *lanes)
    return (kind, seg.get("roadId"))


def _record(seg: Any) -> tuple:
    def named(value: Any) -> Any:
        return value.value if isinstance(value, ContactPoint) else value

    if hasattr(seg, "s_start"):
        return ("lane", seg.road, seg.lane, named(seg.s_start))
    if hasattr(seg, "contact"):
        return ("joint", seg.road, named(seg.contact), seg.lane_start, seg.lane_end)
    return (seg.type, seg.road)


def _areas(el: etree._Element, record: Junction, where: str) -> None:
    boundaries = _children(el, "boundary")
    assert [b.sourceline for b in boundaries] == [b.line for b in record.boundaries], where
    for b, boundary in zip(boundaries, record.boundaries):
        written = sorted(((_segment(s), s.sourceline) for s in _children(b, "segment")), key=lambda x: x[1])
        read_ = [(_record(s), s.line) for s in (*boundary.segments, *boundary.unknown)]
        assert written == sorted(read_, key=lambda x: x[1]), where
    grids = _children(el, "elevationGrid")
    assert [(number(g.get("sStart")), number(g.get("gridSpacing")), g.sourceline) for g in grids] == [
        (g.s_start, g.spacing, g.line) for g in record.grids
    ], where
    for g, grid in zip(grids, record.grids):
        rows = [tuple(numbers(r.get(k)) for k in ("center", "left", "right")) for r in _children(g, "elevation")]
        assert rows == [(r.center, r.left, r.right) for r in grid.rows], where
    views = _children(el, "planView")
    assert [v.sourceline for v in views] == [v.line for v in record.plan_views], where
    for v, view in zip(views, record.plan_views):
        written = [
            (*(number(g.get(k)) for k in ("s", "x", "y", "hdg", "length")), tuple(local(c) for c in g), g.sourceline)
            for g in _children(v, "geometry")
        ]
        assert written == [(g.s, g.x, g.y, g.hdg, g.length, g.shapes, g.line) for g in view.geometries], where


def _junction(el: etree._Element, record: Junction) -> None:
    where = describe_junction(record)
    assert (el.get("id"), el.sourceline, el.get("mainRoad")) == (record.id, record.line, record.main_road)
    assert (el.get("type") or "default") == record.type.value, where
    for name, value in (("sStart", record.s_start), ("sEnd", record.s_end), ("orientation", record.orientation)):
        written = el.get(name)
        assert (written is None) == (not record.xml.given(name)), where
        if written is not None:
            assert (number(written) if isinstance(value, float) else written) == spelt(value, record, name), where
    connections = _children(el, "connection")
    assert len(connections) == len(record.connections), where
    for c, connection in zip(connections, record.connections):
        _connection(c, connection, where)
    _parts(el, record, where)
    _areas(el, record, where)
    tags = [local(c) for c in el if local(c)]
    assert tuple(tags) == record.xml.children, where
    first: dict[str, int] = {}
    for child in el:
        if local(child):
            first.setdefault(local(child), child.sourceline)
    wanted = ("connection", "crossPath", "boundary", "elevationGrid", "link", "predecessor", "successor")
    assert {t: first[t] for t in wanted if t in first} == first_lines(record), where


def _road_of(el: etree._Element) -> str | None:
    roads = [a for a in el.iterancestors() if local(a) == "road"]
    return roads[-1].get("id") if roads else None


def check_ids(document: Document, root: etree._Element) -> None:
    """The id table holds every element at each recorded path, with its id attributes, line and road."""
    assert document.ids is not None
    for path, names in RECORDED.items():
        written = [
            (tuple((k, el.get(k)) for k in names if el.get(k) is not None), el.sourceline, _road_of(el))
            for el in root.iterfind("/".join(f"{{*}}{step}" for step in path.split("/")))
        ]
        assert [(e.values, e.line, e.road) for e in document.ids.at(path)] == written, path


def _check(path: Path) -> int:
    """Every comparison on one file; the number of junction elements compared."""
    data = path.read_bytes()
    document = read(data).document
    assert document is not None
    tree = parse_tree(data)
    if tree is None:  # not well-formed: nothing to compare with
        return 0
    root = tree.getroot()
    elements = [el for el in root.iterchildren("{*}junction") if el.get("id") is not None]
    assert len(elements) == len(document.junctions)
    for el, record in zip(elements, document.junctions):
        _junction(el, record)
    check_ids(document, root)
    return len(elements)


@pytest.mark.corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_corpus_document_carries_the_junctions_and_ids(corpus_dir: Path, path: Path) -> None:
    _check(path)


@pytest.mark.parametrize("path", FIXTURES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_fixture_document_carries_the_junctions_and_ids(path: Path) -> None:
    _check(path)


def test_the_fixtures_hold_junctions_of_every_type() -> None:
    # what makes the comparisons above meaningful: junctions of each type, with parts, are compared
    documents = [read(path.read_bytes()).document for path in FIXTURES]
    junctions = [j for d in documents if d is not None for j in d.junctions]
    assert {j.type.value for j in junctions} == {"default", "direct", "virtual", "crossing"}
    assert all(any(getattr(j, part) for j in junctions) for part in ("cross_paths", "boundaries", "grids"))
    assert any(c.predecessor for j in junctions for c in j.connections)
