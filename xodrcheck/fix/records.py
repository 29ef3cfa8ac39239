"""Fixes of lane records (``L019``, ``L002``): a lane's ``<access>``, ``<material>``, ``<rule>`` or ``<visibility>``
records listed out of ``sOffset`` order, and width records of the centre lane, which has none."""

from __future__ import annotations

import math
from collections.abc import Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import Edit, remove_element
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element

#: The lane records whose order the standard fixes and the model does not keep (their meaning: from sOffset on).
ORDERED = ("access", "material", "rule", "visibility")


def _offset(element: Element) -> float | None:
    try:
        value = float(element.get("sOffset") or "")
    except ValueError:
        return None
    return value if math.isfinite(value) else None


@fixer("L019", "sort-lane-records", safe=True, bound="moves nothing")
def sort_lane_records(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Lists a lane's ``<access>``, ``<material>``, ``<rule>`` or ``<visibility>`` records in ascending ``sOffset``
    (records of one offset keep their order).

    Each record holds from its ``sOffset`` until the next of its kind, which is what the sorted list says without
    depending on how a reader treats one that goes back (Annex F ``road.lane.*.elem_asc_order``). The records' own
    text is moved whole into the slots the records of that kind took; nothing else moves, no geometry is involved.
    """
    for finding in findings:
        records = [e for e in ws.text.at_line(finding.line or 0) if e.tag in ORDERED and e.parent is not None]
        if len(records) != 1 or records[0].parent is None or records[0].parent.tag != "lane":
            continue
        siblings = records[0].parent.findall(records[0].tag)
        read = [_offset(e) for e in siblings]
        offsets = [o for o in read if o is not None]
        if len(offsets) != len(read):
            yield Skip(finding, f"a <{records[0].tag}> of the lane has no readable sOffset")
            continue
        order = sorted(range(len(siblings)), key=lambda k: offsets[k])  # stable: equal offsets keep their order
        data = ws.text.data
        edits = tuple(
            Edit(slot.start, slot.end, data[siblings[k].start : siblings[k].end])
            for slot, k in zip(siblings, order)
            if siblings[k] is not slot
        )
        yield Repair((finding,), edits, f"{_where(finding)}: listed its <{records[0].tag}> records by sOffset")


def _where(finding: Finding) -> str:
    return f"road {finding.road} lane {finding.lane}"


@fixer("L002", "remove-centre-lane-width", safe=True, bound="moves nothing")
def remove_centre_lane_width(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes the ``<width>`` and ``<border>`` records of a centre lane 0.

    The centre lane has no width by definition (Annex F ``road.lane.center_lane_no_width``): readers ignore such
    records, and so does the geometry here, so leaving them out moves no lane. Nothing else of the lane is touched.
    """
    for finding in findings:
        lanes = [e for e in ws.text.at_line(finding.line or 0) if e.tag in ("width", "border")]
        centre = lanes[0].parent if len(lanes) == 1 else None
        if centre is None or centre.tag != "lane" or centre.parent is None or centre.parent.tag != "center":
            continue
        records = [c for c in centre.children if c.tag in ("width", "border")]
        yield Repair(
            (finding,),
            tuple(remove_element(ws.text, r) for r in records),
            f"road {finding.road} lane section s={finding.section_s:g}: removed the centre lane's "
            f"{len(records)} width record(s)",
        )
