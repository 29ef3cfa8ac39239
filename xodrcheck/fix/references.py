"""Unsafe fixes of dangling references (``R010``, ``R012``): a road link to a road or junction that does not exist, a
junction lane link to a lane that does not exist (where the lane meant is not plain). Dropping them loses what the
author may have meant to link; the repair says what was dropped."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import Edit, remove_element
from xodrcheck.fix.junctions import connection_at, lane_link_at, lane_link_repair
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element
from xodrcheck.model import ContactPoint, ElementType, Road

_WORD = {ContactPoint.START: "predecessor", ContactPoint.END: "successor"}


def _dangling_end(ws: Workspace, road: Road, finding: Finding) -> ContactPoint | None:
    ends = []
    for end in (ContactPoint.START, ContactPoint.END):
        link = road.link_at(end)
        if link is None or (finding.line and link.line != finding.line):
            continue
        exists = ws.road(link.element_id) if link.element_type is ElementType.ROAD else ws.junction(link.element_id)
        if exists is None:
            ends.append(end)
    return ends[0] if len(ends) == 1 else None


def _lane_link_edits(ws: Workspace, road: Road, end: ContactPoint) -> list[Edit] | None:
    """Edits removing the lanes' own links at ``end`` (they led into what the road link named)."""
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    if not road.lane_sections:
        return []
    edits: list[Edit] = []
    for lane in road.lane_sections[index].lanes:
        if not (lane.predecessors if end is ContactPoint.START else lane.successors):
            continue
        element = ws.lane_element(road, index, lane)
        links = element.findall("link") if element is not None else []
        if len(links) != 1:
            return None
        link = links[0]
        going = link.findall(_WORD[end])
        staying = [c for c in link.children if c not in going]
        edits += [remove_element(ws.text, link)] if not staying else [remove_element(ws.text, c) for c in going]
    return edits


@fixer("R010", "drop-dangling-road-link", safe=False, bound="moves nothing; drops a link and its lanes' links")
def drop_dangling_road_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a road's ``predecessor`` (``successor``) that names a road or junction the file does not have, with the
    lanes' links at that end, which led into it; the road's ``<link>`` goes when nothing is left in it.

    Nothing can be reached through a link to nothing, but the author may have meant another id: the repair names
    what it dropped. Moves nothing.
    """
    for finding in findings:
        road = ws.road(finding.road)
        end = _dangling_end(ws, road, finding) if road is not None else None
        if road is None or end is None:
            continue
        element = ws.road_link_element(road, end)
        lanes = _lane_link_edits(ws, road, end)
        if element is None or element.parent is None or lanes is None:
            yield Skip(finding, "the link or the lanes' links are not plain in the file")
            continue
        parent: Element = element.parent
        alone = all(c is element for c in parent.children)
        edits = (remove_element(ws.text, parent if alone else element), *lanes)
        link = road.link_at(end)
        assert link is not None
        yield Repair(
            (finding,),
            edits,
            f"road {road.id}: dropped its {_WORD[end]} {link.element_type.value} {link.element_id} (no such "
            f"{link.element_type.value}) and {len(lanes)} lane link(s) into it",
        )


@fixer("R012", "drop-junction-lane-link", safe=False, bound="moves nothing; drops a lane link of a connection")
def drop_junction_lane_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a junction ``laneLink`` that names a lane the road does not have, where no single lane is plainly
    meant (``correct-junction-lane-link`` corrects the others).

    The link leads nowhere; the repair names it. Moves nothing.
    """
    for finding in findings:
        found = connection_at(ws, finding)
        ll = lane_link_at(found[1], finding) if found is not None else None
        if found is None or ll is None:
            continue
        junction, c = found
        yield lane_link_repair(
            ws,
            finding,
            (junction, c, ll),
            lambda element: (remove_element(ws.text, element),),
            f"dropped laneLink from {ll.from_lane} to {ll.to_lane}",
        )
