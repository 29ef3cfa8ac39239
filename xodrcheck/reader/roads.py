"""``<road>`` elements to :class:`~xodrcheck.model.Road`: attributes, links, plan view and road-level profiles.

Lanes are built by :mod:`xodrcheck.reader.lanes`. What cannot be built is skipped with a finding; a road without an
``id`` is skipped whole (nothing could refer to it), a road with an unusable ``length`` keeps the sum of its geometry
lengths (and says so).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from lxml import etree

from xodrcheck import model
from xodrcheck.findings import Severity
from xodrcheck.model import (
    ContactPoint,
    ElementType,
    Geometry,
    PRange,
    Profile,
    Road,
    RoadLink,
    TrafficRule,
    UnreadLink,
    XmlFacts,
)
from xodrcheck.reader.context import ELEMENT_DIRS, LEAF, Context, cubics, describe
from xodrcheck.reader.lanes import build_layers
from xodrcheck.rules import xml as R
from xodrcheck.rules.shared import road_uids as RU
from xodrcheck.rules.shared.lane_uids import SECTION_REQ as LANE_SECTION_REQUIRED
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.model import (
        Bridge,
        CrossSectionSurface,
        ObjectReference,
        Railroad,
        RoadObject,
        RoadType,
        Shape,
        Signal,
        SignalReference,
        Surface,
        Tunnel,
    )

ELEMENT_TYPES = {"road": ElementType.ROAD, "junction": ElementType.JUNCTION}
CONTACT_POINTS = {"start": ContactPoint.START, "end": ContactPoint.END}
_TRAFFIC_RULES = {"rht": TrafficRule.RHT, "lht": TrafficRule.LHT}
P_RANGES = {"arclength": PRange.ARC_LENGTH, "normalized": PRange.NORMALIZED}

# attribute names as lists, the type of ``el.keys()``, which Context.floats compares them with
_GEOMETRY = ["s", "x", "y", "hdg", "length"]
_GEOMETRY_NONNEG = (0, 4)
_SPIRAL = ["curvStart", "curvEnd"]
_POLY3 = ["a", "b", "c", "d"]
_PARAM_POLY3 = ["aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"]
_NONE: tuple[int, ...] = ()
#: Children of ``<geometry>`` that are not its shape.
_GEOMETRY_EXTRAS = frozenset({"userData", "include", "dataQuality"})
SKIP_GEOMETRY = "the geometry is skipped"


# ---------------------------------------------------------------------------------------------------------- plan view
def _line(ctx: Context, kind: etree._Element, head: tuple[float, ...], line: int, xml: XmlFacts) -> Geometry | None:
    return model.Line(head[0], head[1], head[2], head[3], head[4], line, xml)


def _arc(ctx: Context, kind: etree._Element, head: tuple[float, ...], line: int, xml: XmlFacts) -> Geometry | None:
    k = ctx.number(kind, "curvature", SKIP_GEOMETRY)
    return None if k is None else model.Arc(head[0], head[1], head[2], head[3], head[4], k, line, xml)


def _spiral(ctx: Context, kind: etree._Element, head: tuple[float, ...], line: int, xml: XmlFacts) -> Geometry | None:
    k = ctx.floats(kind, _SPIRAL, _NONE, SKIP_GEOMETRY)
    return None if k is None else model.Spiral(head[0], head[1], head[2], head[3], head[4], k[0], k[1], line, xml)


def _poly3(ctx: Context, kind: etree._Element, head: tuple[float, ...], line: int, xml: XmlFacts) -> Geometry | None:
    c = ctx.floats(kind, _POLY3, _NONE, SKIP_GEOMETRY)
    if c is None:
        return None
    return model.Poly3(head[0], head[1], head[2], head[3], head[4], c[0], c[1], c[2], c[3], line, xml)


def _param_poly3(
    ctx: Context, kind: etree._Element, head: tuple[float, ...], line: int, xml: XmlFacts
) -> Geometry | None:
    c = ctx.floats(kind, _PARAM_POLY3, _NONE, SKIP_GEOMETRY)
    if c is None:
        return None
    p_range = PRange.NORMALIZED
    raw = kind.get("pRange")
    if raw is None:
        then = (
            "read as normalized (p in [0, 1]), the OpenDRIVE 1.4 default also used by libOpenDRIVE and esmini; "
            "CARLA reads arcLength instead"
        )
        if ctx.version is not None and ctx.version < (1, 5):
            ctx.missing(kind, "pRange", then, severity=Severity.INFO)
        else:
            ctx.missing(kind, "pRange", "it is required since OpenDRIVE 1.5; " + then)
    else:
        chosen = ctx.choice(kind, "pRange", P_RANGES, SKIP_GEOMETRY)
        if chosen is None:
            return None
        p_range = chosen
    return model.ParamPoly3(
        head[0], head[1], head[2], head[3], head[4], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], p_range, line, xml
    )


_KINDS = {"line": _line, "arc": _arc, "spiral": _spiral, "poly3": _poly3, "paramPoly3": _param_poly3}
_SHAPES = frozenset(_KINDS)


def _geometry(ctx: Context, el: etree._Element) -> Geometry | None:
    head = ctx.floats(el, _GEOMETRY, _GEOMETRY_NONNEG, SKIP_GEOMETRY)
    kind = None
    unknown = None
    for child in el:
        tag = child.tag
        if tag in _KINDS:
            if kind is not None:
                ctx.report(
                    R.UNKNOWN_GEOMETRY,
                    f"{describe(el)} has both <{kind.tag}> and <{tag}> (line {child.sourceline}); a geometry has "
                    f"exactly one shape, so it is skipped",
                    el,
                    uid=RU.GEOMETRY_ONE_ELEMENT,
                )
                return None
            kind = child
        elif unknown is None and isinstance(tag, str) and tag not in _GEOMETRY_EXTRAS:
            unknown = child
    if kind is None:
        if unknown is not None:
            why = f"has <{unknown.tag}> (line {unknown.sourceline}), which is not an OpenDRIVE geometry shape"
        else:
            why = "has no shape element"
        ctx.report(
            R.UNKNOWN_GEOMETRY,
            f"{describe(el)} {why} (expected one of line, arc, spiral, poly3, paramPoly3); {SKIP_GEOMETRY}, "
            "leaving a gap in the reference line",
            el,
            uid=RU.GEOMETRY_ONE_ELEMENT,
        )
        return None
    if head is None:
        return None
    return _KINDS[kind.tag](ctx, kind, head, el.sourceline, ctx.facts(el, _SHAPES))


def _plan_view(ctx: Context, el: etree._Element) -> tuple[Geometry, ...]:
    out = []
    seen = False
    for g in el:
        if g.tag == "geometry":
            seen = True
            geometry = _geometry(ctx, g)
            if geometry is not None:
                out.append(geometry)
    if not seen:
        ctx.missing_child(el, "geometry", "the road has no reference line", RU.GEOMETRY_REFLINE_EXISTS)
    elif len(out) > 1:
        ctx.check_order(out, "<geometry>", el, RU.GEOMETRY_ORDER)
    return tuple(out)


# ---------------------------------------------------------------------------------------------------------- links
def _road_link(ctx: Context, el: etree._Element) -> RoadLink | None:
    then = "the link is ignored"
    raw_type = el.get("elementType")
    element_id = el.get("elementId")
    if raw_type is None:
        ctx.missing(el, "elementType", then)
        return None
    if element_id is None:
        ctx.missing(el, "elementId", then)
        return None
    element_type = ELEMENT_TYPES.get(raw_type.strip().lower())
    if element_type is None:
        ctx.invalid(el, "elementType", raw_type, "which is not one of junction, road", then)
        return None
    contact = ctx.choice(el, "contactPoint", CONTACT_POINTS, "read as absent")
    element_s = element_dir = None
    if el.get("elementS") is not None:
        element_s = ctx.number(el, "elementS", "read as absent", nonneg=True)
    if el.get("elementDir") is not None:
        element_dir = ctx.choice(el, "elementDir", ELEMENT_DIRS, "read as absent")
    return model.RoadLink(element_type, element_id, contact, element_s, element_dir, el.sourceline, ctx.facts(el, LEAF))


def _links(ctx: Context, el: etree._Element) -> tuple[RoadLink | None, RoadLink | None, tuple[UnreadLink, ...]]:
    """The road's predecessor and successor, and the links among them it could not read."""
    found: dict[str, etree._Element] = {}
    for child in el:
        tag = child.tag
        if tag == "predecessor" or tag == "successor":
            if tag in found:
                ctx.repeated(child, found[tag])
            else:
                found[tag] = child
    links: dict[str, RoadLink | None] = {}
    unread = []
    for tag, child in found.items():
        links[tag] = link = _road_link(ctx, child)
        if link is None:
            unread.append(
                UnreadLink(
                    tag, child.get("elementType"), child.get("elementId"), child.sourceline, ctx.facts(child, LEAF)
                )
            )
    return links.get("predecessor"), links.get("successor"), tuple(unread)


# ---------------------------------------------------------------------------------------------------------- road
#: Children of ``<road>`` that may appear at most once.
_ONCE = frozenset({"link", "planView", "elevationProfile", "lateralProfile", "objects", "signals"})
#: Children of ``<road>`` the reader reads (the others are unknown there).
_ROAD = _ONCE | {"lanes", "type", "surface", "railroad"}


def build_road(ctx: Context, el: etree._Element) -> Road | None:
    """The road of ``el``, or ``None`` (with a finding) when it has no id."""
    get = el.get
    road_id = get("id")
    if road_id is None:
        ctx.missing(el, "id", "the road is skipped (nothing could refer to it)")
        return None
    ctx.road = road_id
    try:
        return _road(ctx, el, road_id)
    finally:
        ctx.road = None


def _children(
    ctx: Context, el: etree._Element
) -> tuple[dict[str, etree._Element], list[etree._Element], tuple[str, ...]]:
    """The first of each child of a road that may appear once (a repeated one is reported and skipped) or that the
    reader reads once (``<surface>``, ``<railroad>``); its ``<lanes>`` (one per lane layer in 1.9: :func:`build_layers`
    sorts them out); and the tags of all its children."""
    first: dict[str, etree._Element] = {}
    lanes: list[etree._Element] = []
    tags = []
    for child in el:
        tag = child.tag
        tags.append(tag)
        if tag == "lanes":
            lanes.append(child)
        elif tag in _ONCE:
            if tag in first:
                ctx.repeated(child, first[tag], RU.GEOMETRY_ONLY_ONE_REFLINE if tag == "planView" else None)
            else:
                first[tag] = child
        elif (tag == "surface" or tag == "railroad") and tag not in first:
            first[tag] = child
    return first, lanes, tuple(tags)


def _reference_line(ctx: Context, el: etree._Element, plan_view: etree._Element | None) -> tuple[Geometry, ...]:
    if plan_view is None:
        ctx.missing_child(el, "planView", "the road has no reference line", RU.GEOMETRY_REFLINE_EXISTS)
        return ()
    return _plan_view(ctx, plan_view)


def _length(ctx: Context, el: etree._Element, plan_view: tuple[Geometry, ...]) -> float:
    """The road's ``length``; when it is missing or unusable (with a finding), the sum of its geometries' lengths."""
    try:
        length = ctx.numbers[el.get("length")]
        if length >= 0.0:
            return length
    except (TypeError, ValueError):
        pass
    total = sum(g.length for g in plan_view)
    given = ctx.number(el, "length", f"the sum of its geometry lengths ({metres(total)}) is used", nonneg=True)
    return total if given is None else given


def _junction(ctx: Context, el: etree._Element) -> str | None:
    """The id of the junction the road belongs to; ``None`` for "-1" (outside any junction), or with a finding when
    the attribute is missing or empty."""
    raw = el.get("junction")
    if raw is None:
        ctx.missing(el, "junction", 'read as "-1" (not inside a junction)')
        return None
    junction = None if raw.strip() == "-1" else raw
    if junction is not None and not junction.strip():
        ctx.invalid(el, "junction", raw, "which is empty", 'read as "-1" (not inside a junction)')
        return None
    return junction


def _lateral(ctx: Context, el: etree._Element | None) -> tuple[Profile, tuple[Shape, ...], CrossSectionSurface | None]:
    """The superelevation profile, the shapes and the cross section surface of a ``<lateralProfile>``."""
    if el is None:
        return (), (), None
    superelevation = cubics(ctx, el, "superelevation", RU.SUPERELEVATION_ORDER)
    shapes: tuple[Shape, ...] = ()
    surface = None
    if len(el) > len(superelevation):  # more than superelevations: read here, most roads have none
        from xodrcheck.reader import road_records

        shapes = tuple(road_records.shape(ctx, child) for child in el.iterchildren("shape"))
        found = el.find("crossSectionSurface")
        surface = None if found is None else road_records.cross_section_surface(ctx, found)
    return superelevation, shapes, surface


def _records(
    ctx: Context, el: etree._Element, first: dict[str, etree._Element]
) -> tuple[tuple[RoadType, ...], Surface | None, Railroad | None]:
    """The road's types, surface and railroad (read by :mod:`.road_records`, loaded for a road that has one)."""
    if el.find("type") is None and "surface" not in first and "railroad" not in first:
        return (), None, None
    from xodrcheck.reader import road_records

    types = tuple(road_records.road_type(ctx, child) for child in el.iterchildren("type"))
    surface = None if "surface" not in first else road_records.surface(ctx, first["surface"])
    railroad = None if "railroad" not in first else road_records.railroad(ctx, first["railroad"])
    return types, surface, railroad


#: What a road without ``<objects>`` holds: no objects, references, tunnels or bridges.
_NO_OBJECTS: tuple[tuple[RoadObject, ...], tuple[ObjectReference, ...], tuple[Tunnel, ...], tuple[Bridge, ...]] = (
    (),
    (),
    (),
    (),
)


def _objects(
    ctx: Context, road_id: str, first: dict[str, etree._Element]
) -> tuple[tuple[RoadObject, ...], tuple[ObjectReference, ...], tuple[Tunnel, ...], tuple[Bridge, ...]]:
    """The road's objects, object references, tunnels and bridges (an ``<objects>`` without an element in it holds
    none: the objects' reader and model are not loaded for it)."""
    if "objects" not in first or next(first["objects"].iterchildren(etree.Element), None) is None:
        return _NO_OBJECTS
    from xodrcheck.reader.objects import read_objects

    found = read_objects(ctx, road_id, first["objects"])
    return found.objects, found.references, found.tunnels, found.bridges


def _signals(
    ctx: Context, road_id: str, first: dict[str, etree._Element]
) -> tuple[tuple[Signal, ...], tuple[SignalReference, ...]]:
    if "signals" not in first:
        return (), ()
    from xodrcheck.reader.signals import read_signals

    return read_signals(ctx, road_id, first["signals"])


def _road(ctx: Context, el: etree._Element, road_id: str) -> Road:
    first, lanes, tags = _children(ctx, el)
    plan_view = _reference_line(ctx, el, first.get("planView"))
    length = _length(ctx, el, plan_view)
    junction = _junction(ctx, el)
    rule = _traffic_rule(ctx, el)
    pred = succ = None
    unread: tuple[UnreadLink, ...] = ()
    link = first.get("link")
    if link is not None:
        pred, succ, unread = _links(ctx, link)
    elevation: Profile = ()
    if "elevationProfile" in first:
        elevation = cubics(ctx, first["elevationProfile"], "elevation", RU.ELEVATION_ORDER)
    superelevation, shapes, cross_section = _lateral(ctx, first.get("lateralProfile"))
    permanent = temporary = None
    if not lanes:
        ctx.missing_child(el, "lanes", "the road has no lanes", LANE_SECTION_REQUIRED)
    else:
        permanent, temporary = build_layers(ctx, lanes)
    types, surface, railroad = _records(ctx, el, first)
    objects, object_references, tunnels, bridges = _objects(ctx, road_id, first)
    signals, references = _signals(ctx, road_id, first)
    return model.Road(
        id=road_id,
        length=length,
        junction=junction,
        name=el.get("name"),
        rule=rule,
        predecessor=pred,
        successor=succ,
        plan_view=plan_view,
        elevation=elevation,
        superelevation=superelevation,
        lane_offset=() if permanent is None else permanent.lane_offset,
        lane_sections=() if permanent is None else permanent.lane_sections,
        objects=objects,
        signals=signals,
        line=el.sourceline,
        temporary_lanes=temporary,
        lanes=permanent,
        types=types,
        shapes=shapes,
        cross_section_surface=cross_section,
        surface=surface,
        railroad=railroad,
        object_references=object_references,
        tunnels=tunnels,
        bridges=bridges,
        signal_references=references,
        xml=ctx.facts(el, _ROAD, children=tags),
        unread_links=unread,
    )


def _traffic_rule(ctx: Context, el: etree._Element) -> TrafficRule:
    """``@rule``: right-hand traffic when absent (the standard's default) or not a value of its type."""
    if el.get("rule") is None:
        return TrafficRule.RHT
    return ctx.choice(el, "rule", _TRAFFIC_RULES, "read as RHT, the standard's default") or TrafficRule.RHT
