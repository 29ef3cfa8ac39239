"""``<junction>`` elements to :class:`~xodrcheck.model.Junction`: connections and lane links, read with findings as
topology needs them; the junction's other parts are read by :mod:`.junction_parts` (loaded for a junction that has
some)."""

from __future__ import annotations

from dataclasses import replace

from lxml import etree

from xodrcheck import model
from xodrcheck.model import ConnectionType, Junction, JunctionLaneLink, JunctionType, LaneLayer
from xodrcheck.reader.context import LEAF, Context
from xodrcheck.reader.lanes import LAYERS, layered
from xodrcheck.reader.roads import CONTACT_POINTS

_JUNCTION_TYPES = {t.value: t for t in JunctionType}
_CONNECTION_TYPES = {t.value: t for t in ConnectionType}
#: Children of a junction :mod:`.junction_parts` reads.
PARTS = frozenset(
    {
        "crossPath",
        "priority",
        "controller",
        "surface",
        "planView",
        "objects",
        "boundary",
        "elevationGrid",
        "roadSection",
    }
)
_JUNCTION = PARTS | {"connection"}
_CONNECTION = frozenset({"laneLink", "predecessor", "successor"})


# ------------------------------------------------------------------------------------------------------ connections
def _layer(ctx: Context, el: etree._Element, name: str) -> LaneLayer:
    return ctx.choice(el, name, LAYERS, "read as permanent, the standard's default") or LaneLayer.PERMANENT


def _lane_links(ctx: Context, el: etree._Element) -> tuple[tuple[JunctionLaneLink, ...], tuple[JunctionLaneLink, ...]]:
    """The connection's lane links between permanent-layer lanes, then those with an end on a temporary layer."""
    out = []
    temporary = []
    with_layers = layered(ctx)
    for ll in el.iterchildren("laneLink"):
        try:
            from_lane, to_lane = int(ll.get("from")), int(ll.get("to"))
        except (TypeError, ValueError):
            for name in ("from", "to"):  # report whichever is missing or not an integer
                ctx.integer(ll, name, "the lane link is ignored")
            continue
        from_layer = to_layer = LaneLayer.PERMANENT
        if with_layers and (ll.get("fromLayer") is not None or ll.get("toLayer") is not None):
            from_layer, to_layer = _layer(ctx, ll, "fromLayer"), _layer(ctx, ll, "toLayer")
        zone = ctx.opt_number(ll, "overlapZone")
        link = JunctionLaneLink(from_lane, to_lane, ll.sourceline, from_layer, to_layer, zone, ctx.facts(ll, LEAF))
        if LaneLayer.TEMPORARY in (from_layer, to_layer):
            temporary.append(link)
        else:
            out.append(link)
    return tuple(out), tuple(temporary)


def _connection(ctx: Context, c: etree._Element) -> model.Connection:
    get = c.get
    connection_id = get("id")
    if connection_id is None:
        ctx.missing(c, "id", "the connection is kept with an empty id")
        connection_id = ""
    contact = None
    if get("contactPoint") is not None:
        contact = ctx.choice(c, "contactPoint", CONTACT_POINTS, "read as absent")
    links, temporary_links = _lane_links(ctx, c)
    predecessor = successor = None
    if c.find("predecessor") is not None or c.find("successor") is not None:  # a virtual connection's ends
        from xodrcheck.reader.junction_parts import connection_ends

        predecessor, successor = connection_ends(ctx, c)
    return model.Connection(
        connection_id,
        get("incomingRoad"),
        get("connectingRoad"),
        get("linkedRoad"),
        contact,
        links,
        c.sourceline,
        temporary_links,
        ctx.opt_enum(c, "type", _CONNECTION_TYPES),
        predecessor,
        successor,
        ctx.facts(c, _CONNECTION),
    )


# ------------------------------------------------------------------------------------------------------ junctions
def build_junction(ctx: Context, el: etree._Element) -> Junction | None:
    """The junction of ``el``, or ``None`` (with a finding) when it has no id."""
    junction_id = el.get("id")
    if junction_id is None:
        ctx.missing(el, "id", "the junction is skipped (nothing could refer to it)")
        return None
    ctx.junction = junction_id
    try:
        return _junction(ctx, el, junction_id)
    finally:
        ctx.junction = None


def _junction(ctx: Context, el: etree._Element, junction_id: str) -> Junction:
    junction_type = JunctionType.DEFAULT
    if el.get("type") is not None:
        junction_type = ctx.choice(el, "type", _JUNCTION_TYPES, "read as default") or JunctionType.DEFAULT
    connections = tuple(_connection(ctx, c) for c in el.iterchildren("connection"))
    junction = Junction(junction_id, el.get("name"), junction_type, connections, el.sourceline, el.get("mainRoad"))
    if any(child.tag in PARTS for child in el) or any(
        el.get(name) is not None for name in ("sStart", "sEnd", "orientation")
    ):
        from xodrcheck.reader.junction_parts import with_parts

        junction = with_parts(ctx, el, junction)
    return replace(junction, xml=ctx.facts(el, _JUNCTION))
