"""Junction topology (``J0xx``): connections and their lane links, read from the model alone.

Terms: a connection leads from its *incoming road* into a *connecting road* (default junctions) or a *linked road*
(direct junctions) at the connection's ``contactPoint`` (the end of the connecting road that touches the incoming
road). The incoming road touches the junction at the end whose link names the junction
(:meth:`Context.incoming_contact`). A lane *travels into* the junction when its traffic runs toward that end.
Whether connection lanes meet or cross in the plane is geometry (``J1xx``, :mod:`xodrcheck.rules.junction_geometry`).
"""

from __future__ import annotations

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import (
    ContactPoint,
    ElementType,
    JunctionLaneLink,
    JunctionType,
    LaneDirection,
)
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared import road_uids as RU
from xodrcheck.rules.shared.context import Context, travel_direction
from xodrcheck.rules.shared.resolved import Resolved, resolved_connections


def _toward(end: ContactPoint) -> int:
    """The travel direction (+1 along s, -1 against) that runs toward a road's ``end``."""
    return 1 if end is ContactPoint.END else -1


def _lanes_of(r: Resolved, ll: JunctionLaneLink, ctx: Context):
    a = ctx.lane_at(r.incoming, r.incoming_end, ll.from_lane)
    b = ctx.lane_at(r.target, r.contact, ll.to_lane)
    return a, b


@rule(
    "J001",
    "junction-incoming-not-linked",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(RU.LINKAGE_BOTH_SIDES,),
    every_version=True,
)
def junction_incoming_not_linked(ctx: Context):
    """A connection's incoming road does not link to the junction.

    Neither its predecessor nor its successor names the junction; in a direct junction the linked road must link to
    it too. The junction's connection is one side of the linkage, the road's link the other: Annex F
    ``road.linkage.both_sides_consistency`` (1.9: "shall be defined at both sides of the road linkage and shall be
    consistent"); older files are checked too, as plausibility.

    Readers that walk from a road into its junction never find this connection.

    Passes::

        <road id="1" ...><link><successor elementType="junction" elementId="100"/></link>...</road>
        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/></junction>

    Fails (road 1 ends at road 10 directly)::

        <road id="1" ...><link><successor elementType="road" elementId="10" contactPoint="start"/></link>...</road>
        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/></junction>
    """
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.VIRTUAL:
            continue  # a virtual junction's main road runs through it without linking to it
        reported: set[str] = set()
        for c in junction.connections:
            names = [("incoming", c.incoming_road)]
            if junction.type is JunctionType.DIRECT:
                names.append(("linked", c.linked_road))
            for role, road_id in names:
                road = ctx.road(road_id)
                if road is None or road.id in reported:
                    continue
                if road.ends_linked_to(ElementType.JUNCTION, junction.id):
                    continue
                reported.add(road.id)
                yield junction_incoming_not_linked.finding(
                    f"junction {junction.id} connection {c.id}: {role} road {road.id} does not link to the junction "
                    f"(predecessor: {_describe(road.predecessor)}, successor: {_describe(road.successor)})",
                    road=road.id,
                    line=c.line or None,
                )


def _describe(link) -> str:
    return "none" if link is None else f"{link.element_type.value} {link.element_id}"


@rule(
    "J002",
    "connection-contact-point",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.CONNECTION_START_ALONG, U.CONNECTION_END_OPPOSITE),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def connection_contact_point(ctx: Context):
    """A connection's ``contactPoint`` does not match the connecting road's links.

    ``contactPoint="start"`` says the connecting road starts at the incoming road, so its predecessor must be the
    incoming road; ``"end"`` says it ends there, so its successor must be (ASAM's
    ``junctions.connection.start_along_linkage`` and ``end_opposite_linkage``). In a direct junction the linked road's
    link at the contact point names the junction. A connection without ``contactPoint`` is reported too (naming no
    rule of the standard: which end it would be is unknown).

    A missing contactPoint is plausibility: the schema makes it optional and the connecting road's links still say
    which end meets the incoming road; a warning under the default profile.

    Passes::

        <road id="10" junction="100"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>...
        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/>

    Fails (road 10 starts at road 1, not ends there)::

        <road id="10" junction="100"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>...
        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="end"/>
    """
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.VIRTUAL:
            continue
        direct = junction.type is JunctionType.DIRECT
        for c in junction.connections:
            target = ctx.road(ctx.connected_road_id(c))
            if target is None or c.incoming_road is None:
                continue
            at = f"junction {junction.id} connection {c.id}"
            if c.contact_point is None:
                yield connection_contact_point.finding(
                    f"{at} has no contactPoint: which end of road {target.id} touches road {c.incoming_road}?",
                    uid=NO_UID,
                    road=target.id,
                    line=c.line or None,
                )
                continue
            link = target.link_at(c.contact_point)
            word = "predecessor" if c.contact_point is ContactPoint.START else "successor"
            uid = U.CONNECTION_START_ALONG if c.contact_point is ContactPoint.START else U.CONNECTION_END_OPPOSITE
            if direct:
                if link is None or link.element_type is not ElementType.JUNCTION or link.element_id != junction.id:
                    yield connection_contact_point.finding(
                        f"{at}: contactPoint {c.contact_point.value} says linked road {target.id} meets the junction "
                        f"at its {c.contact_point.value}, but its {word} is {_describe(link)}",
                        uid=uid,
                        road=target.id,
                        **ctx.end_at(target, c.contact_point),
                        line=c.line or None,
                    )
                continue
            if link is not None and link.names(ElementType.ROAD, c.incoming_road):
                continue
            other = target.link_at(ContactPoint.END if c.contact_point is ContactPoint.START else ContactPoint.START)
            hint = ""
            if other is not None and other.names(ElementType.ROAD, c.incoming_road):
                hint = f"; its other end is: contactPoint should be {'end' if word == 'predecessor' else 'start'}"
            yield connection_contact_point.finding(
                f"{at}: contactPoint {c.contact_point.value} says connecting road {target.id} "
                f"{'starts' if c.contact_point is ContactPoint.START else 'ends'} at incoming road {c.incoming_road}, "
                f"but its {word} is {_describe(link)}{hint}",
                uid=uid,
                road=target.id,
                **ctx.end_at(target, c.contact_point),
                line=c.line or None,
            )


@rule("J003", "junction-lane-link-direction", Category.JUNCTION, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def junction_lane_link_direction(ctx: Context):
    """A junction ``laneLink`` joins lanes whose traffic runs in opposite directions.

    Traffic leaving the incoming lane into the junction must continue along the connecting lane away from the contact
    point (or, for a link describing the other direction, both the other way). Which way a lane runs follows from its
    side and its road's traffic rule (``RHT``: right lanes along s), turned round by ``direction="reversed"`` (1.8).
    A link that joins a lane without one direction of traffic (a sidewalk, shoulder, border, curb, median or ``none``
    lane, or one open both ways: ``direction="both"``, type ``bidirectional``) has no direction to contradict.

    Plausibility: the standard states no rule on the direction of a junction's linked lanes; a warning under the
    default profile, the rule's error under ``--profile strict`` or ``generator``.

    Passes (road 1 ends at the junction; road 10 starts there)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-1"/></connection>

    Fails::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="1"/></connection>
    """
    for r in resolved_connections(ctx):
        for ll in r.connection.lane_links:
            a, b = _lanes_of(r, ll, ctx)
            if a is None or b is None:
                continue
            along_a, along_b = travel_direction(r.incoming, a), travel_direction(r.target, b)
            if along_a is None or along_b is None:
                continue  # a lane without one direction (sidewalk, shoulder, direction="both"...): none to contradict
            into = along_a == _toward(r.incoming_end)
            onward = along_b == -_toward(r.contact)
            if into == onward:
                continue
            yield junction_lane_link_direction.finding(
                f"junction {r.junction.id} connection {r.connection.id}: laneLink {ll.from_lane} -> {ll.to_lane} "
                f"joins lane {a.id} of road {r.incoming.id}, which runs {'into' if into else 'out of'} the junction, "
                f"to lane {b.id} of road {r.target.id}, which runs {'away from' if onward else 'toward'} road "
                f"{r.incoming.id}: traffic would reverse where they meet",
                road=r.incoming.id,
                lane=a.id,
                **ctx.end_at(r.incoming, r.incoming_end),
                line=ll.line or r.connection.line or None,
            )


@rule(
    "J004",
    "junction-lane-link-outbound",
    Category.JUNCTION,
    Severity.WARNING,
    uids=(U.CONNECTION_ONE_LINK,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def junction_lane_link_outbound(ctx: Context):
    """A junction ``laneLink`` starts at a lane whose traffic leaves the junction.

    A connection describes traffic arriving on the incoming road; its lane links go from lanes that travel into the
    junction to lanes of the connecting road. Links from lanes that carry traffic out of the junction describe the
    reverse direction, which belongs to the connection whose incoming road is the other end of that connecting road
    (OpenDRIVE 1.7: "a connecting road shall only have the laneLink element for that direction"). From 1.8 on an error
    (ASAM's ``junctions.connection.one_link_to_incoming``: "its <laneLink> elements shall only be specified for the
    lanes that lead into the junction"; its first sentence is ``connection-duplicate``'s); in 1.7 files a warning;
    older files, written before the standard said so and often listing both directions, get an info. Direct junctions
    are not checked: their lane links join the linked roads' lanes in both directions (12.6.1 links lane 1 of the
    road that ends at the junction, whose traffic leaves it). Lanes without one direction of traffic (sidewalk,
    shoulder, border, curb, median, ``none``; ``direction="both"``, ``bidirectional``) neither lead into the junction
    nor out of it and are not checked.

    Passes (right-hand traffic; road 1 ends at the junction, so lane -1 travels into it)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-1"/></connection>

    Fails (lane 1 of road 1 travels out of the junction)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="1" to="1"/></connection>
    """
    severity = (
        Severity.ERROR if ctx.version_at_least(8) else Severity.WARNING if ctx.version_at_least(7) else Severity.INFO
    )
    uid = U.CONNECTION_ONE_LINK if severity is Severity.ERROR else NO_UID
    for r in resolved_connections(ctx):
        if r.junction.type is JunctionType.DIRECT:
            continue  # 12.6: a direct junction's lane links join the roads' lanes in both directions
        for ll in r.connection.lane_links:
            a = ctx.lane_at(r.incoming, r.incoming_end, ll.from_lane)
            if a is None:
                continue
            along = travel_direction(r.incoming, a)
            if along is None or along == _toward(r.incoming_end):
                continue  # into the junction, or no one direction (sidewalk, shoulder, direction="both"...)
            reversed_ = a.direction is LaneDirection.REVERSED
            traffic = r.incoming.rule.value + (', direction="reversed"' if reversed_ else "")
            yield junction_lane_link_outbound.finding(
                f"junction {r.junction.id} connection {r.connection.id}: laneLink {ll.from_lane} -> {ll.to_lane} "
                f"starts at lane {a.id} of road {r.incoming.id}, whose traffic ({traffic}) leaves the junction; list "
                "only lanes that enter it",
                severity=severity,
                uid=uid,
                road=r.incoming.id,
                lane=a.id,
                **ctx.end_at(r.incoming, r.incoming_end),
                line=ll.line or r.connection.line or None,
            )


@rule("J005", "incoming-lane-unconnected", Category.JUNCTION, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def incoming_lane_unconnected(ctx: Context):
    """A drivable lane that travels into a junction has no ``laneLink`` in it: its traffic reaches a dead end.

    Every road linking to the junction is checked, whether or not a connection names it (in a direct junction a lane
    of a linked road is linked by the laneLinks whose ``to`` names it). Roads with a connection
    that has no laneLink at all are skipped (which lanes such a connection joins is not stated), and so are lanes of
    zero width at the junction and lanes open both ways (``bidirectional``, ``direction="both"``: shared centre
    lanes that often end at a junction).

    Plausibility: the standard does not require every incoming lane to be linked; a warning under the default
    profile, an error under ``--profile strict`` or ``generator`` (a JunctionArt invariant).

    Passes::

        <road id="1"> <link><successor elementType="junction" elementId="100"/></link>
          ... <right><lane id="-1" type="driving">...</right>
        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>

    Fails (road 1 has two lanes into the junction; only lane -1 is linked)::

        <road id="1"> <link><successor elementType="junction" elementId="100"/></link>
          ... <right><lane id="-1" type="driving">...<lane id="-2" type="driving">...</right>
        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
    """
    linked: dict[tuple[str, str], set[int]] = {}
    implicit: set[tuple[str, str]] = set()
    for junction in ctx.document.junctions:
        for c in junction.connections:
            if c.incoming_road is None:
                continue
            key = (junction.id, c.incoming_road)
            if not c.lane_links:
                implicit.add(key)
            linked.setdefault(key, set()).update(ll.from_lane for ll in c.lane_links)
            if junction.type is JunctionType.DIRECT and c.linked_road is not None:
                # 12.6: a direct junction's lane links join the lanes of both roads, both ways
                linked.setdefault((junction.id, c.linked_road), set()).update(ll.to_lane for ll in c.lane_links)
                if not c.lane_links:
                    implicit.add((junction.id, c.linked_road))
    for road in ctx.document.roads:
        if road.junction is not None or not road.lane_sections:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None or link.element_type is not ElementType.JUNCTION:
                continue
            into = ctx.junction(link.element_id)
            if into is None or into.type is JunctionType.VIRTUAL or (into.id, road.id) in implicit:
                continue
            index = ctx.section_index_at(road, end)
            if index is None:  # the road has lane sections (checked above)
                continue
            section = road.lane_sections[index]
            have = linked.get((into.id, road.id), set())
            for lane in section.lanes:
                if not lane.drivable or lane.id in have:
                    continue
                if travel_direction(road, lane) != _toward(end):  # out of the junction, or no one direction
                    continue
                if ctx.zero_width_at(road, index, lane.id, end) is not False:
                    continue
                yield incoming_lane_unconnected.finding(
                    f"road {road.id} lane {lane.id} ({lane.type.value}) runs into junction {into.id} at the "
                    f"road's {end.value}, but no laneLink of the junction starts at it",
                    road=road.id,
                    lane=lane.id,
                    section_s=section.s,
                    s=section.s if end is ContactPoint.START else road.length,
                    line=lane.line or None,
                )
