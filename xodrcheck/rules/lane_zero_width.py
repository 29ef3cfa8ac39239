"""Lanes of zero width over a stretch of their lane section (``G015``): where the number of lanes really changes.

A lane section holds a fixed number of lanes. A lane whose width is zero over part of its section (a width record
that says 0 from some ``sOffset`` on, or a border on its inner neighbour) is absent there: the number of lanes changes
inside the section. The widths come from :func:`xodrcheck.rules.lane_shape.lane_width_bounds`, exact per polynomial
piece; a lane's own record counts as zero when its width stays under ``zero_width`` over the record's whole interval,
so a lane that narrows smoothly to zero at its section's end is not one.
"""

from __future__ import annotations

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Lane, Road
from xodrcheck.rules.lane_shape import lane_width_bounds
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres


def _zero_records(
    lane: Lane, s0: float, s1: float, a, b, zero, min_length: float
) -> list[tuple[float, float, int, bool]]:
    """``(start, end, line, zero)`` for each of the lane's own records over the section ``[s0, s1]``; records shorter
    than ``min_length`` (or past the section's end) are left out."""
    records = lane.widths or lane.borders
    out = []
    for k, record in enumerate(records):
        lo = s0 + record.s
        hi = s1 if k + 1 == len(records) else min(s1, s0 + records[k + 1].s)
        if hi - lo < min_length:
            continue
        inside = (a >= lo - 1e-9) & (b <= hi + 1e-9)
        if inside.any():
            out.append((lo, hi, record.line, bool(zero[inside].all())))
    return out


@rule(
    "G015",
    "lane-zero-width-stretch",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.SECTION_USAGE_LANE_NUM, U.SECTION_LONG_ZERO_WIDTH),
)
def lane_zero_width_stretch(ctx: Context):
    """A lane has zero width over a stretch of its lane section and a width elsewhere: the number of lanes changes
    inside the section.

    Annex F ``road.lane_section.lanesec_usage_lane_num``: "a new lane section shall be defined each time the number of
    lanes change." A lane that is there over part of a section only (zero width from some ``sOffset`` on, or up to
    it) makes readers that count lanes per section see a lane that is not there. End the lane section where the lane
    ends (or start one where it starts) and leave the lane out of the other. A lane narrowing to zero exactly at its
    section's end, or widening from zero at its start, is a lane that closes or opens, not this. Stretches shorter than
    ``min_section_length`` are ignored; zero means narrower than ``zero_width`` over a whole width record.

    A lane of zero width over its whole lane section, longer than ``long_zero_width`` (1 m), is a warning from
    OpenDRIVE 1.9 on: "using lanes with a width of 0 for long distances should be avoided"
    (``road.lane_section.lane_long_zero_width``).

    Passes (lane -2 narrows to zero over the whole section, and a new section starts there)::

        <laneSection s="0"> ... <lane id="-2"><width sOffset="0" a="3.5" b="-0.07" c="0" d="0"/> ...
        <laneSection s="50"> ... (no lane -2)

    Fails (lane -2 is 0 m wide from sOffset 30 to the section's end at 100)::

        <laneSection s="0"> ... <lane id="-2"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>
                                             <width sOffset="30" a="0" b="0" c="0" d="0"/>
    """
    tol = ctx.tolerances
    for road, geometry, index, section in ctx.usable_sections():
        bounds = lane_width_bounds(ctx, road, index)
        if bounds is None:
            continue
        lanes, a, b, low, high = bounds
        s0, s1 = geometry.section_range(index)
        zero = (high < tol.zero_width) & (low > -tol.zero_width)
        for row, lane in enumerate(lanes):
            records = _zero_records(lane, s0, s1, a, b, zero[row], tol.min_section_length)
            stretches = [r for r in records if r[3]]
            if not stretches:
                continue
            if len(stretches) < len(records):
                yield _finding(road, geometry, index, section.s, lane, stretches)
            elif s1 - s0 > tol.long_zero_width:
                yield _long_finding(road, index, section, lane, s1 - s0)


def _long_finding(road: Road, index: int, section, lane: Lane, length: float):
    return lane_zero_width_stretch.finding(
        f"road {road.id}: lane {lane.id} of the lane section at s={metres(section.s)} has zero width over the whole "
        f"section ({length:.4g} m); leave the lane out instead of running it at zero width",
        severity=Severity.WARNING,
        uid=U.SECTION_LONG_ZERO_WIDTH,
        road=road.id,
        lane=lane.id,
        section_s=section.s,
        s=section.s,
        line=lane.line or section.line or None,
    )


def _finding(road: Road, geometry, index: int, section_s: float, lane: Lane, stretches):
    start, end, line, _ = stretches[0]
    point = geometry.lane_points(index, lane.id, np.array([start]), "outer")
    more = f" (and {len(stretches) - 1} more stretch(es))" if len(stretches) > 1 else ""
    return lane_zero_width_stretch.finding(
        f"road {road.id}: lane {lane.id} of the lane section at s={metres(section_s)} has zero width from "
        f"s={metres(start)} to s={metres(end)}{more} and a width elsewhere in the section, so the number of lanes "
        "changes inside it; start a new lane section where the lane ends or begins, without it",
        road=road.id,
        lane=lane.id,
        section_s=section_s,
        s=start,
        x=float(point.x[0]),
        y=float(point.y[0]),
        uid=U.SECTION_USAGE_LANE_NUM,
        line=line or lane.line or None,
    )
