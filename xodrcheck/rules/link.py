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

The joints, the lanes linked across them and where they touch come from :mod:`xodrcheck.rules.shared.link_joints`; what
must meet at a lane-section boundary from :mod:`xodrcheck.rules.shared.lane_boundary`.
"""

from __future__ import annotations

import math

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import ContactPoint, LaneSection, Road
from xodrcheck.rules.geometry import profile_steps
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import junction_uids as JU
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared import road_uids as RU
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.lane_boundary import (
    boundary_links,
    change_text,
    group_heights,
    inner_pairs,
    lanes_text,
    link_groups,
    unlinked_band,
)
from xodrcheck.rules.shared.lane_joints import opposed
from xodrcheck.rules.shared.link_joints import (
    border_gap,
    describe_joint,
    height_steps,
    in_junction,
    joint_line,
    joints,
    junction_uid,
    lane_pairs,
    location,
)
from xodrcheck.rules.shared.road_ends import reference_end, road_end
from xodrcheck.rules.shared.sampled import angle_between, section_lines, warning_note
from xodrcheck.support.quantities import metres


@rule(
    "K101",
    "link-gap",
    Category.LINK,
    Severity.ERROR,
    uids=(RU.GEOMETRY_CONTACT_POINT,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
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
    for road, end, neighbour in joints(ctx):
        if neighbour.connection is not None or in_junction(ctx, road) or in_junction(ctx, neighbour.road):
            continue
        mine = reference_end(ctx, road, end)
        theirs = reference_end(ctx, neighbour.road, neighbour.contact)
        if mine is None or theirs is None:
            continue
        gap = math.hypot(mine.x - theirs.x, mine.y - theirs.y)
        severity = tol.grade(gap)
        if severity is not None:
            yield link_gap.finding(
                f"gap of {gap:.4g} m between {describe_joint(road, end, neighbour)}: their reference lines are at "
                f"({mine.x:.3f}, {mine.y:.3f}) and ({theirs.x:.3f}, {theirs.y:.3f}); move one road's geometry so they "
                f"meet{warning_note(severity, tol)}",
                severity=severity,
                uid=None if severity is Severity.ERROR else NO_UID,
                **location(road, end, mine, joint_line(road, end, neighbour)),
            )


@rule(
    "K102",
    "link-kink",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_HEADING),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
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

    Outside junctions Annex F has no checker rule for a kink between linked roads (``road.geometry.contact_point``
    asks only that they meet): plausibility, a warning under the default profile, the rule's error under ``--profile
    strict`` or ``generator``.

    Passes (road 2 continues road 1 straight on)::

        <road id="1"> ... <geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
        <road id="2"> ... <geometry s="0" x="100" y="0" hdg="0" length="100"><line/></geometry>

    Fails (road 2 turns 0.1 rad at the joint)::

        <road id="2"> ... <geometry s="0" x="100" y="0" hdg="0.1" length="100"><line/></geometry>
    """
    tol = ctx.tolerances
    for road, end, neighbour in joints(ctx):
        mine = road_end(ctx, road, end).border(0, "outer")
        theirs = road_end(ctx, neighbour.road, neighbour.contact).border(0, "outer")
        if mine is None or theirs is None:
            continue
        kink = angle_between(mine.outward, theirs.outward + math.pi)
        severity = tol.grade(kink, "heading")
        if severity is not None:
            yield link_kink.finding(
                f"heading changes by {math.degrees(kink):.3g} deg ({kink:.3g} rad) between "
                f"{describe_joint(road, end, neighbour)}: make the headings at the contact points agree"
                f"{warning_note(severity, tol, 'heading')}",
                severity=severity,
                uid=junction_uid(ctx, road, neighbour, severity, JU.DIRECT_HEADING),
                **location(road, end, mine, joint_line(road, end, neighbour)),
            )


@rule(
    "K103",
    "lane-border-gap",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_SMOOTH),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def lane_border_gap(ctx: Context):
    """Two lanes linked across a road link or a junction connection do not meet: their borders are apart.

    For every lane link across a joint (lane ``<predecessor>``/``<successor>`` at a road link, ``<laneLink>`` of a
    junction connection), the inner and outer border of one lane at its road's end must coincide with the borders of
    the other lane at its contact point (in either order). This catches gaps and overlaps between linked lanes (ASAM's
    ``lane.smoothness.contact_point_no_horizontal_gaps``), crossed lane links and lanes linked to a lane of another
    width. A road link naming a lane whose traffic runs the other way (on the wrong side of lane 0) is
    ``lane-link-direction``'s one finding, not a border gap too. Borders over ``gap`` (1 cm, ASAM's threshold) apart
    are an error, over ``position`` (1 mm) a warning. An error at a junction connection enforces
    ``junctions.connection.smooth_fit`` (1.9) or, in a direct junction, ``junctions.direct.linked_lane_smoothness``:
    the linked lanes fit smoothly as described for roads (10.3).

    Elsewhere (road links outside junctions) Annex F has no checker rule for it (11.1 says in words that drivable
    lanes are continuous): plausibility, a warning under the default profile, the rule's error under ``--profile
    strict`` or ``generator``.

    Passes (lane -1 of both roads is 3.5 m wide and the roads meet)::

        <road id="1"> ... <lane id="-1"><link><successor id="-1"/></link><width a="3.5" .../></lane>
        <road id="2"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.5" .../></lane>

    Fails (road 2's lane -1 is 3.0 m wide: its outer border is 0.5 m off)::

        <road id="2"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.0" .../></lane>
    """
    tol = ctx.tolerances
    done: set[frozenset] = set()
    for road, end, neighbour in joints(ctx, once=False):
        mine, theirs = road_end(ctx, road, end), road_end(ctx, neighbour.road, neighbour.contact)
        for lane, other, line in lane_pairs(road, end, neighbour):
            key = frozenset({(road.id, end, lane), (neighbour.road.id, neighbour.contact, other)})
            if key in done:
                continue
            done.add(key)
            if neighbour.connection is None and _opposed_at_link(ctx, road, end, lane, neighbour, other):
                continue  # a link to a lane on the wrong side: lane-link-direction's one finding
            found = border_gap(mine, lane, theirs, other)
            if found is None:
                continue
            gap, point = found
            severity = tol.grade(gap)
            if severity is None:
                continue
            yield lane_border_gap.finding(
                f"lane {lane} of road {road.id} and lane {other} of road {neighbour.road.id} are linked at "
                f"{describe_joint(road, end, neighbour)} but their borders are {gap:.4g} m apart: fix the link, the "
                f"widths or the geometry so the linked lanes meet{warning_note(severity, tol)}",
                severity=severity,
                uid=junction_uid(ctx, road, neighbour, severity),
                **location(road, end, point, line or joint_line(road, end, neighbour), lane),
            )


def _opposed_at_link(ctx: Context, road: Road, end: ContactPoint, lane_id: int, neighbour, other_id: int) -> bool:
    """Whether lanes linked across a road link carry traffic running opposite ways (``lane-link-direction``)."""
    lane, other = ctx.lane_at(road, end, lane_id), ctx.lane_at(neighbour.road, neighbour.contact, other_id)
    if lane is None or other is None:
        return False
    return opposed(road, lane, neighbour.road, other, end is not neighbour.contact)


@rule(
    "K104",
    "link-step",
    Category.LINK,
    Severity.ERROR,
    uids=(JU.CONNECTION_SMOOTH_FIT, JU.DIRECT_SMOOTH),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
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

    Elsewhere (road links outside junctions) Annex F has no checker rule for it (11.1 says in words that drivable
    lanes are continuous): plausibility, a warning under the default profile, the rule's error under ``--profile
    strict`` or ``generator``.

    Passes (both roads at 0 m where they meet)::

        <road id="1" length="100"> ... <elevation s="0" a="0" b="0" c="0" d="0"/>
        <road id="2" length="100"> ... <elevation s="0" a="0" b="0" c="0" d="0"/>

    Fails (road 1 lies 5 m higher: a 5 m step where it meets road 2)::

        <road id="1" length="100"> ... <elevation s="0" a="5.0" b="0" c="0" d="0"/>
    """
    tol = ctx.tolerances
    for step in height_steps(ctx, tol.position):
        severity = tol.grade(step.size)
        if step.points is None:  # height_steps yields steps with points only
            continue
        mine, theirs = step.points
        what = (
            "their reference lines"
            if step.lane is None
            else f"lane {step.lane} of road {step.road.id} and lane {step.other} of road {step.neighbour.road.id}"
        )
        lanes = f"; {len(step.lanes)} linked lane pair(s) step" if step.lanes else ""
        joint = describe_joint(step.road, step.end, step.neighbour)
        yield link_step.finding(
            f"the road surface steps by {step.size:.4g} m in height between {joint}: {what} meet at "
            f"({mine.x:.3f}, {mine.y:.3f}) at z={mine.z:.3f} and z={theirs.z:.3f}{lanes}; make the elevation, "
            f"superelevation and lane heights continue across the contact{warning_note(severity, tol)}",
            severity=severity,
            uid=junction_uid(ctx, step.road, step.neighbour, severity),
            **location(step.road, step.end, mine, step.line, step.lane),
        )


@rule(
    "L101",
    "lane-border-discontinuous",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LINK_MULTIPLE,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
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
    ``zero-width-lane-linked``'s: a link from or to a lane of zero width at the boundary, an opening or closing lane,
    is reported there once, not again as a border jump here.)

    Apart from that rule, Annex F has no checker rule for lanes that jump between lane sections (11.1 says in words
    that drivable lanes are continuous): plausibility, a warning under the default profile, the rule's error under
    ``--profile strict`` or ``generator``.

    Passes (lane -1 keeps 3.5 m across the boundary at s=50)::

        <laneSection s="0"> ... <lane id="-1"><link><successor id="-1"/></link><width a="3.5" .../>
        <laneSection s="50"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="3.5" .../>

    Fails (the width jumps from 3.5 m to 2.5 m at s=50)::

        <laneSection s="50"> ... <lane id="-1"><link><predecessor id="-1"/></link><width a="2.5" .../>
    """
    for road in ctx.document.roads:
        geometry = ctx.usable_geometry(road)
        if geometry is None:
            continue
        sections = road.lane_sections
        surface_steps: set[float] | None = None
        for i in range(1, len(sections)):
            pairs = boundary_links(sections[i - 1], sections[i])
            if not pairs:
                continue
            if surface_steps is None:  # the road's own elevation or superelevation steps: profile-step says so
                surface_steps = {step[2].s for step in profile_steps(road, ctx.tolerances) if step[0] != "laneOffset"}
            old, new = section_lines(ctx, road, i - 1), section_lines(ctx, road, i)
            inner_of = {lane.id: inner for side in geometry.side_lanes(i - 1) for inner, lane in inner_pairs(side)}
            inner_new = {lane.id: inner for side in geometry.side_lanes(i) for inner, lane in inner_pairs(side)}
            usable_pairs = {
                (a, b): line
                for (a, b), line in pairs.items()
                if a != 0
                and b != 0
                and a in old.t
                and b in new.t  # a missing lane is lane-link-missing-lane's
                and not _opposed_in_road(road, sections[i - 1], a, sections[i], b)
                # a lane linked where it has zero width (opening or closing) is zero-width-lane-linked's finding
                and not ctx.zero_width_at(road, i - 1, a, ContactPoint.END)
                and not ctx.zero_width_at(road, i, b, ContactPoint.START)
            }
            for group, line in link_groups(usable_pairs):
                yield from _boundary_finding(
                    ctx, road, geometry, i, group, line, (old, new), (inner_of, inner_new), usable_pairs, surface_steps
                )


def _opposed_in_road(road: Road, before: LaneSection, a: int, after: LaneSection, b: int) -> bool:
    """Whether the link from lane ``a`` to lane ``b`` of the next section names a lane whose traffic runs the other
    way (``lane-link-direction`` reports that link: its borders jump as a consequence, not a second defect)."""
    lane, target = before.lane(a), after.lane(b)
    return lane is not None and target is not None and opposed(road, lane, road, target, True)


def _boundary_finding(ctx, road, geometry, i, group, line, lines, inners, pairs, surface_steps):
    """The finding (if any) for one group of linked lanes at the start of lane section ``i``."""
    tolerances = ctx.tolerances
    tol = tolerances.position
    before, after = road.lane_sections[i - 1], road.lane_sections[i]
    (a_in, a, b_in, b), (old, new), (inner_of, inner_new) = group, lines, inners
    t_before = (float(old.t[inner_of[a_in]][-1]), float(old.t[a][-1]))
    t_after = (float(new.t[inner_new[b_in]][0]), float(new.t[b][0]))
    jump = max(abs(p - q) for p, q in zip(t_before, t_after))
    z_before = group_heights(geometry, old, i - 1, a_in, a, inner_of, -1)
    z_after = group_heights(geometry, new, i, b_in, b, inner_new, 0)
    step = max(abs(p - q) for p, q in zip(z_before, z_after)) if after.s not in surface_steps else 0.0
    severity = tolerances.grade(max(jump, step))
    if severity is None:
        return
    what = []
    if jump > tol:
        what.append(f"its borders jump by {jump:.4g} m ({change_text(t_before, t_after)})")
    if step > tol:
        what.append(f"its surface steps by {step:.4g} m in height (z {change_text(z_before, z_after)})")
    fix = ", heights and level flags" if step > tol else ""
    advice, uid = f"make the widths{fix} continue or link the right lanes", NO_UID
    if jump > tol and a_in == a and b_in == b:
        split = unlinked_band(b, t_before, new, inner_new, {y for _, y in pairs}, 0, tol)
        merge = None if split else unlinked_band(a, t_after, old, inner_of, {x for x, _ in pairs}, -1, tol)
        if split:
            advice, uid = f"lane {a} splits into {lanes_text(*split)}: link it to each of them", U.LINK_MULTIPLE
        elif merge:
            advice, uid = f"{lanes_text(*merge)} merge into lane {b}: link each of them to it", U.LINK_MULTIPLE
    point = new.borders[b]
    yield lane_border_discontinuous.finding(
        f"road {road.id}: {lanes_text(a_in, a)} of the lane section at s={metres(before.s)} "
        f"continue{'s' if a_in == a else ''} as {lanes_text(b_in, b)} at s={metres(after.s)}, but "
        f"{' and '.join(what)}; {advice}{warning_note(severity, tolerances)}",
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
