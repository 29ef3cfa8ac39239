"""The ``<OpenDRIVE>`` root to a :class:`~xodrcheck.model.Document`: header, roads, junctions, controllers, junction
groups, stations and vmsGroups, the root's facts, the table of every element and the ids as written."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import Document
from xodrcheck.reader.context import Context, describe
from xodrcheck.reader.elements import element_table
from xodrcheck.reader.header import KNOWN_VERSIONS, build_header
from xodrcheck.reader.ids import id_table
from xodrcheck.reader.junctions import build_junction
from xodrcheck.reader.roads import build_road
from xodrcheck.rules import xml as R

__all__ = ["KNOWN_VERSIONS", "build_document"]

_ROOT = frozenset({"header", "road", "controller", "junction", "junctionGroup", "station", "vmsGroup"})


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
        elif tag == "controller" or tag == "vmsGroup":
            from xodrcheck.reader import signals

            if tag == "controller":
                controllers.append(signals.controller(ctx, child))
            else:
                vms_groups.append(signals.vms_group(ctx, child))
        elif tag == "junctionGroup":
            from xodrcheck.reader.junction_parts import junction_group

            groups.append(junction_group(ctx, child))
        elif tag == "station":
            from xodrcheck.reader.road_records import station

            stations.append(station(ctx, child))
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
        id_table(root),
    )
