"""Redundant records (``G9xx``): records that repeat what the previous one already says.

Harmless for readers, but they bloat files and hide where a profile really changes (Annex F
``performance.avoid_redundant_info``).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import Cubic, Lane, LaneSection, Line, Profile, Road, RoadType
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

#: Relative floating-point noise under which two coefficients count as equal (a representation limit of the written
#: numbers, not a checking tolerance).
_NOISE = 1e-9
#: Lane children the model reads; a lane section whose lanes carry anything else is never called redundant.
_READ = frozenset({"link", "width", "border", "roadMark", "speed", "userData"})


def _close(a: float, b: float, scale: float = 1.0) -> bool:
    return math.isclose(a, b, rel_tol=_NOISE, abs_tol=_NOISE * scale)


def continues(prev: Cubic, nxt: Cubic) -> bool:
    """Whether ``nxt`` is ``prev``'s polynomial re-expanded at ``nxt.s`` (the same curve: ``nxt`` says nothing new)."""
    h = nxt.s - prev.s
    a = prev.a + h * (prev.b + h * (prev.c + h * prev.d))
    b = prev.b + h * (2.0 * prev.c + 3.0 * h * prev.d)
    c = prev.c + 3.0 * h * prev.d
    scale = 1.0 + abs(prev.a) + abs(h) * (abs(prev.b) + abs(h) * (abs(prev.c) + abs(h) * abs(prev.d)))
    return _close(a, nxt.a, scale) and _close(b, nxt.b, scale) and _close(c, nxt.c, scale) and _close(prev.d, nxt.d)


def _redundant(profile: Profile) -> list[tuple[Cubic, Cubic]]:
    return [(p, n) for p, n in itertools.pairwise(profile) if continues(p, n)]


@rule(
    "G901",
    "redundant-record",
    Category.GEOMETRY,
    Severity.INFO,
    uids=(U.AVOID_REDUNDANT_INFO,),
    every_version=True,
)
def redundant_record(ctx: Context):
    """A record repeats what the previous one already says.

    An elevation, superelevation, laneOffset, width or border record that continues the previous record's polynomial
    unchanged, a line that continues the previous line's heading, a road ``<type>`` equal to the previous one, or a
    lane section that continues the previous one unchanged (the same lanes with the same types, levels, lane links
    from each lane to itself, widths continuing the previous section's, the same road marks and speeds, nothing else
    recorded on its lanes). Annex F ``performance.avoid_redundant_info`` (a "should"; reported as information, below
    what the wording allows, see ``SEVERITY_DEVIATIONS``).

    Delete the second record (or, for lines and lane sections, merge the two). Equal means equal up to floating-point
    noise.

    Passes::

        <width sOffset="0" a="3.5" b="0" c="0" d="0"/><width sOffset="20" a="3.5" b="0.01" c="0" d="0"/>

    Fails (the second record says the same as the first)::

        <width sOffset="0" a="3.5" b="0" c="0" d="0"/><width sOffset="20" a="3.5" b="0" c="0" d="0"/>
    """
    for road in ctx.document.roads:
        yield from _profiles(road)
        yield from _lines(road)
        yield from _lanes(road)
    yield from _sections(ctx)
    yield from _types(ctx)


def _profiles(road: Road) -> Iterator[Finding]:
    for name, profile in (
        ("elevation", road.elevation),
        ("superelevation", road.superelevation),
        ("laneOffset", road.lane_offset),
    ):
        for prev, nxt in _redundant(profile):
            yield redundant_record.finding(
                f"road {road.id}: the {name} record at s={metres(nxt.s)} continues the one at s={metres(prev.s)} "
                "unchanged",
                road=road.id,
                s=nxt.s,
                line=nxt.line or None,
            )


def _lines(road: Road) -> Iterator[Finding]:
    for first, second in itertools.pairwise(road.plan_view):
        if isinstance(first, Line) and isinstance(second, Line) and _same_heading(first.hdg, second.hdg):
            yield redundant_record.finding(
                f"road {road.id}: the line at s={metres(second.s)} continues the line at s={metres(first.s)} in the "
                "same heading; one line would do",
                road=road.id,
                s=second.s,
                line=second.line or None,
            )


def _lanes(road: Road) -> Iterator[Finding]:
    for section in road.lane_sections:
        for lane in section.lanes:
            for name, profile in (("width", lane.widths), ("border", lane.borders)):
                for prev, nxt in _redundant(profile):
                    yield redundant_record.finding(
                        f"road {road.id} lane {lane.id} (lane section s={metres(section.s)}): the {name} record at "
                        f"sOffset={metres(nxt.s)} continues the one at sOffset={metres(prev.s)} unchanged",
                        road=road.id,
                        lane=lane.id,
                        section_s=section.s,
                        s=section.s + nxt.s,
                        line=nxt.line or None,
                    )


def _same_heading(h1: float, h2: float) -> bool:
    d = math.remainder(h1 - h2, math.tau)
    return abs(d) <= _NOISE


# -------------------------------------------------------------------------------------------------- lane sections
def _sections(ctx: Context) -> Iterator[Finding]:
    candidates = [
        (road, prev, nxt)
        for road in ctx.document.roads
        for prev, nxt in itertools.pairwise(road.lane_sections)
        if _section_continues(prev, nxt)
    ]
    if not candidates:
        return
    unread = _sections_with_unread_records(ctx)
    for road, prev, nxt in candidates:
        if prev.line in unread or nxt.line in unread:
            continue
        yield redundant_record.finding(
            f"road {road.id}: the lane section at s={metres(nxt.s)} continues the one at s={metres(prev.s)} unchanged "
            "(the same lanes, types, links, widths, marks and speeds); merge the two",
            road=road.id,
            section_s=nxt.s,
            s=nxt.s,
            line=nxt.line or None,
        )


def _section_continues(prev: LaneSection, nxt: LaneSection) -> bool:
    if prev.single_side or nxt.single_side:
        return False
    before = {lane.id: lane for lane in prev.lanes}
    after = {lane.id: lane for lane in nxt.lanes}
    if before.keys() != after.keys():
        return False
    return all(_lane_continues(prev, before[i], nxt, after[i]) for i in before)


def _lane_continues(prev: LaneSection, a: Lane, nxt: LaneSection, b: Lane) -> bool:
    if (a.type, a.type_name, a.level) != (b.type, b.type_name, b.level):
        return False
    if a.successors not in ((), (a.id,)) or b.predecessors not in ((), (a.id,)):
        return False
    if a.temporary_successors or b.temporary_predecessors:
        return False  # linked to the temporary lane layer here: 1.9 requires the new section (11.4)
    if not (
        _profile_continues(prev.s, a.widths, nxt.s, b.widths)
        and _profile_continues(prev.s, a.borders, nxt.s, b.borders)
    ):
        return False
    return _same_first(a.road_marks, b.road_marks, ("type", "weight", "color", "width", "lane_change")) and _same_first(
        a.speeds, b.speeds, ("max", "unit")
    )


def _profile_continues(origin_a: float, a: Profile, origin_b: float, b: Profile) -> bool:
    """Whether lane profile ``b`` (relative to ``origin_b``) goes on as ``a`` (relative to ``origin_a``) ends."""
    if not a or not b:
        return not a and not b
    last, first = a[-1], b[0]
    if not _close(first.s, 0.0):
        return False
    shifted = Cubic(origin_a + last.s, last.a, last.b, last.c, last.d)
    return continues(shifted, Cubic(origin_b, first.a, first.b, first.c, first.d))


def _same_first(a: tuple, b: tuple, fields: tuple[str, ...]) -> bool:
    """Whether ``b`` (road marks or speeds) starts at its section's start with what ``a`` ends with."""
    if not a or not b:
        return not a and not b
    return _close(b[0].s, 0.0) and all(getattr(a[-1], f) == getattr(b[0], f) for f in fields)


def _sections_with_unread_records(ctx: Context) -> set[int]:
    """Source lines of lane sections whose lanes carry records the model does not read (access, height, material,
    rule, a road mark's own lines...): such a section may differ from its neighbour in ways not compared here."""
    out: set[int] = set()
    for road in ctx.document.roads:
        for section in road.lane_sections:
            for lane in (*section.left, *section.center, *section.right):
                if any(tag not in _READ for tag in lane.xml.children) or any(m.xml.children for m in lane.road_marks):
                    out.add(section.line)
                    break
    return out


# ---------------------------------------------------------------------------------------------------- road types
def _types(ctx: Context) -> Iterator[Finding]:
    for road in ctx.document.roads:
        for prev, nxt in itertools.pairwise(t for t in road.types if t.s is not None):
            if _type_key(prev) == _type_key(nxt):
                yield redundant_record.finding(
                    f"road {road.id}: the <type> at s={metres(nxt.s)} repeats the one at s={metres(prev.s)} (type "
                    f"{nxt.type}); a road type holds until the next one, so delete it",
                    road=road.id,
                    s=nxt.s,
                    line=nxt.line,
                )


def _type_key(record: RoadType) -> tuple:
    """What a road type says: its type, country and speed (``max`` as a value, or its text when that is not one)."""
    speed = record.speed
    if speed is None:
        return (record.type, record.country, None)
    written = speed.max if speed.max is not None else speed.xml.text("max")
    return (record.type, record.country, (written, speed.unit))
