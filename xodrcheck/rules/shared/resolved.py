"""Connections of a junction whose roads and ends are all known (:func:`resolved_connections`), as the junction
topology rules compare them."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from xodrcheck.model import Connection, ContactPoint, ElementType, Junction, JunctionType, Road
from xodrcheck.rules.shared.context import Context


@dataclass(frozen=True, slots=True)
class Resolved:
    """A connection whose roads and ends are all known."""

    junction: Junction
    connection: Connection
    incoming: Road
    incoming_end: ContactPoint
    target: Road
    contact: ContactPoint


def resolved_connections(ctx: Context) -> Iterator[Resolved]:
    """Connections of default and direct junctions whose incoming and target roads exist, with their ends."""
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.VIRTUAL:
            continue
        for c in junction.connections:
            incoming = ctx.road(c.incoming_road)
            target = ctx.road(ctx.connected_road_id(c))
            if incoming is None or target is None or c.contact_point is None:
                continue
            end = ctx.incoming_contact(junction, c)
            if end is None or not incoming.lane_sections or not target.lane_sections:
                continue
            if not _contact_agrees(junction, c, target, c.contact_point):
                continue  # reported by connection-contact-point; its lanes cannot be told apart
            yield Resolved(junction, c, incoming, end, target, c.contact_point)


def _contact_agrees(junction: Junction, c: Connection, target: Road, contact: ContactPoint) -> bool:
    """Whether the target road's link at the connection's contact point names the incoming road (default junction)
    or the junction (direct junction)."""
    link = target.link_at(contact)
    if link is None:
        return False
    if junction.type is JunctionType.DIRECT:
        return link.names(ElementType.JUNCTION, junction.id)
    return link.names(ElementType.ROAD, c.incoming_road)
