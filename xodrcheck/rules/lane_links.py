"""Lane links written where there is nothing to link, or where links leave it unclear which lane continues which
(``L024``, ``L025``)."""

from __future__ import annotations

import itertools
from collections import defaultdict

from xodrcheck.findings import Category, Severity
from xodrcheck.model import ContactPoint, ElementType, Lane
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.lane_joints import Joint, joints, opposed, side_lanes
from xodrcheck.support.quantities import metres

_WORD = {ContactPoint.START: "predecessor", ContactPoint.END: "successor"}
#: What a lane's ``<link>`` holds when it is not empty.
_LINK_TARGETS = frozenset(_WORD.values())


@rule("L024", "lane-link-not-omitted", Category.LANE, Severity.ERROR, uids=(U.LINK_NO_LINK,))
def lane_link_not_omitted(ctx: Context):
    """A lane has a ``<link>`` with nothing in it, or lane links where its road starts or ends in a junction.

    Annex F ``road.lane.link.no_link``: "the ``<link>`` element shall be omitted if the lane starts or ends in a
    junction or has no link." An empty ``<link/>`` says nothing and shall be left out. Where the road's predecessor
    (successor) is a junction, the junction's ``laneLink`` elements say which lanes continue which: a lane's own
    predecessor (successor) there cannot name a lane of one road, and is left out. (A lane link at a road end without
    any road link: ``lane-link-missing-lane``.)

    Passes::

        <road id="1" ...><link><successor elementType="junction" elementId="100"/></link>
          ... <lane id="-1" type="driving"><width .../></lane>

    Fails::

        <road id="1" ...><link><successor elementType="junction" elementId="100"/></link>
          ... <lane id="-1" type="driving"><link><successor id="-1"/></link><width .../></lane>
    """
    for road in ctx.document.roads:
        for layer in (road.lanes, road.temporary_lanes):
            for section in () if layer is None else layer.lane_sections:
                for lane in (*section.left, *section.center, *section.right):
                    own = lane.link
                    if own is not None and not any(tag in _LINK_TARGETS for tag in own.xml.children):
                        yield lane_link_not_omitted.finding(
                            f"road {road.id} lane {lane.id} (lane section s={metres(section.s)}): the lane's <link> "
                            f"(line {own.line}) holds no predecessor or successor; leave the empty <link> out",
                            road=road.id,
                            lane=lane.id,
                            section_s=section.s,
                            s=section.s,
                            line=own.line,
                        )
    for road in ctx.document.roads:
        if not road.lane_sections:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None or link.element_type is not ElementType.JUNCTION:
                continue
            index = ctx.section_index_at(road, end) or 0
            section = road.lane_sections[index]
            s = section.s if end is ContactPoint.START else road.section_end(index)
            for lane in section.lanes:
                targets = lane.predecessors if end is ContactPoint.START else lane.successors
                if targets:
                    yield lane_link_not_omitted.finding(
                        f"road {road.id} lane {lane.id} (lane section s={metres(section.s)}): the road's {_WORD[end]} "
                        f"is junction {link.element_id}, yet the lane names {_WORD[end]} lane "
                        f"{', '.join(map(str, targets))}; the junction's laneLinks say where lanes continue: leave the "
                        f"lane's {_WORD[end]} out",
                        road=road.id,
                        lane=lane.id,
                        section_s=section.s,
                        s=s,
                        line=lane.line or None,
                    )


@rule("L025", "lane-links-ambiguous", Category.LANE, Severity.ERROR, uids=(U.LINK_USE_JUNCTIONS,))
def lane_links_ambiguous(ctx: Context):
    """Lane links across a joint leave it unclear which lane continues which: a junction is needed there.

    Annex F ``road.lane.link.use_junctions``: "two lanes shall only be linked if their linkage is clear. If the
    relationship to a predecessor or successor is ambiguous, junctions shall be used." A lane may split into lanes side
    by side, and lanes side by side may merge into one (``multiple_connections``); links are ambiguous when a lane
    splits into lanes that are not side by side (lane -1 into -1 and -3, past -2), or when a split and a merge share a
    lane (lane -1 into -1 and -2 while lane -2 also leads into -2): lanes cross or weave there, which is what a
    junction's connecting roads describe. Links in both directions across the joint count, but not a link to a lane
    whose traffic runs the other way (``lane-link-direction``'s).

    Passes (lane -1 splits into -1 and -2)::

        <lane id="-1"><link><successor id="-1"/><successor id="-2"/></link>...</lane>

    Fails (lane -1 splits into -1 and -3, passing over -2)::

        <lane id="-1"><link><successor id="-1"/><successor id="-3"/></link>...</lane>
    """
    seen: set = set()
    for joint in joints(ctx):
        mine, other = joint.mine, joint.other
        key = frozenset({(mine.road.id, mine.index, mine.end), (other.road.id, other.index, other.end)})
        if key in seen:
            continue
        seen.add(key)
        here, there = defaultdict(set), defaultdict(set)
        for lane in side_lanes(mine.section):
            for target in mine.links(lane):
                if _usable(joint, lane, other.section.lane(target), False):
                    here[lane.id].add(target)
                    there[target].add(lane.id)
        if joint.mutual:
            for lane in side_lanes(other.section):
                for target in other.links(lane):
                    if _usable(joint, lane, mine.section.lane(target), True):
                        here[target].add(lane.id)
                        there[lane.id].add(target)
        yield from _ambiguous(mine, other, here, there)


def _usable(joint: Joint, lane: Lane, target: Lane | None, from_other: bool) -> bool:
    """Whether a link counts here: to a side lane that exists, and not to a lane whose traffic runs the other way
    (``lane-link-direction`` reports that link, one finding for one cause)."""
    if target is None or target.id == 0:
        return False
    near, far = (joint.other, joint.mine) if from_other else (joint.mine, joint.other)
    return not opposed(near.road, lane, far.road, target, joint.same_orientation)


def _ambiguous(mine, other, here: dict[int, set[int]], there: dict[int, set[int]]):
    """Findings for one joint: ``here`` maps this side's lanes to the other side's they link, ``there`` the reverse."""
    for side, links, back, far in ((mine, here, there, other), (other, there, here, mine)):
        for lane_id in sorted(links):
            targets = sorted(links[lane_id])
            if len(targets) < 2:
                continue
            where = side.where(lane_id) | {"line": (side.section.lane(lane_id).line or None)}
            named = ", ".join(map(str, targets))
            if not _side_by_side(targets):
                yield lane_links_ambiguous.finding(
                    f"{side.describe()}: lane {lane_id} is linked to lanes {named} of {far.describe()}, which are not "
                    "side by side; lanes that cross like this need a junction",
                    **where,
                )
                continue
            merging = [t for t in targets if len(back[t]) > 1]
            if merging and side is mine:
                t = merging[0]
                others = ", ".join(str(x) for x in sorted(back[t]) if x != lane_id)
                yield lane_links_ambiguous.finding(
                    f"{side.describe()}: lane {lane_id} splits into lanes {named} of {far.describe()}, and lane {t} "
                    f"there also continues lane {others}: a split and a merge share a lane, so which lane continues "
                    "which is unclear; use a junction",
                    **where,
                )


def _side_by_side(ids: list[int]) -> bool:
    """Whether sorted lane ids are neighbours on one side of the centre (-1, -2, -3 or 2, 3)."""
    same_side = all(i > 0 for i in ids) or all(i < 0 for i in ids)
    return same_side and all(b - a == 1 for a, b in itertools.pairwise(ids))
