"""Junction connections against each other (``J006``-``J008``): lanes merging into one, connections repeated, a
connecting road named as an incoming road; read from the model alone (terms as in :mod:`.junction`)."""

from __future__ import annotations

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import Connection, ContactPoint
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.resolved import resolved_connections


@rule("J006", "junction-merge", Category.JUNCTION, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def junction_merge(ctx: Context):
    """Two different incoming lanes are linked into the same lane of a connecting road at the same end.

    A connecting lane starts at one incoming lane; two lanes cannot both continue into its start. (Connecting lanes
    from different approaches that end in the same outgoing lane are normal: traffic merges there under the
    junction's priorities, and is not reported. Connecting lanes of one approach that meet inside the junction are
    a geometric matter, for the junction geometry rules.)

    Plausibility: the standard states no rule against it; a warning under the default profile, an error under
    ``--profile strict`` or ``generator`` (the JunctionArt paper's rule: connection lanes of one road do not merge).

    Passes::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
        <connection id="1" incomingRoad="1" connectingRoad="11" contactPoint="start"><laneLink from="-2" to="-1"/>

    Fails (lanes -1 and -2 both into lane -1 of road 10)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-1"/><laneLink from="-2" to="-1"/></connection>
    """
    sources: dict[tuple[str, str, ContactPoint, int], list] = {}
    for r in resolved_connections(ctx):
        for ll in r.connection.lane_links:
            key = (r.junction.id, r.target.id, r.contact, ll.to_lane)
            sources.setdefault(key, []).append((r.connection, ll))
    for (junction_id, target, contact, lane_id), links in sources.items():
        distinct = {(c.incoming_road, ll.from_lane) for c, ll in links}
        if len(distinct) < 2:
            continue
        names = ", ".join(f"road {road} lane {lane}" for road, lane in sorted(distinct))
        c, ll = links[1]
        yield junction_merge.finding(
            f"junction {junction_id}: lane {lane_id} of road {target} at its {contact.value} is entered from "
            f"{len(distinct)} lanes ({names}); give each incoming lane its own connecting lane",
            road=target,
            lane=lane_id,
            line=ll.line or c.line or None,
        )


@rule(
    "J007",
    "connection-duplicate",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.CONNECTION_ONE_LINK,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def connection_duplicate(ctx: Context):
    """A connecting road appears in more than one connection from the same incoming road.

    In OpenDRIVE 1.7 files: in more than one connection at all.

    Each connecting road is represented by at most one connection per incoming road (1.8; ASAM's
    ``junctions.connection.one_link_to_incoming``); 1.7 allowed exactly one connection per connecting road
    (``one_connection_element``). Readers keep one of the duplicates and lose the other's lane links. (The second
    sentence of ``one_link_to_incoming``, lane links only from lanes that enter the junction, is
    ``junction-lane-link-outbound``'s.)

    The 1.7 rule is not in the 1.9 annex: on 1.7 files the finding is plausibility, a warning under the default
    profile.

    Passes::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>

    Fails::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
        <connection id="1" incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-2" to="-2"/>
    """
    one_per_road = ctx.version == (1, 7)
    for junction in ctx.document.junctions:
        first_pair: dict[tuple[str | None, str], Connection] = {}
        first_road: dict[str, Connection] = {}
        for c in junction.connections:
            if c.connecting_road is None:
                continue
            pair = (c.incoming_road, c.connecting_road)
            if pair in first_pair:
                yield connection_duplicate.finding(
                    f"junction {junction.id}: connections {first_pair[pair].id} and {c.id} both lead from road "
                    f"{c.incoming_road} into connecting road {c.connecting_road}; merge them",
                    road=c.connecting_road,
                    line=c.line or None,
                )
            elif one_per_road and c.connecting_road in first_road:
                yield connection_duplicate.finding(
                    f"junction {junction.id}: connecting road {c.connecting_road} is in connections "
                    f"{first_road[c.connecting_road].id} and {c.id}; OpenDRIVE 1.7 allows one connection per "
                    "connecting road",
                    uid=NO_UID,
                    road=c.connecting_road,
                    line=c.line or None,
                )
            first_pair.setdefault(pair, c)
            first_road.setdefault(c.connecting_road, c)


@rule(
    "J008",
    "connecting-road-is-incoming",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.CONNECTION_NOT_INCOMING,),
    every_version=True,
)
def connecting_road_is_incoming(ctx: Context):
    """A road is the connecting road of one connection and the incoming road of another.

    Connecting roads lie inside their junction and join incoming roads; they are never incoming roads themselves
    (ASAM's ``junctions.connection.connect_road_no_incoming_road``).

    Passes::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/>

    Fails::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/>
        <connection id="1" incomingRoad="10" connectingRoad="11" contactPoint="start"/>
    """
    connecting = {c.connecting_road for j in ctx.document.junctions for c in j.connections if c.connecting_road}
    for junction in ctx.document.junctions:
        for c in junction.connections:
            if c.incoming_road is not None and c.incoming_road in connecting:
                yield connecting_road_is_incoming.finding(
                    f"junction {junction.id} connection {c.id}: incoming road {c.incoming_road} is also a connecting "
                    "road",
                    road=c.incoming_road,
                    line=c.line or None,
                )
