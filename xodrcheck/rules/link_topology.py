"""Road-link topology (``K0xx``): links that agree with each other, read from the model alone.

Whether linked ends really meet in position and heading is geometry (``K1xx``, :mod:`xodrcheck.rules.link`).
"""

from __future__ import annotations

from xodrcheck.findings import Category, Severity
from xodrcheck.model import ContactPoint, ElementType, JunctionType, Road, RoadLink
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context

_WORD = {ContactPoint.START: "predecessor", ContactPoint.END: "successor"}


def _describe(link: RoadLink | None) -> str:
    if link is None:
        return "nothing"
    cp = f" ({link.contact_point.value})" if link.contact_point is not None else ""
    return f"{link.element_type.value} {link.element_id}{cp}"


def _junction_refers_to(ctx: Context, junction_id: str, road: Road) -> bool:
    """Whether a junction knows ``road``: as an incoming or linked road of a connection, or as the road one of its
    connecting roads starts or ends at (a road that only leaves the junction is never an incoming road)."""
    junction = ctx.junction(junction_id)
    if junction is None:
        return True  # reported by road-link-target-missing
    for c in junction.connections:
        if road.id in (c.incoming_road, c.linked_road):
            return True
    members = ctx.roads_in_junction.get(junction.id, ())
    return any(member.ends_linked_to(ElementType.ROAD, road.id) for member in members)


@rule("K001", "link-not-reciprocal", Category.LINK, Severity.ERROR, uids=(U.LINKAGE_BOTH_SIDES,), every_version=True)
def link_not_reciprocal(ctx: Context):
    """A road link is not returned: the linked road does not link back at the named contact point.

    When road A's successor is road B at B's start, B's predecessor must be road A at A's end (Annex F
    ``road.linkage.both_sides_consistency``, 1.9: linked at both sides, consistently). Through a junction:
    a road whose predecessor or successor is a junction must be known to that junction (an incoming road of one of its
    connections, or the road one of its connecting roads starts or ends at), and a connecting road's links name the
    roads it joins, whose own links name the junction. A connecting road never links to its own junction.

    Passes::

        <road id="1" ...><link><successor elementType="road" elementId="2" contactPoint="start"/></link>...</road>
        <road id="2" ...><link><predecessor elementType="road" elementId="1" contactPoint="end"/></link>...</road>

    Fails (road 2 does not link back)::

        <road id="1" ...><link><successor elementType="road" elementId="2" contactPoint="start"/></link>...</road>
        <road id="2" ...><link/>...</road>
    """
    for road in ctx.document.roads:
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None:
                continue
            where = {"road": road.id, **ctx.end_at(road, end), "line": link.line or road.line or None}
            mine = f"road {road.id}: {_WORD[end]} is {_describe(link)}"
            if link.element_type is ElementType.JUNCTION:
                if road.junction is not None and road.junction == link.element_id:
                    yield link_not_reciprocal.finding(
                        f"{mine}, its own junction: a connecting road links to the roads it joins, not to its junction",
                        **where,
                    )
                elif not _junction_refers_to(ctx, link.element_id, road):
                    yield link_not_reciprocal.finding(
                        f"{mine}, but junction {link.element_id} has no connection from road {road.id} and none of "
                        f"its connecting roads links to it",
                        **where,
                    )
                continue
            target = ctx.road(link.element_id)
            if target is None or link.contact_point is None:
                continue  # reported by road-link-target-missing / link-contact-point-missing
            back = target.link_at(link.contact_point)
            if back is not None and back.names(ElementType.ROAD, road.id):
                if back.contact_point is not None and back.contact_point is not end:
                    yield link_not_reciprocal.finding(
                        f"{mine}, but road {target.id}'s {_WORD[link.contact_point]} names road {road.id} at its "
                        f"{back.contact_point.value}, not at its {end.value}",
                        **where,
                    )
                continue
            if (
                back is not None
                and back.element_type is ElementType.JUNCTION
                and road.junction is not None
                and back.element_id == road.junction
            ):
                continue  # a connecting road's link to an incoming/outgoing road, which links to the junction
            yield link_not_reciprocal.finding(
                f"{mine}, but road {target.id}'s {_WORD[link.contact_point]} is {_describe(back)}, not road {road.id}",
                **where,
            )


@rule(
    "K002",
    "link-contact-point-missing",
    Category.LINK,
    Severity.ERROR,
    uids=(U.LINKAGE_ROAD_ATTRIBUTES,),
    every_version=True,
)
def link_contact_point_missing(ctx: Context):
    """A link to a road does not say which end of that road it reaches (``contactPoint``).

    Without it, readers guess, and lane links across the joint cannot be resolved (Annex F
    ``road.linkage.road_link_attribute_usage``; a link without ``elementType="road"`` is ``link-attribute-usage``'s).
    (A link with ``elementS``, into the middle of a road, needs none.)

    Passes::

        <successor elementType="road" elementId="2" contactPoint="start"/>

    Fails::

        <successor elementType="road" elementId="2"/>
    """
    for road in ctx.document.roads:
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if (
                link is not None
                and link.element_type is ElementType.ROAD
                and link.contact_point is None
                and link.element_s is None
            ):
                yield link_contact_point_missing.finding(
                    f"road {road.id}: {_WORD[end]} road {link.element_id} has no contactPoint (start or end)",
                    road=road.id,
                    **ctx.end_at(road, end),
                    line=link.line or road.line or None,
                )


@rule("K003", "junction-needed", Category.LINK, Severity.ERROR, uids=(U.LINKAGE_JUNCTION_NEEDED,), every_version=True)
def junction_needed(ctx: Context):
    """Several roads outside junctions link directly to the same end of one road: that is a junction.

    A road end joins at most one other road end directly; where more meet, the standard requires a junction (Annex F
    ``road.linkage.is_junction_needed``). Links are grouped by the end they reach (road and contact point), so two
    roads reaching the two different ends of a road are fine.

    Passes::

        <road id="1" junction="-1"><link><successor elementType="road" elementId="3" contactPoint="start"/></link>
        <road id="2" junction="-1"><link><predecessor elementType="road" elementId="3" contactPoint="end"/></link>

    Fails (roads 1 and 2 both end at the start of road 3)::

        <road id="1" junction="-1"><link><successor elementType="road" elementId="3" contactPoint="start"/></link>
        <road id="2" junction="-1"><link><successor elementType="road" elementId="3" contactPoint="start"/></link>
    """
    reaching: dict[tuple[str, ContactPoint | None], list[tuple[Road, ContactPoint, RoadLink]]] = {}
    for road in ctx.document.roads:
        if road.junction is not None:
            continue  # connecting roads of one junction share their ends on purpose
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None or link.element_type is not ElementType.ROAD or link.element_s is not None:
                continue
            target = ctx.road(link.element_id)
            if target is not None and target.junction is not None:
                junction = ctx.junction(target.junction)
                if junction is not None and junction.type is not JunctionType.DIRECT:
                    continue  # linking a connecting road directly: see link-not-reciprocal
            reaching.setdefault((link.element_id, link.contact_point), []).append((road, end, link))
    for (target_id, contact), links in reaching.items():
        if len(links) < 2:
            continue
        names = ", ".join(f"road {r.id} ({_WORD[e]})" for r, e, _ in links)
        at = f"the {contact.value} of road {target_id}" if contact is not None else f"road {target_id}"
        for road, end, link in links:
            yield junction_needed.finding(
                f"{len(links)} roads link directly to {at}: {names}; where more than two road ends meet, use a "
                "junction",
                road=road.id,
                **ctx.end_at(road, end),
                line=link.line or road.line or None,
            )
