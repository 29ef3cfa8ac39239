"""Serialise a :class:`junctionart.opendrive.Document` to OpenDRIVE 1.8 (default), 1.9 or 1.7 XML.

The generator's maps use nothing that changed between these versions, so the three differ only in the header's
``revMinor`` (1.9 adds lane layers, curved object outlines and more, none of which the generator makes; 1.8 stays the
default while CARLA, SUMO and ASAM's checker read at most 1.8).

The text is built directly, line by line, in lxml's pretty-print layout (an element tree cost most of the writing
time); element order follows the schema of the declared version. Floats are written with ``repr`` (the shortest
string that reads back to the same double), so the file round-trips exactly; the output bytes depend only on the
document.
Files are written atomically: a temporary file in the target folder, then ``os.replace``
(:func:`xodrcheck.support.atomic.atomic_file`).
"""

from __future__ import annotations

import functools
import math
import os
import re
from pathlib import Path

from .errors import JunctionArtError, OutputError
from .opendrive import (
    Arc,
    Controller,
    Cubic,
    Document,
    Geometry,
    Junction,
    Lane,
    LaneSection,
    Line,
    Link,
    ObjectMarking,
    ParamPoly3,
    Road,
    RoadMark,
    RoadObject,
    Signal,
    Validity,
)

REV_MINOR = {"1.8": 8, "1.9": 9, "1.7": 7}


def fmt(x: float) -> str:
    """Shortest round-trip text of a finite float; -0.0 is written as 0.0."""
    x = float(x)
    if not math.isfinite(x):
        raise JunctionArtError(f"cannot write non-finite number {x!r}")
    if x == 0.0:
        return "0.0"
    return repr(x)


_ESCAPES = {"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}
_BAD_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")
_SPECIAL = re.compile('[&<>"\n\r\t]')


@functools.lru_cache(maxsize=4096)  # ids, types and names repeat throughout a file
def _esc(text: str) -> str:
    """``text`` as an XML attribute value (escaped as libxml2 does); characters XML cannot hold are refused."""
    if _BAD_XML.search(text):
        raise JunctionArtError(f"cannot write {text!r}: it holds a character XML does not allow")
    return _SPECIAL.sub(lambda m: _ESCAPES[m.group()], text)


_INDENT = tuple("  " * depth for depth in range(10))


class _Out:
    """The indented XML text, built line by line (two spaces per level, as lxml's ``pretty_print``)."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def leaf(self, depth: int, tag: str, attrs: str = "") -> None:
        self.lines.append(f"{_INDENT[depth]}<{tag}{attrs}/>")

    def open(self, depth: int, tag: str, attrs: str = "") -> None:
        self.lines.append(f"{_INDENT[depth]}<{tag}{attrs}>")

    def close(self, depth: int, tag: str) -> None:
        self.lines.append(f"{_INDENT[depth]}</{tag}>")


def _link(out: _Out, depth: int, tag: str, link: Link) -> None:
    cp = f' contactPoint="{_esc(link.contact_point)}"' if link.contact_point is not None else ""
    out.leaf(depth, tag, f' elementType="{_esc(link.element_type)}" elementId="{_esc(link.element_id)}"{cp}')


def _geometry(add, g: Geometry) -> None:
    add(f'      <geometry s="{fmt(g.s)}" x="{fmt(g.x)}" y="{fmt(g.y)}" hdg="{fmt(g.hdg)}" length="{fmt(g.length)}">')
    if isinstance(g, Line):
        add("        <line/>")
    elif isinstance(g, Arc):
        add(f'        <arc curvature="{fmt(g.curvature)}"/>')
    elif isinstance(g, ParamPoly3):
        add(
            f'        <paramPoly3 aU="{fmt(g.au)}" bU="{fmt(g.bu)}" cU="{fmt(g.cu)}" dU="{fmt(g.du)}"'
            f' aV="{fmt(g.av)}" bV="{fmt(g.bv)}" cV="{fmt(g.cv)}" dV="{fmt(g.dv)}" pRange="normalized"/>'
        )
    else:  # pragma: no cover - the model has no other kinds
        raise JunctionArtError(f"unknown geometry {type(g).__name__}")
    add("      </geometry>")


@functools.lru_cache(maxsize=1024)  # most widths are the same full-width record
def _cubic_line(depth: int, tag: str, c: Cubic, s_name: str) -> str:
    return f'{_INDENT[depth]}<{tag} {s_name}="{fmt(c.s)}" a="{fmt(c.a)}" b="{fmt(c.b)}" c="{fmt(c.c)}" d="{fmt(c.d)}"/>'


@functools.lru_cache(maxsize=1024)  # a handful of distinct marks make up most of a file
def _mark_line(m: RoadMark) -> str:
    change = f' laneChange="{_esc(m.lane_change)}"' if m.lane_change is not None else ""
    return (
        f'{_INDENT[6]}<roadMark sOffset="{fmt(m.s)}" type="{_esc(m.type)}" weight="standard" '
        f'color="{_esc(m.color)}" width="{fmt(m.width)}"{change}/>'
    )


def _lane(add, lane: Lane) -> None:
    head = f'          <lane id="{lane.id}" type="{_esc(lane.type)}" level="false"'
    linked = lane.predecessor is not None or lane.successor is not None
    if not (linked or (lane.id != 0 and lane.widths) or lane.marks or lane.heights):
        add(head + "/>")
        return
    add(head + ">")
    if linked:
        add("            <link>")
        if lane.predecessor is not None:
            add(f'              <predecessor id="{lane.predecessor}"/>')
        if lane.successor is not None:
            add(f'              <successor id="{lane.successor}"/>')
        add("            </link>")
    if lane.id != 0:
        for w in lane.widths:
            add(_cubic_line(6, "width", w, "sOffset"))
    for m in lane.marks:
        add(_mark_line(m))
    for h in lane.heights:
        add(f'            <height sOffset="{fmt(h.s)}" inner="{fmt(h.inner)}" outer="{fmt(h.outer)}"/>')
    add("          </lane>")


def _side(add, tag: str, lanes) -> None:
    add(f"        <{tag}>")
    for lane in lanes:
        _lane(add, lane)
    add(f"        </{tag}>")


def _section(add, sec: LaneSection) -> None:
    add(f'      <laneSection s="{fmt(sec.s)}">')
    if sec.left:
        _side(add, "left", sorted(sec.left, key=lambda lane: -lane.id))
    _side(add, "center", (sec.center,))
    if sec.right:
        _side(add, "right", sorted(sec.right, key=lambda lane: -lane.id))
    add("      </laneSection>")


def _road(out: _Out, road: Road, version: str = "1.8") -> None:
    add = out.lines.append
    out.open(
        1,
        "road",
        f' name="{_esc(road.name or f"road {road.id}")}" length="{fmt(road.length)}" '
        f'id="{_esc(road.id)}" junction="{_esc(road.junction)}" rule="{_esc(road.rule)}"',
    )
    if road.predecessor is not None or road.successor is not None:
        out.open(2, "link")
        if road.predecessor is not None:
            _link(out, 3, "predecessor", road.predecessor)
        if road.successor is not None:
            _link(out, 3, "successor", road.successor)
        out.close(2, "link")
    if road.speed_kmh is not None:
        out.open(2, "type", f' s="0.0" type="{_esc(road.road_type)}"')
        out.leaf(3, "speed", f' max="{fmt(road.speed_kmh)}" unit="km/h"')
        out.close(2, "type")
    add("    <planView>")
    for g in road.geometry:
        _geometry(add, g)
    add("    </planView>")
    add("    <elevationProfile>")
    if road.elevation:
        for c in road.elevation:
            add(_cubic_line(3, "elevation", c, "s"))
    else:
        add('      <elevation s="0.0" a="0.0" b="0.0" c="0.0" d="0.0"/>')
    add("    </elevationProfile>")
    add("    <lateralProfile/>")  # empty: valid, and tells readers there is no superelevation
    add("    <lanes>")
    for c in road.lane_offset:
        add(_cubic_line(3, "laneOffset", c, "s"))
    for sec in road.sections:
        _section(add, sec)
    add("    </lanes>")
    if road.objects or road.bridges:
        add("    <objects>")
        for obj in road.objects:
            _object(add, obj, version)
        for b in road.bridges:  # after the objects: the schemas' order (object*, objectReference*, tunnel*, bridge*)
            add(f'      <bridge s="{fmt(b.s)}" length="{fmt(b.length)}" name="{b.name}" id="{b.id}" type="{b.type}"/>')
        add("    </objects>")
    if road.signals:
        add("    <signals>")
        for sig in road.signals:
            _signal(add, sig)
        add("    </signals>")
    add("  </road>")


def _validity(add, depth: int, validity: tuple[Validity, ...]) -> None:
    for v in validity:
        add(f'{_INDENT[depth]}<validity fromLane="{v.from_lane}" toLane="{v.to_lane}"/>')


def _object(add, o: RoadObject, version: str) -> None:
    box = "" if o.length is None or o.width is None else f' length="{fmt(o.length)}" width="{fmt(o.width)}"'
    add(
        f'      <object id="{_esc(o.id)}" type="{_esc(o.type)}" name="{_esc(o.name)}" s="{fmt(o.s)}" t="{fmt(o.t)}"'
        f' zOffset="0.0" orientation="{_esc(o.orientation)}"{box} hdg="0.0" pitch="0.0" roll="0.0" height="0.0">'
    )
    add("        <outlines>")
    add('          <outline id="0" closed="true">')
    for k, c in enumerate(o.outline):
        add(f'            <cornerRoad s="{fmt(c.s)}" t="{fmt(c.t)}" dz="0.0" height="0.0" id="{k}"/>')
    in_outline = version == "1.9"  # 1.9 puts an outline's markings into it; 1.7 and 1.8 into the object (13.8)
    if in_outline:
        _markings(add, 6, o.markings)
    add("          </outline>")
    add("        </outlines>")
    _validity(add, 4, o.validity)
    if not in_outline:
        _markings(add, 4, o.markings)
    add("      </object>")


def _markings(add, depth: int, markings: tuple[ObjectMarking, ...]) -> None:
    """``<markings>`` through outline corners (``cornerReference`` ids are the corners' indices)."""
    if not markings:
        return
    add(f"{_INDENT[depth]}<markings>")
    for m in markings:
        add(
            f'{_INDENT[depth + 1]}<marking width="{fmt(m.width)}" color="{_esc(m.color)}" zOffset="{fmt(m.z_offset)}"'
            f' spaceLength="{fmt(m.space_length)}" lineLength="{fmt(m.line_length)}" startOffset="0.0"'
            ' stopOffset="0.0">'
        )
        for k in m.corners:
            add(f'{_INDENT[depth + 2]}<cornerReference id="{k}"/>')
        add(f"{_INDENT[depth + 1]}</marking>")
    add(f"{_INDENT[depth]}</markings>")


def _signal(add, g: Signal) -> None:
    head = (
        f'      <signal s="{fmt(g.s)}" t="{fmt(g.t)}" id="{_esc(g.id)}" name="{_esc(g.name)}"'
        f' dynamic="{"yes" if g.dynamic else "no"}" orientation="{_esc(g.orientation)}" zOffset="{fmt(g.z_offset)}"'
        f' country="{_esc(g.country)}" type="{_esc(g.type)}" subtype="{_esc(g.subtype)}" hOffset="{fmt(g.h_offset)}"'
        f' pitch="0.0" roll="0.0" height="{fmt(g.height)}" width="{fmt(g.width)}"'
    )
    if not (g.validity or g.dependencies or g.references):
        add(head + "/>")
        return
    add(head + ">")
    _validity(add, 4, g.validity)
    for d in g.dependencies:
        add(f'        <dependency id="{_esc(d.element_id)}" type="{_esc(d.type)}"/>')
    for r in g.references:
        add(
            f'        <reference elementType="{_esc(r.element_type)}" elementId="{_esc(r.element_id)}"'
            f' type="{_esc(r.type)}"/>'
        )
    add("      </signal>")


def _controller(out: _Out, c: Controller) -> None:
    out.open(1, "controller", f' id="{_esc(c.id)}" name="{_esc(c.name)}"')
    for sid in c.signals:
        out.leaf(2, "control", f' signalId="{_esc(sid)}"')
    out.close(1, "controller")


def _junction(out: _Out, j: Junction) -> None:
    head = f' name="{_esc(j.name)}" id="{_esc(j.id)}"'
    if j.type != "default":  # a default junction is written as before, without the attribute
        head += f' type="{_esc(j.type)}"'
    if not j.connections:
        out.leaf(1, "junction", head)
        return
    out.open(1, "junction", head)
    road_attr = "linkedRoad" if j.type == "direct" else "connectingRoad"
    for c in j.connections:
        attrs = (
            f' id="{_esc(c.id)}" incomingRoad="{_esc(c.incoming_road)}" '
            f'{road_attr}="{_esc(c.connecting_road)}" contactPoint="{_esc(c.contact_point)}"'
        )
        if not c.lane_links:
            out.leaf(2, "connection", attrs)
            continue
        out.open(2, "connection", attrs)
        for ll in c.lane_links:
            out.leaf(3, "laneLink", f' from="{ll.from_lane}" to="{ll.to_lane}"')
        out.close(2, "connection")
    for jc in j.controllers:
        out.leaf(2, "controller", f' id="{_esc(jc.id)}" sequence="{jc.sequence}"')
    out.close(1, "junction")


def to_bytes(doc: Document, version: str = "1.8") -> bytes:
    """The file content for OpenDRIVE ``version`` ("1.8", "1.9" or "1.7"): the XML declaration first, UTF-8, indented
    two spaces per level, deterministic."""
    if version not in REV_MINOR:
        raise JunctionArtError(f"version {version!r}: must be one of {', '.join(REV_MINOR)}")
    out = _Out()
    out.lines.append('<?xml version="1.0" encoding="UTF-8"?>')
    out.open(0, "OpenDRIVE")
    h = doc.header
    date = f' date="{_esc(h.date)}"' if h.date else ""
    bounds = "".join(f' {k}="{fmt(getattr(h, k))}"' for k in ("north", "south", "east", "west"))
    out.leaf(
        1,
        "header",
        f' revMajor="1" revMinor="{REV_MINOR[version]}" name="{_esc(h.name)}" version="1.00"'
        f'{date}{bounds} vendor="{_esc(h.vendor)}"',
    )
    for road in doc.roads:
        _road(out, road, version)
    for c in doc.controllers:
        _controller(out, c)
    for j in doc.junctions:
        _junction(out, j)
    out.close(0, "OpenDRIVE")
    out.lines.append("")
    return "\n".join(out.lines).encode("utf-8")


def write(doc: Document, path: str | os.PathLike[str], version: str = "1.8") -> Path:
    """Write ``doc`` to ``path`` atomically (:mod:`xodrcheck.support.atomic`, shared by every command of both tools): on
    any error, Ctrl-C or SIGTERM no file and no temporary file is left behind. Raises :class:`OutputError` naming
    ``path`` and the cause when it cannot be written."""
    from xodrcheck.support.atomic import OutputError as _TargetError
    from xodrcheck.support.atomic import check_target, write_bytes

    try:
        check_target(path)  # before the document is serialised
        return write_bytes(path, to_bytes(doc, version))
    except _TargetError as exc:
        raise OutputError(str(exc)) from None
