"""The ``<OpenDRIVE>`` root to a :class:`~xodrcheck.model.Document`: header, roads, junctions, controllers, junction
groups, stations and vmsGroups, the root's facts and the table of every element."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import Document, Platform, PlatformSegment, Side, Station, StationType
from xodrcheck.reader.context import LEAF, Context, describe
from xodrcheck.reader.elements import element_table
from xodrcheck.reader.header import KNOWN_VERSIONS, build_header
from xodrcheck.reader.junctions import build_junction, junction_group
from xodrcheck.reader.roads import build_road
from xodrcheck.reader.signals import controller, vms_group
from xodrcheck.rules import xml as R

__all__ = ["KNOWN_VERSIONS", "build_document"]

_ROOT = frozenset({"header", "road", "controller", "junction", "junctionGroup", "station", "vmsGroup"})
_STATION_TYPES = {t.value: t for t in StationType}
_SIDES = {"left": Side.LEFT, "right": Side.RIGHT}


def _station(ctx: Context, el: etree._Element) -> Station:
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


_PLATFORM = frozenset({"segment"})
_STATION = frozenset({"platform"})


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
    for child in root.iterchildren("header"):
        if header_el is None:
            header_el = child
            header = build_header(ctx, child)
        else:
            ctx.repeated(child, header_el)
    if header_el is None:
        ctx.report(R.MISSING_ELEMENT, f"{describe(root)} has no <header>; the OpenDRIVE version is unknown", root)
    roads = []
    junctions = []
    controllers = []
    groups = []
    stations = []
    vms_groups = []
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
            controllers.append(controller(ctx, child))
        elif tag == "junctionGroup":
            groups.append(junction_group(ctx, child))
        elif tag == "station":
            stations.append(_station(ctx, child))
        elif tag == "vmsGroup":
            vms_groups.append(vms_group(ctx, child))
        ctx.forget_invalid()
    return Document(
        header,
        tuple(roads),
        tuple(junctions),
        tuple(controllers),
        source,
        tuple(groups),
        tuple(stations),
        tuple(vms_groups),
        ctx.facts(root, _ROOT),
        element_table(root),
    )
