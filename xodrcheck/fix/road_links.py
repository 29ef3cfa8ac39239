"""Fixes of road links (``K001``): a link one road makes and the other does not return, where their ends meet."""

from __future__ import annotations

import math
from collections.abc import Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix import places
from xodrcheck.fix.linking import add_link
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import encode_value
from xodrcheck.model import ContactPoint, ElementType, Road
from xodrcheck.rules.shared.lane_joints import WORD


def _link_markup(ws: Workspace, end: ContactPoint, road: Road, contact: ContactPoint) -> bytes:
    enc = ws.text.encoding
    return (
        b"<" + WORD[end].encode() + b' elementType="road" elementId="' + encode_value(road.id, enc) + b'" '
        b'contactPoint="' + contact.value.encode() + b'"/>'
    )


@fixer("K001", "return-road-link", safe=True, bound="moves nothing")
def return_road_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Gives a road the link back that its neighbour makes to it, where it has no link at that end and the two
    reference lines meet there within the ``gap`` tolerance.

    Road A's successor is road B at B's start, and B has no predecessor: B's predecessor becomes road A at A's end.
    The roads already join there (A says so, the geometry agrees); the link makes both sides say it. Nothing moves.
    Links that name something else at that end are left for a person to judge.
    """
    for finding in findings:
        road = ws.road(finding.road)
        if road is None:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
                continue
            if finding.s is not None and abs(finding.s - ws.end_s(road, end)) > 1e-6:
                continue
            target = ws.road(link.element_id)
            if target is None or target.id == road.id:
                continue
            if target.link_at(link.contact_point) is not None:
                yield Skip(finding, f"road {target.id} links something else at its {link.contact_point.value}")
                break
            here, there = places.end_pose(ws, road, end), places.end_pose(ws, target, link.contact_point)
            if here is None or there is None or math.hypot(here[0] - there[0], here[1] - there[1]) > ws.tolerances.gap:
                yield Skip(finding, f"the ends of roads {road.id} and {target.id} do not meet within the gap tolerance")
                break
            element = ws.road_element(target)
            markup = _link_markup(ws, link.contact_point, road, end)
            edit = add_link(ws, element, markup, link.contact_point) if element is not None else None
            if edit is None:
                yield Skip(finding, f"road {target.id}'s <link> is not plain in the file")
                break
            yield Repair(
                (finding,),
                (edit,),
                f"road {target.id}: added {WORD[link.contact_point]} road {road.id} ({end.value}), returning its link",
            )
            break
