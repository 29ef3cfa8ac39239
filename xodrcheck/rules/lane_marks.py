"""Road markings of lanes (``L034``): a ``<roadMark>`` describes the lane's outer border line (11.9)."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import Lane, RoadMark, RoadMarkLine
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

_NOT_CHECKED = (
    "a <roadMark> says which border it styles only through the tOffset of its <line> elements (in <type> or "
    "<explicit>): one without lines, or whose lines follow a <sway>, is read as the outer border's, as 11.9 defines "
    "it, and cannot be told from one meant for another line"
)


def _lines(mark: RoadMark) -> Iterator[RoadMarkLine]:
    """The ``<line>`` records of a road mark's ``<type>`` and ``<explicit>``."""
    for holder in (mark.type_lines, mark.explicit):
        if holder is not None:
            yield from holder.lines


@rule(
    "L034",
    "road-mark-off-outer-border",
    Category.LANE,
    Severity.ERROR,
    partial={U.ROAD_MARK_ONLY_OUTER: _NOT_CHECKED},
)
def road_mark_off_outer_border(ctx: Context) -> Iterator[Finding]:
    """A lane's ``<roadMark>`` draws its line in the inner half of the lane, not on the lane's outer border.

    A ``<roadMark>`` gives the style of the line at its lane's outer border (11.9), and shall only describe that
    outer marking (Annex F ``road.lane.road_mark.only_outer``, 1.9); a line elsewhere (the inner border's, which
    belongs to the neighbouring lane's ``<roadMark>``, or a marking inside the lane, which is a signal) is another
    element's. The ``tOffset`` of a ``<line>`` moves it from the outer border (positive to the left, as t); a line
    moved toward the lane's inside by more than half the lane's width (at the road mark's start) is nearer the inner
    border than the outer one. The centre lane's marks (the centre line) are not checked, nor lines following a
    ``<sway>``.

    Passes (a double line straddling the outer border of right lane -1, 3.5 m wide)::

        <roadMark sOffset="0" type="solid solid"><type name="double" width="0.4">
          <line length="0" space="0" tOffset="-0.15" sOffset="0" width="0.1"/>
          <line length="0" space="0" tOffset="0.15" sOffset="0" width="0.1"/></type></roadMark>

    Fails (the line lies on the inner border of lane -1, the centre line's place)::

        <roadMark sOffset="0" type="solid"><type name="inner" width="0.15">
          <line length="0" space="0" tOffset="3.5" sOffset="0" width="0.15"/></type></roadMark>
    """
    for road in ctx.document.roads:
        for index, section in enumerate(road.lane_sections):
            for lane in (*section.left, *section.right):
                for mark in lane.road_marks:
                    if mark.sways or lane.id == 0:
                        continue
                    lines = [(line, line.t_offset) for line in _lines(mark) if line.t_offset is not None]
                    if not lines:
                        continue
                    width = ctx.lane_width(road, index, lane.id, section.s + mark.s)
                    if width is None or width <= 0.0:
                        continue
                    inward = 1.0 if lane.id < 0 else -1.0  # toward lane 0: +t for right lanes, -t for left lanes
                    for line, t in lines:
                        if t * inward > width / 2:
                            yield _inner_line(road.id, section.s, lane, mark, line, t, width)
                            break


def _inner_line(
    road: str, section_s: float, lane: Lane, mark: RoadMark, line: RoadMarkLine, t: float, width: float
) -> Finding:
    """The finding for a line of ``mark`` nearer the lane's inner border than its outer one."""
    return road_mark_off_outer_border.finding(
        f"road {road} lane {lane.id} (lane section s={metres(section_s)}): the <roadMark> at line {mark.line} draws a "
        f"line with tOffset={metres(t)}, {metres(abs(t))} m from the lane's outer border toward its inside, in a lane "
        f"{metres(width)} m wide: a road mark describes only the outer border's line; give the inner border's line to "
        "the lane whose outer border it is (or lane 0), and a marking inside the lane as a signal",
        uid=U.ROAD_MARK_ONLY_OUTER,
        road=road,
        lane=lane.id,
        section_s=section_s,
        s=section_s,
        line=line.line,
    )
