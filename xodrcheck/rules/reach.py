"""Where traffic can go (``L040``-``L042``, ``J040``): rules over the lane graph (:mod:`xodrcheck.graph`).

Each link is checked where it is (``lane-not-continued``, ``incoming-lane-unconnected``, ``lane-link-direction``,
``junction-lane-link-direction``...); these rules look at the network those links make: lanes whose traffic cannot
go on, lanes no route reaches, parts of a map traffic enters and never leaves, junction approaches with no way
through. The graph holds the drivable lanes driven one way, linked lanes and lane changes where the road marks allow
them; lanes driven both ways (``direction="both"``, type ``bidirectional``: shared centre lanes that often end at a
junction) are not reported. Where a lane-level rule already reports the cause at the same place (a missing, reversed or
dangling link), these rules say nothing more there. The standard states none of this: the project's plausibility
rules, warnings.
"""

from __future__ import annotations

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.graph import build, topology
from xodrcheck.graph.build import LaneGraph, Node, lane_graph
from xodrcheck.graph.direction import leaving
from xodrcheck.graph.reach import goes_on, traps, unentered
from xodrcheck.model import ContactPoint, Lane, LaneDirection, LaneType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared.context import Context

#: Stops a lane-level rule already reports (a dangling, reversed or unresolvable link) or the graph does not follow.
_REPORTED_ELSEWHERE = frozenset({build.MISSING, build.AGAINST, topology.BROKEN, topology.UNFOLLOWED})


def _both_ways(lane: Lane) -> bool:
    return lane.direction is LaneDirection.BOTH or lane.type is LaneType.BIDIRECTIONAL


def _lane(ctx: Context, node: Node) -> tuple[Road, Lane]:
    road = ctx.document.road_by_id[node.road]
    lane = road.lane_sections[node.index].lane(node.lane)
    assert lane is not None  # a node is a lane of its section
    return road, lane


def _where(road: Road, node: Node, lane: Lane, end: ContactPoint) -> dict:
    section = road.lane_sections[node.index]
    s = section.s if end is ContactPoint.START else road.section_end(node.index)
    return {"road": road.id, "lane": lane.id, "section_s": section.s, "s": s, "line": lane.line or None}


def _unlinked_with_width(ctx: Context, road: Road, node: Node, kind: str, end: ContactPoint) -> bool:
    """Whether ``lane-not-continued`` reports this lane end: a joint inside a road or at a road link where no link
    names the lane and it has width (``incoming-lane-unconnected`` likewise at a junction with laneLinks)."""
    if kind not in (topology.SECTION, topology.ROAD, topology.JUNCTION):
        return False
    return ctx.zero_width_at(road, node.index, node.lane, end) is False


@rule("L040", "lane-dead-end", Category.LANE, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def lane_dead_end(ctx: Context):
    """Traffic on a drivable lane can go no further, away from any open edge of the map.

    No link leads on from the lane's end and no road mark lets traffic change into a neighbouring lane before it: a
    lane that closes at zero width beside a solid line, say, or a lane whose links lead only into lanes no vehicle
    drives (a parking lane, a shoulder). Lanes that end where their road ends without a link leave the map there and
    are fine. Missing, reversed and dangling links are the lane-level rules' (``lane-not-continued``,
    ``incoming-lane-unconnected``, ``lane-link-direction``...); this rule reports what is left.

    Plausibility: no rule of the standard says that a lane must lead somewhere (11.1 asks drivable lanes to be
    continuous, with no UID); a warning by default, the rule's own severity under ``--profile strict``.

    Passes (lane -2 closes at zero width; the broken line lets its traffic move into lane -1)::

        <lane id="-1" type="driving"><link><successor id="-1"/></link>
          <roadMark sOffset="0" type="broken"/>...</lane>
        <lane id="-2" type="driving"><width sOffset="0" a="3.5" b="-0.07" c="0" d="0"/></lane>

    Fails (the same, beside a solid line)::

        <lane id="-1" type="driving"><link><successor id="-1"/></link>
          <roadMark sOffset="0" type="solid"/>...</lane>
        <lane id="-2" type="driving"><width sOffset="0" a="3.5" b="-0.07" c="0" d="0"/></lane>
    """
    graph = lane_graph(ctx.document)
    onward = goes_on(graph)
    for i, stop in sorted(graph.stops.items()):
        node = graph.nodes[i]
        if onward[i] or stop.kind in _REPORTED_ELSEWHERE:
            continue
        road, lane = _lane(ctx, node)
        end = leaving(node.travel)
        if _both_ways(lane) or _unlinked_with_width(ctx, road, node, stop.kind, end):
            continue
        if stop.kind == topology.JUNCTION and "have no laneLink" in stop.why:
            continue  # which lanes such a connection joins is not stated
        yield lane_dead_end.finding(
            f"{node.describe()} ({node.type}) leads nowhere: {stop.why}, and no road mark lets its traffic change "
            "lanes before its end; link it on, or mark a line traffic may cross",
            **_where(road, node, lane, end),
        )


@rule("L041", "lane-unreachable", Category.LANE, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def lane_unreachable(ctx: Context):
    """No route reaches a drivable lane: no link leads into it and no road mark lets traffic change into it.

    Traffic enters the map at its open edges (roads that start without a link). Each lane where a stretch no route
    reaches begins is reported once (lanes side by side that nothing enters, once together); what lies past it is
    reached only through it. A lane that appears beside another behind a solid line, or a connecting lane no
    junction ``laneLink`` leads into, is such a lane. A full-width lane without a link at its start is
    ``lane-not-continued``'s.

    Plausibility: no rule of the standard says that every lane must be reachable; a warning by default, the rule's
    own severity under ``--profile strict``.

    Passes (lane -2 opens from zero width at s=50; the broken line lets lane -1's traffic move into it)::

        <laneSection s="50"><right>
          <lane id="-1" type="driving"><link><predecessor id="-1"/></link>
            <roadMark sOffset="0" type="broken"/>...</lane>
          <lane id="-2" type="driving"><width sOffset="0" a="0" b="0.07" c="0" d="0"/></lane>
        </right></laneSection>

    Fails (the same, beside a solid line)::

        <laneSection s="50"><right>
          <lane id="-1" type="driving"><link><predecessor id="-1"/></link>
            <roadMark sOffset="0" type="solid"/>...</lane>
          <lane id="-2" type="driving"><width sOffset="0" a="0" b="0.07" c="0" d="0"/></lane>
        </right></laneSection>
    """
    graph = lane_graph(ctx.document)
    nothing_in = unentered(graph)
    if not nothing_in.any():
        return
    links = topology.Topology(ctx.document)
    groups: dict[tuple[str, int, int], list[int]] = {}
    for i in np.flatnonzero(nothing_in).tolist():  # lanes side by side, joined by lane changes: one finding
        node = graph.nodes[i]
        groups.setdefault((node.road, node.index, node.travel), []).append(i)
    for members in groups.values():
        node = graph.nodes[members[0]]
        road, lane = _lane(ctx, node)
        if _both_ways(lane):
            continue
        start = leaving(-node.travel)
        behind = links.onward(road, node.index, lane, -node.travel)
        if behind.kind in _REPORTED_ELSEWHERE:
            continue
        unlinked = behind.kind in (topology.SECTION, topology.ROAD) and not behind.targets
        if unlinked and _unlinked_with_width(ctx, road, node, behind.kind, start):
            continue  # lane-not-continued's
        if behind.targets and _entered_elsewhere(graph, behind):
            continue
        beside = [str(graph.nodes[k].lane) for k in members[1:]]
        also = f" (nor lane(s) {', '.join(beside)} beside it)" if beside else ""
        yield lane_unreachable.finding(
            f"no route reaches {node.describe()} ({node.type}){also}: {_entry_words(behind)}",
            **_where(road, node, lane, start),
        )


def _entered_elsewhere(graph: LaneGraph, behind: topology.Onward) -> bool:
    """Whether the lanes linked across a lane's start are missing or of the graph's types (so it is a link against
    the direction of travel, or to nothing, that keeps traffic out: ``lane-link-direction``, ``lane-link-missing-lane``
    and the junction rules report those), rather than all of other types (parking, shoulder...)."""
    for t in behind.targets:
        lane = t.road.lane_sections[t.index].lane(t.lane)
        if lane is None or any((t.road.id, t.index, t.lane, d) in graph.index for d in (1, -1)):
            return True
    return False


def _entry_words(behind: topology.Onward) -> str:
    if behind.kind == topology.JUNCTION:
        return f"no lane of junction {behind.junction} leads into it and no road mark lets traffic change into it"
    if behind.targets:
        named = ", ".join(f"lane {t.lane} of road {t.road.id}" for t in behind.targets)
        return f"it is linked only from {named}, which no vehicle drives on"
    return "no lane links into it and no road mark lets traffic change into it"


@rule("L042", "lanes-trapped", Category.LANE, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def lanes_trapped(ctx: Context):
    """Traffic that enters a part of the map can never leave it: its lanes lead only among themselves.

    The part has a way round (traffic can circle in it) but no link leads out of it, back to the rest of the map or to
    an open edge: a one-way loop with an entry and no exit, say. Reported once per part, where traffic enters it. On
    a map without open edges the main part (the largest strongly connected one) is the map itself and is not reported.

    Plausibility: no rule of the standard forbids a part of a map that traffic cannot leave; a warning by default,
    the rule's own severity under ``--profile strict``.

    Passes (road 2, a loop, leads back into itself through connecting road 11 and out to road 3 through 12)::

        <junction id="100">
          <connection incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
          <connection incomingRoad="2" connectingRoad="11" contactPoint="start"><laneLink from="-1" to="-1"/>
          <connection incomingRoad="2" connectingRoad="12" contactPoint="start"><laneLink from="-1" to="-1"/>
        </junction>

    Fails (the same without connecting road 12 and road 3: what enters road 2 circles for ever)::

        <junction id="100">
          <connection incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
          <connection incomingRoad="2" connectingRoad="11" contactPoint="start"><laneLink from="-1" to="-1"/>
        </junction>
    """
    graph = lane_graph(ctx.document)
    for members in traps(graph):
        inside = np.zeros(len(graph.nodes), dtype=bool)
        inside[members] = True
        entering = np.flatnonzero(inside[graph.target] & ~inside[graph.source])
        node = graph.nodes[int(graph.target[entering[0]])]
        road, lane = _lane(ctx, node)
        roads = sorted({graph.nodes[k].road for k in members.tolist()}, key=_natural)
        shown = ", ".join(roads[:8]) + (f" and {len(roads) - 8} more" if len(roads) > 8 else "")
        yield lanes_trapped.finding(
            f"traffic entering {node.describe()} can never leave: the {len(members)} lanes of road(s) {shown} "
            "lead only among themselves, with no exit from the map and no way back; link a lane out of them",
            **_where(road, node, lane, leaving(-node.travel)),
        )


def _natural(road_id: str) -> tuple:
    return (0, int(road_id), "") if road_id.isdigit() else (1, 0, road_id)


@rule("J040", "junction-no-way-through", Category.JUNCTION, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def junction_no_way_through(ctx: Context):
    """A lane enters a junction, but no way leads through it: every connecting lane its laneLinks lead into stops
    inside the junction.

    A connecting lane that has no successor, or leads only into lanes driven the other way or into other connecting
    lanes that do, leaves the approach without an exit; one that reaches an open edge of the map leaves the map (a
    lane with no laneLink at all is ``incoming-lane-unconnected``'s; the dead end itself is reported where it is, by
    ``lane-not-continued`` or ``lane-dead-end``: this rule says which approach it leaves without a way through).

    Plausibility: the standard states no rule that every approach must have a way through a junction; a warning by
    default, the rule's own severity under ``--profile strict``.

    Passes (connecting road 10 continues into road 2)::

        <road id="10" junction="100"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>
          <successor elementType="road" elementId="2" contactPoint="start"/></link>...
          <lane id="-1"><link><predecessor id="-1"/><successor id="-1"/></link>...

    Fails (its lane -1 names no lane of road 2)::

        <road id="10" junction="100"><link><predecessor elementType="road" elementId="1" contactPoint="end"/>
          <successor elementType="road" elementId="2" contactPoint="start"/></link>...
          <lane id="-1"><link><predecessor id="-1"/></link>...
    """
    graph = lane_graph(ctx.document)
    out: dict[int, list[int]] = {}
    for a, b in zip(graph.source.tolist(), graph.target.tolist()):
        out.setdefault(a, []).append(b)
    for i, node in enumerate(graph.nodes):
        if node.junction is not None:
            continue
        inside = [j for j in out.get(i, ()) if graph.nodes[j].junction is not None]
        junction = graph.nodes[inside[0]].junction if inside else None
        if junction is None:
            continue
        stops = _stops_inside(graph, out, inside, junction)
        if stops is None:
            continue
        road, lane = _lane(ctx, node)
        if _both_ways(lane):
            continue
        first = graph.nodes[stops[0]]
        why = graph.stops[stops[0]].why if stops[0] in graph.stops else "it leads on only inside the junction"
        yield junction_no_way_through.finding(
            f"{node.describe()} enters junction {junction}, but no way leads through it: its laneLinks lead into "
            f"{len(inside)} connecting lane(s), and {first.describe()} stops there ({why})",
            **_where(road, node, lane, leaving(node.travel)),
        )


def _stops_inside(graph: LaneGraph, out: dict[int, list[int]], starts: list[int], junction: str) -> list[int] | None:
    """The junction's lanes where traffic from ``starts`` stops, when none of them leads out of the junction (``None``
    when one does)."""
    seen = set(starts)
    todo = list(starts)
    stops = []
    while todo:
        k = todo.pop()
        onward = out.get(k, [])
        if graph.ends_open(k):
            return None  # it leaves the map there
        if not onward:
            stops.append(k)
        for j in onward:
            if graph.nodes[j].junction != junction:
                return None
            if j not in seen:
                seen.add(j)
                todo.append(j)
    return sorted(stops) or sorted(seen)
