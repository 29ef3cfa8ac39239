"""Railroads (chapter 15): rail and tram lanes, switches, stations: ``W001``-``W005``."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import Lane, LaneSection, LaneType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover - the model's railroad modules load for a file with stations or switches
    from xodrcheck.model import Station, Switch

_RAIL = (LaneType.RAIL, LaneType.TRAM)


@rule("W001", "rail-lanes-per-road", Category.RAILROAD, Severity.ERROR, uids=(U.ONE_RAIL_PER_ROAD,))
def rail_lanes_per_road(ctx: Context):
    """A lane section has more than one ``rail`` or ``tram`` lane.

    There shall only be one tram or one rail lane per road (Annex F ``road.railroad.one_rail_per_road``, 15.2): a
    road carries one pair of tracks; a second track is a road of its own.

    Passes::

        <right><lane id="-1" type="tram" .../></right>

    Fails::

        <left><lane id="1" type="tram" .../></left> <right><lane id="-1" type="tram" .../></right>
    """
    for road in ctx.document.roads:
        for section in road.lane_sections:
            rails = [lane for lane in section.lanes if lane.type in _RAIL]
            if len(rails) > 1:
                ids = ", ".join(f"{lane.id} ({lane.type.value})" for lane in rails)
                yield rail_lanes_per_road.finding(
                    f"road {road.id}: the lane section at s={metres(section.s)} has {len(rails)} rail-bound lanes "
                    f"({ids}): one pair of tracks per road; model each further track as a road of its own",
                    road=road.id,
                    section_s=section.s,
                    s=section.s,
                    line=section.line,
                )


@rule("W002", "rail-reference-line-off-centre", Category.RAILROAD, Severity.ERROR, uids=(U.RAIL_REFLINE_CENTERED,))
def rail_reference_line_off_centre(ctx: Context):
    """The reference line of a road with a rail or tram lane does not run along the centre of that lane.

    The road reference line shall be in the centre of the pair of railroad tracks (Annex F
    ``road.railroad.rail_refline_centered``, 15.2): the track is the lane, so its centre is at ``t = 0`` (a
    ``<laneOffset>`` of half the lane's width moves a one-sided rail lane onto the line). Checked at the start, middle
    and end of each lane section; the tolerance is ``gap``.

    Passes::

        <laneOffset s="0" a="1.25" .../> ... <right><lane id="-1" type="rail"><width a="2.5" .../>

    Fails::

        <right><lane id="-1" type="rail"><width a="2.5" .../>   <!-- centre at t = -1.25 -->
    """
    tol = ctx.tolerances.gap
    for road in ctx.document.roads:
        for index, section in enumerate(road.lane_sections):
            rails = [lane for lane in section.lanes if lane.type in _RAIL]
            if len(rails) != 1:
                continue  # none, or several (rail-lanes-per-road)
            geometry = ctx.geometry(road.id)
            lane = rails[0]
            if geometry is None or lane.id not in geometry.placed_lane_ids(index):
                continue
            start, end = section.s, road.section_end(index)
            s = np.array([start, (start + end) / 2, end])
            inner, outer = geometry.inner_outer(index, lane.id, s)
            centre = (np.asarray(inner) + np.asarray(outer)) / 2
            worst = int(np.argmax(np.abs(centre)))
            if abs(centre[worst]) > tol:
                yield rail_reference_line_off_centre.finding(
                    f"road {road.id}: the centre of {lane.type.value} lane {lane.id} is at t={centre[worst]:.3f} m at "
                    f"s={metres(s[worst])}, not on the reference line: the reference line runs in the centre of the "
                    "tracks (shift the lane onto it with <laneOffset>)",
                    road=road.id,
                    lane=lane.id,
                    section_s=section.s,
                    s=float(s[worst]),
                    line=lane.line,
                )


def _stations(ctx: Context) -> tuple[Station, ...]:
    return ctx.document.stations


@rule(
    "W003",
    "station-without-platform",
    Category.RAILROAD,
    Severity.ERROR,
    uids=(U.PLATFORMS_MIN_AMOUNT, U.ONE_PLATFORM_PER_STATION, U.PLATFORMS_MIN_SEGMENTS, U.SEGMENTS_PER_PLATFORM),
)
def station_without_platform(ctx: Context):
    """A ``<station>`` has no ``<platform>``, or a ``<platform>`` has no ``<segment>``.

    Each station shall have at least one platform (Annex F ``road.railroad.platforms.min_amount`` and
    ``stations.one_platform_per_station``), and each platform at least one segment, which names the track beside it
    (``platforms.min_segments`` and ``segment.segments_per_platform_min_amount``; 15.4). Each of the two pairs of
    UIDs states one requirement, so a defect gives one finding per UID.

    Passes::

        <station id="1" name="Main"><platform id="1"><segment roadId="1" sStart="10" sEnd="60" side="right"/>

    Fails::

        <station id="1" name="Main"/>
    """
    for station in _stations(ctx):
        platforms = station.platforms
        name = f"station {station.id!r} ({station.name})"
        if not platforms:
            for uid in (U.PLATFORMS_MIN_AMOUNT, U.ONE_PLATFORM_PER_STATION):
                yield station_without_platform.finding(
                    f"{name} has no <platform>: a station has at least one platform, where passengers get on and off",
                    uid=uid,
                    line=station.line or None,
                )
        for platform in platforms:
            if not platform.segments:
                for uid in (U.PLATFORMS_MIN_SEGMENTS, U.SEGMENTS_PER_PLATFORM):
                    yield station_without_platform.finding(
                        f"platform {platform.id!r} of {name} has no <segment>: a segment names the track "
                        "(road, sStart, sEnd, side) the platform lies beside",
                        uid=uid,
                        line=platform.line or None,
                    )


def _switches(ctx: Context) -> list[tuple[str, Switch]]:
    """(road id, switch) for every switch of the file."""
    return [
        (road.id, switch)
        for road in ctx.document.roads
        if road.railroad is not None
        for switch in road.railroad.switches
    ]


def _id(switch: Switch) -> str:
    return "?" if switch.id is None else switch.id


@rule(
    "W004",
    "switch-topology",
    Category.RAILROAD,
    Severity.ERROR,
    uids=(U.SWITCH_CONNECTION, U.SINGLE_SWITCH_NO_PARTNER),
)
def switch_topology(ctx: Context):
    """Switches are connected through a main track, or a single switch names a partner.

    A side track connects two switches placed on main tracks; main tracks shall not be used to connect two switches
    (Annex F ``road.railroad.switch.check_switch_conn``): a road that is one switch's side track is not another
    switch's main track. Partner switches are two switches linked by a side track; a single switch (whose side track
    reaches no other switch) has no partner (``switch.single_switch_no_partner``; 15.3).

    Passes::

        <switch id="12" ...><mainTrack id="1" .../><sideTrack id="2" .../><partner id="32"/></switch>
        <switch id="32" ...><mainTrack id="3" .../><sideTrack id="2" .../><partner id="12"/></switch>

    Fails::

        <switch id="12" ...><mainTrack id="1" .../><sideTrack id="2" .../><partner id="32"/></switch>
        <switch id="32" ...><mainTrack id="2" .../><sideTrack id="3" .../></switch>
    """
    switches = _switches(ctx)
    side_of: dict[str, list[str]] = {}
    for _, switch in switches:
        side = None if switch.side_track is None else switch.side_track.id
        if side is not None:
            side_of.setdefault(side, []).append(_id(switch))
    for road_id, switch in switches:
        sid = _id(switch)
        main = None if switch.main_track is None else switch.main_track.id
        side = None if switch.side_track is None else switch.side_track.id
        others = [other for other in side_of.get(main or "", []) if other != sid]
        if others:
            yield switch_topology.finding(
                f"switch {sid!r} on road {road_id} has road {main} as its main track, which is the side track of "
                f"switch {others[0]!r}: two switches are connected by a side track, not a main track",
                uid=U.SWITCH_CONNECTION,
                road=road_id,
                line=switch.line or None,
            )
        partner = switch.partner
        if partner is None:
            continue
        linked = [other for other in side_of.get(side or "", []) if other != sid]
        if not linked:
            yield switch_topology.finding(
                f"switch {sid!r} on road {road_id} names partner {partner.id!r}, but its side track "
                f"{side} reaches no other switch: a single switch has no partner (remove <partner>, or give both "
                "switches the side track that links them)",
                uid=U.SINGLE_SWITCH_NO_PARTNER,
                road=road_id,
                line=partner.line or None,
            )


@rule("W005", "rail-lane-too-narrow", Category.RAILROAD, Severity.ERROR, uids=(U.RAIL_LANE_WIDTH,))
def rail_lane_too_narrow(ctx: Context) -> Iterator[Finding]:
    """A ``rail`` or ``tram`` lane is narrower than the rail-bound vehicles using it somewhere along its section.

    The width of the lane shall be at least the width of the rail-bound vehicles (Annex F
    ``road.railroad.rail_lane_width_validity``, 15.2): the lane is the space the vehicle takes, not the track gauge.
    OpenDRIVE names no vehicle, so the width is compared with an assumed one, the tolerance
    ``rail_vehicle_min_width`` (2.2 m: the Tatra KT4 articulated tram, 2,200 mm wide per its maker's data, built for
    1,435 mm and 1,000 mm gauge and still in service, is among the narrowest rail-bound vehicles; most trams are
    2.3-2.65 m wide; raise it to the vehicles a map is for). The lane's smallest width over each lane
    section is exact: the minimum of its width cubics between knots (the one evaluation the lane-shape rules share,
    ``<width>`` or ``<border>`` records alike). A lane without width or border records is lane-width-undefined's (L022).

    Passes::

        <right><lane id="-1" type="tram"><width sOffset="0" a="2.65" b="0" c="0" d="0"/></lane></right>

    Fails (1.435 m: the gauge, not the vehicle)::

        <right><lane id="-1" type="tram"><width sOffset="0" a="1.435" b="0" c="0" d="0"/></lane></right>
    """
    limit = ctx.tolerances.rail_vehicle_min_width
    for road, section, lane, minimum, s, everywhere in _narrow_rail_lanes(ctx, limit):
        where = (
            f"at most {minimum:.4g} m wide along the whole section"
            if everywhere
            else f"{minimum:.4g} m wide at s={metres(s)}"
        )
        yield rail_lane_too_narrow.finding(
            f"road {road.id}: {lane.type.value} lane {lane.id} of the lane section at s={metres(section.s)} is "
            f"{where}: narrower than {metres(limit)} m, the narrowest rail-bound vehicle assumed (tolerance "
            "rail_vehicle_min_width); widen the lane to the vehicles' width (the lane is the space the vehicle takes, "
            "not the gauge), or set the tolerance to the vehicles of this map",
            road=road.id,
            lane=lane.id,
            section_s=section.s,
            s=section.s if everywhere else s,
            line=lane.line or section.line or None,
        )


def _narrow_rail_lanes(ctx: Context, limit: float) -> Iterator[tuple[Road, LaneSection, Lane, float, float, bool]]:
    """(road, section, lane, smallest width, s where reached, whether the lane is narrower along its whole section)
    for every rail or tram lane narrower than ``limit`` somewhere; widths from the exact per-piece cubics."""
    from xodrcheck.rules.lane_shape import lane_minima, lane_width_bounds

    for road in ctx.document.roads:
        if not any(lane.type in _RAIL for section in road.lane_sections for lane in section.lanes):
            continue
        if ctx.usable_geometry(road) is None:
            continue
        for index, section in enumerate(road.lane_sections):
            if not any(lane.type in _RAIL for lane in section.lanes):
                continue
            bounds = lane_width_bounds(ctx, road, index)
            widest = {} if bounds is None else {lane.id: float(np.max(row)) for lane, row in zip(bounds[0], bounds[4])}
            for lane, minimum, s in lane_minima(ctx, road, index):
                if lane.type in _RAIL and minimum < limit - 1e-6:
                    yield road, section, lane, minimum, s, widest.get(lane.id, limit) < limit - 1e-6
