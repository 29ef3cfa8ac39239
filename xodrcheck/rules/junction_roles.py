"""What a junction joins and who has priority in it (``J014``-``J019``), from the model and the junction's parts.

* Priorities (12.4.1): each ``<priority>`` is a pair of one ``high`` and one ``low`` road; on a crossing only one
  crossing road is ``high``; priorities are for junctions whose priorities no signal gives.
* Virtual junctions (12.7): no controllers or traffic lights; one range ``sStart``..``sEnd`` on the main road; every
  connecting road branches off the main road, starting or ending there at ``sStart`` or ``sEnd``.
* When a junction is needed at all (12.2): only where roads cannot be linked directly, because a road has two or more
  possible predecessors or successors; not where only two roads meet.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.model import ContactPoint, ElementType, Junction, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction, written_id
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import Priority


@dataclass(frozen=True, slots=True)
class RoadSignal:
    """A ``<signal>`` or ``<signalReference>`` of a road, as J015 and J016 weigh it."""

    road: str
    kind: str
    id: str | None
    s: float | None
    dynamic: bool
    line: int


def signals_by_road(ctx: Context) -> dict[str, tuple[RoadSignal, ...]]:
    """Road id -> its signals and signal references, in file order."""
    out: dict[str, list[RoadSignal]] = {}
    for road in ctx.document.roads:
        found = [RoadSignal(road.id, "signal", s.id, s.s, s.dynamic is True, s.line) for s in road.signals]
        found += [RoadSignal(road.id, "signalReference", r.id, r.s, False, r.line) for r in road.signal_references]
        if found:
            out.setdefault(road.id, []).extend(sorted(found, key=lambda sig: sig.line))
    return {k: tuple(v) for k, v in out.items()}


def legs(ctx: Context, junction: Junction) -> dict[str, ContactPoint | None]:
    """Roads outside the junction that touch it, with the end that does (``None``: unknown): roads whose predecessor
    or successor names it, and the incoming (and, in a direct junction, linked) roads of its connections."""
    out: dict[str, ContactPoint | None] = {}
    for road, end in ctx.junction_link_ends.get(junction.id, ()):
        if road.junction != junction.id:
            out.setdefault(road.id, end)
    for c in junction.connections:
        for road_id in (c.incoming_road, c.linked_road if junction.type is JunctionType.DIRECT else None):
            found = ctx.road(road_id)
            if found is not None and found.junction != junction.id:
                out.setdefault(found.id, None)
    return out


# ---------------------------------------------------------------------------------------------------- priorities
@rule(
    "J014",
    "junction-priority-pair",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.PRIORITY_HIGH_AND_LOW, U.CROSSING_ONE_HIGH),
)
def junction_priority_pair(ctx: Context):
    """A junction ``<priority>`` is not a pair of two roads, or a crossing gives priority to more than one road.

    Each ``<priority>`` names one road with priority (``high``) and one road without (``low``)
    (``junctions.priority.high_and_low_attr``, 12.4.1): both attributes, two different roads. On a crossing, only one
    of the roads named by its ``<roadSection>`` elements has ``high`` priority
    (``junctions.crossing.only_one_high_prio``, 12.8).

    Passes::

        <junction id="555" type="crossing"><priority high="2" low="1"/>
          <roadSection id="0" roadId="1" sStart="50" sEnd="60"/><roadSection id="1" roadId="2" .../></junction>

    Fails (both crossing roads have priority)::

        <junction id="555" type="crossing"><priority high="2" low="1"/><priority high="1" low="2"/>...
    """
    for j in ctx.document.junctions:
        for p in j.priorities:
            missing = [name for name, value in (("high", p.high), ("low", p.low)) if not (value or "").strip()]
            if missing or p.high == p.low:
                why = f"has no {' and no '.join(missing)}" if missing else f"names road {p.high} as both high and low"
                yield junction_priority_pair.finding(
                    f"{describe_junction(j)}: <priority> {why}; a priority is a pair: the road with priority (high) "
                    "and the road that yields to it (low)",
                    uid=U.PRIORITY_HIGH_AND_LOW,
                    road=p.high or p.low,
                    line=p.line or j.line or None,
                )
        if j.type is not JunctionType.CROSSING:
            continue
        crossing_roads = {r.road for r in j.road_sections if r.road is not None}
        high: dict[str, Priority] = {}
        for p in j.priorities:
            if p.high in crossing_roads:
                high.setdefault(p.high, p)
        if len(high) > 1:
            names = ", ".join(sorted(high))
            last = list(high.values())[-1]
            yield junction_priority_pair.finding(
                f"{describe_junction(j)}: roads {names} each have high priority; on a crossing only one of the "
                "crossing roads has priority (the railway, say), the others yield",
                uid=U.CROSSING_ONE_HIGH,
                road=last.high,
                line=last.line or j.line or None,
            )


def _near_junction(ctx: Context, road: Road, end: ContactPoint | None, s: float | None) -> bool:
    """Whether a signal at ``s`` of an incoming road stands on its last ``signal_reach`` metres before the junction."""
    if s is None or end is None:
        return end is None  # unknown end: any signal of the road counts
    reach = ctx.tolerances.signal_reach
    return s <= reach if end is ContactPoint.START else s >= road.length - reach


@rule(
    "J015",
    "junction-priority-with-signals",
    Category.JUNCTION,
    Severity.WARNING,
    uids=(U.PRIORITY_NO_SIGNALS,),
)
def junction_priority_with_signals(ctx: Context):
    """A junction states priorities while signals regulate it.

    ``<priority>`` elements are only needed where priorities cannot be derived from signs or signals in a junction or
    on the roads leading to it; they should only be used if there are no signals (``junctions.priority.no_signals``,
    12.4.1), or the two may contradict each other. Reported when a junction with ``<priority>`` elements also has
    ``<controller>`` elements, signals or signal references on its own roads, or signals on an incoming road within
    ``signal_reach`` (50 m) of the junction.

    Passes (no signals: the priorities say who yields)::

        <junction id="100"><connection .../><priority high="1" low="3"/></junction>

    Fails (a stop sign on connecting road 12 already says it)::

        <road id="12" junction="100"> ... <signals><signal id="7" s="1" type="206" .../></signals></road>
        <junction id="100"><connection .../><priority high="1" low="3"/></junction>
    """
    prioritised = [j for j in ctx.document.junctions if j.priorities]
    signals = signals_by_road(ctx) if prioritised else {}
    for j in prioritised:
        found: list[str] = []
        if j.controllers:
            found.append(f"{len(j.controllers)} controller(s) (line {j.controllers[0].line})")
        for road in ctx.roads_in_junction.get(j.id, ()):
            for sig in signals.get(road.id, ()):
                found.append(f"{sig.kind} {sig.id} on its road {road.id} (line {sig.line})")
        for road_id, end in legs(ctx, j).items():
            leg = ctx.road(road_id)
            for sig in signals.get(road_id, ()):
                if sig.kind == "signal" and leg is not None and _near_junction(ctx, leg, end, sig.s):
                    found.append(f"signal {sig.id} on incoming road {road_id} at s={metres(sig.s)} (line {sig.line})")
        if found:
            shown = "; ".join(found[:3]) + (f"; {len(found) - 3} more" if len(found) > 3 else "")
            yield junction_priority_with_signals.finding(
                f"{describe_junction(j)} has {len(j.priorities)} <priority> element(s) and is regulated by signals: "
                f"{shown}; state priorities only where no signal gives them",
                line=j.priorities[0].line or j.line or None,
            )


# ---------------------------------------------------------------------------------------------------- virtual junctions
@rule("J016", "virtual-junction-controlled", Category.JUNCTION, Severity.ERROR, uids=(U.VIRTUAL_NO_CONTROLLERS,))
def virtual_junction_controlled(ctx: Context):
    """A virtual junction has controllers or traffic lights.

    Virtual junctions (driveways, parking lot entries) shall not have controllers and therefore no traffic lights
    (``junctions.virtual.no_controllers``, 12.7): reported are ``<controller>`` elements of the junction and dynamic
    signals (``dynamic="yes"``) on its connecting roads or on its main road between ``sStart`` and ``sEnd``. A
    junction with traffic lights is a common junction.

    Passes::

        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="70" orientation="+"><connection .../>

    Fails::

        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="70" orientation="+"><connection .../>
          <controller id="1"/></junction>
    """
    virtual = [j for j in ctx.document.junctions if j.type is JunctionType.VIRTUAL]
    signals = signals_by_road(ctx) if virtual else {}
    for j in virtual:
        for controller in j.controllers:
            yield virtual_junction_controlled.finding(
                f"{describe_junction(j)} has <controller> {controller.id}: virtual junctions have no controllers and "
                "no traffic lights; use a common junction for a signalised branch",
                line=controller.line or j.line or None,
            )
        lo, hi = j.s_start, j.s_end
        own = [road.id for road in ctx.roads_in_junction.get(j.id, ())]
        for road_id in [*own, j.main_road]:
            for sig in signals.get(road_id or "", ()):
                if not sig.dynamic:
                    continue
                on_main = road_id == j.main_road and road_id not in own
                if on_main and (sig.s is None or lo is None or hi is None or not lo <= sig.s <= hi):
                    continue  # a traffic light on the main road outside the junction's range
                yield virtual_junction_controlled.finding(
                    f"{describe_junction(j)}: dynamic signal {sig.id} on road {road_id} at s={metres(sig.s)} is a "
                    "traffic light in the virtual junction; virtual junctions have no traffic lights",
                    road=road_id,
                    s=sig.s,
                    line=sig.line or None,
                )


@rule("J017", "virtual-junction-range", Category.JUNCTION, Severity.ERROR, uids=(U.VIRTUAL_ONE_START_END,))
def virtual_junction_range(ctx: Context):
    """A virtual junction does not name one range ``sStart``..``sEnd`` on its main road.

    A virtual junction lies on its main road between one ``sStart`` and one ``sEnd`` (``junctions.virtual
    .only_one_start_end``, 12.7): both are given, are numbers, ``sStart`` is not after ``sEnd``, and both lie on the
    main road (0 to its length).

    Passes::

        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="70" orientation="+">

    Fails (road 1 is 100 m long)::

        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="170" orientation="+">
    """
    for j in ctx.document.junctions:
        if j.type is not JunctionType.VIRTUAL:
            continue
        main = ctx.road(j.main_road)
        start, end = j.s_start, j.s_end
        problems = [
            f"{name} is {'missing' if raw is None else f'{raw!r}, not a number'}"
            for name, raw, value in (("sStart", j.xml.text("sStart"), start), ("sEnd", j.xml.text("sEnd"), end))
            if value is None
        ]
        if start is not None and end is not None and start > end:
            problems.append(f"sStart {metres(start)} lies after sEnd {metres(end)}")
        if main is not None and math.isfinite(main.length):
            tol = ctx.tolerances.length_abs
            for name, value in (("sStart", start), ("sEnd", end)):
                if value is not None and not -tol <= value <= main.length + tol:
                    problems.append(
                        f"{name} {metres(value)} is not on main road {main.id} (0 to {metres(main.length)})"
                    )
        if problems:
            yield virtual_junction_range.finding(
                f"{describe_junction(j)}: {'; '.join(problems)}; a virtual junction covers one range sStart..sEnd of "
                "its main road",
                road=j.main_road,
                line=j.line or None,
            )


def _main_road_ends(road: Road, main: str) -> Iterator[tuple[ContactPoint, float | None, int]]:
    """(end, elementS, line) of each link of ``road`` to road ``main``."""
    for end in (ContactPoint.START, ContactPoint.END):
        link = road.link_at(end)
        if link is not None and link.names(ElementType.ROAD, main):
            yield end, link.element_s, link.line


@rule(
    "J018",
    "virtual-junction-branches",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.VIRTUAL_MAIN_ROAD_ONLY, U.VIRTUAL_START_END),
)
def virtual_junction_branches(ctx: Context):
    """A connecting road of a virtual junction does not branch off the main road at ``sStart`` or ``sEnd``.

    Virtual junctions are for branches off the main road only (``junctions.virtual.main_road_only``, 12.7): the
    junction names its main road and every connecting road joins it (a predecessor or successor naming it); a main
    road the file does not define is ``undefined-reference``'s. Each connecting road
    starts or ends at the main road at ``sStart`` or at ``sEnd`` (``junctions.virtual.connecting_roads_start_end``):
    its link's ``elementS`` is one of the two.

    Passes::

        <road id="2" junction="555"><link><predecessor elementType="road" elementId="1" elementS="50" elementDir="+"/>
        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="70" orientation="+">
          <connection id="0" incomingRoad="1" connectingRoad="2" contactPoint="start">...

    Fails (road 2 leaves the main road at s=60)::

        <road id="2" junction="555"><link><predecessor elementType="road" elementId="1" elementS="60" elementDir="+"/>
    """
    tol = ctx.tolerances.length_abs
    for j in ctx.document.junctions:
        if j.type is not JunctionType.VIRTUAL:
            continue
        if j.main_road is None:
            yield virtual_junction_branches.finding(
                f"{describe_junction(j)} names no main road: a virtual junction joins branches to the main road "
                "it names",
                uid=U.VIRTUAL_MAIN_ROAD_ONLY,
                line=j.line or None,
            )
            continue
        if ctx.road(j.main_road) is None:
            continue  # a main road that does not exist: undefined-reference (ids.only_ref_defined_ids)
        seen: set[str] = set()
        for c in j.connections:
            road = ctx.road(c.connecting_road)
            if road is None or road.id in seen or road.id == j.main_road:
                continue
            seen.add(road.id)
            ends = list(_main_road_ends(road, j.main_road))
            if not ends:
                yield virtual_junction_branches.finding(
                    f"{describe_junction(j)} connection {written_id(c)}: connecting road {road.id} does not join main "
                    f"road {j.main_road} (predecessor: {_link_text(road.predecessor)}, successor: "
                    f"{_link_text(road.successor)}); a virtual junction is for branches off its main road only",
                    uid=U.VIRTUAL_MAIN_ROAD_ONLY,
                    road=road.id,
                    line=c.line or j.line or None,
                )
                continue
            marks = [v for v in (j.s_start, j.s_end) if v is not None]
            for end, element_s, line in ends:
                if element_s is None or not marks or any(abs(element_s - m) <= tol for m in marks):
                    continue
                yield virtual_junction_branches.finding(
                    f"{describe_junction(j)}: connecting road {road.id} "
                    f"{'starts' if end is ContactPoint.START else 'ends'} at s={metres(element_s)} of main road "
                    f"{j.main_road}, but the junction spans sStart={metres(j.s_start)} to sEnd={metres(j.s_end)}: "
                    "connecting roads start or end at sStart or sEnd",
                    uid=U.VIRTUAL_START_END,
                    road=road.id,
                    s=0.0 if end is ContactPoint.START else road.length,
                    line=line or road.line or None,
                )


def _link_text(link) -> str:
    return "none" if link is None else f"{link.element_type.value} {link.element_id}"


# ---------------------------------------------------------------------------------------------------- when to use
#: A road end at a junction: the road's id and its contact point (``None`` where the file does not say, and in a
#: direct junction, whose connections name roads only).
RoadEnd = tuple[str, ContactPoint | None]


def reachable(ctx: Context, junction: Junction) -> dict[RoadEnd, set[RoadEnd]]:
    """Road end outside the junction -> the road ends outside it that a connection leads it to (in a common junction:
    the road at the connecting road's other end; in a direct junction: the linked road), and the other way round.
    Ends, not roads: a road that meets the junction with both ends offers two ways on (a loop), which is the
    ambiguity a junction resolves."""
    out: dict[RoadEnd, set[RoadEnd]] = {}
    for c in junction.connections:
        if c.incoming_road is None:
            continue
        source: RoadEnd = (c.incoming_road, None)
        target: RoadEnd | None = None
        if junction.type is JunctionType.DIRECT:
            target = (c.linked_road, None) if c.linked_road is not None else None
        else:
            connecting = ctx.road(c.connecting_road)
            if connecting is None or c.contact_point is None:
                continue
            near = connecting.link_at(c.contact_point)
            if near is not None and near.names(ElementType.ROAD, c.incoming_road):
                source = (c.incoming_road, near.contact_point)
            link = connecting.link_at(c.contact_point.opposite)
            if link is not None and link.element_type is ElementType.ROAD:
                target = (link.element_id, link.contact_point)
        if target is None:
            continue
        out.setdefault(source, set()).add(target)
        out.setdefault(target, set()).add(source)
    return out


def _both_ends(ctx: Context, junction: Junction) -> set[str]:
    """Roads outside the junction that meet it with both ends (each end is a leg of its own)."""
    ends: dict[str, int] = {}
    for road, _ in ctx.junction_link_ends.get(junction.id, ()):
        if road.junction != junction.id:
            ends[road.id] = ends.get(road.id, 0) + 1
    return {road_id for road_id, count in ends.items() if count == 2}


@rule(
    "J019",
    "junction-unneeded",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.COMMON_WHEN_TO_USE, U.COMMON_NOT_ONLY_TWO),
)
def junction_unneeded(ctx: Context):
    """A junction joins roads that could be linked directly.

    Junctions are only used where roads cannot be linked directly: they resolve the ambiguity of a road with two or
    more possible predecessors or successors (``junctions.common.when_to_use``, 12.2, an error). A common or direct
    junction whose connections lead every road to at most one other road, and every road from at most one, has no
    such ambiguity: link the roads (through a connecting road of its own, if need be) instead. Junctions should not be
    used where only two roads meet (``junctions.common.not_only_two``, 1.9, a warning; where those two could be
    linked directly the error above is the one finding). Virtual junctions and
    crossings do not change which road follows which, and are not reported.

    Passes: a T junction (road 1 can continue on road 2 or road 3).

    Fails (road 1 continues only on road 2, and road 2 only on road 1)::

        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/>
          <connection id="1" incomingRoad="2" connectingRoad="11" contactPoint="start"/></junction>
    """
    for junction in ctx.document.junctions:
        if junction.type not in (JunctionType.DEFAULT, JunctionType.DIRECT) or not junction.connections:
            continue
        name = describe_junction(junction)
        paths = reachable(ctx, junction)
        if paths and all(len(targets) <= 1 for targets in paths.values()):
            pairs = sorted({tuple(sorted((a[0], b[0]))) for a, targets in paths.items() for b in targets})
            shown = ", ".join(f"{a}-{b}" for a, b in pairs)
            yield junction_unneeded.finding(
                f"{name} leads each road to one other road only ({shown}): no road has two possible successors or "
                "predecessors, so the roads can be linked directly; a junction is only for that ambiguity",
                uid=U.COMMON_WHEN_TO_USE,
                line=junction.line or None,
            )
            continue  # the error says it: not also the warning that only two roads meet
        touching = legs(ctx, junction)
        if len(touching) + len(_both_ends(ctx, junction)) <= 2:
            roads = " and ".join(f"road {r}" for r in touching) or "no road"
            yield junction_unneeded.finding(
                f"{name}: only {roads} meet in it; where two roads meet, link them directly (junctions are for "
                "three or more)",
                uid=U.COMMON_NOT_ONLY_TWO,
                severity=Severity.WARNING,
                line=junction.line or None,
            )
