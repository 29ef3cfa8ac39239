"""A road's records beside its reference line and lanes: ``<type>`` (with ``<speed>``), the lateral profile's
``<shape>`` records and ``<crossSectionSurface>``, ``<surface>`` (OpenCRG, also a junction's) and ``<railroad>``; and
the file's ``<station>`` elements.

Read as the file gives them (:meth:`Context.opt_number <xodrcheck.reader.context.Context.opt_number>` and the like):
the schema rule reports bad values, so nothing here adds a finding.
"""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import (
    CrgMode,
    CrgOrientation,
    CrgPurpose,
    CrossSectionSurface,
    MaxSpeed,
    Platform,
    PlatformSegment,
    Railroad,
    RoadSpeed,
    RoadType,
    Shape,
    Side,
    Station,
    StationType,
    Surface,
    SurfaceCoefficients,
    SurfaceCrg,
    SurfacePolynomial,
    SurfaceStrip,
    Switch,
    SwitchPartner,
    SwitchPosition,
    SwitchTrack,
)
from xodrcheck.reader.context import ELEMENT_DIRS, LEAF, Context

_MAX_SPEEDS = {word.value: word for word in MaxSpeed}
_CRG_MODES = {mode.value: mode for mode in CrgMode}
_CRG_PURPOSES = {purpose.value: purpose for purpose in CrgPurpose}
_CRG_ORIENTATIONS = {o.value: o for o in CrgOrientation}
_SWITCH_POSITIONS = {p.value: p for p in SwitchPosition}
#: The polynomials of a cross section surface strip (10.5.4), in the standard's order.
STRIP_POLYNOMIALS = ("width", "constant", "linear", "quadratic", "cubic")
_STRIP = frozenset(STRIP_POLYNOMIALS)
_SHAPE = ("s", "t", "a", "b", "c", "d")
_COEFFICIENTS = frozenset({"coefficients"})


# ------------------------------------------------------------------------------------------------------ road types
def road_type(ctx: Context, el: etree._Element) -> RoadType:
    """A ``<type>`` and its ``<speed>`` (the first; the schema allows one)."""
    speed = None
    for child in el.iterchildren("speed"):
        speed = _speed(ctx, child)
        break
    return RoadType(
        ctx.opt_number(el, "s"),
        el.get("type"),
        el.get("country"),
        speed,
        el.sourceline,
        ctx.facts(el, frozenset({"speed"})),
    )


def _speed(ctx: Context, el: etree._Element) -> RoadSpeed:
    raw = el.get("max")
    value: float | MaxSpeed | None = None
    if raw is not None:
        value = _MAX_SPEEDS.get(raw)
        if value is None:
            value = ctx.opt_number(el, "max")
    return RoadSpeed(value, el.get("unit"), el.sourceline, ctx.facts(el, LEAF))


# ------------------------------------------------------------------------------------------------------ lateral profile
def shape(ctx: Context, el: etree._Element) -> Shape:
    s, t, a, b, c, d = (ctx.opt_number(el, name) for name in _SHAPE)
    return Shape(s, t, a, b, c, d, el.sourceline, ctx.facts(el, LEAF))


def _coefficients(ctx: Context, el: etree._Element) -> SurfaceCoefficients:
    n = ctx.opt_number
    return SurfaceCoefficients(
        n(el, "s"), n(el, "a"), n(el, "b"), n(el, "c"), n(el, "d"), el.sourceline, ctx.facts(el, LEAF)
    )


def _polynomial(ctx: Context, el: etree._Element) -> SurfacePolynomial:
    records = tuple(_coefficients(ctx, c) for c in el.iterchildren("coefficients"))
    return SurfacePolynomial(el.tag, records, el.sourceline, ctx.facts(el, _COEFFICIENTS))


def _strip(ctx: Context, el: etree._Element) -> SurfaceStrip:
    polynomials = tuple(_polynomial(ctx, child) for child in el.iterchildren(*STRIP_POLYNOMIALS))
    return SurfaceStrip(ctx.opt_integer(el, "id"), el.get("mode"), polynomials, el.sourceline, ctx.facts(el, _STRIP))


def cross_section_surface(ctx: Context, el: etree._Element) -> CrossSectionSurface:
    """A ``<crossSectionSurface>`` (1.8): its ``<tOffset>`` and the strips of every ``<surfaceStrips>``."""
    t_offset = None
    strips: list[SurfaceStrip] = []
    for child in el:
        tag = child.tag
        if tag == "tOffset" and t_offset is None:
            t_offset = _polynomial(ctx, child)
        elif tag == "surfaceStrips":
            strips.extend(_strip(ctx, strip) for strip in child.iterchildren("strip"))
    known = frozenset({"tOffset", "surfaceStrips"})
    return CrossSectionSurface(t_offset, tuple(strips), el.sourceline, ctx.facts(el, known))


# ------------------------------------------------------------------------------------------------------ surface
def _crg(ctx: Context, el: etree._Element) -> SurfaceCrg:
    n = ctx.opt_number
    return SurfaceCrg(
        el.get("file"),
        n(el, "sStart"),
        n(el, "sEnd"),
        ctx.opt_enum(el, "orientation", _CRG_ORIENTATIONS),
        ctx.opt_enum(el, "mode", _CRG_MODES),
        ctx.opt_enum(el, "purpose", _CRG_PURPOSES),
        n(el, "sOffset"),
        n(el, "tOffset"),
        n(el, "xOffset"),
        n(el, "yOffset"),
        n(el, "zOffset"),
        n(el, "zScale"),
        n(el, "hOffset"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def surface(ctx: Context, el: etree._Element) -> Surface:
    """A road's or junction's ``<surface>`` and its ``<CRG>`` records."""
    crgs = tuple(_crg(ctx, crg) for crg in el.iterchildren("CRG"))
    return Surface(crgs, el.sourceline, ctx.facts(el, frozenset({"CRG"})))


# ------------------------------------------------------------------------------------------------------ railroad
def _track(ctx: Context, el: etree._Element) -> SwitchTrack:
    return SwitchTrack(
        el.get("id"),
        ctx.opt_number(el, "s"),
        ctx.opt_enum(el, "dir", ELEMENT_DIRS),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _switch(ctx: Context, el: etree._Element) -> Switch:
    main = side = partner = None
    for child in el:
        tag = child.tag
        if tag == "mainTrack" and main is None:
            main = _track(ctx, child)
        elif tag == "sideTrack" and side is None:
            side = _track(ctx, child)
        elif tag == "partner" and partner is None:
            partner = SwitchPartner(child.get("id"), child.get("name"), child.sourceline, ctx.facts(child, LEAF))
    return Switch(
        el.get("id"),
        el.get("name"),
        ctx.opt_enum(el, "position", _SWITCH_POSITIONS),
        main,
        side,
        partner,
        el.sourceline,
        ctx.facts(el, frozenset({"mainTrack", "sideTrack", "partner"})),
    )


def railroad(ctx: Context, el: etree._Element) -> Railroad:
    """A road's ``<railroad>`` and its switches."""
    switches = tuple(_switch(ctx, switch) for switch in el.iterchildren("switch"))
    return Railroad(switches, el.sourceline, ctx.facts(el, frozenset({"switch"})))


# ------------------------------------------------------------------------------------------------------ stations
def station(ctx: Context, el: etree._Element) -> Station:
    """A top-level ``<station>``, its platforms and their segments."""
    platforms = []
    for p in el.iterchildren("platform"):
        segments = tuple(
            PlatformSegment(
                seg.get("roadId"),
                ctx.opt_number(seg, "sStart"),
                ctx.opt_number(seg, "sEnd"),
                ctx.opt_enum(seg, "side", _SIDES),
                seg.sourceline,
                ctx.facts(seg, LEAF),
            )
            for seg in p.iterchildren("segment")
        )
        platforms.append(Platform(p.get("id"), p.get("name"), segments, p.sourceline, ctx.facts(p, _PLATFORM)))
    return Station(
        el.get("id"),
        el.get("name"),
        ctx.opt_enum(el, "type", _STATION_TYPES),
        tuple(platforms),
        el.sourceline,
        ctx.facts(el, _STATION),
    )


_STATION_TYPES = {t.value: t for t in StationType}
_SIDES = {"left": Side.LEFT, "right": Side.RIGHT}
_PLATFORM = frozenset({"segment"})
_STATION = frozenset({"platform"})
