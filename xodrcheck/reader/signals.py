"""A road's ``<signals>`` to :mod:`xodrcheck.model.signals` records (signals with their boards, positions,
validities, dependencies, references and semantics; signal references), and the file's ``<controller>`` and 1.9
``<vmsGroup>`` elements. Read as the file gives them (the schema rule reports bad values)."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import (
    Control,
    Controller,
    DisplayArea,
    PositionInertial,
    PositionRoad,
    ReferenceType,
    Semantic,
    Semantics,
    Sign,
    Signal,
    SignalDependency,
    SignalLink,
    SignalReference,
    StaticBoard,
    VmsBoard,
    VmsBoardReference,
    VmsGroup,
)
from xodrcheck.reader.context import LEAF, Context
from xodrcheck.reader.lanes import layered
from xodrcheck.reader.objects import ORIENTATIONS, validities

_YES_NO = {"yes": True, "no": False}
_REFERENCE_TYPES = {t.value: t for t in ReferenceType}
_BOARD = frozenset({"validity", "dependency", "reference"})
_SIGN = _BOARD | {"semantics"}
_SIGNAL = _SIGN | {"positionRoad", "positionInertial", "staticBoard", "vmsBoard"}
_STATIC_BOARD = _BOARD | {"sign"}
_VMS_BOARD = _BOARD | {"displayArea"}


def semantics(ctx: Context, el: etree._Element) -> Semantics | None:
    """The element's first ``<semantics>``: every child is one behaviour."""
    for sem in el.iterchildren("semantics"):
        items = tuple(
            Semantic(
                item.tag,
                item.get("type"),
                ctx.opt_number(item, "value"),
                item.get("unit"),
                item.sourceline,
                ctx.facts(item),
            )
            for item in sem.iterchildren(etree.Element)
        )
        return Semantics(items, sem.sourceline, ctx.facts(sem))
    return None


def _dependencies(ctx: Context, el: etree._Element) -> tuple[SignalDependency, ...]:
    return tuple(
        SignalDependency(d.get("id"), d.get("type"), d.sourceline, ctx.facts(d, LEAF))
        for d in el.iterchildren("dependency")
    )


def _links(ctx: Context, el: etree._Element) -> tuple[SignalLink, ...]:
    return tuple(
        SignalLink(
            ctx.opt_enum(r, "elementType", _REFERENCE_TYPES),
            r.get("elementId"),
            r.get("type"),
            r.sourceline,
            ctx.facts(r, LEAF),
        )
        for r in el.iterchildren("reference")
    )


def _sign(ctx: Context, el: etree._Element) -> Sign:
    n = ctx.opt_number
    found = (validities(ctx, el), _dependencies(ctx, el), _links(ctx, el), semantics(ctx, el))
    return Sign(
        el.get("id"),
        el.get("type"),
        el.get("subtype"),
        el.get("country"),
        el.sourceline,
        el.get("name"),
        el.get("countryRevision"),
        ctx.opt_enum(el, "dynamic", _YES_NO),
        ctx.opt_enum(el, "orientation", ORIENTATIONS),
        n(el, "value"),
        el.get("text"),
        el.get("unit"),
        n(el, "height"),
        n(el, "width"),
        n(el, "v"),
        n(el, "z"),
        *found,
        ctx.facts(el, _SIGN),
    )


def _static_board(ctx: Context, el: etree._Element) -> StaticBoard:
    signs = tuple(_sign(ctx, sign) for sign in el.iterchildren("sign"))
    found = (validities(ctx, el), _dependencies(ctx, el), _links(ctx, el))
    return StaticBoard(signs, *found, el.sourceline, ctx.facts(el, _STATIC_BOARD))


def _vms_board(ctx: Context, el: etree._Element) -> VmsBoard:
    n = ctx.opt_number
    areas = tuple(
        DisplayArea(
            ctx.opt_integer(a, "index"),
            a.get("width"),
            a.get("height"),
            n(a, "v"),
            n(a, "z"),
            a.sourceline,
            ctx.facts(a, LEAF),
        )
        for a in el.iterchildren("displayArea")
    )
    found = (validities(ctx, el), _dependencies(ctx, el), _links(ctx, el))
    return VmsBoard(
        el.get("displayType"),
        n(el, "displayHeight"),
        n(el, "displayWidth"),
        n(el, "v"),
        n(el, "z"),
        areas,
        *found,
        el.sourceline,
        ctx.facts(el, _VMS_BOARD),
    )


def _position_road(ctx: Context, el: etree._Element | None) -> PositionRoad | None:
    if el is None:
        return None
    n = ctx.opt_number
    return PositionRoad(
        el.get("roadId"),
        n(el, "s"),
        n(el, "t"),
        n(el, "zOffset"),
        n(el, "hOffset"),
        n(el, "pitch"),
        n(el, "roll"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _position_inertial(ctx: Context, el: etree._Element | None) -> PositionInertial | None:
    if el is None:
        return None
    n = ctx.opt_number
    return PositionInertial(
        n(el, "x"),
        n(el, "y"),
        n(el, "z"),
        n(el, "hdg"),
        n(el, "pitch"),
        n(el, "roll"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _signal(ctx: Context, road: str, el: etree._Element) -> Signal:
    n = ctx.opt_number
    found = validities(ctx, el)
    dependencies = _dependencies(ctx, el)
    links = _links(ctx, el)
    position_road = _position_road(ctx, next(el.iterchildren("positionRoad"), None))
    position_inertial = _position_inertial(ctx, next(el.iterchildren("positionInertial"), None))
    own_semantics = semantics(ctx, el)
    boards = tuple(_static_board(ctx, b) for b in el.iterchildren("staticBoard"))
    vms = tuple(_vms_board(ctx, b) for b in el.iterchildren("vmsBoard"))
    return Signal(
        road,
        el.get("id"),
        el.get("type"),
        el.get("subtype"),
        el.get("country"),
        ctx.opt_enum(el, "dynamic", _YES_NO),
        ctx.opt_enum(el, "orientation", ORIENTATIONS),
        n(el, "s"),
        n(el, "t"),
        el.sourceline,
        n(el, "zOffset"),
        el.get("name"),
        el.get("countryRevision"),
        n(el, "value"),
        el.get("text"),
        el.get("unit"),
        n(el, "height"),
        n(el, "length"),
        n(el, "width"),
        n(el, "hOffset"),
        n(el, "pitch"),
        n(el, "roll"),
        *_layered_flags(ctx, el),
        found,
        dependencies,
        links,
        position_road,
        position_inertial,
        own_semantics,
        boards,
        vms,
        ctx.facts(el, _SIGNAL),
    )


def _layered_flags(ctx: Context, el: etree._Element) -> tuple[bool | None, bool | None]:
    """``invalidated`` and ``temporary`` (1.9; ``None`` for older files)."""
    if not layered(ctx):
        return None, None
    return ctx.opt_boolean(el, "invalidated"), ctx.opt_boolean(el, "temporary")


def _reference(ctx: Context, road: str, el: etree._Element) -> SignalReference:
    found = validities(ctx, el)
    return SignalReference(
        road,
        el.get("id"),
        ctx.opt_number(el, "s"),
        ctx.opt_number(el, "t"),
        ctx.opt_enum(el, "orientation", ORIENTATIONS),
        found,
        el.sourceline,
        ctx.facts(el, frozenset({"validity"})),
    )


def read_signals(ctx: Context, road: str, el: etree._Element) -> tuple[tuple[Signal, ...], tuple[SignalReference, ...]]:
    """The signals and signal references of a ``<signals>`` element of road ``road``, in file order."""
    signals: list[Signal] = []
    references: list[SignalReference] = []
    for child in el:
        if child.tag == "signal":
            signals.append(_signal(ctx, road, child))
        elif child.tag == "signalReference":
            references.append(_reference(ctx, road, child))
    return tuple(signals), tuple(references)


def controller(ctx: Context, el: etree._Element) -> Controller:
    """A top-level ``<controller>`` and its controls."""
    controls = tuple(
        Control(c.get("signalId"), c.get("type"), c.sourceline, ctx.facts(c, LEAF)) for c in el.iterchildren("control")
    )
    return Controller(
        el.get("id"),
        el.get("name"),
        ctx.opt_integer(el, "sequence"),
        controls,
        el.sourceline,
        ctx.facts(el, frozenset({"control"})),
    )


def vms_group(ctx: Context, el: etree._Element) -> VmsGroup:
    """A top-level ``<vmsGroup>`` (1.9) and its board references."""
    references = tuple(
        VmsBoardReference(
            r.get("signalId"),
            ctx.opt_integer(r, "vmsIndex"),
            ctx.opt_integer(r, "groupIndex"),
            r.sourceline,
            ctx.facts(r, LEAF),
        )
        for r in el.iterchildren("vmsBoardReference")
    )
    return VmsGroup(el.get("id"), references, el.sourceline, ctx.facts(el, frozenset({"vmsBoardReference"})))
