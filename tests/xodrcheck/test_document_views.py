"""The reader's document carries everything the rules read from the XML tree today (issue 27, one reader).

For every corpus map and every rule fixture, what the XML views build from the tree the rules see (``Context.tree``:
:mod:`xodrcheck.objects.read`, :mod:`xodrcheck.signals`, the walks some
rules made over the tree themselves, and the lanes as written (:func:`lane_elements`, the walk the lane rules made
before they read the document); road types and shapes, which the rules read from the document, against the tree
directly) is compared, field by field, with the same records of
:class:`xodrcheck.model.Document`. Where the two spell a value differently (a raw attribute against an enumeration, a
count against the records) the test converts the view's spelling, so that every value is compared.

Where the document leaves out by design what a view keeps - elements the reader cannot name (a road, lane or junction
without an id, a lane section without a valid ``s``), and repeats of an element the standard allows once (the reader
reports them and reads the first) - the view's side is narrowed the same way; the narrowing is counted, and it never
happens on the corpus. Junctions, which the rules read from the document only, are compared with the XML in
``test_document_junctions.py``.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from tests.conftest import corpus_files
from xodrcheck.model import Document, Lane, LaneSection, Road
from xodrcheck.objects.read import read_road_objects
from xodrcheck.reader import read
from xodrcheck.rules.context import Context
from xodrcheck.signals import read_signals
from xodrcheck.xmlvalues import integer, local, number

HERE = Path(__file__).parent
FIXTURES = sorted((HERE / "rules" / "fixtures").rglob("*.xodr")) + sorted((HERE / "opendrive19").glob("*.xodr"))


# ------------------------------------------------------------------------------------------------------ spelling
def raw(value: Any, record: Any, name: str) -> str | None:
    """A document value as the file spelt it: an enumeration's value, ``yes``/``no`` for a yes-no attribute, the
    text of an invalid one (``None``: absent)."""
    if value is None:
        return record.xml.text(name)
    if isinstance(value, bool):
        return "yes" if value else "no"
    return getattr(value, "value", value)


def same(view: Any, record: Any, fields: str, where: str) -> None:
    """The named fields (space-separated) are equal on the view's record and the document's."""
    for name in fields.split():
        assert getattr(view, name) == getattr(record, name), f"{where}: {name}"


class Narrowed:
    """How often the view's side had to be narrowed to what the document keeps by design."""

    count = 0


def _ids_or_skip(road: etree._Element) -> bool:
    if road.get("id") is None:
        Narrowed.count += 1
        return False
    return True


# ------------------------------------------------------------------------------------------------------ the files
def _documents(path: Path) -> tuple[Document, etree._ElementTree | None]:
    data = path.read_bytes()
    document = read(data).document
    assert document is not None
    return document, Context(document, path=str(path), data=data).tree


def _roads_by_id(document: Document) -> dict[str, list[Road]]:
    out: dict[str, list[Road]] = {}
    for road in document.roads:
        out.setdefault(road.id, []).append(road)
    return out


# ------------------------------------------------------------------------------------------------------ objects
def _validities(view: tuple, records: tuple, where: str, layers: bool = True) -> None:
    kept = [v for v in records if v.from_lane is not None and v.to_lane is not None] if layers else list(records)
    assert len(view) == len(kept), where
    for v, r in zip(view, kept):
        same(v, r, "from_lane to_lane line" + (" layer" if layers else ""), where)


def _outline(view: Any, record: Any, where: str) -> None:
    same(view, record, "id outer closed fill_type lane_type line wrapped", where)
    assert len(view.corners) == len(record.corners), where
    for a, b in zip(view.corners, record.corners):
        assert type(a).__name__ == type(b).__name__, where
        same(a, b, "height id line " + ("s t dz" if hasattr(a, "s") else "u v z"), where)
    assert len(view.curves) == len(record.curves), where
    for a, b in zip(view.curves, record.curves):
        same(a, b, "u v z height hdg length shape id line", where)
    assert len(view.points) == len(record.points), where
    for p, q in zip(view.points, record.points):
        same(p, q, "kind id line", where)
        assert (p.id_text is None) == (not q.xml.given("id")), where
    assert (view.markings is None) == (record.markings is None), where
    if view.markings is not None:
        _markings(view.markings, record.markings, where)


def _markings(view: Any, record: Any, where: str) -> None:
    same(view, record, "line", where)
    assert len(view.markings) == len(record.markings), where
    for m, n in zip(view.markings, record.markings):
        fields = "color side width z_offset space_length line_length start_offset stop_offset weight line"
        same(m, n, fields, where)
        assert [(c.id, c.line) for c in m.references] == [(c.id, c.line) for c in n.references], where


def _object(view: Any, record: Any) -> None:
    where = f"object {view.id} line {view.line}"
    fields = (
        "road id type s t z_offset hdg length width radius height invalidated temporary line subtype name pitch "
        "roll perp_to_road valid_length outlines_line"
    )
    same(view, record, fields, where)
    assert view.orientation == raw(record.orientation, record, "orientation"), where
    assert view.attributes == frozenset(record.xml.attributes), where
    assert len(view.outlines) == len(record.outlines), where
    for o, p in zip(view.outlines, record.outlines):
        _outline(o, p, where)
    assert len(view.repeats) == len(record.repeats), where
    for r, q in zip(view.repeats, record.repeats):
        fields = (
            "s length distance t_start t_end bt ct dt line z_offset_start z_offset_end length_start length_end "
            "width_start width_end height_start height_end radius_start radius_end detach"
        )
        same(r, q, fields, where)
    _validities(view.validities, record.validities, where)
    assert (view.skeleton is None) == (record.skeleton is None), where
    if view.skeleton is not None:
        same(view.skeleton, record.skeleton, "line", where)
        for a, b in zip(view.skeleton.polylines, record.skeleton.polylines, strict=True):
            same(a, b, "id line", where)
            for v, w in zip(a.vertices, b.vertices, strict=True):
                same(v, w, "kind a b c radius width length id intersection_point line", where)
    for a, b in zip(view.markings, record.markings, strict=True):
        _markings(a, b, where)
    for a, b in zip(view.borders, record.borders, strict=True):
        same(a, b, "outline_id type width use_complete_outline line", where)
        assert [(c.id, c.line) for c in a.references] == [(c.id, c.line) for c in b.references], where
    for a, b in zip(view.materials, record.materials, strict=True):
        same(a, b, "surface friction roughness road_mark_color line", where)
    for a, b in zip(view.surfaces, record.surfaces, strict=True):
        same(a, b, "line", where)
        for c, d in zip(a.crgs, b.crgs, strict=True):
            same(c, d, "file hide_road_surface_crg z_scale line", where)


def check_objects(document: Document, root: etree._Element) -> None:
    views = read_road_objects(root, document.version)
    roads = _roads_by_id(document)
    assert set(views) == {road for road, found in roads.items() if any(_has_objects(r) for r in found)}
    for road_id, view in views.items():
        objects = [o for r in roads[road_id] for o in r.objects]
        references = [o for r in roads[road_id] for o in r.object_references]
        tunnels = [o for r in roads[road_id] for o in r.tunnels]
        bridges = [o for r in roads[road_id] for o in r.bridges]
        assert len(view.objects) == len(objects), road_id
        for a, b in zip(view.objects, objects):
            _object(a, b)
        assert len(view.references) == len(references), road_id
        for a, b in zip(view.references, references):
            same(a, b, "road id s t z_offset valid_length line", road_id)
            assert a.orientation == raw(b.orientation, b, "orientation"), road_id
            _validities(a.validities, b.validities, road_id)
        for kind, records in (("tunnel", tunnels), ("bridge", bridges)):
            structures = [s for s in view.structures if s.kind == kind]
            assert len(structures) == len(records), road_id
            for a, b in zip(structures, records):
                same(a, b, "road id s length type name line", road_id)
                _validities(a.validities, b.validities, road_id)


def _has_objects(road: Road) -> bool:
    return bool(road.objects or road.object_references or road.tunnels or road.bridges)


# ------------------------------------------------------------------------------------------------------ signals
def check_signals(document: Document, root: etree._Element) -> None:
    view = read_signals(root)
    signals = [s for road in document.roads for s in road.signals]
    references = [s for road in document.roads for s in road.signal_references]
    assert len(view.signals) == len(signals)
    for a, b in zip(view.signals, signals):
        where = f"signal {a.id} line {a.line}"
        same(a, b, "road id type subtype country s t line", where)
        assert a.dynamic == raw(b.dynamic, b, "dynamic"), where
        assert a.orientation == raw(b.orientation, b, "orientation"), where
        _validities(a.validities, b.validities, where, layers=False)
        assert len(a.static_boards) == len(b.static_boards), where
        for signs, board in zip(a.static_boards, b.static_boards):
            for sign, record in zip(signs, board.signs, strict=True):
                same(sign, record, "id type subtype country line", where)
        assert a.vms_boards == len(b.vms_boards), where
        semantics = [(s.line, tuple(item.kind for item in s.items)) for s in b.all_semantics()]
        assert list(a.semantics) == semantics, where
    assert len(view.references) == len(references)
    for a, b in zip(view.references, references):
        same(a, b, "road id line s", f"signal reference {a.id}")
        assert a.orientation == raw(b.orientation, b, "orientation")
        _validities(a.validities, b.validities, f"signal reference {a.id}", layers=False)
    assert len(view.controllers) == len(document.controllers)
    for a, b in zip(view.controllers, document.controllers):
        same(a, b, "id line", f"controller {a.id}")
        assert [(c.signal_id, c.line) for c in a.controls] == [(c.signal_id, c.line) for c in b.controls]
    assert len(view.vms_groups) == len(document.vms_groups)
    for a, b in zip(view.vms_groups, document.vms_groups):
        same(a, b, "id line", f"vmsGroup {a.id}")
        assert [(r.signal_id, number(r.vms_index), r.line) for r in a.references] == [
            (r.signal_id, r.vms_index, r.line) for r in b.references
        ]


def _narrow() -> bool:
    Narrowed.count += 1
    return False


# ------------------------------------------------------------------------------------------------------ road records
def _same_speed(view: tuple[str | None, str | None] | None, record: Any) -> bool:
    """A road type's ``<speed>`` (``max`` and ``unit`` as written) against the document's."""
    if view is None or record is None:
        return view is None and record is None
    written, unit = view
    value = record.max
    if unit != record.unit:
        return False
    if written is None:
        return value is None and not record.xml.given("max")
    if value is None:
        return record.xml.text("max") == written
    return getattr(value, "value", None) == written or number(written) == value


def check_road_records(document: Document, root: etree._Element) -> None:
    """Every road's ``<type>`` (with its ``<speed>``) and ``<shape>`` records as written, against the document's."""
    roads = [road for road in _all(root, "road") if _ids_or_skip(road)]
    assert len(roads) == len(document.roads)
    for el, road in zip(roads, document.roads):
        assert (el.get("id"), el.sourceline) == (road.id, road.line)
        types = list(el.iterchildren("{*}type"))
        assert len(types) == len(road.types), road.id
        for type_el, record in zip(types, road.types):
            written = (number(type_el.get("s")), type_el.get("type"), type_el.get("country"), type_el.sourceline)
            assert written == (record.s, record.type, record.country, record.line), road.id
            speed = next(type_el.iterchildren("{*}speed"), None)
            assert _same_speed(None if speed is None else (speed.get("max"), speed.get("unit")), record.speed)
        shapes = list(el.iterfind("{*}lateralProfile/{*}shape"))
        assert len(shapes) == len(road.shapes), road.id
        for shape_el, shape in zip(shapes, road.shapes):
            written_shape = tuple(number(shape_el.get(name)) for name in ("s", "t", "a", "b", "c", "d"))
            assert written_shape == (shape.s, shape.t, shape.a, shape.b, shape.c, shape.d), road.id
            assert shape_el.sourceline == shape.line, road.id


# ------------------------------------------------------------------------------------------------------ lanes
_GROUPS = ("left", "center", "right")
#: Lane records as the views read them: tag -> the document's field.
_RECORDS = {
    "access": "access",
    "material": "materials",
    "rule": "rules",
    "visibility": "visibilities",
    "height": "heights",
    "speed": "speeds",
    "width": "widths",
    "border": "borders",
}


def _layers(document: Document) -> Iterator[tuple[Road, str, Any]]:
    """(road, layer as the file names it, its ``<lanes>`` record) in file order."""
    for road in document.roads:
        layers = [lanes for lanes in (road.lanes, road.temporary_lanes) if lanes is not None]
        for lanes in sorted(layers, key=lambda lanes: lanes.line):
            yield road, lanes.layer.value, lanes


def _listed(section: LaneSection) -> list[tuple[str, Lane]]:
    """The section's lanes as the file lists them: its groups in file order, each group's lanes in file order."""
    out: list[tuple[str, Lane]] = []
    for group in dict.fromkeys(tag for tag in section.xml.children if tag in _GROUPS):
        out.extend((group, lane) for lane in getattr(section, group))
    return out


def _lane(view: Any, group: str, lane: Lane, layered: bool, where: str) -> None:
    el = view.element
    assert (view.group, view.id, el.sourceline) == (group, lane.id, lane.line), where
    assert (el.get("type") or "") == lane.type_name, where
    assert el.get("direction") == raw(lane.direction, lane, "direction"), where
    for tag, name in _RECORDS.items():
        written = [(number(r.get("sOffset")), r.sourceline) for r in el.iterchildren(f"{{*}}{tag}")]
        assert written == [(r.s, r.line) for r in getattr(lane, name)], f"{where}: {tag}"
    for tag in ("width", "border"):
        written_cubic = [
            tuple(number(r.get(k)) for k in ("sOffset", "a", "b", "c", "d")) for r in el.iterchildren(f"{{*}}{tag}")
        ]
        assert written_cubic == [(r.s, r.a, r.b, r.c, r.d) for r in getattr(lane, f"{tag}s")], where
    for a, b in zip(el.iterchildren("{*}access"), lane.access, strict=True):
        assert (a.get("rule"), a.get("restriction")) == (raw(b.rule, b, "rule"), b.restriction), where
    marks = list(el.iterchildren("{*}roadMark"))
    assert [(number(m.get("sOffset")), m.sourceline) for m in marks] == [(m.s, m.line) for m in lane.road_marks], where
    for mark, record in zip(marks, lane.road_marks):  # what L034 reads
        assert (next(mark.iterchildren("{*}sway"), None) is not None) == bool(record.sways), where
        lines = [
            (number(x.get("tOffset")), x.sourceline)
            for holder in mark.iterchildren("{*}type", "{*}explicit")
            for x in holder.iterchildren("{*}line")
        ]
        holders = [h for h in (record.type_lines, record.explicit) if h is not None]
        assert sorted(lines, key=lambda x: x[1]) == sorted(
            [(x.t_offset, x.line) for h in holders for x in h.lines], key=lambda x: x[1]
        ), where
    link = next(el.iterchildren("{*}link"), None)
    assert (link is None) == (lane.link is None), where
    if link is None or lane.link is None:
        return
    assert link.sourceline == lane.link.line, where
    targets: dict[tuple[str, str], list[int]] = {}
    for item in link.iterchildren("{*}predecessor", "{*}successor"):
        layer = (item.get("layer") or "permanent") if layered else "permanent"
        targets.setdefault((local(item), layer), []).append(int(item.get("id")))
    assert targets.get(("predecessor", "permanent"), []) == list(lane.predecessors), where
    assert targets.get(("successor", "permanent"), []) == list(lane.successors), where
    assert targets.get(("predecessor", "temporary"), []) == list(lane.temporary_predecessors), where
    assert targets.get(("successor", "temporary"), []) == list(lane.temporary_successors), where


@dataclass(frozen=True)
class SectionXml:
    """A ``<laneSection>`` element and where it sits (``s`` ``None``: missing or not a number)."""

    road: str | None
    lanes_element: etree._Element
    element: etree._Element
    s: float | None
    layer: str  # the ``layer`` of its ``<lanes>`` (``permanent`` when absent)


@dataclass(frozen=True)
class LaneXml:
    """A ``<lane>`` element of a lane section's ``<left>``, ``<center>`` or ``<right>`` (``id`` ``None``: not an
    integer)."""

    section: SectionXml
    group: str
    element: etree._Element
    id: int | None


def lane_elements(root: etree._Element) -> tuple[list[SectionXml], list[LaneXml]]:
    """Every ``<road>/<lanes>/<laneSection>`` and its ``<left|center|right>/<lane>`` elements, in file order."""
    sections: list[SectionXml] = []
    lanes: list[LaneXml] = []
    for road_el in root.iterchildren("{*}road"):
        for lanes_el in road_el.iterchildren("{*}lanes"):
            for section_el in lanes_el.iterchildren("{*}laneSection"):
                layer = lanes_el.get("layer") or "permanent"
                section = SectionXml(road_el.get("id"), lanes_el, section_el, number(section_el.get("s")), layer)
                sections.append(section)
                for group_el in section_el.iterchildren(*(f"{{*}}{g}" for g in _GROUPS)):
                    for lane_el in group_el.iterchildren("{*}lane"):
                        lanes.append(LaneXml(section, local(group_el), lane_el, integer(lane_el.get("id"))))
    return sections, lanes


def check_lanes(document: Document, root: etree._Element) -> None:
    view_sections, view_lanes = lane_elements(root)
    layered = document.version is None or document.version >= (1, 9)
    lanes_of: dict[int, list[Any]] = {}
    for lane in view_lanes:
        lanes_of.setdefault(id(lane.section), []).append(lane)
    read = {lanes.line for _, _, lanes in _layers(document)}  # a repeated <lanes> of a layer is reported, not read
    sections = [
        s
        for s in view_sections
        if (s.road is not None and s.s is not None and s.lanes_element.sourceline in read) or _narrow()
    ]
    records = [
        (road, layer, lanes, section) for road, layer, lanes in _layers(document) for section in lanes.lane_sections
    ]
    assert len(sections) == len(records)
    offsets: dict[int, etree._Element | None] = {}
    for view_section, (road, layer, lanes, section) in zip(sections, records):
        where = f"road {road.id} section {section.s}"
        assert (view_section.road, view_section.s) == (road.id, section.s), where
        assert view_section.layer == layer or not layered, where
        assert view_section.element.sourceline == section.line, where
        assert view_section.lanes_element.sourceline == lanes.line, where
        length = view_section.element.get("length")
        assert (length is not None) == section.xml.given("length"), where
        if layered:
            assert number(length) == section.length, where
        offsets[lanes.line] = next(view_section.lanes_element.iterchildren("{*}laneOffset"), None)
        listed = _listed(section)
        groups = {}  # the first <left>, <center> and <right>: a repeated one is reported, not read
        for group in view_section.element.iterchildren(*(f"{{*}}{g}" for g in _GROUPS)):
            groups.setdefault(local(group), group)
        found = [
            lane
            for lane in lanes_of.get(id(view_section), [])
            if (lane.id is not None and lane.element.getparent() is groups[lane.group]) or _narrow()
        ]
        assert len(found) == len(listed), where
        for lane_view, (group, lane) in zip(found, listed):
            _lane(lane_view, group, lane, layered, where)
    for road, _, lanes in _layers(document):
        offset = offsets.get(lanes.line)
        if offset is not None:
            assert (number(offset.get("s")), offset.sourceline) == (lanes.lane_offset[0].s, lanes.lane_offset[0].line)
        else:
            assert lanes.lane_offset == () or not lanes.lane_sections, road.id


# ------------------------------------------------------------------------------------------------------ ids (R020)
def _all(root: etree._Element, path: str) -> list[etree._Element]:
    return list(root.iterfind("/".join(f"{{*}}{step}" for step in path.split("/"))))


def _written(root: etree._Element, path: str, attribute: str = "id") -> list[tuple[str | None, int]]:
    return [(el.get(attribute), el.sourceline) for el in _all(root, path)]


def check_ids(document: Document, root: etree._Element) -> None:
    """The elements R020/R021 and T013 find by path, with the ids they name."""
    roads = document.roads
    signals = [s for r in roads for s in r.signals]
    switches = [w for r in roads if r.railroad is not None for w in r.railroad.switches]
    platforms = [p for station in document.stations for p in station.platforms]
    objects_written = [o for o in _written(root, "road/objects/object") if o[0] is not None or _narrow()]
    expected = {
        ("road/objects/object", "id"): [o for r in roads for o in r.objects],
        ("road/objects/bridge", "id"): [o for r in roads for o in r.bridges],
        ("road/objects/tunnel", "id"): [o for r in roads for o in r.tunnels],
        ("road/objects/objectReference", "id"): [o for r in roads for o in r.object_references],
        ("road/signals/signal", "id"): signals,
        ("road/signals/signalReference", "id"): [o for r in roads for o in r.signal_references],
        ("road/signals/signal/dependency", "id"): [d for s in signals for d in s.dependencies],
        ("road/signals/signal/staticBoard/sign", "id"): [sign for s in signals for sign in s.signs],
        ("road/railroad/switch", "id"): switches,
        ("road/railroad/switch/mainTrack", "id"): [w.main_track for w in switches if w.main_track],
        ("road/railroad/switch/sideTrack", "id"): [w.side_track for w in switches if w.side_track],
        ("road/railroad/switch/partner", "id"): [w.partner for w in switches if w.partner],
        ("controller", "id"): document.controllers,
        ("controller/control", "signalId"): [c for controller in document.controllers for c in controller.controls],
        ("junction/controller", "id"): [c for j in document.junctions for c in j.controllers],
        ("junction/roadSection", "roadId"): [r for j in document.junctions for r in j.road_sections],
        ("junctionGroup", "id"): document.junction_groups,
        ("junctionGroup/junctionReference", "junction"): [r for g in document.junction_groups for r in g.junctions],
        ("station", "id"): document.stations,
        ("station/platform", "id"): platforms,
        ("station/platform/segment", "roadId"): [s for p in platforms for s in p.segments],
        ("vmsGroup", "id"): document.vms_groups,
        ("vmsGroup/vmsBoardReference", "signalId"): [r for g in document.vms_groups for r in g.references],
    }
    field = {"signalId": "signal_id", "roadId": "road_id", "junction": "junction"}
    for (path, attribute), records in expected.items():
        written = objects_written if path == "road/objects/object" else _written(root, path, attribute)
        name = field.get(attribute, "id")
        if path.endswith("roadSection"):
            name = "road"
        assert written == [(getattr(r, name), r.line) for r in records], path
    assert [r for r in _written(root, "road") if r[0] is not None or _narrow()] == [(r.id, r.line) for r in roads]
    junctions = _written(root, "junction")
    assert [j for j in junctions if j[0] is not None or _narrow()] == [(j.id, j.line) for j in document.junctions]
    assert _written(root, "road/signals/signal/positionRoad", "roadId") == [
        (s.position_road.road_id, s.position_road.line) for s in signals if s.position_road is not None
    ]
    references = [
        (r.get("elementType"), r.get("elementId"), r.sourceline) for r in _all(root, "road/signals/signal/reference")
    ]
    assert references == [
        (raw(r.element_type, r, "elementType"), r.element_id, r.line) for s in signals for r in s.references
    ]
    paths = [
        (c.get("crossingRoad"), c.get("roadAtStart"), c.get("roadAtEnd"), c.sourceline)
        for c in _all(root, "junction/crossPath")
    ]
    junctions = document.junctions
    assert paths == [
        (c.crossing_road, c.road_at_start, c.road_at_end, c.line) for j in junctions for c in j.cross_paths
    ]
    assert [r for r in _written(root, "junction", "mainRoad") if r[0] is not None] == [
        (j.main_road, j.line) for j in junctions if j.main_road is not None
    ]
    priorities = [(p.get("high"), p.get("low"), p.sourceline) for p in _all(root, "junction/priority")]
    assert priorities == [(p.high, p.low, p.line) for j in junctions for p in j.priorities]
    segments = _written(root, "junction/boundary/segment", "roadId")
    expected = [(x.road, x.line) for j in junctions for b in j.boundaries for x in b.segments]
    expected += [(x.road, x.line) for j in junctions for b in j.boundaries for x in b.unknown]
    assert sorted(segments, key=lambda x: x[1]) == sorted(expected, key=lambda x: x[1])
    for tag in ("predecessor", "successor"):
        ends = _written(root, f"junction/connection/{tag}", "elementId")
        records = [getattr(c, tag) for j in junctions for c in j.connections]
        assert ends == [(e.element_id, e.line) for e in records if e is not None], tag


# ------------------------------------------------------------------------------------------------- header (H002, H003)
def check_header(document: Document, root: etree._Element) -> None:
    header = document.header
    found = [("".join(el.itertext()).strip(), el.sourceline) for el in _all(root, "header/geoReference")]
    assert found == ([(g.text, g.line) for g in header.geo_references] if header else [])
    behaviours = []
    for regulations in _all(root, "header/defaultRegulations"):
        for semantics in regulations.iterfind(".//{*}semantics"):
            owner = semantics.getparent()
            behaviours += [(local(owner), owner.sourceline, local(el), el.sourceline) for el in semantics]
    expected = []
    regulations = None if header is None else header.default_regulations
    if regulations is not None:
        owners = [("roadRegulations", r) for r in regulations.road_regulations]
        owners += [("signalRegulations", r) for r in regulations.signal_regulations]
        for tag, owner in sorted(owners, key=lambda item: item[1].line):
            if owner.semantics is not None:
                expected += [(tag, owner.line, item.kind, item.line) for item in owner.semantics.items]
    assert behaviours == expected


# --------------------------------------------------------------------------------------------------- rail (W003, W004)
def check_rail(document: Document, root: etree._Element) -> None:
    stations = [
        (
            st.get("id"),
            st.get("name"),
            st.sourceline,
            [(p.get("id"), p.sourceline, len(p.findall("{*}segment"))) for p in st.iterfind("{*}platform")],
        )
        for st in _all(root, "station")
    ]
    assert stations == [
        (s.id, s.name, s.line, [(p.id, p.line, len(p.segments)) for p in s.platforms]) for s in document.stations
    ]
    switches = []
    for road in _all(root, "road"):
        for switch in road.iterfind("{*}railroad/{*}switch"):
            tracks = [next(switch.iterchildren(f"{{*}}{k}"), None) for k in ("mainTrack", "sideTrack", "partner")]
            ids = [None if t is None else (t.get("id"), t.sourceline) for t in tracks]
            switches.append((road.get("id", "?"), switch.get("id"), switch.sourceline, *ids))
    expected = []
    for road in document.roads:
        for w in () if road.railroad is None else road.railroad.switches:
            ids = [None if t is None else (t.id, t.line) for t in (w.main_track, w.side_track, w.partner)]
            expected.append((road.id, w.id, w.line, *ids))
    assert switches == expected


# ------------------------------------------------------------------------------------------------ surfaces (U0xx, B055)
_CRG = (
    "file",
    "sStart",
    "sEnd",
    "orientation",
    "mode",
    "purpose",
    "sOffset",
    "tOffset",
    "zOffset",
    "zScale",
    "hOffset",
)


_CRG_FIELDS = {"sStart": "s_start", "sEnd": "s_end", "sOffset": "s_offset", "tOffset": "t_offset"}
_CRG_FIELDS |= {"zOffset": "z_offset", "zScale": "z_scale", "hOffset": "h_offset"}


def matches(written: str | None, record: Any, name: str, value: Any) -> bool:
    """Whether attribute ``name`` as written is ``value`` of the document's ``record``: absent and ``None``; a number
    and its value; an enumeration's spelling; the text of an invalid value."""
    if written is None:
        return value is None and not record.xml.given(name)
    if value is None:
        return record.xml.text(name) == written
    if isinstance(value, float):
        return number(written) == value
    return raw(value, record, name) == written


def _same_crg(written: etree._Element, crg: Any) -> bool:
    return written.sourceline == crg.line and all(
        matches(written.get(name), crg, name, getattr(crg, _CRG_FIELDS.get(name, name))) for name in _CRG
    )


def check_surfaces(document: Document, root: etree._Element) -> None:
    owners = []
    for owner in root:
        if local(owner) in ("road", "junction") and owner.get("id") is not None:
            surfaces = owner.findall("{*}surface")
            if len(surfaces) > 1:  # the schema allows one: the document holds the first
                _narrow()
            owners.append((local(owner), owner.get("id"), surfaces[0].findall("{*}CRG") if surfaces else []))
    expected = [
        (kind, o.id, () if o.surface is None else o.surface.crgs)
        for kind, o in sorted(
            [("road", r) for r in document.roads] + [("junction", j) for j in document.junctions],
            key=lambda item: item[1].line,
        )
    ]
    assert len(owners) == len(expected)
    for a, b in zip(owners, expected):
        assert a[:2] == b[:2]
        assert len(a[2]) == len(b[2]), a[:2]
        for x, y in zip(a[2], b[2]):
            assert _same_crg(x, y), (x, y)
    for road_el, road in zip([r for r in _all(root, "road") if _ids_or_skip(r)], document.roads):
        profile = road_el.find("{*}lateralProfile")
        surface = None if profile is None else profile.find("{*}crossSectionSurface")
        css = road.cross_section_surface
        assert (surface is None) == (css is None), road.id
        if surface is None or css is None:
            continue
        assert surface.sourceline == css.line, road.id
        others = [(local(el), el.sourceline) for el in profile if local(el) in ("shape", "superelevation")]
        read_ = [("shape", x.line) for x in road.shapes] + [("superelevation", x.line) for x in road.superelevation]
        assert sorted(others, key=lambda item: item[1]) == sorted(read_, key=lambda item: item[1]), road.id
        t_offset = surface.find("{*}tOffset")
        assert (t_offset is None) == (css.t_offset is None), road.id
        if t_offset is not None and css.t_offset is not None:
            assert _coefficients(t_offset) == [(c.s, c.line) for c in css.t_offset.coefficients], road.id
        strips = [s for group in surface.iterfind("{*}surfaceStrips") for s in group.iterfind("{*}strip")]
        assert [(s.get("id"), s.sourceline) for s in strips] == [(str(s.id), s.line) for s in css.strips], road.id
        for strip, record in zip(strips, css.strips):
            polynomials = [(local(p), _coefficients(p)) for p in strip if local(p) in STRIP]
            assert polynomials == [(p.kind, [(c.s, c.line) for c in p.coefficients]) for p in record.polynomials]


STRIP = ("width", "constant", "linear", "quadratic", "cubic")


def _coefficients(el: etree._Element) -> list[tuple[float | None, int]]:
    return [(number(c.get("s")), c.sourceline) for c in el.iterfind("{*}coefficients")]


# ------------------------------------------------------------------------------------------------- countries (G053)
def check_countries(document: Document, root: etree._Element) -> None:
    written = sorted((local(el), el.sourceline, el.get("country")) for el in root.iterfind(".//*[@country]"))
    read_ = [("type", t.line, t.country) for r in document.roads for t in r.types if t.xml.given("country")]
    signals = [s for r in document.roads for s in r.signals]
    read_ += [("signal", s.line, s.country) for s in signals if s.xml.given("country")]
    read_ += [("sign", sign.line, sign.country) for s in signals for sign in s.signs if sign.xml.given("country")]
    assert written == sorted(read_)


# ------------------------------------------------------------------------------------------------- road links (K004)
def check_links(document: Document, root: etree._Element) -> None:
    read_ = {
        (road.id, tag): (link.xml.attributes, link.line)
        for road in document.roads
        for tag, link in (("predecessor", road.predecessor), ("successor", road.successor))
        if link is not None
    }
    written = {}
    for road in _all(root, "road"):
        for el in road.iterfind("{*}link/{*}*"):
            key = (road.get("id"), local(el))
            if key[1] in ("predecessor", "successor") and ((_ids_or_skip(road) and key in read_) or _narrow()):
                written[key] = (tuple(el.keys()), el.sourceline)  # (a link the reader cannot use is reported, not read)
    assert written == read_
    virtual = {
        (j.get("id"), j.get("mainRoad")) for j in _all(root, "junction") if j.get("type") == "virtual" and j.get("id")
    }
    assert virtual == {(j.id, j.main_road) for j in document.junctions if j.type.value == "virtual"}


# ------------------------------------------------------------------------------------------------- what G901 compares
_READ = frozenset({"link", "width", "border", "roadMark", "speed", "userData"})


def _more_than_compared(lane: Lane) -> bool:
    """A lane with records G901 does not compare (it then leaves its section alone)."""
    others = (lane.access, lane.materials, lane.rules, lane.visibilities, lane.heights, lane.xml.unknown)
    marks = any(m.type_lines or m.explicit or m.sways or m.xml.children for m in lane.road_marks)
    extra = any(tag not in _READ for tag in lane.xml.children)
    return any(others) or marks or extra


def check_unread(document: Document, root: etree._Element) -> None:
    written = set()
    for section in root.iter("{*}laneSection"):
        for lane in section.iter("{*}lane"):
            children = [c for c in lane if isinstance(c.tag, str)]
            marks = [c for c in children if local(c) == "roadMark"]
            if any(local(c) not in _READ for c in children) or any(len(m) for m in marks):
                written.add(section.sourceline)
                break
    read_ = {
        section.line
        for road, _, lanes in _layers(document)
        for section in lanes.lane_sections
        if any(_more_than_compared(lane) for lane in section.lanes)
    }
    assert written == read_


# ------------------------------------------------------------------------------------------------- outlines (G061)
def check_outlines(document: Document, root: etree._Element) -> None:
    shapes = {"cornerRoad", "cornerLocal", "curveLocal"}
    written = [
        (outline.sourceline, any(local(c) in shapes for c in outline))
        for outline in root.iterfind("{*}road/{*}objects/{*}object//{*}outline")
    ]
    read_ = [(o.line, bool(o.points)) for r in document.roads for obj in r.objects for o in obj.outlines]
    assert sorted(written) == sorted(read_)


# ------------------------------------------------------------------------------------------------- lane access (L016)
def check_access(document: Document, root: etree._Element) -> None:
    written = [
        (access.get("rule"), number(access.get("sOffset")), access.sourceline)
        for lane in root.iter("lane")
        for access in lane.iterchildren("access")
    ]
    read_ = [
        (raw(a.rule, a, "rule"), a.s, a.line)
        for _, _, lanes in _layers(document)
        for section in lanes.lane_sections
        for _, lane in _listed(section)
        for a in lane.access
    ]
    assert written == read_


# ------------------------------------------------------------------------------------------------- the tests
CHECKS = (
    check_objects,
    check_signals,
    check_ids,
    check_header,
    check_rail,
    check_surfaces,
    check_countries,
    check_links,
    check_unread,
    check_outlines,
    check_access,
)


def _check(path: Path) -> int:
    """Every comparison on one file; the number of narrowings."""
    Narrowed.count = 0
    data = path.read_bytes()
    document = read(data).document
    assert document is not None
    ctx = Context(document, path=str(path), data=data)
    tree = ctx.tree
    if tree is None:  # not well-formed: the rules read no tree, and the views are empty
        return 0
    root = tree.getroot()
    for check in CHECKS:
        check(document, root)
    check_road_records(document, root)
    check_lanes(document, root)
    return Narrowed.count


@pytest.mark.corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_corpus_document_carries_the_views(corpus_dir: Path, path: Path) -> None:
    assert _check(path) == 0


@pytest.mark.parametrize("path", FIXTURES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_fixture_document_carries_the_views(path: Path) -> None:
    _check(path)
