"""Fixes of lane links (``L024``, ``R015``, ``L011``): an empty ``<link/>``, a lane's link into a junction, a lane's
link at a road end that links to nothing (all three the standard says to leave out), and a lane link not returned."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix import places
from xodrcheck.fix.edits import Edit, remove_element
from xodrcheck.fix.linking import across, add_link
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element
from xodrcheck.model import ContactPoint, ElementType, Lane, Road
from xodrcheck.rules.shared.lane_joints import WORD, Side

_WORD = WORD
#: How far along the road (m) a lane's centre may lie from the joint and still count as there.
_AT_JOINT = 0.5


def _located(ws: Workspace, finding: Finding) -> tuple[Road, int, Lane, Element] | str:
    """The finding's road, lane section index, lane and lane element, or why they cannot be found."""
    road = ws.road(finding.road)
    if road is None or finding.lane is None or finding.section_s is None:
        return "the finding names no lane"
    index = next((k for k, sec in enumerate(road.lane_sections) if sec.s == finding.section_s), None)
    lane = road.lane_sections[index].lane(finding.lane) if index is not None else None
    if index is None or lane is None:
        return f"road {road.id} has no lane {finding.lane} in a lane section at s={finding.section_s:g}"
    element = ws.lane_element(road, index, lane)
    if element is None:
        return f"the <lane> of road {road.id} lane {lane.id} is not found in the file"
    return road, index, lane, element


def _blank_besides(ws: Workspace, parent: Element, kept: Iterable[Element]) -> bool:
    """Whether ``parent`` holds nothing but whitespace and ``kept`` (no comment, text or other element)."""
    data, at = ws.text.data, parent.head_end
    rest = []
    for child in sorted(kept, key=lambda e: e.start):
        rest.append(data[at : child.start])
        at = child.end
    rest.append(data[at : parent.inner_end])
    return not b"".join(rest).strip()


def _drop_links(ws: Workspace, link: Element, tags: set[str]) -> list[Edit] | None:
    """Edits removing the ``tags`` children of a lane's ``<link>``, and the ``<link>`` itself when nothing would be
    left in it; ``None`` when it would be left holding only other content (a comment, ``<userData>``)."""
    going = [c for c in link.children if c.tag in tags]
    staying = [c for c in link.children if c.tag not in tags]
    if not any(c.tag in ("predecessor", "successor") for c in staying):
        if staying or not _blank_besides(ws, link, going):
            return None
        return [remove_element(ws.text, link)]
    return [remove_element(ws.text, c) for c in going]


@fixer("L024", "remove-empty-lane-link", safe=True, bound="moves nothing")
def remove_empty_lane_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a lane's empty ``<link/>`` (or ``<link></link>`` with only whitespace inside).

    The standard says the element shall be omitted where a lane has no link (Annex F ``road.lane.link.no_link``); an
    empty one says nothing, so leaving it out changes no route and moves nothing. A ``<link>`` holding a comment or
    ``<userData>`` is left alone.
    """
    for finding in findings:
        links = [
            e for e in ws.text.at_line(finding.line or 0, "link") if e.parent is not None and e.parent.tag == "lane"
        ]
        empty = [e for e in links if not any(c.tag in ("predecessor", "successor") for c in e.children)]
        if not empty:
            continue  # a lane link into a junction: remove-lane-link-into-junction's
        if len(empty) > 1:
            yield Skip(finding, "several empty <link> elements on its line; which one is meant is unclear")
            continue
        link = empty[0]
        if link.children or not _blank_besides(ws, link, ()):
            yield Skip(finding, "the empty <link> holds a comment or other content, which would be lost")
            continue
        yield Repair((finding,), (remove_element(ws.text, link),), f"{_lane_words(finding)}: removed its empty <link>")


def _lane_words(finding: Finding) -> str:
    section = f" (lane section s={finding.section_s:g})" if finding.section_s is not None else ""
    return f"road {finding.road} lane {finding.lane}{section}"


def _ends_of(road: Road, index: int) -> list[ContactPoint]:
    """The road ends the lane section at ``index`` touches."""
    ends = []
    if index == 0:
        ends.append(ContactPoint.START)
    if index == len(road.lane_sections) - 1:
        ends.append(ContactPoint.END)
    return ends


def _grouped(ws: Workspace, findings: list[Finding]) -> Iterator[tuple[list[Finding], tuple | str]]:
    """Findings by the lane they name (a lane linked at both ends gives two findings and one repair)."""
    groups: dict[tuple, list[Finding]] = {}
    for finding in findings:
        groups.setdefault((finding.road, finding.section_s, finding.lane), []).append(finding)
    for group in groups.values():
        yield group, _located(ws, group[0])


@fixer("L024", "remove-lane-link-into-junction", safe=True, bound="moves nothing")
def remove_lane_link_into_junction(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a lane's ``predecessor`` (``successor``) where its road's predecessor (successor) is a junction.

    There the junction's ``laneLink`` elements say which lane continues which; a lane id alone cannot name a lane of
    the junction's roads, so no route uses it and the standard says to omit it (Annex F ``road.lane.link.no_link``).
    The ``<link>`` goes too when nothing else is left in it. Moves nothing.
    """
    for group, located in _grouped(ws, [f for f in findings if not _on_empty_link(ws, f)]):
        if isinstance(located, str):
            yield from (Skip(f, located) for f in group)
            continue
        road, index, lane, element = located
        tags = set()
        for end in _ends_of(road, index):
            link = road.link_at(end)
            targets = lane.predecessors if end is ContactPoint.START else lane.successors
            if link is not None and link.element_type is ElementType.JUNCTION and targets:
                tags.add(_WORD[end])
        links = element.findall("link")
        edits = _drop_links(ws, links[0], tags) if len(links) == 1 and tags else None
        if edits is None:
            yield from (
                Skip(f, "the lane's <link> holds other content, or nothing leads into a junction") for f in group
            )
            continue
        words = " and ".join(sorted(tags))
        yield Repair(tuple(group), tuple(edits), f"{_lane_words(group[0])}: removed its {words} into the junction")


def _on_empty_link(ws: Workspace, finding: Finding) -> bool:
    return any(
        e.parent is not None
        and e.parent.tag == "lane"
        and not any(c.tag in ("predecessor", "successor") for c in e.children)
        for e in ws.text.at_line(finding.line or 0, "link")
    )


@fixer("R015", "remove-lane-link-to-nothing", safe=True, bound="moves nothing")
def remove_lane_link_to_nothing(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a lane's ``predecessor`` (``successor``) at a road start (end) that links to no road or junction,
    where no other road ends near that end.

    Without a road link there is nothing for the lane link to lead into: no route uses it, and the standard says to
    omit it (Annex F ``road.lane.link.no_link``). Where another road's end lies within the road's width of this end,
    the road link may be what is missing: that is left for a person to decide. Links to a lane that does not exist in
    a linked road are left alone too. Moves nothing.
    """
    missing = [f for f in findings if (f.rule_uid or "").endswith("ids.only_ref_defined_ids")]
    yield from (Skip(f, "it names a lane the linked road lacks; which lane is meant is unclear") for f in missing)
    for group, located in _grouped(ws, [f for f in findings if f not in missing]):
        if isinstance(located, str):
            yield from (Skip(f, located) for f in group)
            continue
        road, index, lane, element = located
        tags, near = set(), []
        for end in _ends_of(road, index):
            targets = lane.predecessors if end is ContactPoint.START else lane.successors
            if road.link_at(end) is None and targets:
                tags.add(_WORD[end])
                near += places.roads_near_end(ws, road, end)
        if not tags:
            yield from (Skip(f, "the road links something at that end") for f in group)
            continue
        if near:
            yield from (
                Skip(f, f"road {near[0]} ends there: the road link may be what is missing (link the roads)")
                for f in group
            )
            continue
        links = element.findall("link")
        edits = _drop_links(ws, links[0], tags) if len(links) == 1 else None
        if edits is None:
            yield from (Skip(f, "the lane's <link> holds other content, which would be lost") for f in group)
            continue
        words = " and ".join(sorted(tags))
        yield Repair(
            tuple(group), tuple(edits), f"{_lane_words(group[0])}: removed its {words} (the road links nothing there)"
        )


def _joint_side(road: Road, index: int, finding: Finding) -> Side | None:
    """The side of the joint a finding names: the section's start or end, told by the finding's ``s``."""
    section = road.lane_sections[index]
    start, end = section.s, road.section_end(index)
    if finding.s is None or start == end:
        return None
    if finding.s == start:
        return Side(road, index, ContactPoint.START)
    return Side(road, index, ContactPoint.END) if finding.s == end else None


@fixer("L011", "return-lane-link", safe=True, bound="moves nothing")
def return_lane_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Gives a lane the link back that lanes across a joint make to it, where it links nothing there and each of
    those lanes' centre lies inside it at the joint.

    Lane A's successor is lane B and B has no predecessor: B's predecessor becomes A (A and A' merging into B give
    B both). The lanes already continue each other (A says so, the geometry agrees); the link makes both sides say it
    (Annex F ``road.lane.link.lanes_across_laneSections``). A lane that names other lanes there is left alone: what
    it means to say is for a person to judge. Nothing moves.
    """
    for group, located in _grouped(ws, findings):
        if isinstance(located, str):
            yield from (Skip(f, located) for f in group)
            continue
        road, index, lane, element = located
        side = _joint_side(road, index, group[0])
        other = across(ws, side) if side is not None else None
        if side is None or other is None:
            yield from (Skip(f, "the joint the finding names is not plain") for f in group)
            continue
        if side.links(lane):
            yield from (Skip(f, f"lane {lane.id} names other lanes there; adding one would split it") for f in group)
            continue
        sources = [a for a in other.section.lanes if a.id != 0 and lane.id in other.links(a)]
        held = [
            places.lanes_holding(ws, road, index, side.s, centre, _AT_JOINT)
            if (centre := places.lane_centre(ws, other.road, other.index, other.s, a.id)) is not None
            else None
            for a in sources
        ]
        if not sources or any(h != [lane.id] for h in held):
            yield from (
                Skip(f, f"the lanes linking to lane {lane.id} do not all lie in it at the joint") for f in group
            )
            continue
        word = WORD[side.end].encode()
        markup = b"".join(b"<" + word + b' id="' + str(a.id).encode() + b'"/>' for a in sources)
        edit = add_link(ws, element, markup, side.end)
        if edit is None:
            yield from (Skip(f, "the lane's <link> is not plain in the file") for f in group)
            continue
        names = ", ".join(str(a.id) for a in sources)
        yield Repair(
            tuple(group),
            (edit,),
            f"{_lane_words(group[0])}: added {WORD[side.end]} lane {names} of road {other.road.id}, returning its link",
        )
