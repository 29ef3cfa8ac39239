"""The ``<OpenDRIVE>`` root to a :class:`~xodrcheck.model.Document`: header, roads, junctions, top-level counts."""

from __future__ import annotations

from lxml import etree

from xodrcheck import model
from xodrcheck.model import (
    Document,
    Header,
    Junction,
    JunctionLaneLink,
    JunctionType,
    LaneLayer,
    Offset,
)
from xodrcheck.reader.context import Context, describe
from xodrcheck.reader.lanes import LAYERS, layered
from xodrcheck.reader.roads import CONTACT_POINTS, build_road
from xodrcheck.rules import xml as R

#: Versions this reader knows: 1.1 to 1.9.
KNOWN_VERSIONS = frozenset((1, minor) for minor in range(1, 10))

_JUNCTION_TYPES = {t.value: t for t in JunctionType}
_OFFSET = ["x", "y", "z", "hdg"]
_NONE: tuple[int, ...] = ()
_BOUNDS = ("north", "south", "east", "west")


def build_header(ctx: Context, el: etree._Element) -> Header:
    rev_major = ctx.integer(el, "revMajor", "the OpenDRIVE version is unknown")
    rev_minor = ctx.integer(el, "revMinor", "the OpenDRIVE version is unknown")
    if rev_major is not None and rev_minor is not None:
        if (rev_major, rev_minor) in KNOWN_VERSIONS:
            ctx.version = (rev_major, rev_minor)
        else:
            ctx.report(
                R.UNKNOWN_VERSION,
                f"{describe(el)} declares OpenDRIVE {rev_major}.{rev_minor}, which is not one of 1.1 to 1.9; "
                "it is read as an OpenDRIVE 1.9 file, so what that version changed may be misread",
                el,
            )
    north, south, east, west = (ctx.number(el, name, "read as absent", required=False) for name in _BOUNDS)
    geo_reference = offset = None
    for child in el:
        tag = child.tag
        if tag == "geoReference":
            if geo_reference is None:
                geo_reference = (child.text or "").strip()
        elif tag == "offset" and offset is None:
            v = ctx.floats(child, _OFFSET, _NONE, "the offset is ignored")
            if v is not None:
                offset = Offset(*v)
    return Header(
        rev_major,
        rev_minor,
        el.get("name"),
        el.get("version"),
        el.get("date"),
        el.get("vendor"),
        north,
        south,
        east,
        west,
        geo_reference=geo_reference,
        offset=offset,
        line=el.sourceline,
    )


def _lane_links(ctx: Context, el: etree._Element) -> tuple[tuple[JunctionLaneLink, ...], tuple[JunctionLaneLink, ...]]:
    """The connection's lane links between permanent-layer lanes, then those with an end on a temporary layer."""
    out = []
    temporary = []
    with_layers = layered(ctx)
    for ll in el.iterchildren("laneLink"):
        try:
            link = model.JunctionLaneLink(int(ll.get("from")), int(ll.get("to")), ll.sourceline)
        except (TypeError, ValueError):
            for name in ("from", "to"):  # report whichever is missing or not an integer
                ctx.integer(ll, name, "the lane link is ignored")
            continue
        if with_layers and (ll.get("fromLayer") is not None or ll.get("toLayer") is not None):
            link = model.JunctionLaneLink(
                link.from_lane, link.to_lane, link.line, _layer(ctx, ll, "fromLayer"), _layer(ctx, ll, "toLayer")
            )
            if LaneLayer.TEMPORARY in (link.from_layer, link.to_layer):
                temporary.append(link)
                continue
        out.append(link)
    return tuple(out), tuple(temporary)


def _layer(ctx: Context, el: etree._Element, name: str) -> LaneLayer:
    return ctx.choice(el, name, LAYERS, "read as permanent, the standard's default") or LaneLayer.PERMANENT


def build_junction(ctx: Context, el: etree._Element) -> Junction | None:
    """The junction of ``el``, or ``None`` (with a finding) when it has no id."""
    junction_id = el.get("id")
    if junction_id is None:
        ctx.missing(el, "id", "the junction is skipped (nothing could refer to it)")
        return None
    ctx.junction = junction_id
    try:
        junction_type = JunctionType.DEFAULT
        if el.get("type") is not None:
            junction_type = ctx.choice(el, "type", _JUNCTION_TYPES, "read as default") or JunctionType.DEFAULT
        connections = []
        for c in el.iterchildren("connection"):
            get = c.get
            connection_id = get("id")
            if connection_id is None:
                ctx.missing(c, "id", "the connection is kept with an empty id")
                connection_id = ""
            contact = None
            if get("contactPoint") is not None:
                contact = ctx.choice(c, "contactPoint", CONTACT_POINTS, "read as absent")
            links, temporary_links = _lane_links(ctx, c)
            connections.append(
                model.Connection(
                    connection_id,
                    get("incomingRoad"),
                    get("connectingRoad"),
                    get("linkedRoad"),
                    contact,
                    links,
                    c.sourceline,
                    temporary_links,
                )
            )
        crossing_roads = tuple(
            dict.fromkeys(road for r in el.iterchildren("roadSection") if (road := r.get("roadId")) is not None)
        )
        main_road = el.get("mainRoad") if junction_type is JunctionType.VIRTUAL else None
        return Junction(
            junction_id, el.get("name"), junction_type, tuple(connections), el.sourceline, main_road, crossing_roads
        )
    finally:
        ctx.junction = None


def build_document(ctx: Context, root: etree._Element, source: str | None) -> Document | None:
    """The document of ``root``; ``None`` (with a finding) when the root is not ``<OpenDRIVE>``."""
    if root.tag != "OpenDRIVE":
        ctx.report(
            R.WRONG_ROOT,
            f"the root element is <{root.tag}>, not <OpenDRIVE>: this is not an OpenDRIVE file and nothing is read",
            root,
        )
        return None
    header_el = None
    header = None
    roads = []
    junctions = []
    controllers = 0
    extras: dict[str, int] = {}
    for child in root.iterchildren("header"):
        if header_el is None:
            header_el = child
            header = build_header(ctx, child)
        else:
            ctx.repeated(child, header_el)
    if header_el is None:
        ctx.report(R.MISSING_ELEMENT, f"{describe(root)} has no <header>; the OpenDRIVE version is unknown", root)
    for child in root:
        tag = child.tag
        if tag == "road":
            road = build_road(ctx, child)
            if road is not None:
                roads.append(road)
        elif tag == "junction":
            junction = build_junction(ctx, child)
            if junction is not None:
                junctions.append(junction)
        elif tag == "controller":
            controllers += 1
        elif tag != "header" and isinstance(tag, str):
            extras[tag] = extras.get(tag, 0) + 1
    return Document(header, tuple(roads), tuple(junctions), controllers, source, extras)
