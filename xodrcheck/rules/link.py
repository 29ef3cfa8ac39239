"""Positions at contacts (``K1xx``, ``L1xx``): linked road ends and linked lanes really meet.

A *joint* is a pair of road ends that touch: a road link between two roads, or, in a junction, an incoming road's end
and a connection's connecting (or linked) road at the connection's contact point (:meth:`Context.neighbours`). Each
joint is checked once.

* The reference line must leave one road where it enters the other (``K101``; ASAM ``road.geometry.contact_point``)
  for a road link outside junctions. The laneOffset may change there, with the lanes renumbered (a lane next to lane 0
  ends, as at a lane-section boundary): whether the lanes meet is ``K103``'s. In a junction a connecting road may
  carry its reference line anywhere (RoadRunner puts it on a lane border of the incoming road), so there only the
  lanes are compared.
* At every joint, the lane-0 lines' headings must agree (``K102``): a start-to-start or end-to-end link means the
  roads run in opposite directions, so the headings pointing out of the two ends must be opposite.
* Every pair of lanes linked across the joint (lane ``<link>`` records at a road link, ``<laneLink>`` records of a
  junction connection) must have coinciding borders: the two border points of one lane equal those of the other, in
  either order (``K103``).
* The surfaces meet in height too (``K104``): the reference lines (outside junctions) and the touching points of every
  pair of linked lanes have the same z (elevation, superelevation, lane height; ASAM OpenDRIVE Annex D.1.4).
* Inside a road, lanes linked across a lane-section boundary keep their borders, in plan view and in height (``L101``).

Deviations are graded (:meth:`~xodrcheck.config.Tolerances.grade`): distances over ``gap`` (1 cm, the threshold of
ASAM's ``lane.smoothness.contact_point_no_horizontal_gaps``) and angles over ``kink`` (0.01 rad) are errors; over the
strict ``position`` (1 mm) and ``heading`` (1 mrad) tolerances, warnings. ``--profile strict`` makes every deviation
over the strict values an error.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator
from dataclasses import field

from xodrcheck.classcache import dataclass
from xodrcheck.findings import Category, Severity
from xodrcheck.lanes import RoadGeometry
from xodrcheck.model import ContactPoint, ElementType, JunctionType, Road
from xodrcheck.rules import junction_uids as JU
from xodrcheck.rules import lane_uids as U
from xodrcheck.rules import road_uids as RU
from xodrcheck.rules.context import Context, Neighbour, link_at
from xodrcheck.rules.geometry import profile_steps
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.sampled import (
    EndPoint,
    RoadEnd,
    SectionLines,
    angle_between,
    end_s,
    reference_end,
    road_end,
    section_lines,
    usable,
    warning_note,
)


def _joints(ctx: Context, once: bool = True) -> Iterator[tuple[Road, ContactPoint, Neighbour]]:
    """Pairs of touching road ends (road, its end, the neighbour at the other end): each pair once, or with ``once``
    false once per way it is declared (a road link, and each junction connection)."""
    seen: set[tuple] = set()
    for road in ctx.document.roads:
        if usable(ctx, road) is None:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            for neighbour in ctx.neighbours(road, end):
                if usable(ctx, neighbour.road) is None:
                    continue
                pair = frozenset({(road.id, end), (neighbour.road.id, neighbour.contact)})
                key = (pair, None if once or neighbour.connection is None else neighbour.connection.id)
                if len(pair) < 2 or key in seen:
                    continue
                seen.add(key)
                yield road, end, neighbour


def _where(road: Road, end: ContactPoint, point: EndPoint, line: int, lane: int | None = None) -> dict:
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    return {
        "road": road.id,
        "lane": lane,
        "section_s": road.lane_sections[index].s,
        "s": end_s(road, end),
        "x": point.x,
        "y": point.y,
        "z": point.z if math.isfinite(point.z) else None,
        "line": line or road.line or None,
    }


def _joint_line(road: Road, end: ContactPoint, neighbour: Neighbour) -> int:
    if neighbour.connection is not None:
        return neighbour.connection.line
    link = link_at(road, end)
    return link.line if link is not None else 0


def _describe(road: Road, end: ContactPoint, neighbour: Neighbour) -> str:
    junction, connection = neighbour.junction, neighbour.connection
    via = f" (junction {junction.id}, connection {connection.id})" if connection and junction else ""
    return f"the {end.value} of road {road.id} and the {neighbour.contact.value} of road {neighbour.road.id}{via}"


def _junction_uid(
    ctx: Context, road: Road, neighbour: Neighbour, severity: Severity | None, direct: str = JU.DIRECT_SMOOTH
) -> str:
    """The junction rule an error at a junction joint enforces: the linked lanes of a common junction's connection
    (from the incoming road into the connecting road, and from the connecting road on) fit smoothly
    (``junctions.connection.smooth_fit``), those of a direct junction too (``direct``); other road links and warnings
    name none."""
    junction = neighbour.junction or ctx.junction_of(road) or ctx.junction_of(neighbour.road)
    if severity is not Severity.ERROR or junction is None:
        return NO_UID
    if junction.type is JunctionType.DIRECT:
        return direct
    return JU.CONNECTION_SMOOTH_FIT if junction.type is JunctionType.DEFAULT else NO_UID


def _in_junction(ctx: Context, road: Road) -> bool:
    return road.junction is not None and ctx.junction(road.junction) is not None


@rule("K101", "link-gap", Category.LINK, Severity.ERROR, uids=(RU.GEOMETRY_CONTACT_POINT,), every_version=True)
def link_gap(ctx: Context):
    """Two roads linked outside a junction do not meet: their reference lines are apart at the contact points.

    Where road A links to road B, A's reference line at its end must be B's at the linked end (ASAM
    ``road.geometry.contact_point``: "the road reference line of a new road shall always begin at the contactPoint
    element of its successor or predecessor road"). A gap over ``gap`` (1 cm, ASAM's checker's threshold) is an error,
    one over ``position`` (1 mm) a warning (which names no rule of the standard: below ASAM's threshold). The
    laneOffset may change at the link, the lanes renumbered (a lane next to lane 0 ends there); the lanes themselves
    are compared by ``lane-border-gap``, which also checks junction connections lane by lane.

    Passes (road 1 ends at x=100, road 2 starts there)::

        <road id="1" length="100"> ... <geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
        <road id="2" length="100"> ... <geometry s="0" x="100" y="0" hdg="0" length="100"><line/></geometry>

    Fails (road 2 starts 5 cm further on; 5 mm would be a warning)::

        <road id="2" length="100"> ... <geometry s="0" x="100.05" y="0" hdg="0" length="100"><line/></geometry>
    """
    tol = ctx.tolerances
    for road, end, neighbour in _joints(ctx):
        if neighbour.connection is not None or _in_junction(ctx, road) or _in_junction(ctx, neighbour.road):
            continue
        mine = reference_end(ctx, road, end)
        theirs = reference_end(ctx, neighbour.road, neighbour.contact)
        if mine is None or theirs is None:
            continue
        gap = math.hypot(mine.x - theirs.x, mine.y - theirs.y)
        severity = tol.grade(gap)
        if severity is not None:
            yield link_gap.finding(
                f"gap of {gap:.4g} m between {_describe(road, end, neighbour)}: their reference lines are at "
                f"({mine.x:.3f}, {mine.y:.3f}) and ({theirs.x:.3f}, {theirs.y:.3f}); move one road's geometry so they "
                f"meet{warning_note(severity, tol)}",
                severity=severity,
                uid=None if severity is Severity.ERROR else NO_UID,
                **_where(road, end, mine, _joint_line(road, end, neighbour)),
            )


@rule(
    "K102",
    "link-kink",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_HEADING),
    every_version=True,
)
def link_kink(ctx: Context):
    """Two linked roads meet at an angle: the heading changes abruptly at the contact (a kink, with or without a gap).

    Compared on the lane-0 lines (reference line plus laneOffset) at every road link and every junction connection.
    A kink over ``kink`` (0.01 rad, 0.57 deg: the first road's course leaves the second by the 1 cm ``gap`` within a
    metre) is an error, one over ``heading`` (1 mrad) a warning. A start-to-start or end-to-end link joins roads
    running in opposite directions: the heading leaving one road must be the opposite of the heading leaving the other.
    At a junction connection an error enforces ``junctions.connection.smooth_fit`` (1.9: the linked lanes fit
    smoothly, no kink); at a direct junction ``junctions.direct.road_ramp_heading`` (the junction lies where the
    headings of road and ramp are identical).

    Passes (road 2 continues road 1 straight on)::

        <road id="1"> ... <geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
        <road id="2"> ... <geometry s="0" x="100" y="0" hdg="0" length="100"><line/></geometry>

    Fails (road 2 turns 0.1 rad at the joint)::

        <road id="2"> ... <geometry s="0" x="100" y="0" hdg="0.1" length="100"><line/></geometry>
    """
    tol = ctx.tolerances
    for road, end, neighbour in _joints(ctx):
        mine = road_end(ctx, road, end).border(0, "outer")
        theirs = road_end(ctx, neighbour.road, neighbour.contact).border(0, "outer")
        if mine is None or theirs is None:
            continue
        kink = angle_between(mine.outward, theirs.outward + math.pi)
        severity = tol.grade(kink, "heading")
        if severity is not None:
            yield link_kink.finding(
                f"heading changes by {math.degrees(kink):.3g} deg ({kink:.3g} rad) between "
                f"{_describe(road, end, neighbour)}: make the headings at the contact points agree"
                f"{warning_note(severity, tol, 'heading')}",
                severity=severity,
                uid=_junction_uid(ctx, road, neighbour, severity, JU.DIRECT_HEADING),
                **_where(road, end, mine, _joint_line(road, end, neighbour)),
            )


def _lane_pairs(road: Road, end: ContactPoint, neighbour: Neighbour) -> list[tuple[int, int, int]]:
    """(lane of ``road``, lane of the neighbour, source line) for every lane link across the joint."""
    if neighbour.connection is not None:
        connection = neighbour.connection
        if connection.incoming_road == road.id:
            return [(ll.from_lane, ll.to_lane, ll.line) for ll in connection.lane_links]
        return [(ll.to_lane, ll.from_lane, ll.line) for ll in connection.lane_links]
    pairs: dict[tuple[int, int], int] = {}
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    for lane in road.lane_sections[index].lanes:
        for other in lane.predecessors if end is ContactPoint.START else lane.successors:
            pairs.setdefault((lane.id, other), lane.line)
    back = link_at(neighbour.road, neighbour.contact)
    if back is not None and back.element_type is ElementType.ROAD and back.element_id == road.id:
        other_index = 0 if neighbour.contact is ContactPoint.START else len(neighbour.road.lane_sections) - 1
        for lane in neighbour.road.lane_sections[other_index].lanes:
            links = lane.predecessors if neighbour.contact is ContactPoint.START else lane.successors
            for mine in links:
                pairs.setdefault((mine, lane.id), lane.line)
    return [(a, b, line) for (a, b), line in pairs.items() if a != 0 and b != 0]


def _plan_distance(p: EndPoint, q: EndPoint) -> float:
    return math.hypot(p.x - q.x, p.y - q.y)


def _touching(mine: RoadEnd, lane: int, theirs: RoadEnd, other: int) -> tuple[tuple[EndPoint, EndPoint], ...] | None:
    """The touching points of two linked lanes (ASAM OpenDRIVE Annex D.1.1) as two pairs: each edge of ``lane`` (inner,
    outer; raised by lane height) with the edge of ``other`` it meets, in the order that fits best in plan view (a
    start-to-start link meets inner with outer). ``None`` when a lane is not there."""
    inner_a, outer_a = mine.edge(lane, "inner"), mine.edge(lane, "outer")
    inner_b, outer_b = theirs.edge(other, "inner"), theirs.edge(other, "outer")
    if inner_a is None or outer_a is None or inner_b is None or outer_b is None:
        return None
    straight = ((inner_a, inner_b), (outer_a, outer_b))
    crossed = ((inner_a, outer_b), (outer_a, inner_b))
    return min(straight, crossed, key=lambda pairs: max(_plan_distance(p, q) for p, q in pairs))


def _border_gap(mine: RoadEnd, lane: int, theirs: RoadEnd, other: int) -> tuple[float, EndPoint] | None:
    pairs = _touching(mine, lane, theirs, other)
    if pairs is None:
        return None
    return max(_plan_distance(p, q) for p, q in pairs), pairs[1][0]


@rule(
    "K103",
    "lane-border-gap",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_SMOOTH),
    every_version=True,
)
def lane_border_gap(ctx: Context):
    """Two lanes linked across a road link or a junction connection do not meet: their borders are apart.

    For every lane link across a joint (lane ``<predecessor>``/``<successor>`` at a road link, ``<laneLink>`` of a
    junction connection), the inner and outer border of one lane at its road's end must coincide with the borders of
    the other lane at its contact point (in either order). This catches gaps and overlaps between linked lanes (ASAM's
    ``lane.smoothness.contact_point_no_horizontal_gaps``), crossed lane links and lanes linked to a lane of another
    width. Borders over ``gap`` (1 cm, ASAM's threshold) apart are an error, over ``position`` (1 mm) a warning. An
    error at a junction connection enforces ``junctions.connection.smooth_fit`` (1.9) or, in a direct junction,
    ``junctions.direct.linked_lane_smoothness``: the linked lanes fit smoothly as described for roads (10.3).

    Passes (lane -1 of both roads is 3.5 m wide and the roads meet)::

        <road id="1"> ... <lane id="-1"><link><successor id="-1"/></link><width a="3.5" .../></lane>
        <road id="2"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.5" .../></lane>

    Fails (road 2's lane -1 is 3.0 m wide: its outer border is 0.5 m off)::

        <road id="2"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.0" .../></lane>
    """
    tol = ctx.tolerances
    done: set[frozenset] = set()
    for road, end, neighbour in _joints(ctx, once=False):
        mine, theirs = road_end(ctx, road, end), road_end(ctx, neighbour.road, neighbour.contact)
        for lane, other, line in _lane_pairs(road, end, neighbour):
            key = frozenset({(road.id, end, lane), (neighbour.road.id, neighbour.contact, other)})
            if key in done:
                continue
            done.add(key)
            found = _border_gap(mine, lane, theirs, other)
            if found is None:
                continue
            gap, point = found
            severity = tol.grade(gap)
            if severity is None:
                continue
            yield lane_border_gap.finding(
                f"lane {lane} of road {road.id} and lane {other} of road {neighbour.road.id} are linked at "
                f"{_describe(road, end, neighbour)} but their borders are {gap:.4g} m apart: fix the link, the "
                f"widths or the geometry so the linked lanes meet{warning_note(severity, tol)}",
                severity=severity,
                uid=_junction_uid(ctx, road, neighbour, severity),
                **_where(road, end, point, line or _joint_line(road, end, neighbour), lane),
            )


@dataclass
class _Step:
    """The largest height difference found at one joint, and how many contacts there step."""

    road: Road
    end: ContactPoint
    neighbour: Neighbour
    size: float = 0.0
    lane: int | None = None
    other: int | None = None
    points: tuple[EndPoint, EndPoint] | None = None
    line: int = 0
    lanes: set[tuple[int, int]] = field(default_factory=set)

    def add(self, dz: float, pair: tuple[EndPoint, EndPoint], lanes: tuple[int, int] | None, line: int, tol: float):
        if not dz > tol:  # NaN (a damaged elevation) too
            return
        if lanes is not None:
            self.lanes.add(lanes)
        if dz > self.size:
            self.size, self.points, self.line = dz, pair, line
            self.lane, self.other = lanes if lanes is not None else (None, None)


def _steps(ctx: Context, tol: float) -> Iterator[_Step]:
    """Per joint (pair of touching road ends), the height differences above ``tol`` between the reference lines (road
    links outside junctions) and between the touching points of every pair of linked lanes."""
    steps: dict[frozenset, _Step] = {}
    for road, end, neighbour in _joints(ctx, once=False):
        key = frozenset({(road.id, end), (neighbour.road.id, neighbour.contact)})
        step = steps.get(key)
        if step is None:
            step = steps[key] = _Step(road, end, neighbour)
            if neighbour.connection is None and not _in_junction(ctx, road) and not _in_junction(ctx, neighbour.road):
                here = reference_end(ctx, road, end)
                there = reference_end(ctx, neighbour.road, neighbour.contact)
                if here is not None and there is not None:
                    line = _joint_line(road, end, neighbour)
                    step.add(abs(here.z - there.z), (here, there), None, line, tol)
        mine, theirs = road_end(ctx, road, end), road_end(ctx, neighbour.road, neighbour.contact)
        flipped = step.road is not road  # the joint seen from its other road: keep the first road's view
        for lane, other, line in _lane_pairs(road, end, neighbour):
            pairs = _touching(mine, lane, theirs, other)
            if pairs is None:
                continue
            for p, q in pairs:
                pair, lanes = ((q, p), (other, lane)) if flipped else ((p, q), (lane, other))
                step.add(abs(p.z - q.z), pair, lanes, line or _joint_line(road, end, neighbour), tol)
    yield from (step for step in steps.values() if step.points is not None)


@rule(
    "K104",
    "link-step",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_SMOOTH),
    every_version=True,
)
def link_step(ctx: Context):
    """Two linked roads or lanes do not meet in height: the road surface steps up or down at the contact.

    Where two roads touch (a road link, or an incoming road and a connecting road of a junction connection), their
    reference lines (road links outside junctions) and every pair of linked lanes must meet in 3D, not only in plan view
    (ASAM OpenDRIVE Annex D.1.4, "vertical gaps": the z of the touching points must match). ``z`` is evaluated exactly:
    the elevation profile, the superelevation that tilts the lateral axis (a roll mismatch shows as a step at the lane
    edges) and each lane's ``<height>``. A step over ``gap`` (1 cm) is an error, over ``position`` (1 mm) a warning;
    one finding per contact, at its largest step, counting the lane pairs that step. Horizontal gaps are ``link-gap``
    and ``lane-border-gap``. At a junction connection an error enforces ``junctions.connection.smooth_fit`` (1.9) or
    ``junctions.direct.linked_lane_smoothness`` (direct junctions), as ``lane-border-gap``'s.

    Passes (both roads at 0 m where they meet)::

        <road id="1" length="100"> ... <elevation s="0" a="0" b="0" c="0" d="0"/>
        <road id="2" length="100"> ... <elevation s="0" a="0" b="0" c="0" d="0"/>

    Fails (road 1 lies 5 m higher: a 5 m step where it meets road 2)::

        <road id="1" length="100"> ... <elevation s="0" a="5.0" b="0" c="0" d="0"/>
    """
    tol = ctx.tolerances
    for step in _steps(ctx, tol.position):
        severity = tol.grade(step.size)
        if step.points is None:  # _steps yields steps with points only
            continue
        mine, theirs = step.points
        what = (
            "their reference lines"
            if step.lane is None
            else f"lane {step.lane} of road {step.road.id} and lane {step.other} of road {step.neighbour.road.id}"
        )
        lanes = f"; {len(step.lanes)} linked lane pair(s) step" if step.lanes else ""
        joint = _describe(step.road, step.end, step.neighbour)
        yield link_step.finding(
            f"the road surface steps by {step.size:.4g} m in height between {joint}: {what} meet at "
            f"({mine.x:.3f}, {mine.y:.3f}) at z={mine.z:.3f} and z={theirs.z:.3f}{lanes}; make the elevation, "
            f"superelevation and lane heights continue across the contact{warning_note(severity, tol)}",
            severity=severity,
            uid=_junction_uid(ctx, step.road, step.neighbour, severity),
            **_where(step.road, step.end, mine, step.line, step.lane),
        )


def _inner_pairs(side):
    """(id of the lane whose outer border is the inner border, lane) for the lanes of one side, inner to outer."""
    inner = 0
    for lane in side.lanes:
        yield inner, lane
        inner = lane.id


@rule(
    "L101",
    "lane-border-discontinuous",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LINK_MULTIPLE,),
    every_version=True,
)
def lane_border_discontinuous(ctx: Context):
    """Lanes linked across a lane-section boundary inside a road do not meet: a border jumps at the boundary.

    At the start ``s`` of each lane section, every lane linked to a lane of the previous section (by the previous
    lane's ``<successor>`` or its own ``<predecessor>``) must have the same inner and outer border ``t`` as that lane
    has at the end of its section. A lane that appears at full width beside a
    lane it is linked to, or a width record that does not continue the previous section's width, is reported.

    The lanes must also meet in height: the z of each edge (elevation, superelevation unless the lane is ``level``,
    and the lane's ``<height>``) must not step at the boundary (ASAM OpenDRIVE Annex D.1.4). Where the road's own
    elevation or superelevation steps, ``profile-step`` reports it instead. A jump or step over ``gap`` (1 cm) is an
    error, over ``position`` (1 mm) a warning.

    A lane split abruptly into lanes side by side, or lanes merged abruptly into one, is linked to each of them
    (Annex F ``road.lane.link.multiple_connections``); the lane and the band they cover together must meet. Where a
    lane is linked to only one of the lanes it splits into (the jump is closed by unlinked lanes beside the linked one),
    the finding names that rule. (Its second sentence, non-zero width where lanes connect, is
    ``zero-width-lane-linked``'s.)

    Passes (lane -1 keeps 3.5 m across the boundary at s=50)::

        <laneSection s="0"> ... <lane id="-1"><link><successor id="-1"/></link><width a="3.5" .../>
        <laneSection s="50"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.5" .../>

    Fails (the width jumps from 3.5 m to 2.5 m at s=50)::

        <laneSection s="50"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="2.5" .../>
    """
    for road in ctx.document.roads:
        geometry = usable(ctx, road)
        if geometry is None:
            continue
        sections = road.lane_sections
        surface_steps: set[float] | None = None
        for i in range(1, len(sections)):
            before, after = sections[i - 1], sections[i]
            pairs: dict[tuple[int, int], int] = {}
            for lane in before.lanes:
                for nxt in lane.successors:
                    pairs.setdefault((lane.id, nxt), lane.line)
            for lane in after.lanes:
                for prev in lane.predecessors:
                    pairs.setdefault((prev, lane.id), lane.line)
            if not pairs:
                continue
            if surface_steps is None:  # the road's own elevation or superelevation steps: profile-step says so
                surface_steps = {step[2].s for step in profile_steps(road, ctx.tolerances) if step[0] != "laneOffset"}
            old, new = section_lines(ctx, road, i - 1), section_lines(ctx, road, i)
            inner_of = {lane.id: inner for side in geometry.side_lanes(i - 1) for inner, lane in _inner_pairs(side)}
            inner_new = {lane.id: inner for side in geometry.side_lanes(i) for inner, lane in _inner_pairs(side)}
            usable_pairs = {
                (a, b): line
                for (a, b), line in pairs.items()
                if a != 0 and b != 0 and a in old.t and b in new.t  # a missing lane is lane-link-missing-lane's
            }
            for group, line in _link_groups(usable_pairs):
                yield from _boundary_finding(
                    ctx, road, geometry, i, group, line, (old, new), (inner_of, inner_new), usable_pairs, surface_steps
                )


def _boundary_finding(ctx, road, geometry, i, group, line, lines, inners, pairs, surface_steps):
    """The finding (if any) for one group of linked lanes at the start of lane section ``i``."""
    tolerances = ctx.tolerances
    tol = tolerances.position
    before, after = road.lane_sections[i - 1], road.lane_sections[i]
    (a_in, a, b_in, b), (old, new), (inner_of, inner_new) = group, lines, inners
    t_before = (float(old.t[inner_of[a_in]][-1]), float(old.t[a][-1]))
    t_after = (float(new.t[inner_new[b_in]][0]), float(new.t[b][0]))
    jump = max(abs(p - q) for p, q in zip(t_before, t_after))
    z_before = _group_heights(geometry, old, i - 1, a_in, a, inner_of, -1)
    z_after = _group_heights(geometry, new, i, b_in, b, inner_new, 0)
    step = max(abs(p - q) for p, q in zip(z_before, z_after)) if after.s not in surface_steps else 0.0
    severity = tolerances.grade(max(jump, step))
    if severity is None:
        return
    what = []
    if jump > tol:
        what.append(f"its borders jump by {jump:.4g} m ({_change(t_before, t_after)})")
    if step > tol:
        what.append(f"its surface steps by {step:.4g} m in height (z {_change(z_before, z_after)})")
    fix = ", heights and level flags" if step > tol else ""
    advice, uid = f"make the widths{fix} continue or link the right lanes", NO_UID
    if jump > tol and a_in == a and b_in == b:
        split = _unlinked_band(b, t_before, new, inner_new, {y for _, y in pairs}, 0, tol)
        merge = None if split else _unlinked_band(a, t_after, old, inner_of, {x for x, _ in pairs}, -1, tol)
        if split:
            advice, uid = f"lane {a} splits into {_lanes(*split)}: link it to each of them", U.LINK_MULTIPLE
        elif merge:
            advice, uid = f"{_lanes(*merge)} merge into lane {b}: link each of them to it", U.LINK_MULTIPLE
    point = new.borders[b]
    yield lane_border_discontinuous.finding(
        f"road {road.id}: {_lanes(a_in, a)} of the lane section at s={before.s:g} continue"
        f"{'s' if a_in == a else ''} as {_lanes(b_in, b)} at s={after.s:g}, but {' and '.join(what)}; {advice}"
        f"{warning_note(severity, tolerances)}",
        severity=severity,
        uid=uid,
        road=road.id,
        lane=b,
        section_s=after.s,
        s=after.s,
        x=float(point.x[0]),
        y=float(point.y[0]),
        z=z_after[1] if math.isfinite(z_after[1]) else None,
        line=line or after.line or None,
    )


def _unlinked_band(lane_id, want, lines, inner_of, linked, k, tol) -> tuple[int, int] | None:
    """Lanes side by side around ``lane_id`` whose others have no link across the boundary and whose band's inner
    and outer border at sample ``k`` are ``want`` (within ``tol``): what a lane split into (or merged from) when it
    should have linked them all. ``None`` when there is no such band."""
    sign = 1 if lane_id > 0 else -1
    inward, outward = [lane_id], [lane_id]
    while (nxt := inward[-1] - sign) * sign > 0 and nxt in lines.t and nxt not in linked:
        inward.append(nxt)
    while (nxt := outward[-1] + sign) in lines.t and nxt not in linked:
        outward.append(nxt)
    for inner in inward:
        for outer in outward:
            if inner == outer == lane_id:
                continue
            band = (float(lines.t[inner_of[inner]][k]), float(lines.t[outer][k]))
            if max(abs(p - q) for p, q in zip(band, want)) <= tol:
                return inner, outer
    return None


def _link_groups(pairs: dict[tuple[int, int], int]) -> Iterator[tuple[tuple[int, int, int, int], int]]:
    """What must meet across a lane-section boundary, from the lane links ``(before, after) -> line``.

    A lane linked to one lane: the two lanes. A lane split into several lanes side by side (several successors), or
    several lanes side by side merged into one (``road.lane.link.multiple_connections``): the lane and the band the
    others cover together. Yields ``(innermost before, outermost before, innermost after, outermost after)`` with the
    line of the first link; a band that is not side by side on one side (reported by ``lane-links-ambiguous`` and
    ``lane-link-direction``) falls back to its single links.
    """
    after_of: dict[int, list[int]] = {}
    before_of: dict[int, list[int]] = {}
    for a, b in sorted(pairs):
        after_of.setdefault(a, []).append(b)
        before_of.setdefault(b, []).append(a)
    done: set[tuple[int, int]] = set()
    for a, targets in sorted(after_of.items()):
        band = _band(targets) if len(targets) > 1 and all(len(before_of[b]) == 1 for b in targets) else None
        if band is not None:
            inner, outer = band
            done.update((a, b) for b in targets)
            yield (a, a, inner, outer), pairs[(a, targets[0])]
    for b, sources in sorted(before_of.items()):
        band = _band(sources) if len(sources) > 1 and all(len(after_of[a]) == 1 for a in sources) else None
        if band is not None:
            inner, outer = band
            done.update((a, b) for a in sources)
            yield (inner, outer, b, b), pairs[(sources[0], b)]
    for (a, b), line in sorted(pairs.items()):
        if (a, b) not in done:
            yield (a, a, b, b), line


def _band(ids: list[int]) -> tuple[int, int] | None:
    """(innermost, outermost) of lane ids side by side on one side of the centre, else ``None``."""
    ordered = sorted(ids, key=abs)
    sign = 1 if ordered[0] > 0 else -1
    if any(i * sign <= 0 for i in ordered) or any(abs(q) - abs(p) != 1 for p, q in itertools.pairwise(ordered)):
        return None
    return ordered[0], ordered[-1]


def _lanes(inner: int, outer: int) -> str:
    return f"lane {inner}" if inner == outer else f"lanes {inner} to {outer}"


def _group_heights(
    geometry: RoadGeometry, lines: SectionLines, index: int, inner: int, outer: int, inner_of: dict, k: int
) -> tuple[float, float]:
    """z of the inner edge of lane ``inner`` and of the outer edge of lane ``outer`` (the same lane, or a band)."""
    z_inner = _edge_heights(geometry, lines, index, inner, inner_of[inner], k)[0]
    z_outer = _edge_heights(geometry, lines, index, outer, inner_of[outer], k)[1]
    return z_inner, z_outer


def _change(before: tuple[float, float], after: tuple[float, float]) -> str:
    return f"inner {before[0]:.3f} -> {after[0]:.3f}, outer {before[1]:.3f} -> {after[1]:.3f}"


def _edge_heights(
    geometry: RoadGeometry, lines: SectionLines, index: int, lane_id: int, inner_id: int, k: int
) -> tuple[float, float]:
    """z of a lane's inner and outer edge at sample ``k`` of its section's lines, lane height included."""
    if geometry.has_height(index, lane_id):
        s = lines.s[k:][:1]
        edges = (geometry.lane_points(index, lane_id, s, where, raised=True) for where in ("inner", "outer"))
        inner, outer = (float(points.z[0]) for points in edges)
        return inner, outer
    return float(lines.borders[inner_id].z[k]), float(lines.borders[lane_id].z[k])
