"""The OpenDRIVE reader on small inline documents: lane sections, lanes and their records, junctions."""

from __future__ import annotations

import pytest

from tests.xodrcheck.readerdocs import (
    CENTER,
    clean,
    codes,
    first_road,
    lanes_of,
    only,
    road,
    section,
    xodr,
)
from xodrcheck import model as m
from xodrcheck.findings import Severity
from xodrcheck.reader import read


def test_lane_sections_and_sides():
    sec = section(
        '<left><lane id="2" type="sidewalk"/><lane id="1" type="driving"/></left>',
        CENTER,
        '<right><lane id="-1" type="driving"/></right>',
        attrs='s="0" singleSide="true"',
    )
    r = first_road(xodr(road(lanes=lanes_of(sec, section(CENTER, attrs='s="4.5"')))))
    first, second = r.lane_sections
    assert (first.s, first.single_side, second.s, second.single_side) == (0.0, True, 4.5, None)
    assert [lane.id for lane in first.left] == [2, 1]
    assert [lane.id for lane in first.center] == [0]
    assert [lane.id for lane in first.right] == [-1]
    assert [lane.id for lane in first.lanes] == [2, 1, 0, -1]
    assert first.lane(2).type is m.LaneType.SIDEWALK


def test_lane_fields_and_records():
    lane = (
        '<lane id="-1" type="driving" level="true">'
        '<link><predecessor id="-2"/><successor id="-1"/></link>'
        '<width sOffset="0" a="3" b="0.1" c="0" d="0"/><width sOffset="2" a="3.2" b="0" c="0" d="0"/>'
        '<roadMark sOffset="0" type="solid" weight="bold" color="white" width="0.15" laneChange="none"/>'
        '<roadMark sOffset="1.5" type="broken"/>'
        '<speed sOffset="0" max="13.9" unit="m/s"/>'
        '<userData><vectorLane travelDir="forward"/></userData>'
        "</lane>"
    )
    r = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    got = r.lane_sections[0].right[0]
    assert (got.id, got.type, got.level, got.type_name, got.line) == (-1, m.LaneType.DRIVING, True, "driving", 3)
    assert (got.predecessors, got.successors) == ((-2,), (-1,))
    assert got.widths == (m.Cubic(0.0, 3.0, 0.1, 0.0, 0.0, 3), m.Cubic(2.0, 3.2, 0.0, 0.0, 0.0, 3))
    assert got.borders == ()
    assert got.road_marks == (
        m.RoadMark(0.0, "solid", "bold", "white", 0.15, "none", 3),
        m.RoadMark(1.5, "broken", None, None, None, None, 3),
    )
    assert got.speeds == (m.Speed(0.0, 13.9, "m/s", 3),)
    assert got.side is m.Side.RIGHT and got.drivable


def test_lane_defaults():
    got = first_road(xodr(road())).lane_sections[0].center[0]
    assert (got.level, got.predecessors, got.successors, got.widths, got.road_marks, got.speeds) == (
        False,
        (),
        (),
        (),
        (),
        (),
    )


def test_lane_border_records():
    lane = '<lane id="1" type="driving"><border sOffset="0" a="3" b="0" c="0" d="0"/></lane>'
    got = first_road(xodr(road(lanes=lanes_of(section(f"<left>{lane}</left>", CENTER))))).lane_sections[0].left[0]
    assert got.borders == (m.Cubic(0.0, 3.0, 0.0, 0.0, 0.0, 3),) and got.widths == ()


def test_several_lane_links_of_1_8():
    lane = (
        '<lane id="-1" type="driving"><link><predecessor id="-1"/><predecessor id="-2"/>'
        '<successor id="-1"/><successor id="-3"/></link></lane>'
    )
    got = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))))).lane_sections[0].right[0]
    assert (got.predecessors, got.successors) == ((-1, -2), (-1, -3))


@pytest.mark.parametrize(
    ("spelling", "lane_type"),
    [
        ("driving", m.LaneType.DRIVING),
        ("Driving", m.LaneType.DRIVING),
        ("HOV", m.LaneType.HOV),
        ("hov", m.LaneType.HOV),
        ("mwyentry", m.LaneType.MWY_ENTRY),
        ("roadWorks", m.LaneType.ROAD_WORKS),
        ("roadworks", m.LaneType.ROAD_WORKS),
        ("onRamp", m.LaneType.ON_RAMP),
        ("curb", m.LaneType.CURB),
        ("slipLane", m.LaneType.SLIP_LANE),
        ("none", m.LaneType.NONE),
    ],
)
def test_lane_types_are_matched_without_case(spelling, lane_type):
    lane = f'<lane id="-1" type="{spelling}"/>'
    got = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))))).lane_sections[0].right[0]
    assert got.type is lane_type and got.type_name == spelling


def test_every_lane_type_of_the_model_is_readable():
    for lane_type in m.LaneType:
        if lane_type is m.LaneType.UNKNOWN:
            continue
        lane = f'<lane id="-1" type="{lane_type.value}"/>'
        got = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))))).lane_sections[0]
        assert got.right[0].type is lane_type


def test_unknown_lane_type_is_kept_with_its_name():
    lane = '<lane id="-1" type="carriageway"/>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    finding = only(result, "X208")
    assert finding.severity is Severity.WARNING and '"carriageway"' in finding.message
    assert (finding.road, finding.section_s, finding.lane) == ("1", 0.0, -1)
    got = result.document.roads[0].lane_sections[0].right[0]
    assert (got.type, got.type_name, got.drivable) == (m.LaneType.UNKNOWN, "carriageway", False)


def test_lane_without_type():
    result = read(xodr(road(lanes=lanes_of(section(CENTER, '<right><lane id="-1"/></right>')))))
    assert "'type'" in only(result, "X205").message
    assert result.document.roads[0].lane_sections[0].right[0].type is m.LaneType.UNKNOWN


@pytest.mark.parametrize(
    ("spelling", "direction"),
    [
        ("standard", m.LaneDirection.STANDARD),
        ("reversed", m.LaneDirection.REVERSED),
        ("both", m.LaneDirection.BOTH),
        ("Both", m.LaneDirection.BOTH),
    ],
)
def test_lane_direction_of_1_8(spelling, direction):
    lane = f'<lane id="-1" type="driving" direction="{spelling}"/>'
    got = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))))).lane_sections[0].right[0]
    assert got.direction is direction


def test_lane_direction_is_absent_before_1_8_and_by_default():
    """11.3.1: @direction is new in 1.8 (the schema reports it in older files); absent, the standard direction."""
    lane = '<lane id="-1" type="driving" direction="reversed"/>'
    for version in ((1, 7), (1, 8)):
        data = xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))), version=version)
        got = first_road(data).lane_sections[0].right[0]
        assert got.direction is (None if version < (1, 8) else m.LaneDirection.REVERSED)
    plain = first_road(xodr(road(lanes=lanes_of(section(CENTER, '<right><lane id="-1" type="driving"/></right>')))))
    assert plain.lane_sections[0].right[0].direction is None


def test_lane_with_invalid_direction():
    lane = '<lane id="-1" type="driving" direction="up"/>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    assert 'direction="up"' in only(result, "X206").message
    assert result.document.roads[0].lane_sections[0].right[0].direction is None


@pytest.mark.parametrize(
    ("version", "required"),
    [
        ((1, 1), False),
        ((1, 4), False),
        ((1, 5), True),
        ((1, 6), True),
        ((1, 7), True),
        ((1, 8), False),
        ((1, 9), False),
    ],
)
def test_centre_lane_type_is_required_where_the_schema_says(version, required):
    """The centre lane's ``type`` is ``use="required"`` in the 1.5 to 1.7 schemas, optional in 1.8 and 1.9 (and, like
    every attribute there, in 1.1 to 1.4); a side lane's stays reported."""
    centre = '<center><lane id="0"/></center>'
    result = read(
        xodr(road(lanes=lanes_of(section(centre, '<right><lane id="-1" type="driving"/></right>'))), version=version)
    )
    assert codes(result) == (["X205"] if required else [])
    assert result.document.roads[0].lane_sections[0].center[0].type is m.LaneType.UNKNOWN
    side = read(xodr(road(lanes=lanes_of(section(CENTER, '<right><lane id="-1"/></right>'))), version=version))
    assert codes(side) == ["X205"]


def test_lane_with_invalid_level():
    lane = '<lane id="-1" type="driving" level="maybe"/>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    assert 'level="maybe"' in only(result, "X206").message
    assert result.document.roads[0].lane_sections[0].right[0].level is False


@pytest.mark.parametrize("lane_id", ["one", "1.5", ""])
def test_lane_with_invalid_id_is_skipped(lane_id):
    lanes = f'<right><lane id="{lane_id}" type="driving"/><lane id="-2" type="driving"/></right>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, lanes)))))
    assert "not an integer" in only(result, "X206").message
    assert [lane.id for lane in result.document.roads[0].lane_sections[0].right] == [-2]


def test_lane_link_with_invalid_id_is_ignored():
    lane = '<lane id="-1" type="driving"><link><predecessor id="x"/><successor id="-1"/></link></lane>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    only(result, "X206")
    got = result.document.roads[0].lane_sections[0].right[0]
    assert (got.predecessors, got.successors) == ((), (-1,))


def test_lane_records_invalid_or_missing():
    lane = (
        '<lane id="-1" type="driving"><width sOffset="-1" a="3" b="0" c="0" d="0"/>'
        '<roadMark sOffset="0"/><speed sOffset="0" max="fast"/><roadMark sOffset="0" type="solid" width="wide"/></lane>'
    )
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    assert sorted(codes(result)) == ["X205", "X206", "X206", "X206"]
    got = result.document.roads[0].lane_sections[0].right[0]
    assert got.widths == () and got.speeds == ()
    assert got.road_marks == (m.RoadMark(0.0, "solid", None, None, None, None, 3),)


def test_lane_records_out_of_order():
    lane = (
        '<lane id="-1" type="driving"><width sOffset="5" a="3" b="0" c="0" d="0"/>'
        '<width sOffset="1" a="3" b="0" c="0" d="0"/></lane>'
    )
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    finding = only(result, "X209")
    assert "<width>" in finding.message and finding.lane == -1


def test_lane_heights():
    """``<height sOffset inner outer>`` (11.7.3) is read in file order; a record missing a value is skipped with a
    finding, and descending ``sOffset`` values are reported."""
    lane = (
        '<lane id="-2" type="sidewalk"><width sOffset="0" a="2" b="0" c="0" d="0"/>'
        '<height sOffset="4" inner="0.12" outer="0.15"/><height sOffset="0" inner="0" outer="0.02"/>'
        '<height sOffset="6" inner="0.1"/></lane>'
    )
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    assert sorted(codes(result)) == ["X205", "X209"]
    got = result.document.roads[0].lane_sections[0].right[0]
    assert got.heights == (m.LaneHeight(4.0, 0.12, 0.15, 3), m.LaneHeight(0.0, 0.0, 0.02, 3))
    assert "<height>" in only(result, "X209").message


def test_lane_sections_out_of_order():
    result = read(xodr(road(lanes=lanes_of(section(CENTER, attrs='s="5"'), section(CENTER)))))
    assert "<laneSection>" in only(result, "X209").message


def test_lane_section_without_lane_0():
    result = read(xodr(road(lanes=lanes_of(section('<right><lane id="-1" type="driving"/></right>')))))
    finding = only(result, "X203")
    assert "centre lane 0" in finding.message and finding.section_s == 0.0
    assert [lane.id for lane in result.document.roads[0].lane_sections[0].right] == [-1]
    result = read(xodr(road(lanes=lanes_of(section('<center><lane id="1" type="none"/></center>')))))
    assert "centre lane 0" in only(result, "X203").message


def test_lane_section_with_invalid_start_is_skipped():
    result = read(xodr(road(lanes=lanes_of(section(CENTER, attrs='s="x"'), section(CENTER, attrs='s="1"')))))
    assert "lane section and its lanes are skipped" in only(result, "X206").message
    assert [s.s for s in result.document.roads[0].lane_sections] == [1.0]


def test_lanes_without_lane_section_and_road_without_lanes():
    result = read(xodr(road(lanes="<lanes/>")))
    assert "<laneSection>" in only(result, "X203").message
    result = read(xodr(road(lanes="")))
    assert "<lanes>" in only(result, "X203").message
    assert result.document.roads[0].lane_sections == ()


def test_repeated_side_reads_the_first():
    sec = section(CENTER, '<right><lane id="-1" type="driving"/></right><right><lane id="-2" type="driving"/></right>')
    result = read(xodr(road(lanes=lanes_of(sec))))
    only(result, "X204")
    assert [lane.id for lane in result.document.roads[0].lane_sections[0].right] == [-1]


# ------------------------------------------------------------------------------------------------------------ junctions
def test_junction_and_connections():
    junction = (
        '<junction id="J1" name="cross" type="default">'
        '<connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start">'
        '<laneLink from="-1" to="-1"/><laneLink from="-2" to="-1"/></connection>'
        '<connection id="1" incomingRoad="2" connectingRoad="11" contactPoint="end"/>'
        "</junction>"
    )
    j = clean(xodr(road(), junction)).junctions[0]
    assert (j.id, j.name, j.type, j.line) == ("J1", "cross", m.JunctionType.DEFAULT, 4)
    first, second = j.connections
    assert first == m.Connection(
        "0",
        "1",
        "10",
        None,
        m.ContactPoint.START,
        (m.JunctionLaneLink(-1, -1, 4), m.JunctionLaneLink(-2, -1, 4)),
        4,
    )
    assert (second.incoming_road, second.connecting_road, second.contact_point) == ("2", "11", m.ContactPoint.END)
    assert j.incoming_roads == ("1", "2")


@pytest.mark.parametrize("kind", ["default", "direct", "virtual", "crossing"])
def test_junction_types(kind):
    assert clean(xodr(road(), f'<junction id="J" type="{kind}"/>')).junctions[0].type is m.JunctionType(kind)


def test_junction_type_defaults_to_default():
    assert clean(xodr(road(), '<junction id="J"/>')).junctions[0].type is m.JunctionType.DEFAULT


def test_direct_junction_linked_road():
    junction = '<junction id="J" type="direct"><connection id="0" incomingRoad="1" linkedRoad="2"/></junction>'
    c = clean(xodr(road(), junction)).junctions[0].connections[0]
    assert (c.incoming_road, c.linked_road, c.connecting_road, c.contact_point) == ("1", "2", None, None)


def test_junction_problems():
    junctions = (
        '<junction name="no id"/>',
        (
            '<junction id="J" type="roundabout"><connection incomingRoad="1" connectingRoad="2" contactPoint="side">'
            '<laneLink from="a" to="-1"/><laneLink to="-1"/><laneLink from="1" to="1"/></connection></junction>'
        ),
    )
    result = read(xodr(road(), *junctions))
    assert sorted(codes(result)) == ["X205", "X205", "X205", "X206", "X206", "X206"]
    assert [j.id for j in result.document.junctions] == ["J"]
    j = result.document.junctions[0]
    assert j.type is m.JunctionType.DEFAULT
    assert j.connections[0].id == "" and j.connections[0].contact_point is None
    assert j.connections[0].lane_links == (m.JunctionLaneLink(1, 1, 5),)
    assert all(f.message.startswith("junction J:") for f in result.findings if f.line == 5)
