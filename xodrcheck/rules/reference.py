"""Reference rules (``R0xx``): ids are unique and every id a file refers to exists where it should.

These need no geometry. A reference that cannot be resolved is reported here once; the link, lane and junction rules
skip what they cannot resolve, so one defect gives one finding.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import ContactPoint, ElementType, JunctionType, LaneSection, Road
from xodrcheck.rules.registry import NO_UID, Rule, rule
from xodrcheck.rules.shared import feature_uids as F
from xodrcheck.rules.shared import junction_uids as JU
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres


def _duplicates(rule_: Rule, items: Iterable, what: str, **where):
    first: dict[str, int] = {}
    for item in items:
        if item.id in first:
            seen = f" (first at line {first[item.id]})" if first[item.id] else ""
            yield rule_.finding(f"{what} id {item.id!r} is used again{seen}", line=item.line or None, **where)
        else:
            first[item.id] = item.line


@rule("R001", "duplicate-road-id", Category.REFERENCE, Severity.ERROR, uids=(F.ID_UNIQUE_IN_CLASS,), every_version=True)
def duplicate_road_id(ctx: Context):
    """Two roads share an id. Links, connections and tools that look roads up by id reach only one of them.

    Passes::

        <road id="1" length="10" junction="-1">...</road>
        <road id="2" length="10" junction="-1">...</road>

    Fails::

        <road id="1" length="10" junction="-1">...</road>
        <road id="1" length="20" junction="-1">...</road>
    """
    yield from _duplicates(duplicate_road_id, ctx.document.roads, "road")


@rule(
    "R002",
    "duplicate-junction-id",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ID_UNIQUE_IN_CLASS,),
    every_version=True,
)
def duplicate_junction_id(ctx: Context):
    """Two junctions share an id.

    Passes::

        <junction id="100">...</junction>
        <junction id="200">...</junction>

    Fails::

        <junction id="100">...</junction>
        <junction id="100">...</junction>
    """
    yield from _duplicates(duplicate_junction_id, ctx.document.junctions, "junction")


@rule(
    "R003",
    "duplicate-lane-id",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(U.LANE_ID_UNIQUE, F.ID_UNIQUE_IN_LANE_SECTION),
    every_version=True,
)
def duplicate_lane_id(ctx: Context):
    """Two lanes of one lane section share an id.

    Annex F ``road.lane.lane_id_unique`` (1.9): lane ids are unique per lane section and lane layer; the lane sections
    of the temporary layer are checked too. Before 1.9 the finding names ``ids.id_unique_in_lane_section`` (lane IDs
    shall be unique within a lane section), which the 1.9 rule refines.

    Passes::

        <right><lane id="-1" type="driving">...</lane><lane id="-2" type="sidewalk">...</lane></right>

    Fails::

        <right><lane id="-1" type="driving">...</lane><lane id="-1" type="sidewalk">...</lane></right>
    """
    from xodrcheck.standard import applies

    uid = U.LANE_ID_UNIQUE if applies(U.LANE_ID_UNIQUE, ctx.version) else F.ID_UNIQUE_IN_LANE_SECTION
    for road in ctx.document.roads:
        temporary = road.temporary_lanes.lane_sections if road.temporary_lanes is not None else ()
        for section in (*road.lane_sections, *temporary):
            lanes = (*section.left, *section.center, *section.right)
            first: dict[int, int] = {}
            for lane in lanes:
                if lane.id in first:
                    seen = f" (first at line {first[lane.id]})" if first[lane.id] else ""
                    yield duplicate_lane_id.finding(
                        f"lane id {lane.id} appears twice in the {_layer(section, temporary)}lane section at "
                        f"s={metres(section.s)} of road {road.id}{seen}",
                        uid=uid,
                        road=road.id,
                        lane=lane.id,
                        section_s=section.s,
                        s=section.s,
                        line=lane.line or None,
                    )
                else:
                    first[lane.id] = lane.line


def _layer(section, temporary) -> str:
    return "temporary layer's " if any(section is other for other in temporary) else ""


@rule(
    "R004",
    "duplicate-connection-id",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ID_UNIQUE_IN_CLASS,),
    every_version=True,
)
def duplicate_connection_id(ctx: Context):
    """Two connections of one junction share an id.

    Passes::

        <junction id="100"><connection id="0" .../><connection id="1" .../></junction>

    Fails::

        <junction id="100"><connection id="0" .../><connection id="0" .../></junction>
    """
    for junction in ctx.document.junctions:
        yield from _duplicates(duplicate_connection_id, junction.connections, f"junction {junction.id}: connection")


@rule(
    "R010",
    "road-link-target-missing",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ONLY_REF_DEFINED_IDS,),
    every_version=True,
)
def road_link_target_missing(ctx: Context):
    """A road's predecessor or successor names a road or junction that does not exist.

    ``elementType`` says where to look: a link of type ``road`` must name an existing road, one of type ``junction``
    an existing junction.

    Passes::

        <road id="1" ...><link><successor elementType="road" elementId="2" contactPoint="start"/></link>...</road>
        <road id="2" ...>...</road>

    Fails (there is no road 7)::

        <road id="1" ...><link><successor elementType="road" elementId="7" contactPoint="start"/></link>...</road>
    """
    for road in ctx.document.roads:
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None:
                continue
            kind = "predecessor" if end is ContactPoint.START else "successor"
            if link.element_type is ElementType.ROAD:
                if ctx.road(link.element_id) is None:
                    hint = (
                        " (a junction has that id: should elementType be junction?)"
                        if ctx.junction(link.element_id)
                        else ""
                    )
                    yield road_link_target_missing.finding(
                        f"road {road.id}: {kind} names road {link.element_id!r}, which does not exist{hint}",
                        road=road.id,
                        **ctx.end_at(road, end),
                        line=link.line or road.line or None,
                    )
            elif ctx.junction(link.element_id) is None:
                hint = " (a road has that id: should elementType be road?)" if ctx.road(link.element_id) else ""
                yield road_link_target_missing.finding(
                    f"road {road.id}: {kind} names junction {link.element_id!r}, which does not exist{hint}",
                    road=road.id,
                    **ctx.end_at(road, end),
                    line=link.line or road.line or None,
                )


@rule(
    "R011",
    "connection-road-missing",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ONLY_REF_DEFINED_IDS,),
    every_version=True,
    basis=Basis.READING,
)
def connection_road_missing(ctx: Context):
    """A junction connection names an incoming, connecting or linked road that does not exist, or lacks one.

    A connection of a default junction needs ``incomingRoad`` and ``connectingRoad``; one of a direct junction
    ``incomingRoad`` and ``linkedRoad``.

    Passes::

        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/></junction>

    Fails (no road 99)::

        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="99" contactPoint="start"/></junction>
    """
    for junction in ctx.document.junctions:
        direct = junction.type is JunctionType.DIRECT
        for c in junction.connections:
            at = f"junction {junction.id} connection {c.id}"
            where: dict[str, Any] = {"road": c.incoming_road, "line": c.line or junction.line or None}
            if c.incoming_road is None:
                yield connection_road_missing.finding(
                    f"{at} has no incomingRoad", uid=NO_UID, **{**where, "road": None}
                )
            elif ctx.road(c.incoming_road) is None:
                yield connection_road_missing.finding(
                    f"{at}: incomingRoad {c.incoming_road!r} does not exist", **{**where, "road": None}
                )
            target = ctx.connected_road_id(c)
            attr = (
                "linkedRoad"
                if direct or (c.connecting_road is None and c.linked_road is not None)
                else "connectingRoad"
            )
            if target is None:
                yield connection_road_missing.finding(f"{at} has no {attr}", uid=NO_UID, **where)
            elif ctx.road(target) is None:
                yield connection_road_missing.finding(f"{at}: {attr} {target!r} does not exist", **where)


@rule(
    "R012",
    "junction-lane-link-missing-lane",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ONLY_REF_DEFINED_IDS,),
    every_version=True,
)
def junction_lane_link_missing_lane(ctx: Context):
    """A junction ``laneLink`` names a lane that does not exist where it must.

    ``from`` must be a lane of the incoming road's lane section at the end that touches the junction; ``to`` a lane
    of the connecting (or linked) road's lane section at the connection's ``contactPoint``.

    Passes (road 10 has lane -1 in its first lane section)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-1"/>
        </connection>

    Fails (road 10 has no lane -3)::

        <connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-3"/>
        </connection>
    """
    for junction in ctx.document.junctions:
        for c in junction.connections:
            if not c.lane_links:
                continue
            incoming = ctx.road(c.incoming_road)
            target = ctx.road(ctx.connected_road_id(c))
            in_end = ctx.incoming_contact(junction, c) if incoming is not None else None
            in_section = ctx.section_at(incoming, in_end) if incoming is not None and in_end is not None else None
            to_section = ctx.section_at(target, c.contact_point) if target and c.contact_point else None
            for ll in c.lane_links:
                line = ll.line or c.line or None
                if (
                    in_section is not None
                    and incoming is not None
                    and in_end is not None
                    and in_section.lane(ll.from_lane) is None
                ):
                    yield junction_lane_link_missing_lane.finding(
                        f"junction {junction.id} connection {c.id}: laneLink from lane {ll.from_lane}, but the "
                        f"incoming road {incoming.id} has no lane {ll.from_lane} at its {in_end.value} (lane section "
                        f"s={metres(in_section.s)})",
                        road=incoming.id,
                        lane=ll.from_lane,
                        **ctx.end_at(incoming, in_end),
                        line=line,
                    )
                if (
                    to_section is not None
                    and target is not None
                    and c.contact_point is not None
                    and to_section.lane(ll.to_lane) is None
                ):
                    yield junction_lane_link_missing_lane.finding(
                        f"junction {junction.id} connection {c.id}: laneLink to lane {ll.to_lane}, but road "
                        f"{target.id} has no lane {ll.to_lane} at its {c.contact_point.value} (lane section "
                        f"s={metres(to_section.s)})",
                        road=target.id,
                        lane=ll.to_lane,
                        **ctx.end_at(target, c.contact_point),
                        line=line,
                    )


@rule(
    "R013",
    "connecting-road-outside-junction",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(JU.CROSS_PATH_JUNCTION_ID,),
    every_version=True,
)
def connecting_road_outside_junction(ctx: Context):
    """A connection's connecting road does not belong to the connection's junction.

    Its ``junction`` attribute names another junction, or ``-1``. Annex F ``junctions.cross_path.correct_junction_id``
    (1.8, listed with cross paths but worded for every road): "The @junction attribute shall contain the id of the
    junction to which a road belongs"; a connecting road belongs to the junction whose connection names it. Older
    files are checked too, as plausibility (a warning unless a profile asks for more).

    Passes::

        <road id="10" length="20" junction="100">...</road>
        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/></junction>

    Fails (road 10 says it is not in a junction)::

        <road id="10" length="20" junction="-1">...</road>
        <junction id="100"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/></junction>
    """
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.DIRECT:
            continue  # a direct junction joins ordinary roads (linkedRoad); they do not belong to it
        for c in junction.connections:
            road = ctx.road(c.connecting_road)
            if road is None or road.junction == junction.id:
                continue
            belongs = (
                'is not in a junction (junction="-1")'
                if road.junction is None
                else (f"says it belongs to junction {road.junction}")
            )
            yield connecting_road_outside_junction.finding(
                f"junction {junction.id} connection {c.id}: connecting road {road.id} {belongs}",
                road=road.id,
                line=c.line or None,
            )


@rule(
    "R014",
    "road-junction-missing",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ONLY_REF_DEFINED_IDS,),
    every_version=True,
)
def road_junction_missing(ctx: Context):
    """A road's ``junction`` attribute names a junction that does not exist.

    Passes::

        <road id="10" length="20" junction="100">...</road>
        <junction id="100">...</junction>

    Fails (there is no junction 300)::

        <road id="10" length="20" junction="300">...</road>
    """
    for road in ctx.document.roads:
        if road.junction is not None and ctx.junction(road.junction) is None:
            yield road_junction_missing.finding(
                f"road {road.id} says it belongs to junction {road.junction!r}, which does not exist",
                road=road.id,
                line=road.line or None,
            )


def _lane_link_targets(
    ctx: Context, road: Road, index: int, end: ContactPoint
) -> tuple[str | None, LaneSection | None]:
    """Where the lane links of section ``index`` at ``end`` point: a description and the lane section there.

    The description is ``None`` when the road has nothing there (no next section, no road link); the section is
    ``None`` when the links are not checked here (into a junction, or an unresolvable road link).
    """
    last = len(road.lane_sections) - 1
    if end is ContactPoint.START and index > 0:
        return f"lane section s={metres(road.lane_sections[index - 1].s)}", road.lane_sections[index - 1]
    if end is ContactPoint.END and index < last:
        return f"lane section s={metres(road.lane_sections[index + 1].s)}", road.lane_sections[index + 1]
    link = road.link_at(end)
    if link is None:
        return None, None
    target = ctx.road(link.element_id) if link.element_type is ElementType.ROAD else None
    if target is None or link.contact_point is None:
        return "", None  # into a junction (its laneLinks say where), or reported by another rule
    return f"road {target.id} at its {link.contact_point.value}", ctx.section_at(target, link.contact_point)


@rule(
    "R015",
    "lane-link-missing-lane",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(U.LINK_NO_LINK, F.ONLY_REF_DEFINED_IDS),
    every_version=True,
)
def lane_link_missing_lane(ctx: Context):
    """A lane's ``predecessor`` or ``successor`` names a lane that does not exist, or there is nothing to link to.

    Inside a road a lane's links point to the previous or next lane section; at the road's ends they point to the
    lane section of the linked road at the link's contact point. A lane link at an end where the road has no
    predecessor or successor points nowhere: Annex F ``road.lane.link.no_link`` says a lane that has no link there
    has no ``<link>`` entry for it (or the road link is missing).

    Passes (road 2 has a lane -1 at its start)::

        <road id="1" ...><link><successor elementType="road" elementId="2" contactPoint="start"/></link>
          ... <lane id="-1" type="driving"><link><successor id="-1"/></link>...</lane> ...

    Fails (road 2 has no lane -2)::

        <road id="1" ...><link><successor elementType="road" elementId="2" contactPoint="start"/></link>
          ... <lane id="-1" type="driving"><link><successor id="-2"/></link>...</lane> ...
    """
    for road in ctx.document.roads:
        for index, section in enumerate(road.lane_sections):
            for end, attr in ((ContactPoint.START, "predecessors"), (ContactPoint.END, "successors")):
                word = "predecessor" if end is ContactPoint.START else "successor"
                lanes_linking = [lane for lane in section.lanes if getattr(lane, attr)]
                if not lanes_linking:
                    continue
                described, target_section = _lane_link_targets(ctx, road, index, end)
                for lane in lanes_linking:
                    where: dict[str, Any] = {
                        "road": road.id,
                        "lane": lane.id,
                        "section_s": section.s,
                        "s": section.s,
                        "line": lane.line or None,
                    }
                    if described is None:
                        targets = ", ".join(map(str, getattr(lane, attr)))
                        yield lane_link_missing_lane.finding(
                            f"road {road.id} lane {lane.id} (lane section s={metres(section.s)}) has {word} lane "
                            f"{targets} but the road has no {word}; remove the lane's {word} (or link the road)",
                            uid=U.LINK_NO_LINK,
                            **where,
                        )
                        continue
                    if target_section is None:
                        continue
                    for target_id in getattr(lane, attr):
                        if target_section.lane(target_id) is None:
                            yield lane_link_missing_lane.finding(
                                f"road {road.id} lane {lane.id} (lane section s={metres(section.s)}): {word} lane "
                                f"{target_id} does not exist in {described}",
                                uid=F.ONLY_REF_DEFINED_IDS,
                                **where,
                            )
