"""Lane records in the file (``L017``-``L022``): how lanes and their records are written, read from the XML.

Annex F rules on the listing of lanes, the records a centre lane may not have, the order of the lane records the reader
does not keep (``<access>``, ``<material>``, ``<rule>``, ``<visibility>``), and which ways of giving a lane's width may
be combined (``<width>`` with ``<border>``, ``<border>`` with ``<laneOffset>``) or must start where the lane section
starts.
"""

from __future__ import annotations

import itertools

from lxml import etree

from xodrcheck.findings import Category, Severity
from xodrcheck.rules import lane_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.lane_xml import LaneXml, by_section, lane_elements, local, number
from xodrcheck.rules.registry import rule
from xodrcheck.support.quantities import metres

#: An ``sOffset`` this close to 0 is 0 (written-number noise, not a tolerance).
_ZERO = 1e-9


@rule("L017", "lane-listing-order", Category.LANE, Severity.WARNING, uids=(U.LANE_LISTING,), xml=True)
def lane_listing_order(ctx: Context):
    """The lanes of a lane section are not listed from left to right (descending id).

    Annex F ``road.lane.lane_listing``: "for better orientation, lanes should be listed from left to right, that is
    with descending ID": ``<left>`` before ``<center>`` before ``<right>``, and in each the lane ids falling (3, 2, 1
    on the left; -1, -2, -3 on the right). Reported once per lane section, at the first lane out of place.

    Passes::

        <left><lane id="2" .../><lane id="1" .../></left><center>...</center>
        <right><lane id="-1" .../><lane id="-2" .../></right>

    Fails::

        <right><lane id="-2" .../><lane id="-1" .../></right>
    """
    for lanes in by_section(ctx):
        listed = [lane for lane in lanes if lane.id is not None and _on_its_side(lane)]
        for before, lane in itertools.pairwise(listed):
            if lane.id is not None and before.id is not None and lane.id > before.id:  # (ids given: filtered above)
                order = " ".join(str(i) for i in sorted((x.id for x in listed if x.id is not None), reverse=True))
                yield lane_listing_order.finding(
                    f"{lane.describe()}: lane {lane.id} is listed after lane {before.id}; list the lanes from left "
                    f"to right, with falling ids ({order})",
                    **lane.where(),
                )
                break


def _on_its_side(lane: LaneXml) -> bool:
    """Whether the lane's id has the sign of its group (a lane on the wrong side is lane-id-sequence's finding)."""
    sign = {"left": 1, "center": 0, "right": -1}[lane.group]
    return lane.id is not None and (lane.id > 0 if sign > 0 else lane.id < 0 if sign < 0 else lane.id == 0)


# ------------------------------------------------------------------------------------------------ centre lane records
_CENTRE_RECORDS = {
    "access": (U.ACCESS_CENTER, "access rules"),
    "height": (U.HEIGHT_CENTER, "a lane height"),
    "material": (U.MATERIAL_CENTER, "a material"),
    "speed": (U.SPEED_CENTER, "a speed limit"),
}


@rule(
    "L018",
    "centre-lane-records",
    Category.LANE,
    Severity.ERROR,
    uids=tuple(uid for uid, _ in _CENTRE_RECORDS.values()),
    xml=True,
)
def centre_lane_records(ctx: Context):
    """The centre lane 0 has ``<access>``, ``<height>``, ``<material>`` or ``<speed>`` records.

    The centre lane is a line, not a surface: Annex F says it shall have no access rules
    (``road.lane.access.center_lane_no_acc_rule``), no lane height (``road.lane.height.center_lane_no_height``), no
    material (``road.lane.material.center_lane_no_material``) and no speed limit
    (``road.lane.speed.center_lane_no_spd_lmt``). Move them to the side lanes they are meant for. (``<width>`` and
    ``<border>``: ``centre-lane-width``.)

    Passes::

        <center><lane id="0" type="none"><roadMark sOffset="0" type="solid" color="white"/></lane></center>

    Fails::

        <center><lane id="0" type="none"><speed sOffset="0" max="50" unit="km/h"/></lane></center>
    """
    for lane in lane_elements(ctx).lanes:
        if lane.group != "center":
            continue
        seen: set[str] = set()
        for child in lane.element.iterchildren(*(f"{{*}}{tag}" for tag in _CENTRE_RECORDS)):
            tag = local(child)
            if tag in seen:
                continue
            seen.add(tag)
            uid, what = _CENTRE_RECORDS[tag]
            yield centre_lane_records.finding(
                f"{lane.describe()}: the centre lane has {what} (<{tag}> at line {child.sourceline}); the centre lane "
                f"has none: give the <{tag}> to the side lanes it is meant for",
                uid=uid,
                **lane.where(child.sourceline),
            )


# ------------------------------------------------------------------------------------------------ record order
#: Lane records the reader does not keep, ordered by ``sOffset``: tag -> the Annex F rule on their order.
_ORDERED = {
    "access": U.ACCESS_ORDER,
    "material": U.MATERIAL_ORDER,
    "rule": U.RULE_ORDER,
    "visibility": U.PROPERTIES_ORDER,
}


@rule("L019", "lane-records-out-of-order", Category.LANE, Severity.ERROR, uids=tuple(_ORDERED.values()), xml=True)
def lane_records_out_of_order(ctx: Context):
    """A lane's ``<access>``, ``<material>``, ``<rule>`` or ``<visibility>`` records come in descending ``sOffset``.

    Annex F: these records are defined in ascending order of s (``road.lane.access.elem_asc_order``,
    ``road.lane.material.elem_asc_order``, ``road.lane.rule.elem_asc_order``, and
    ``road.lane.lane_properties.elem_asc_order`` for lane properties of a type with no rule of its own: the
    ``<visibility>`` records of 1.4 and 1.5). Each is valid until the next one of its type, so out of order the lane's
    properties depend on the reader. (``<width>``, ``<border>``, ``<height>``, ``<roadMark>`` and ``<speed>``:
    ``records-out-of-order``, while reading.)
    Reported once per lane and type, at the first record that goes back.

    Passes::

        <material sOffset="0" friction="0.8"/><material sOffset="50" friction="0.6"/>

    Fails::

        <material sOffset="50" friction="0.6"/><material sOffset="0" friction="0.8"/>
    """
    for lane in lane_elements(ctx).lanes:
        last: dict[str, tuple[float, int | None]] = {}
        reported: set[str] = set()
        for child in lane.element.iterchildren(*(f"{{*}}{tag}" for tag in _ORDERED)):
            tag = local(child)
            s = number(child.get("sOffset"))
            if s is None or tag in reported:
                continue
            if tag in last and s < last[tag][0]:
                reported.add(tag)
                yield lane_records_out_of_order.finding(
                    f"{lane.describe()}: <{tag}> at line {child.sourceline} starts at sOffset {metres(s)}, before the "
                    f"one at line {last[tag][1]} ({metres(last[tag][0])}); list the <{tag}> records in ascending order "
                    "of sOffset",
                    uid=_ORDERED[tag],
                    **lane.where(child.sourceline),
                )
            last[tag] = (s, child.sourceline)


# ------------------------------------------------------------------------------------------------ width, border, offset
def _first(lanes: list[LaneXml], tag: str) -> tuple[LaneXml, etree._Element] | None:
    for lane in lanes:
        for child in lane.element.iterchildren(f"{{*}}{tag}"):
            return lane, child
    return None


@rule(
    "L020",
    "width-and-border-mixed",
    Category.LANE,
    Severity.ERROR,
    uids=(U.BORDER_EXCLUSIVE_WIDTH, U.WIDTH_NO_BORDER),
    xml=True,
)
def width_and_border_mixed(ctx: Context):
    """One lane group (``<left>`` or ``<right>`` of a lane section) uses both ``<width>`` and ``<border>`` records.

    Lane width and lane border are mutually exclusive within a lane group (Annex F
    ``road.lane.border.exclusive_width_border``, and from 1.9 ``road.lane.width.no_width_with_border``): where both are
    given, readers take the widths and ignore the borders, so the lanes are not where the borders say. Describe the
    group's lanes all by widths or all by borders. Reported at the group's first ``<border>`` (and, for 1.9 files,
    at its first ``<width>``).

    Passes::

        <right><lane id="-1"><width sOffset="0" a="3.5" .../></lane><lane id="-2"><width sOffset="0" a="2" .../>

    Fails::

        <right><lane id="-1"><width sOffset="0" a="3.5" .../></lane><lane id="-2"><border sOffset="0" a="-5.5" .../>
    """
    for lanes in by_section(ctx):
        for group in ("left", "right"):
            members = [lane for lane in lanes if lane.group == group]
            width, border = _first(members, "width"), _first(members, "border")
            if width is None or border is None:
                continue
            (w_lane, w_el), (b_lane, b_el) = width, border
            both = (
                f"<{group}> of road {w_lane.road} lane section s={metres(w_lane.section.s)}: lane {w_lane.id} has "
                f"<width> (line {w_el.sourceline}) and lane {b_lane.id} <border> (line {b_el.sourceline}) records"
                if w_lane.section.s is not None
                else f"<{group}> of road {w_lane.road}: <width> (line {w_el.sourceline}) and <border> "
                f"(line {b_el.sourceline}) records"
            )
            advice = "; describe one lane group by widths or by borders, not both (readers ignore the borders)"
            yield width_and_border_mixed.finding(
                both + advice, uid=U.BORDER_EXCLUSIVE_WIDTH, **b_lane.where(b_el.sourceline)
            )
            yield width_and_border_mixed.finding(both + advice, uid=U.WIDTH_NO_BORDER, **w_lane.where(w_el.sourceline))


@rule(
    "L021",
    "border-with-lane-offset",
    Category.LANE,
    Severity.ERROR,
    uids=(U.BORDER_EXCLUSIVE_OFFSET, U.LANE_OFFSET_NO_BORDER),
    xml=True,
)
def border_with_lane_offset(ctx: Context):
    """A road's lanes use ``<border>`` records and ``<laneOffset>`` together.

    A border gives the lane's outer edge in road coordinates, independent of the centre lane; a lane offset moves the
    centre lane. Annex F: ``<border>`` shall not be used together with ``<laneOffset>``
    (``road.lane.border.exclusive_offset_border``), and there shall be no ``<laneOffset>`` if borders are present
    (``road.lanes.lane_offset.no_offset_if_border_defined``). Readers disagree about whether the offset shifts the
    borders. Reported at the first ``<border>`` and the first ``<laneOffset>`` of each ``<lanes>``.

    Passes::

        <lanes><laneSection s="0">... <lane id="-1"><border sOffset="0" a="-3.5" b="0" c="0" d="0"/> ...</lanes>

    Fails::

        <lanes><laneOffset s="0" a="0.5" b="0" c="0" d="0"/>
          <laneSection s="0">... <lane id="-1"><border sOffset="0" a="-3.5" b="0" c="0" d="0"/> ...</lanes>
    """
    by_lanes: dict[etree._Element, list[LaneXml]] = {}
    for lane in lane_elements(ctx).lanes:
        by_lanes.setdefault(lane.section.lanes_element, []).append(lane)
    for lanes_el, lanes in by_lanes.items():
        offset = next(lanes_el.iterchildren("{*}laneOffset"), None)
        if offset is None:
            continue
        border = _first(lanes, "border")
        if border is None:
            continue
        lane, border_el = border
        road = lane.road
        yield border_with_lane_offset.finding(
            f"{lane.describe()}: <border> at line {border_el.sourceline} while road {road}'s lanes have a <laneOffset> "
            f"(line {offset.sourceline}); describe the lanes by <width> records, or drop the lane offset",
            uid=U.BORDER_EXCLUSIVE_OFFSET,
            **lane.where(border_el.sourceline),
        )
        yield border_with_lane_offset.finding(
            f"road {road}: <laneOffset> at line {offset.sourceline} while lane {lane.id} is described by <border> "
            f"records (line {border_el.sourceline}); there is no lane offset where borders are used",
            uid=U.LANE_OFFSET_NO_BORDER,
            road=road,
            s=number(offset.get("s")),
            line=offset.sourceline,
        )


@rule("L022", "lane-width-undefined", Category.LANE, Severity.ERROR, uids=(U.WIDTH_WHOLE_SECTION,), xml=True)
def lane_width_undefined(ctx: Context):
    """A side lane's width is not defined from the start of its lane section: no ``<width>`` at ``sOffset`` 0.

    Annex F ``road.lane.width.width_defined_whole_section`` (1.7): "the width of the lane shall be defined for the full
    length of the lane section. This means that there must be a ``<width>`` element for @s=0." A lane with no width
    (and no border) record at all, or whose first record starts further on, has no width at the section's start;
    readers guess (0, or the first record extended backwards). A lane described by ``<border>`` records needs one at
    ``sOffset`` 0 likewise.

    Passes::

        <lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>

    Fails::

        <lane id="-1" type="driving"><width sOffset="10" a="3.5" b="0" c="0" d="0"/></lane>
    """
    for lane in lane_elements(ctx).lanes:
        if lane.group == "center":
            continue
        for tag in ("width", "border"):
            starts = [
                s for s in (number(r.get("sOffset")) for r in lane.element.iterchildren(f"{{*}}{tag}")) if s is not None
            ]
            if starts:
                break
        else:
            yield lane_width_undefined.finding(
                f"{lane.describe()}: the lane has no <width> record, so no width; give it one at sOffset 0",
                **lane.where(),
            )
            continue
        first = min(starts)
        if first > _ZERO:
            yield lane_width_undefined.finding(
                f"{lane.describe()}: the first <{tag}> record starts at sOffset {metres(first)}, so the lane has no "
                f"width over the first {metres(first)} m of its lane section; add a <{tag}> record at sOffset 0",
                **lane.where(),
            )
