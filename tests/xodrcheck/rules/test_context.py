"""The Context rules receive: raw tree with source lines, lookups, junction resolution, widths, geometry."""

from __future__ import annotations

import dataclasses
import math

import pytest

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.config import Config, Tolerances
from xodrcheck.model import ContactPoint, Lane, LaneDirection, LaneType, TrafficRule
from xodrcheck.reader import read
from xodrcheck.rules.shared.context import Context, travel_direction

JUNCTION = fixture("link-not-reciprocal", "pass_junction.xodr")
SECTIONS = fixture("zero-width-lane-linked", "pass.xodr")
BORDERS = fixture("lane-not-continued", "fail_border.xodr")


def context(path, data: bytes | None = None, config: Config | None = None) -> Context:
    data = path.read_bytes() if data is None else data
    return Context(read(data).document, config, path=str(path), data=data)


def test_tree_keeps_source_lines_even_after_content_before_the_declaration():
    data = JUNCTION.read_bytes()
    shifted = b"<!-- written by a tool -->\n" + data
    plain, moved = context(JUNCTION, data).tree, context(JUNCTION, shifted).tree
    assert plain is not None and moved is not None
    assert moved.getroot().find("road").sourceline == plain.getroot().find("road").sourceline + 1


def test_tree_is_none_for_a_broken_file_and_without_bytes():
    ctx = context(JUNCTION, b"<OpenDRIVE><header revMajor='1' revMinor='7'/><road")
    assert ctx.tree is None
    assert Context(read(JUNCTION).document).tree is None


def test_lookups():
    ctx = context(JUNCTION)
    road10 = ctx.road("10")
    assert road10.id == "10" and ctx.road("nope") is None and ctx.road(None) is None
    assert ctx.junction_of(road10).id == "100" and ctx.junction_of(ctx.road("1")) is None
    assert [r.id for r in ctx.roads_in_junction["100"]] == ["10", "11", "16", "17"]
    assert [c.id for c in ctx.connections_by_incoming[("100", "2")]] == ["1", "2"]
    assert ctx.lane_at(road10, ContactPoint.END, -1).id == -1 and ctx.lane_at(road10, ContactPoint.END, 1) is None
    assert ctx.junction_lane_targets[("11", ContactPoint.START)] == frozenset({-1})
    assert ctx.version == (1, 7) and ctx.version_at_least(7) and not ctx.version_at_least(8)


def test_incoming_contact_and_neighbours_through_a_junction():
    ctx = context(JUNCTION)
    junction = ctx.junction("100")
    c0, c1 = junction.connections[:2]
    assert ctx.incoming_contact(junction, c0) is ContactPoint.END  # road 1's successor is the junction
    assert ctx.incoming_contact(junction, c1) is ContactPoint.START  # road 2's predecessor is
    (n,) = ctx.neighbours(ctx.road("1"), ContactPoint.END)
    assert (n.road.id, n.contact, n.connection.id, n.junction.id) == ("10", ContactPoint.START, "0", "100")
    assert ctx.neighbours(ctx.road("1"), ContactPoint.START) == ()
    (back,) = ctx.neighbours(ctx.road("10"), ContactPoint.START)  # a direct road link
    assert (back.road.id, back.contact, back.connection) == ("1", ContactPoint.END, None)


def test_travel_direction_follows_side_and_traffic_rule():
    road = read(JUNCTION).document.road_by_id["1"]
    assert travel_direction(road, _lane(-1)) == 1 and travel_direction(road, _lane(1)) == -1
    lht = dataclasses.replace(road, rule=TrafficRule.LHT)
    assert travel_direction(lht, _lane(-1)) == -1 and travel_direction(lht, _lane(2)) == 1
    assert road.link_at(ContactPoint.END) is road.successor and ContactPoint.END.opposite is ContactPoint.START


def _lane(lane_id: int, lane_type: LaneType = LaneType.DRIVING, direction: LaneDirection | None = None) -> Lane:
    return Lane(lane_id, lane_type, direction=direction)


def test_travel_direction_of_lanes_without_one():
    """11.3.1: @direction reverses a lane or opens it both ways; the centre lane and lanes whose type carries no
    directed traffic (sidewalk, shoulder, border, curb, median, none...) have no direction; biking lanes have one."""
    road = read(JUNCTION).document.road_by_id["1"]
    assert travel_direction(road, _lane(-1, direction=LaneDirection.REVERSED)) == -1
    assert travel_direction(road, _lane(1, direction=LaneDirection.STANDARD)) == -1
    assert travel_direction(road, _lane(-1, direction=LaneDirection.BOTH)) is None
    assert travel_direction(road, _lane(0, LaneType.NONE)) is None
    assert travel_direction(road, _lane(-1, LaneType.BIDIRECTIONAL)) is None
    assert travel_direction(road, _lane(-1, LaneType.BIKING)) == 1
    for kind in (LaneType.SIDEWALK, LaneType.WALKING, LaneType.SHOULDER, LaneType.BORDER, LaneType.CURB):
        assert travel_direction(road, _lane(-1, kind)) is None
    for kind in (LaneType.MEDIAN, LaneType.NONE, LaneType.PARKING, LaneType.RESTRICTED, LaneType.UNKNOWN):
        assert travel_direction(road, _lane(-1, kind)) is None


def test_widths_at_section_ends_from_width_records():
    ctx = context(SECTIONS)
    road = ctx.road("2")
    assert ctx.width_at_end(road, 1, -2, ContactPoint.START) == pytest.approx(0.0)
    assert ctx.width_at_end(road, 1, -2, ContactPoint.END) == pytest.approx(0.07 * 50)
    assert ctx.zero_width_at(road, 1, -2, ContactPoint.START) is True
    assert ctx.zero_width_at(road, 1, -1, ContactPoint.START) is False
    assert ctx.width_at_end(road, 1, 0, ContactPoint.START) is None  # the centre lane has no width


def test_zero_width_threshold_is_the_configured_tolerance():
    ctx = context(SECTIONS, config=Config(tolerances=Tolerances(zero_width=4.0)))
    assert ctx.zero_width_at(ctx.road("2"), 1, -1, ContactPoint.START) is True


def test_widths_of_border_lanes_come_from_the_geometry():
    ctx = context(BORDERS)
    road = ctx.road("2")
    assert ctx.width_at_end(road, 0, -2, ContactPoint.START) == pytest.approx(3.0)
    assert ctx.geometry("2") is not None


def test_neighbours_through_a_direct_junction_run_both_ways(corpus_dir):
    """soderleden.xodr: direct junction 8 joins road 2 (end) and road 5 (end) to road 0 (start)."""
    path = corpus_dir / "esmini" / "resources" / "xodr" / "soderleden.xodr"
    ctx = context(path)
    (forward,) = ctx.neighbours(ctx.road("2"), ContactPoint.END)
    assert (forward.road.id, forward.contact, forward.junction.id) == ("0", ContactPoint.START, "8")
    backward = ctx.neighbours(ctx.road("0"), ContactPoint.START)
    assert sorted((n.road.id, n.contact) for n in backward) == [("2", ContactPoint.END), ("5", ContactPoint.END)]


def test_position_of_a_place_named_by_road_s_and_lane():
    """Exact (x, y, z): the reference line (and elevation) without a lane, the lane's centre raised by its height with
    one, in the section given or the one containing s; cached; None where there is no such place."""
    ctx = context(fixture("link-step", "pass.xodr"))  # road 1: x = s, elevation 0.02 s, roll 0.03, sidewalks 0.15 up
    phi = 0.03
    assert ctx.position("1", 50.0) == pytest.approx((50.0, 0.0, 1.0))
    x, y, z = ctx.position("1", 50.0, lane=-2)
    t = -(3.5 + 1.0)  # the sidewalk's centre
    assert (x, y) == pytest.approx((50.0, t * math.cos(phi) - 0.15 * math.sin(phi)))
    assert z == pytest.approx(1.0 + t * math.sin(phi) + 0.15 * math.cos(phi))
    assert ctx.position("1", 50.0, lane=-2, section_s=0.0) == (x, y, z)
    assert ctx.position("1", 50.0, lane=-9) == pytest.approx((50.0, 0.0, 1.0))  # no such lane: the reference line
    assert ctx.position("nope", 1.0) is None and ctx.position("1", math.nan) is None
    assert ctx.position("1", 50.0, lane=-2) is ctx.position("1", 50.0, lane=-2)  # cached


def test_locate_fills_coordinates_only_where_a_finding_names_a_place_without_them():
    from xodrcheck.findings import Category, Finding, Severity

    ctx = context(fixture("link-step", "pass.xodr"))
    base = Finding("G901", "redundant-record", Category.GEOMETRY, Severity.INFO, "m", road="1", s=20.0)
    assert (ctx.locate(base).x, ctx.locate(base).y, ctx.locate(base).z) == pytest.approx((20.0, 0.0, 0.4))
    placed = dataclasses.replace(base, x=1.0, y=2.0)
    assert ctx.locate(placed) is placed
    assert ctx.locate(dataclasses.replace(base, s=None)).x is None


def test_junction_link_ends_index_every_road_end_naming_a_junction():
    ctx = context(JUNCTION)
    expected: dict[str, list[tuple[str, ContactPoint]]] = {}
    for road in ctx.document.roads:
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is not None and link.element_type.value == "junction":
                expected.setdefault(link.element_id, []).append((road.id, end))
    got = {j: [(road.id, end) for road, end in ends] for j, ends in ctx.junction_link_ends.items()}
    assert got == expected and sum(map(len, got.values())) >= 3
