"""Lane sections along the road (``L026``): every ``s`` of the road has its lane section, and so its centre lane."""

from __future__ import annotations

from xodrcheck.findings import Category, Severity
from xodrcheck.rules import lane_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.lane_xml import SectionXml, lane_elements
from xodrcheck.rules.registry import rule

#: A lane section starting this close to s=0 starts at 0 (written-number noise, not a tolerance).
_ZERO = 1e-9


def permanent_sections(ctx: Context) -> dict[str, list[SectionXml]]:
    """Road id -> the lane sections of its permanent lane layer (every ``<lanes>`` not marked temporary)."""
    out: dict[str, list[SectionXml]] = {}
    for section in lane_elements(ctx).sections:
        if section.layer != "temporary" and section.road is not None:
            out.setdefault(section.road, []).append(section)
    return out


@rule("L026", "lane-sections-from-start", Category.LANE, Severity.ERROR, uids=(U.CENTER_ELEM_DEFINITION,))
def lane_sections_from_start(ctx: Context):
    """A road's first lane section starts after s=0: from the road's start to there, no lane section, no centre lane.

    Annex F ``road.lane.center_elem_definition``: "one ``<center>`` element shall be defined for each s-coordinate".
    Lane sections run from their ``s`` to the next one's and the last to the road's end, so the first must start at
    s=0, or the road's first metres have no lanes and no centre lane. Start the first lane section at ``s="0"``.
    (A lane section without ``<center>``, or with two: ``missing-element``, ``repeated-element``.)

    Passes::

        <road id="1" length="100"> ... <lanes><laneSection s="0"> ...

    Fails::

        <road id="1" length="100"> ... <lanes><laneSection s="5"> ...
    """
    for road, sections in permanent_sections(ctx).items():
        starts = [section for section in sections if section.s is not None]
        if not starts:
            continue
        first = min(starts, key=lambda section: section.s)  # type: ignore[arg-type,return-value]
        if first.s > _ZERO:  # type: ignore[operator]
            yield lane_sections_from_start.finding(
                f"road {road}: the first lane section starts at s={first.s:g}; from s=0 to there the road has no lane "
                "section and no centre lane: start the first lane section at s=0",
                road=road,
                section_s=first.s,
                s=0.0,
                line=first.element.sourceline,
            )
