"""Lane sections along the road (``L026``-``L028``): every ``s`` of the road has its lane section, and so its centre
lane; every lane section has a lane to drive on and ends on its road."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Lane, Lanes, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

#: A lane section starting this close to s=0 starts at 0 (written-number noise, not a tolerance).
_ZERO = 1e-9


def _layers(ctx: Context) -> Iterator[tuple[Road, Lanes]]:
    """Every lane layer of every road: its permanent ``<lanes>``, then its temporary one."""
    for road in ctx.document.roads:
        for layer in (road.lanes, road.temporary_lanes):
            if layer is not None:
                yield road, layer


@rule(
    "L026",
    "lane-sections-from-start",
    Category.LANE,
    Severity.ERROR,
    uids=(U.CENTER_ELEM_DEFINITION, U.LANE_SECT_FIRST),
)
def lane_sections_from_start(ctx: Context):
    """A road's first lane section starts after s=0: from the road's start to there, no lane section, no centre lane.

    Annex F ``road.lane.center_elem_definition``: "one ``<center>`` element shall be defined for each s-coordinate".
    Lane sections run from their ``s`` to the next one's and the last to the road's end, so the first must start at
    s=0, or the road's first metres have no lanes and no centre lane. OpenDRIVE 1.9 says it outright
    (``road.lane.lane_sect_first``: the first lane section is defined with s=0.0), the name findings on 1.9 files
    carry. Start the first lane section at ``s="0"``.
    (A lane section without ``<center>``, or with two: ``missing-element``, ``repeated-element``.)

    Passes::

        <road id="1" length="100"> ... <lanes><laneSection s="0"> ...

    Fails::

        <road id="1" length="100"> ... <lanes><laneSection s="5"> ...
    """
    for road in ctx.document.roads:
        if not road.lane_sections:
            continue
        first = min(road.lane_sections, key=lambda section: section.s)
        s = first.s
        if s > _ZERO:
            yield lane_sections_from_start.finding(
                f"road {road.id}: the first lane section starts at s={metres(s)}; from s=0 to there the road has no "
                "lane section and no centre lane: start the first lane section at s=0",
                uid=U.LANE_SECT_FIRST if ctx.version is None or ctx.version >= (1, 9) else U.CENTER_ELEM_DEFINITION,
                road=road.id,
                section_s=s,
                s=0.0,
                line=first.line,
            )


@rule(
    "L027",
    "lane-section-without-lanes",
    Category.LANE,
    Severity.WARNING,
    uids=(U.LANE_SECTION_DRIVABLE,),
)
def lane_section_without_lanes(ctx: Context):
    """A lane section has no side lane whose width is given from the section's start: nothing to drive on.

    To be drivable, each lane section should have a ``<left>`` or ``<right>`` lane valid for its whole length
    (OpenDRIVE 1.9, Annex F ``road.lane.lane_section_drivable``): a lane section of either layer with no side lane,
    or whose side lanes all start their width after the section's start. (A section with only its centre lane still
    has a lane, lane 0, at each s: the permanent layer's ``layer_mandatory_permanent`` is broken where a permanent
    section's ``length`` leaves s without a section, ``permanent-section-length``'s.)

    Passes::

        <laneSection s="0"><center>...</center><right><lane id="-1" type="driving"><width sOffset="0" .../>

    Fails::

        <laneSection s="0"><center><lane id="0" type="none"/></center></laneSection>
    """
    for road, layer in _layers(ctx):
        for section in layer.lane_sections:
            side = (*section.left, *section.right)
            if not any(_from_start(lane) for lane in side):
                what = (
                    "has no <left> or <right> lane" if not side else "has no side lane whose width starts at sOffset 0"
                )
                yield lane_section_without_lanes.finding(
                    f"road {road.id}: the {layer.layer.value} layer's lane section at s={metres(section.s)} {what}: no "
                    "part of it is valid for the section's whole length, so it is not drivable",
                    road=road.id,
                    section_s=section.s,
                    s=section.s,
                    line=section.line,
                )


def _from_start(lane: Lane) -> bool:
    """Whether the lane's width (its width records, else its border records) is given from the section's start."""
    for records in (lane.widths, lane.borders):
        if records:
            return min(record.s for record in records) <= _ZERO
    return False


@rule("L028", "lane-section-beyond-road", Category.LANE, Severity.ERROR, uids=(U.SECTION_LENGTH_LIMIT_ROAD,))
def lane_section_beyond_road(ctx: Context):
    """A lane section with a ``length`` runs past the end of its road.

    Annex F ``road.lane_section.lanesec_length_limit_road`` (1.9): a lane section with @length shall not extend beyond
    the end of the road: ``s + length`` is at most the road's ``length`` (within the ``length_abs`` tolerance).

    Passes (road length 100)::

        <lanes layer="temporary"><laneSection s="20" length="30"> ...

    Fails::

        <lanes layer="temporary"><laneSection s="80" length="30"> ...
    """
    for road, layer in _layers(ctx):
        for section in layer.lane_sections:
            length = section.length
            if length is None:
                continue
            end = section.s + length
            if end > road.length + ctx.tolerances.length_abs:
                yield lane_section_beyond_road.finding(
                    f"road {road.id}: the lane section at s={metres(section.s)} with length={metres(length)} ends at "
                    f"s={metres(end)}, {end - road.length:.4g} m past the road's end ({metres(road.length)}); shorten "
                    "it",
                    road=road.id,
                    section_s=section.s,
                    s=section.s,
                    line=section.line,
                )
