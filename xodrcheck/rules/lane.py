"""Lane topology (``L0xx``): centre lanes, lane ids, and lane links across lane sections and road links.

The rules here walk *joints*, where the lanes of one lane section end and those of another begin (between two lane
sections of a road, or at a road link between two roads): what a joint is and how to list them is
:mod:`xodrcheck.rules.shared.lane_joints`'s.
"""

from __future__ import annotations

from typing import Any

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import ContactPoint, Lane, LaneType
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.lane_joints import WORD, Joint, joints, linked_lane_pairs, opposed, side_lanes
from xodrcheck.support.quantities import metres

# ------------------------------------------------------------------------------------------------ centre lane, ids
_CENTRE_ID = U.CENTER_LANE_ID
_NUMBERING = U.LANES_NUMBERED_CORRECTLY


@rule(
    "L001",
    "centre-lane-invalid",
    Category.LANE,
    Severity.ERROR,
    uids=(_CENTRE_ID, _NUMBERING, U.CENTER_LANE_SINGULAR),
    every_version=True,
)
def centre_lane_invalid(ctx: Context):
    """The ``<center>`` of a lane section does not hold exactly the one lane 0, or lane 0 is on a side.

    Lane 0 is the reference line of the lanes: the centre lane has the id 0 (Annex F ``road.lane.center_lane_id``),
    there is only one (``road.lane.center_lane_singular``, 1.9), and only side lanes, numbered away from it, sit under
    ``<left>`` and ``<right>`` (``road.lane.lanes_numbered_correctly``, with ``lane-id-sequence`` for the signs of side
    lanes). (A lane section without any centre lane is reported while reading, as ``missing-element``.)

    Passes::

        <center><lane id="0" type="none"/></center>

    Fails::

        <center><lane id="0" type="none"/><lane id="1" type="none"/></center>
    """
    for road in ctx.document.roads:
        for section in road.lane_sections:
            here = f"road {road.id} lane section s={metres(section.s)}"
            where: dict[str, Any] = {"road": road.id, "section_s": section.s, "s": section.s}
            for lane in section.center:
                if lane.id != 0:
                    yield centre_lane_invalid.finding(
                        f"{here}: the centre holds lane {lane.id}; only lane 0 belongs there",
                        uid=_CENTRE_ID,
                        lane=lane.id,
                        line=lane.line or None,
                        **where,
                    )
            zeros = [lane for lane in section.center if lane.id == 0]
            for lane in zeros[1:]:
                yield centre_lane_invalid.finding(
                    f"{here}: more than one centre lane 0; a lane section has exactly one centre lane",
                    uid=U.CENTER_LANE_SINGULAR,
                    lane=0,
                    line=lane.line or None,
                    **where,
                )
            for lane in (*section.left, *section.right):
                if lane.id == 0:
                    yield centre_lane_invalid.finding(
                        f"{here}: lane 0 is under <left>/<right>; it belongs in <center>",
                        uid=_NUMBERING,
                        lane=0,
                        line=lane.line or None,
                        **where,
                    )


@rule("L002", "centre-lane-width", Category.LANE, Severity.ERROR, uids=(U.CENTER_LANE_NO_WIDTH,), every_version=True)
def centre_lane_width(ctx: Context):
    """The centre lane 0 has ``<width>`` or ``<border>`` records: it has no width by definition.

    Readers ignore them, so the writer's idea of the lane layout and the readers' differ (Annex F
    ``road.lane.center_lane_no_width``).

    Passes::

        <center><lane id="0" type="none"><roadMark sOffset="0" type="solid"/></lane></center>

    Fails::

        <center><lane id="0" type="none"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></center>
    """
    for road in ctx.document.roads:
        for section in road.lane_sections:
            for lane in section.center:
                if lane.id == 0 and (lane.widths or lane.borders):
                    record = (lane.widths or lane.borders)[0]
                    kind = "width" if lane.widths else "border"
                    yield centre_lane_width.finding(
                        f"road {road.id} lane section s={metres(section.s)}: the centre lane 0 has a <{kind}> record; "
                        "remove it (lane 0 has no width)",
                        road=road.id,
                        lane=0,
                        section_s=section.s,
                        s=section.s + record.s,
                        line=record.line or lane.line or None,
                    )


@rule(
    "L003",
    "lane-id-sequence",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LANES_NUMBERED_CORRECTLY, U.LANE_ORDER, U.LANE_ORDER_NO_GAPS),
    every_version=True,
)
def lane_id_sequence(ctx: Context):
    """Lane ids of a side are not 1, 2, 3... (left) or -1, -2, -3... (right) without gaps, or sit on the wrong side.

    Readers number lanes outward from the centre and place each lane outside the previous id; a gap or a positive id
    under ``<right>`` makes them disagree about where a lane is. Annex F: a lane on the wrong side breaks
    ``road.lane.lanes_numbered_correctly``, a side whose numbering does not start at 1 (-1) ``road.lane.lane_order``,
    a gap further out ``road.lane.lane_order_noid_gaps``.

    Passes::

        <left><lane id="2" .../><lane id="1" .../></left> <right><lane id="-1" .../><lane id="-2" .../></right>

    Fails (no lane -1)::

        <right><lane id="-2" type="driving">...</lane></right>
    """
    for road in ctx.document.roads:
        for section in road.lane_sections:
            here = f"road {road.id} lane section s={metres(section.s)}"
            where: dict[str, Any] = {"road": road.id, "section_s": section.s, "s": section.s}
            for name, lanes, sign in (("left", section.left, 1), ("right", section.right, -1)):
                wrong = [lane for lane in lanes if lane.id * sign <= 0]
                for lane in wrong:
                    if lane.id != 0:  # lane 0 on a side: centre-lane-invalid
                        yield lane_id_sequence.finding(
                            f"{here}: lane {lane.id} is under <{name}>; {name} lane ids are "
                            f"{'positive' if sign > 0 else 'negative'}",
                            uid=U.LANES_NUMBERED_CORRECTLY,
                            lane=lane.id,
                            line=lane.line or None,
                            **where,
                        )
                ids = sorted({abs(lane.id) for lane in lanes if lane.id * sign > 0})
                gaps = id_gaps(ids)
                if not gaps:
                    continue
                first = next(lane for lane in lanes if lane.id * sign > 0)
                if gaps[0][0] == 1:
                    yield lane_id_sequence.finding(
                        f"{here}: {name} lane ids start at {(gaps[0][1] + 1) * sign}; the lane next to the centre is "
                        f"{sign}",
                        uid=U.LANE_ORDER,
                        lane=sign,
                        line=first.line or None,
                        **where,
                    )
                    gaps = gaps[1:]
                if gaps:
                    yield lane_id_sequence.finding(
                        f"{here}: {name} lanes skip id(s) {gap_text(gaps, sign)}",
                        uid=U.LANE_ORDER_NO_GAPS,
                        lane=gaps[0][0] * sign,
                        line=first.line or None,
                        **where,
                    )


def id_gaps(ids: list[int]) -> list[tuple[int, int]]:
    """Runs ``(first, last)`` of the ids missing from 1 .. max(ids) (sorted, positive): by runs, not one by one, so that
    a damaged id of 10**12 costs nothing."""
    out, prev = [], 0
    for i in ids:
        if i > prev + 1:
            out.append((prev + 1, i - 1))
        prev = i
    return out


def gap_text(gaps: list[tuple[int, int]], sign: int, most: int = 5) -> str:
    parts = [str(a * sign) if a == b else f"{a * sign} to {b * sign}" for a, b in gaps[:most]]
    more = len(gaps) - most
    count = sum(b - a + 1 for a, b in gaps)
    return (
        ", ".join(parts) + (f" and {more} more run(s)" if more > 0 else "") + (f" ({count} ids)" if count > 3 else "")
    )


# ------------------------------------------------------------------------------------------------ links at joints
#: Lane types that carry traffic other than motor vehicles: a break in them is a warning.
_OTHER_TRAFFIC = frozenset(
    {LaneType.SIDEWALK, LaneType.WALKING, LaneType.BIKING, LaneType.TRAM, LaneType.RAIL, LaneType.PARKING}
)


def _continuity_severity(lane: Lane) -> Severity:
    if lane.drivable:
        return Severity.ERROR
    return Severity.WARNING if lane.type in _OTHER_TRAFFIC else Severity.INFO


@rule("L010", "lane-not-continued", Category.LANE, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def lane_not_continued(ctx: Context):
    """A lane of non-zero width ends at a joint without a lane link to the other side.

    Where a lane section ends and another begins (inside a road, or at a road link), every lane that has width there
    must be linked across: by its own ``predecessor``/``successor``, or by the other side's link back to it. A lane may
    start or end without one only at zero width (a lane that opens or closes). Otherwise a full-width lane appears or
    vanishes at the joint: traffic on it has nowhere to come from or go to.

    A connecting road's lanes need their own links at both ends, as in the standard's junction example (12.4): the
    junction's ``laneLink`` says which incoming lane leads into a connecting lane, but readers that follow lane
    links (routing, lane graphs) walk from the connecting lane through its ``predecessor``; the laneLink does not
    stand in for it (the incoming road links to the junction, not back to the connecting road). An error for
    drivable lanes, a warning for sidewalks, bike, tram, rail and parking lanes, an info for the rest (``none``,
    ``border``, ``shoulder``...), which carry no traffic.

    Plausibility: 11.1 says drivable lanes must be continuous, but Annex F gives no checker rule for a lane that
    appears or vanishes at full width, so a warning under the default profile; ``--profile strict`` or ``generator``
    gives the severities above.

    Passes (lane -2 opens from zero width)::

        <laneSection s="0"><right><lane id="-1" ...><link><successor id="-1"/></link>...</lane></right></laneSection>
        <laneSection s="50"><right>
          <lane id="-1" ...><link><predecessor id="-1"/></link>...</lane>
          <lane id="-2" ...><width sOffset="0" a="0" b="0.1" c="0" d="0"/></lane>
        </right></laneSection>

    Fails (lane -2 appears at full width)::

        <laneSection s="50"><right>
          <lane id="-1" ...><link><predecessor id="-1"/></link>...</lane>
          <lane id="-2" ...><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
        </right></laneSection>
    """
    for joint in joints(ctx):
        mine, other = joint.mine, joint.other
        back_named: set[int] = set()
        if joint.mutual:
            for lane in side_lanes(other.section):
                back_named.update(other.links(lane))
        for lane in side_lanes(mine.section):
            if mine.links(lane) or lane.id in back_named:
                continue
            if ctx.zero_width_at(mine.road, mine.index, lane.id, mine.end) is not False:
                continue  # zero width there (a lane opening or closing), or no width at all
            width = ctx.width_at_end(mine.road, mine.index, lane.id, mine.end)
            before = "previous" if mine.end is ContactPoint.START else "next"
            across = f"the {before} lane section" if mine.road is other.road else f"road {other.road.id}"
            yield lane_not_continued.finding(
                f"{mine.describe()}: lane {lane.id} ({lane.type.value}, {width:.2f} m wide at its "
                f"{mine.end.value}) has no {WORD[mine.end]} in {across}; link it, or let it "
                f"{'open' if mine.end is ContactPoint.START else 'close'} at zero width",
                severity=_continuity_severity(lane),
                line=lane.line or None,
                **mine.where(lane.id),
            )


@rule(
    "L011",
    "lane-link-not-reciprocal",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LINK_ACROSS_SECTIONS,),
    every_version=True,
)
def lane_link_not_reciprocal(ctx: Context):
    """A lane link is not returned: lane A's successor is lane B, but B's predecessor does not name A.

    Applies between the lane sections of a road and across road links where both roads link to each other (Annex F
    ``road.lane.link.lanes_across_laneSections``: a lane that continues is connected in both directions). Readers that
    follow links from one side only see different lane graphs. A link to a lane whose traffic runs the other way (a
    lane on the wrong side of lane 0) is ``lane-link-direction``'s, not reported again here.

    Passes::

        <laneSection s="0">  ... <lane id="-1"><link><successor id="-1"/></link>...
        <laneSection s="50"> ... <lane id="-1"><link><predecessor id="-1"/></link>...

    Fails::

        <laneSection s="0">  ... <lane id="-1"><link><successor id="-1"/></link>...
        <laneSection s="50"> ... <lane id="-1"><link/>...
    """
    for joint in joints(ctx):
        if not joint.mutual:
            continue
        mine, other = joint.mine, joint.other
        for lane in side_lanes(mine.section):
            for target_id in mine.links(lane):
                target = other.section.lane(target_id)
                if target is None or target_id == 0 or lane.id in other.links(target):
                    continue
                if opposed(mine.road, lane, other.road, target, joint.same_orientation):
                    continue  # a link to a lane on the wrong side: lane-link-direction's one finding
                yield lane_link_not_reciprocal.finding(
                    f"{mine.describe()}: lane {lane.id}'s {WORD[mine.end]} is lane {target_id} of "
                    f"{other.describe()}, but that lane's {WORD[other.end]} does not name lane {lane.id}",
                    line=target.line or None,
                    **other.where(target_id),
                )


@rule("L012", "lane-link-direction", Category.LANE, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def lane_link_direction(ctx: Context):
    """A lane link joins lanes whose traffic runs in opposite directions.

    Inside a road and where a road's end meets the next road's start, right lanes continue right lanes and left lanes
    left lanes. Where two starts or two ends meet, the reference lines run against each other and right lanes continue
    left lanes. Each road's traffic rule (``rule="RHT"``/``"LHT"``) says which side drives along s, and
    ``direction="reversed"`` (1.8) turns one lane round. Only lanes with one direction of travel count (vehicle lanes
    and ``biking``; not ``bidirectional`` or ``direction="both"``): a sidewalk, shoulder, median or ``none`` lane may
    continue on the other side of lane 0 (CARLA moves lane 0 to a road's edge that way).

    Plausibility: the standard states no rule on the direction of linked lanes, so a warning under the default
    profile; the rule's error under ``--profile strict`` or ``generator``.

    Passes (road 2 starts at road 1's start)::

        <road id="1"><link><predecessor elementType="road" elementId="2" contactPoint="start"/></link>
          ... <lane id="-1"><link><predecessor id="1"/></link>...

    Fails::

        <road id="1"><link><predecessor elementType="road" elementId="2" contactPoint="start"/></link>
          ... <lane id="-1"><link><predecessor id="-1"/></link>...
    """

    def against(joint: Joint, lane: Lane, target: Lane) -> bool:
        return opposed(joint.mine.road, lane, joint.other.road, target, joint.same_orientation)

    for joint, lane, target in linked_lane_pairs(ctx, against):
        mine, other = joint.mine, joint.other
        yield lane_link_direction.finding(
            f"{mine.describe()}: lane {lane.id}'s {WORD[mine.end]} is lane {target.id} of "
            f"{other.describe()}, whose traffic runs the other way "
            f"({'an end meets a start' if joint.same_orientation else f'two {mine.end.value}s meet'})",
            line=lane.line or None,
            **mine.where(lane.id),
        )


def _own_zero_width_uid(ctx: Context, end: ContactPoint) -> str:
    """The UID a lane linked at its own zero-width end breaks: 1.7's ``zero_width_at_start``/``_at_end``, or for older
    files 1.4's ``multiple_connections`` ("all lanes that are connected shall have a non-zero width")."""
    if not ctx.version_at_least(7) and ctx.version is not None:
        return U.LINK_MULTIPLE
    return U.LINK_ZERO_WIDTH_START if end is ContactPoint.START else U.LINK_ZERO_WIDTH_END


@rule(
    "L013",
    "zero-width-lane-linked",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LINK_ZERO_WIDTH_START, U.LINK_ZERO_WIDTH_END, U.LINK_NEW_LANE_APPEAR, U.LINK_MULTIPLE),
    every_version=True,
)
def zero_width_lane_linked(ctx: Context):
    """A lane is linked where it has zero width: a lane that opens or closes is linked to a neighbour's lane.

    Annex F: "lanes that have a width of zero at the beginning of the lane section shall have no predecessor" (and at
    the end no successor: ``road.lane.link.zero_width_at_start``, ``zero_width_at_end``, 1.7), "if a new lane appears
    besides, only the continuing lane shall be connected to the original lane, not the appearing lane"
    (``road.lane.link.new_lane_appear``) and "all lanes that are connected shall have a non-zero width at the
    connection point" (``road.lane.link.multiple_connections``, 1.4: files older than 1.7 and junction laneLinks; its
    first sentence, several links where a lane splits or lanes merge abruptly, is ``lane-border-discontinuous``'s).
    Junction laneLinks count as links.

    Passes (lane -1 continues into lane -1; lane -2 opens without a predecessor)::

        <lane id="-1"><link><successor id="-1"/></link>...</lane>
        ... next section: <lane id="-2"><width sOffset="0" a="0" b="0.1" c="0" d="0"/></lane>

    Fails (lane -1 is linked to the opening lane -2)::

        <lane id="-1"><link><successor id="-2"/></link>...</lane>
        ... next section: <lane id="-2"><width sOffset="0" a="0" b="0.1" c="0" d="0"/></lane>
    """
    seen: set = set()
    for joint in joints(ctx):
        mine, other = joint.mine, joint.other
        for lane in side_lanes(mine.section):
            targets = [t for t in mine.links(lane) if t != 0 and other.section.lane(t) is not None]
            if not targets:
                continue
            if ctx.zero_width_at(mine.road, mine.index, lane.id, mine.end):
                key = (mine.road.id, mine.index, mine.end, lane.id)
                if key not in seen:
                    seen.add(key)
                    yield zero_width_lane_linked.finding(
                        f"{mine.describe()}: lane {lane.id} has zero width at its {mine.end.value} but a "
                        f"{WORD[mine.end]} (lane {', '.join(map(str, targets))}); a lane that "
                        f"{'opens' if mine.end is ContactPoint.START else 'closes'} has none",
                        uid=_own_zero_width_uid(ctx, mine.end),
                        line=lane.line or None,
                        **mine.where(lane.id),
                    )
                continue
            for target_id in targets:
                key = (other.road.id, other.index, other.end, target_id)
                if key in seen or not ctx.zero_width_at(other.road, other.index, target_id, other.end):
                    continue
                seen.add(key)
                yield zero_width_lane_linked.finding(
                    f"{mine.describe()}: lane {lane.id}'s {WORD[mine.end]} is lane {target_id} of "
                    f"{other.describe()}, which has zero width there (it "
                    f"{'opens' if other.end is ContactPoint.START else 'closes'}); link the continuing lane instead",
                    uid=U.LINK_NEW_LANE_APPEAR,
                    line=lane.line or None,
                    **mine.where(lane.id),
                )
    yield from _zero_width_junction_links(ctx)


def _zero_width_junction_links(ctx: Context):
    for junction in ctx.document.junctions:
        for c in junction.connections:
            incoming = ctx.road(c.incoming_road)
            target = ctx.road(ctx.connected_road_id(c))
            if incoming is None or target is None or c.contact_point is None or not target.lane_sections:
                continue
            in_end = ctx.incoming_contact(junction, c)
            if in_end is None or not incoming.lane_sections:
                continue
            in_index = ctx.section_index_at(incoming, in_end)
            to_index = ctx.section_index_at(target, c.contact_point)
            if in_index is None or to_index is None:  # both roads have lane sections (checked above)
                continue
            for ll in c.lane_links:
                for road, index, end, lane_id in (
                    (incoming, in_index, in_end, ll.from_lane),
                    (target, to_index, c.contact_point, ll.to_lane),
                ):
                    if lane_id == 0 or road.lane_sections[index].lane(lane_id) is None:
                        continue
                    if ctx.zero_width_at(road, index, lane_id, end):
                        yield zero_width_lane_linked.finding(
                            f"junction {junction.id} connection {c.id}: laneLink {ll.from_lane} -> {ll.to_lane} "
                            f"uses lane {lane_id} of road {road.id}, which has zero width at its {end.value}",
                            uid=U.LINK_MULTIPLE,
                            road=road.id,
                            lane=lane_id,
                            section_s=road.lane_sections[index].s,
                            line=ll.line or c.line or None,
                        )
