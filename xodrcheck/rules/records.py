"""Redundant records (``G9xx``): records that repeat what the previous one already says.

Harmless for readers, but they bloat files and hide where a profile really changes (ASAM's
``performance.avoid_redundant_info``).
"""

from __future__ import annotations

import itertools
import math

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Cubic, Line, Profile
from xodrcheck.rules.context import Context
from xodrcheck.rules.registry import rule

#: Relative floating-point noise under which two coefficients count as equal (a representation limit of the written
#: numbers, not a checking tolerance).
_NOISE = 1e-9


def _close(a: float, b: float, scale: float = 1.0) -> bool:
    return math.isclose(a, b, rel_tol=_NOISE, abs_tol=_NOISE * scale)


def continues(prev: Cubic, nxt: Cubic) -> bool:
    """Whether ``nxt`` is ``prev``'s polynomial re-expanded at ``nxt.s``: the same curve, so ``nxt`` says nothing new."""
    h = nxt.s - prev.s
    a = prev.a + h * (prev.b + h * (prev.c + h * prev.d))
    b = prev.b + h * (2.0 * prev.c + 3.0 * h * prev.d)
    c = prev.c + 3.0 * h * prev.d
    scale = 1.0 + abs(prev.a) + abs(h) * (abs(prev.b) + abs(h) * (abs(prev.c) + abs(h) * abs(prev.d)))
    return _close(a, nxt.a, scale) and _close(b, nxt.b, scale) and _close(c, nxt.c, scale) and _close(prev.d, nxt.d)


def _redundant(profile: Profile) -> list[tuple[Cubic, Cubic]]:
    return [(p, n) for p, n in itertools.pairwise(profile) if continues(p, n)]


@rule("G901", "redundant-record", Category.GEOMETRY, Severity.INFO)
def redundant_record(ctx: Context):
    """A record repeats what the previous one already says.

    An elevation, superelevation, laneOffset, width or border record that continues the previous record's polynomial
    unchanged, or a line that continues the previous line's heading.

    Delete the second record (or, for lines, merge the two). Equal means equal up to floating-point noise.

    Passes::

        <width sOffset="0" a="3.5" b="0" c="0" d="0"/><width sOffset="20" a="3.5" b="0.01" c="0" d="0"/>

    Fails (the second record says the same as the first)::

        <width sOffset="0" a="3.5" b="0" c="0" d="0"/><width sOffset="20" a="3.5" b="0" c="0" d="0"/>
    """
    for road in ctx.document.roads:
        for name, profile in (
            ("elevation", road.elevation),
            ("superelevation", road.superelevation),
            ("laneOffset", road.lane_offset),
        ):
            for prev, nxt in _redundant(profile):
                yield redundant_record.finding(
                    f"road {road.id}: the {name} record at s={nxt.s:g} continues the one at s={prev.s:g} unchanged",
                    road=road.id,
                    s=nxt.s,
                    line=nxt.line or None,
                )
        for first, second in zip(road.plan_view, road.plan_view[1:]):
            if isinstance(first, Line) and isinstance(second, Line) and _same_heading(first.hdg, second.hdg):
                yield redundant_record.finding(
                    f"road {road.id}: the line at s={second.s:g} continues the line at s={first.s:g} in the same "
                    "heading; one line would do",
                    road=road.id,
                    s=second.s,
                    line=second.line or None,
                )
        for section in road.lane_sections:
            for lane in section.lanes:
                for name, profile in (("width", lane.widths), ("border", lane.borders)):
                    for prev, nxt in _redundant(profile):
                        yield redundant_record.finding(
                            f"road {road.id} lane {lane.id} (lane section s={section.s:g}): the {name} record at "
                            f"sOffset={nxt.s:g} continues the one at sOffset={prev.s:g} unchanged",
                            road=road.id,
                            lane=lane.id,
                            section_s=section.s,
                            s=section.s + nxt.s,
                            line=nxt.line or None,
                        )


def _same_heading(h1: float, h2: float) -> bool:
    d = math.remainder(h1 - h2, math.tau)
    return abs(d) <= _NOISE
