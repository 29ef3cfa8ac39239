"""The reader's document carries what the file says: for every corpus map and every rule fixture, the records of
:class:`xodrcheck.model.Document` the rules read (lanes as written, road records, types and shapes, objects and their
parts, signals, header, railroads, surfaces, links, ids) are compared, field by field, with the XML tree itself
(issue 27, one reader: the rules read the document, never the tree). Where the two spell a value differently (a raw
attribute against an enumeration, a count against the records) the test converts the tree's spelling, so that every
value is compared.

Where the document leaves out by design what the tree has - elements the reader cannot name (a road, lane or junction
without an id, a lane section without a valid ``s``), and repeats of an element the standard allows once (the reader
reports them and reads the first) - the tree's side is narrowed the same way; the narrowing is counted, and it never
happens on the corpus. Junctions are compared with the XML in ``test_document_junctions.py``.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from tests.conftest import corpus_files
from tests.xodrcheck.treetext import integer, local, number
from xodrcheck.model import Document, Lane, LaneSection, Road
from xodrcheck.reader import parse_tree, read
from xodrcheck.rules.shared.context import Context

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
    return document, parse_tree(data)


# ------------------------------------------------------------------------------------------------------ objects
#: The five numbers without which the reader leaves a ``<repeat>`` out.
_REPEAT = ("s", "length", "distance", "tStart", "tEnd")
_SHAPES = ("cornerRoad", "cornerLocal", "curveLocal")


def _children(el: etree._Element, *tags: str) -> list[etree._Element]:
    return [child for child in el if local(child) in tags]


def _first(el: etree._Element, tag: str) -> list[etree._Element]:
    """The first ``tag`` child (the standard allows one; the reader keeps the first, a second is narrowed)."""
    found = _children(el, tag)
    if len(found) > 1:
        _narrow()
    return found[:1]


Part = tuple[str, int, tuple]


def _written_references(el: etree._Element) -> list[Part]:
    return [("cornerReference", r.sourceline, (integer(r.get("id")),)) for r in _children(el, "cornerReference")]


def _written_markings(el: etree._Element) -> list[Part]:
    out: list[Part] = [("markings", el.sourceline, ())]
    for m in _children(el, "marking"):
        out += [("marking", m.sourceline, (m.get("color"), m.get("side"))), *_written_references(m)]
    return out


def _written_outline(el: etree._Element, wrapped: bool) -> list[Part]:
    out: list[Part] = [("outline", el.sourceline, (integer(el.get("id")), wrapped))]
    out += [(local(p), p.sourceline, (integer(p.get("id")), p.get("id") is not None)) for p in _children(el, *_SHAPES)]
    for markings in _first(el, "markings"):
        out += _written_markings(markings)
    return out


def _written_skeleton(el: etree._Element) -> list[Part]:
    out: list[Part] = [("skeleton", el.sourceline, ())]
    for poly in _children(el, "polyline"):
        out.append(("polyline", poly.sourceline, (integer(poly.get("id")),)))
        out += [(local(v), v.sourceline, ()) for v in _children(poly, "vertexRoad", "vertexLocal")]
    return out


def _written_object(el: etree._Element) -> list[Part]:
    """What the reader keeps of an ``<object>`` element, part by part: (tag, line, values as the file gives them)."""
    head = (el.get("id"), el.get("type"), *(number(el.get(n)) for n in ("s", "t", "zOffset", "length", "width")))
    out: list[Part] = [("object", el.sourceline, (*head, number(el.get("radius")), el.get("orientation")))]
    for child in el:
        tag = local(child)
        if tag == "outline":
            out += _written_outline(child, False)
        elif tag == "outlines":
            out += [part for o in _children(child, "outline") for part in _written_outline(o, True)]
        elif tag == "repeat" and all(number(child.get(n)) is not None for n in _REPEAT):
            out.append(("repeat", child.sourceline, tuple(number(child.get(n)) for n in _REPEAT)))
        elif tag == "validity":
            out.append(("validity", child.sourceline, (integer(child.get("fromLane")), integer(child.get("toLane")))))
        elif tag in ("material", "markings"):
            out += [(tag, child.sourceline, ())] if tag == "material" else _written_markings(child)
        elif tag == "borders":
            out += [
                part
                for b in _children(child, "border")
                for part in [("border", b.sourceline, (integer(b.get("outlineId")),)), *_written_references(b)]
            ]
        elif tag == "surface":
            out += [("surface", child.sourceline, ()), *[("CRG", c.sourceline, ()) for c in _children(child, "CRG")]]
    out += [part for s in _first(el, "skeleton") for part in _written_skeleton(s)]
    out += [("parkingSpace", p.sourceline, ()) for p in _first(el, "parkingSpace")]
    return sorted(out, key=lambda part: part[:2])


def _read_references(refs: tuple) -> list[Part]:
    return [("cornerReference", r.line, (r.id,)) for r in refs]


def _read_markings(group: Any) -> list[Part]:
    out: list[Part] = [("markings", group.line, ())]
    for m in group.markings:
        out += [("marking", m.line, (m.color, m.side)), *_read_references(m.references)]
    return out


def _read_object(obj: Any) -> list[Part]:
    """The document's record of an object, part by part as :func:`_written_object` lists the element's."""
    head = (obj.id, obj.type, obj.s, obj.t, obj.z_offset, obj.length, obj.width, obj.radius)
    out: list[Part] = [("object", obj.line, (*head, raw(obj.orientation, obj, "orientation")))]
    for o in obj.outlines:
        out.append(("outline", o.line, (o.id, o.wrapped)))
        out += [(p.kind, p.line, (p.id, p.xml.given("id"))) for p in o.points]
        out += _read_markings(o.markings) if o.markings is not None else []
    out += [("repeat", r.line, (r.s, r.length, r.distance, r.t_start, r.t_end)) for r in obj.repeats]
    out += [("validity", v.line, (v.from_lane, v.to_lane)) for v in obj.validities]
    out += [("material", m.line, ()) for m in obj.materials]
    out += [part for group in obj.markings for part in _read_markings(group)]
    out += [p for b in obj.borders for p in [("border", b.line, (b.outline_id,)), *_read_references(b.references)]]
    out += [p for s in obj.surfaces for p in [("surface", s.line, ()), *[("CRG", c.line, ()) for c in s.crgs]]]
    if obj.skeleton is not None:
        out.append(("skeleton", obj.skeleton.line, ()))
        for poly in obj.skeleton.polylines:
            out += [("polyline", poly.line, (poly.id,)), *[(v.kind, v.line, ()) for v in poly.vertices]]
    out += [("parkingSpace", obj.parking_space.line, ())] if obj.parking_space is not None else []
    return sorted(out, key=lambda part: part[:2])


def _written_others(group: etree._Element, tag: str) -> list[tuple]:
    """An ``<objects>``' references, tunnels or bridges: (id, line, s, orientation or type, validity lanes)."""
    kind = "orientation" if tag == "objectReference" else "type"
    return [
        (
            el.get("id"),
            el.sourceline,
            number(el.get("s")),
            el.get(kind),
            [(integer(v.get("fromLane")), integer(v.get("toLane")), v.sourceline) for v in _children(el, "validity")],
        )
        for el in _children(group, tag)
    ]


def _read_others(records: tuple, kind: str) -> list[tuple]:
    return [
        (r.id, r.line, r.s, raw(getattr(r, kind), r, kind), [(v.from_lane, v.to_lane, v.line) for v in r.validities])
        for r in records
    ]


def check_objects(document: Document, root: etree._Element) -> None:
    """Every ``<object>`` (with an id), ``<objectReference>``, ``<tunnel>`` and ``<bridge>`` of every road is the
    document's, with its parts (outlines, points, markings, repeats, validities, skeleton, borders, materials,
    surfaces) at their lines and with their values."""
    roads = [r for r in _all(root, "road") if _ids_or_skip(r)]
    assert len(roads) == len(document.roads)
    for road_el, road in zip(roads, document.roads):
        groups = _first(road_el, "objects")
        objects = [o for g in groups for o in _children(g, "object") if o.get("id") is not None]
        assert len(objects) == len(road.objects), road.id
        for el, obj in zip(objects, road.objects):
            assert _written_object(el) == _read_object(obj), f"road {road.id} object {obj.id} line {obj.line}"
        for tag, records, kind in (
            ("objectReference", road.object_references, "orientation"),
            ("tunnel", road.tunnels, "type"),
            ("bridge", road.bridges, "type"),
        ):
            written = [item for g in groups for item in _written_others(g, tag)]
            assert written == _read_others(records, kind), (road.id, tag)


# ------------------------------------------------------------------------------------------------------ signals
def _attributes(element: etree._Element, record: Any, names: str, where: str) -> None:
    """Each named attribute (``xmlName:field``, or one name for both) as the file spelt it equals the record's value
    in the file's spelling; numbers compare by value."""
    for name in names.split():
        xml_name, _, field = name.partition(":")
        value, text = raw(getattr(record, field or xml_name), record, xml_name), element.get(xml_name)
        if isinstance(value, float):
            assert number(text) == value, f"{where}: {xml_name}"
        else:
            assert value == text, f"{where}: {xml_name}"


def _validities_of(element: etree._Element, records: tuple, where: str) -> None:
    written = [
        (integer(v.get("fromLane")), integer(v.get("toLane")), v.sourceline) for v in _children(element, "validity")
    ]
    assert written == [(v.from_lane, v.to_lane, v.line) for v in records], where


def check_signals(document: Document, root: etree._Element) -> None:
    """Signals, signal references, controllers and vmsGroups against the tree's elements."""
    roads = [r for r in _children(root, "road") if _ids_or_skip(r)]
    signals = [(r, e) for r in roads for g in _children(r, "signals") for e in _children(g, "signal")]
    records = [s for road in document.roads for s in road.signals]
    assert len(signals) == len(records)
    for (road, element), record in zip(signals, records):
        where = f"signal {record.id} line {record.line}"
        assert (road.get("id"), element.sourceline) == (record.road, record.line), where
        _attributes(element, record, "id type subtype country s t dynamic orientation", where)
        _validities_of(element, record.validities, where)
        boards = [[sign.sourceline for sign in _children(b, "sign")] for b in _children(element, "staticBoard")]
        assert boards == [[sign.line for sign in b.signs] for b in record.static_boards], where
        assert len(list(_children(element, "vmsBoard"))) == len(record.vms_boards), where
        semantics = [e.sourceline for e in element.iter("{*}semantics")]
        assert semantics == [s.line for s in record.all_semantics()], where
    references = [(r, e) for r in roads for g in _children(r, "signals") for e in _children(g, "signalReference")]
    records = [s for road in document.roads for s in road.signal_references]
    assert len(references) == len(records)
    for (_, element), record in zip(references, records):
        where = f"signal reference {record.id} line {record.line}"
        assert element.sourceline == record.line, where
        _attributes(element, record, "id s orientation", where)
        _validities_of(element, record.validities, where)
    controllers = list(_children(root, "controller"))
    assert [(c.get("id"), c.sourceline) for c in controllers] == [(c.id, c.line) for c in document.controllers]
    for element, record in zip(controllers, document.controllers):
        controls = [(c.get("signalId"), c.sourceline) for c in _children(element, "control")]
        assert controls == [(c.signal_id, c.line) for c in record.controls], f"controller {record.id}"
    groups = list(_children(root, "vmsGroup"))
    assert [(g.get("id"), g.sourceline) for g in groups] == [(g.id, g.line) for g in document.vms_groups]
    for element, record in zip(groups, document.vms_groups):
        written = [
            (r.get("signalId"), number(r.get("vmsIndex")), r.sourceline) for r in element.iter("{*}vmsBoardReference")
        ]
        assert written == [(r.signal_id, r.vms_index, r.line) for r in record.references], f"vmsGroup {record.id}"


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
