"""Lane records in the file (``L017``-``L022``): how lanes and their records are written, read from the document.

Annex F rules on the listing of lanes, the records a centre lane may not have, the order of the lane records the reader
does not check while reading (``<access>``, ``<material>``, ``<rule>``, ``<visibility>``), and which ways of giving a
lane's width may be combined (``<width>`` with ``<border>``, ``<border>`` with ``<laneOffset>``) or must start where
the lane section starts. The lanes of both lane layers; the file's order of ``<left>``, ``<center>`` and ``<right>``
and of a lane's records comes from their :class:`~xodrcheck.model.XmlFacts`.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Lane, Lanes, LaneSection, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover - the model's lane records load for a file with some
    from xodrcheck.model import LaneAccess, LaneMaterial, LaneRule, LaneVisibility

#: An ``sOffset`` this close to 0 is 0 (written-number noise, not a tolerance).
_ZERO = 1e-9
_GROUPS = ("left", "center", "right")


@dataclass(frozen=True, slots=True)
class _Listed:
    """A lane as the file lists it: its road, lane section and group (``left``, ``center`` or ``right``)."""

    road: Road
    section: LaneSection
    group: str
    lane: Lane

    def where(self, line: int | None = None) -> dict:
        """Finding location fields: road, lane, lane section, s and the line (the lane's unless given)."""
        s = self.section.s
        return {"road": self.road.id, "lane": self.lane.id, "section_s": s, "s": s, "line": line or self.lane.line}

    def describe(self) -> str:
        return f"road {self.road.id} lane {self.lane.id} (lane section s={metres(self.section.s)})"


def _layers(ctx: Context) -> Iterator[tuple[Road, Lanes]]:
    """Every road's lane layers (the permanent, then the temporary one)."""
    for road in ctx.document.roads:
        for layer in (road.lanes, road.temporary_lanes):
            if layer is not None:
                yield road, layer


def _listed(road: Road, section: LaneSection) -> list[_Listed]:
    """The lanes of a lane section in the file's order: its groups as the file lists them, each group's lanes."""
    groups = [tag for tag in dict.fromkeys(section.xml.children) if tag in _GROUPS] or list(_GROUPS)
    return [_Listed(road, section, group, lane) for group in groups for lane in getattr(section, group)]


def _sections(ctx: Context) -> Iterator[list[_Listed]]:
    """The lanes of each lane section of every lane layer, in the file's order (sections without lanes too)."""
    for road, layer in _layers(ctx):
        for section in layer.lane_sections:
            yield _listed(road, section)


def _has(owner: Lane | Lanes, records: Sequence, tag: str) -> bool:
    """Whether the lane (or lane layer) has ``<tag>`` records (read, or given but unreadable: the reader said so)."""
    return bool(records) or tag in owner.xml.children


def _line(lane: Lane, records: Sequence) -> int | None:
    """The line of the lane's first record of ``records`` (the lane's when none could be read)."""
    return (records[0].line if records else lane.line) or None


@rule("L017", "lane-listing-order", Category.LANE, Severity.WARNING, uids=(U.LANE_LISTING,))
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
    for lanes in _sections(ctx):
        listed = [lane for lane in lanes if _on_its_side(lane)]
        for before, lane in itertools.pairwise(listed):
            if lane.lane.id > before.lane.id:
                order = " ".join(str(i) for i in sorted((x.lane.id for x in listed), reverse=True))
                yield lane_listing_order.finding(
                    f"{lane.describe()}: lane {lane.lane.id} is listed after lane {before.lane.id}; list the lanes "
                    f"from left to right, with falling ids ({order})",
                    **lane.where(),
                )
                break


def _on_its_side(lane: _Listed) -> bool:
    """Whether the lane's id has the sign of its group (a lane on the wrong side is lane-id-sequence's finding)."""
    sign = {"left": 1, "center": 0, "right": -1}[lane.group]
    i = lane.lane.id
    return i > 0 if sign > 0 else i < 0 if sign < 0 else i == 0


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
    for lanes in _sections(ctx):
        for listed in lanes:
            if listed.group != "center":
                continue
            lane = listed.lane
            records = {"access": lane.access, "height": lane.heights, "material": lane.materials, "speed": lane.speeds}
            for tag in _in_file_order(lane, records):
                uid, what = _CENTRE_RECORDS[tag]
                line = _line(lane, records[tag])
                yield centre_lane_records.finding(
                    f"{listed.describe()}: the centre lane has {what} (<{tag}> at line {line}); the centre lane has "
                    f"none: give the <{tag}> to the side lanes it is meant for",
                    uid=uid,
                    **listed.where(line),
                )


def _in_file_order(lane: Lane, records: Mapping[str, Sequence]) -> list[str]:
    """The tags of ``records`` the lane has, in the order of their first records in the file."""
    listed = [tag for tag in dict.fromkeys(lane.xml.children) if tag in records]
    return listed or [tag for tag, found in records.items() if found]


# ------------------------------------------------------------------------------------------------ record order
#: Lane records the reader does not keep, ordered by ``sOffset``: tag -> the Annex F rule on their order.
_ORDERED = {
    "access": U.ACCESS_ORDER,
    "material": U.MATERIAL_ORDER,
    "rule": U.RULE_ORDER,
    "visibility": U.PROPERTIES_ORDER,
}


@rule("L019", "lane-records-out-of-order", Category.LANE, Severity.ERROR, uids=tuple(_ORDERED.values()))
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
    for lanes in _sections(ctx):
        for listed in lanes:
            lane = listed.lane
            records: tuple[tuple[str, Sequence[LaneAccess | LaneMaterial | LaneRule | LaneVisibility]], ...] = (
                ("access", lane.access),
                ("material", lane.materials),
                ("rule", lane.rules),
                ("visibility", lane.visibilities),
            )
            for tag, of_tag in records:
                placed = [(record.s, record.line or None) for record in of_tag if record.s is not None]
                for (s0, line0), (s, line) in itertools.pairwise(placed):
                    if s < s0:
                        yield lane_records_out_of_order.finding(
                            f"{listed.describe()}: <{tag}> at line {line} starts at sOffset {metres(s)}, before the "
                            f"one at line {line0} ({metres(s0)}); list the <{tag}> records in ascending order of "
                            "sOffset",
                            uid=_ORDERED[tag],
                            **listed.where(line),
                        )
                        break


# ------------------------------------------------------------------------------------------------ width, border, offset
def _first(lanes: list[_Listed], tag: str) -> tuple[_Listed, int | None] | None:
    """The first of ``lanes`` with ``<tag>`` records (``width`` or ``border``) and the first one's line."""
    for listed in lanes:
        records = listed.lane.widths if tag == "width" else listed.lane.borders
        if _has(listed.lane, records, tag):
            return listed, _line(listed.lane, records)
    return None


@rule(
    "L020",
    "width-and-border-mixed",
    Category.LANE,
    Severity.ERROR,
    uids=(U.BORDER_EXCLUSIVE_WIDTH, U.WIDTH_NO_BORDER),
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
    for lanes in _sections(ctx):
        for group in ("left", "right"):
            members = [lane for lane in lanes if lane.group == group]
            width, border = _first(members, "width"), _first(members, "border")
            if width is None or border is None:
                continue
            (w_lane, w_line), (b_lane, b_line) = width, border
            both = (
                f"<{group}> of road {w_lane.road.id} lane section s={metres(w_lane.section.s)}: lane "
                f"{w_lane.lane.id} has <width> (line {w_line}) and lane {b_lane.lane.id} <border> (line {b_line}) "
                "records"
            )
            advice = "; describe one lane group by widths or by borders, not both (readers ignore the borders)"
            yield width_and_border_mixed.finding(both + advice, uid=U.BORDER_EXCLUSIVE_WIDTH, **b_lane.where(b_line))
            yield width_and_border_mixed.finding(both + advice, uid=U.WIDTH_NO_BORDER, **w_lane.where(w_line))


@rule(
    "L021",
    "border-with-lane-offset",
    Category.LANE,
    Severity.ERROR,
    uids=(U.BORDER_EXCLUSIVE_OFFSET, U.LANE_OFFSET_NO_BORDER),
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
    for road, layer in _layers(ctx):
        if not _has(layer, layer.lane_offset, "laneOffset"):
            continue
        border = _first([lane for section in layer.lane_sections for lane in _listed(road, section)], "border")
        if border is None:
            continue
        lane, border_line = border
        offset = layer.lane_offset[0] if layer.lane_offset else None
        offset_line = (layer.line if offset is None else offset.line) or None
        yield border_with_lane_offset.finding(
            f"{lane.describe()}: <border> at line {border_line} while road {road.id}'s lanes have a <laneOffset> "
            f"(line {offset_line}); describe the lanes by <width> records, or drop the lane offset",
            uid=U.BORDER_EXCLUSIVE_OFFSET,
            **lane.where(border_line),
        )
        yield border_with_lane_offset.finding(
            f"road {road.id}: <laneOffset> at line {offset_line} while lane {lane.lane.id} is described by <border> "
            f"records (line {border_line}); there is no lane offset where borders are used",
            uid=U.LANE_OFFSET_NO_BORDER,
            road=road.id,
            s=None if offset is None else offset.s,
            line=offset_line,
        )


@rule("L022", "lane-width-undefined", Category.LANE, Severity.ERROR, uids=(U.WIDTH_WHOLE_SECTION,))
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
    for lanes in _sections(ctx):
        for lane in lanes:
            if lane.group == "center":
                continue
            widths, borders = lane.lane.widths, lane.lane.borders
            tag, records = ("width", widths) if widths else ("border", borders)
            if not records:
                if _has(lane.lane, (), "width") or _has(lane.lane, (), "border"):
                    continue  # records given, none readable: the reader reported them
                yield lane_width_undefined.finding(
                    f"{lane.describe()}: the lane has no <width> record, so no width; give it one at sOffset 0",
                    **lane.where(),
                )
                continue
            first = min(record.s for record in records)
            if first > _ZERO:
                yield lane_width_undefined.finding(
                    f"{lane.describe()}: the first <{tag}> record starts at sOffset {metres(first)}, so the lane has "
                    f"no width over the first {metres(first)} m of its lane section; add a <{tag}> record at sOffset 0",
                    **lane.where(),
                )
