"""The ``<OpenDRIVE>`` root to a :class:`~xodrcheck.model.Document`: header, roads, junctions, controllers, junction
groups, stations and vmsGroups, the root's facts, the table of every element and the ids as written."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from lxml import etree

from xodrcheck.model import Document
from xodrcheck.reader.context import Context
from xodrcheck.reader.elements import element_table
from xodrcheck.reader.header import KNOWN_VERSIONS, build_header
from xodrcheck.reader.ids import id_table
from xodrcheck.reader.junctions import build_junction
from xodrcheck.reader.roads import build_road
from xodrcheck.rules import xml as R

if TYPE_CHECKING:  # pragma: no cover - the rarer kinds' model modules load when one appears
    from xodrcheck.model import Controller, Header, Junction, JunctionGroup, Road, Station, VmsGroup

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
    header = _header(ctx, root)
    parts = _TopLevel()
    for child in root:
        parts.add(ctx, child)
        ctx.forget_invalid()
    return Document(
        header=header,
        roads=tuple(parts.roads),
        junctions=tuple(parts.junctions),
        controllers=tuple(parts.controllers),
        source=source,
        junction_groups=tuple(parts.groups),
        stations=tuple(parts.stations),
        vms_groups=tuple(parts.vms_groups),
        xml=ctx.facts(root, _ROOT),
        elements=element_table(root),
        ids=id_table(root),
    )


def _header(ctx: Context, root: etree._Element) -> Header | None:
    """The first ``<header>`` (a repeat and a missing one are reported)."""
    first = None
    header = None
    for child in root.iterchildren("header"):
        if first is None:
            first = child
            header = build_header(ctx, child)
        else:
            ctx.repeated(child, first)
    if first is None:
        ctx.missing_child(root, "header", "the OpenDRIVE version is unknown")
    return header


@dataclass
class _TopLevel:
    """The records of the root's children, in file order (the rarer kinds' readers load when one appears)."""

    roads: list[Road] = field(default_factory=list)
    junctions: list[Junction] = field(default_factory=list)
    controllers: list[Controller] = field(default_factory=list)
    groups: list[JunctionGroup] = field(default_factory=list)
    stations: list[Station] = field(default_factory=list)
    vms_groups: list[VmsGroup] = field(default_factory=list)

    def add(self, ctx: Context, child: etree._Element) -> None:
        tag = child.tag
        if tag == "road":
            road = build_road(ctx, child)
            if road is not None:
                self.roads.append(road)
        elif tag == "junction":
            junction = build_junction(ctx, child)
            if junction is not None:
                self.junctions.append(junction)
        elif tag == "controller" or tag == "vmsGroup":
            from xodrcheck.reader import signals

            if tag == "controller":
                self.controllers.append(signals.controller(ctx, child))
            else:
                self.vms_groups.append(signals.vms_group(ctx, child))
        elif tag == "junctionGroup":
            from xodrcheck.reader.junction_parts import junction_group

            self.groups.append(junction_group(ctx, child))
        elif tag == "station":
            from xodrcheck.reader.road_records import station

            self.stations.append(station(ctx, child))
