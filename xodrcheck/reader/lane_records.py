"""The records of a lane that neither geometry nor topology needs: ``<access>``, ``<material>``, ``<rule>``,
``<visibility>``, and a road mark's ``<type>``, ``<explicit>`` and ``<sway>`` children. Read as the file gives them
(the schema rule reports bad values)."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import (
    AccessRule,
    LaneAccess,
    LaneMaterial,
    LaneRule,
    LaneVisibility,
    RoadMarkExplicit,
    RoadMarkLine,
    RoadMarkSway,
    RoadMarkType,
)
from xodrcheck.reader.context import LEAF, Context

_ACCESS_RULES = {rule.value: rule for rule in AccessRule}
_LINES = frozenset({"line"})


def access(ctx: Context, el: etree._Element) -> LaneAccess:
    restrictions = tuple(
        r.get("type") for r in el.iterchildren("restriction")
    )  # 1.8: the restrictions as children, each with its type
    return LaneAccess(
        ctx.opt_number(el, "sOffset"),
        ctx.opt_enum(el, "rule", _ACCESS_RULES),
        el.get("restriction"),
        restrictions,
        el.sourceline,
        ctx.facts(el, frozenset({"restriction"})),
    )


def material(ctx: Context, el: etree._Element) -> LaneMaterial:
    n = ctx.opt_number
    return LaneMaterial(
        n(el, "sOffset"),
        el.get("surface"),
        n(el, "friction"),
        n(el, "roughness"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def rule(ctx: Context, el: etree._Element) -> LaneRule:
    return LaneRule(ctx.opt_number(el, "sOffset"), el.get("value"), el.sourceline, ctx.facts(el, LEAF))


def visibility(ctx: Context, el: etree._Element) -> LaneVisibility:
    n = ctx.opt_number
    return LaneVisibility(
        n(el, "sOffset"),
        n(el, "forward"),
        n(el, "back"),
        n(el, "left"),
        n(el, "right"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


# ------------------------------------------------------------------------------------------------------ road marks
def _line(ctx: Context, el: etree._Element) -> RoadMarkLine:
    n = ctx.opt_number
    return RoadMarkLine(
        n(el, "length"),
        n(el, "space"),
        n(el, "tOffset"),
        n(el, "sOffset"),
        el.get("rule"),
        n(el, "width"),
        el.get("color"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def mark_type(ctx: Context, el: etree._Element) -> RoadMarkType:
    """A road mark's ``<type>``: its name, width and stripes."""
    lines = tuple(_line(ctx, line) for line in el.iterchildren("line"))
    return RoadMarkType(el.get("name"), ctx.opt_number(el, "width"), lines, el.sourceline, ctx.facts(el, _LINES))


def explicit(ctx: Context, el: etree._Element) -> RoadMarkExplicit:
    """A road mark's ``<explicit>`` stripes."""
    lines = tuple(_line(ctx, line) for line in el.iterchildren("line"))
    return RoadMarkExplicit(lines, el.sourceline, ctx.facts(el, _LINES))


def sway(ctx: Context, el: etree._Element) -> RoadMarkSway:
    n = ctx.opt_number
    return RoadMarkSway(n(el, "ds"), n(el, "a"), n(el, "b"), n(el, "c"), n(el, "d"), el.sourceline, ctx.facts(el, LEAF))
