"""The complete document (issue 27, one reader): the records beside the geometry, the XML facts of every record, the
element table's XPaths, and which model modules a read loads."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from lxml import etree

from tests.conftest import corpus_files
from tests.xodrcheck.readerdocs import CENTER, clean, first_road, lanes_of, road, section, xodr
from xodrcheck import model as m
from xodrcheck.reader import read
from xodrcheck.reader.xmlsafe import parse


# ------------------------------------------------------------------------------------------------------ lanes
def test_lane_records_beside_the_geometry():
    lane = (
        '<lane id="-1" type="driving" direction="reversed" advisory="inner" roadWorks="true">'
        '<width sOffset="0" a="3.5" b="0" c="0" d="0"/>'
        '<roadMark sOffset="0" type="solid" color="white" material="paint" height="0.02">'
        '<type name="dashed" width="0.15"><line length="3" space="6" tOffset="0" sOffset="0" rule="caution"/></type>'
        '<sway ds="0" a="0.1" b="0" c="0" d="0"/></roadMark>'
        '<material sOffset="0" surface="asphalt" friction="0.8" roughness="0.1"/>'
        '<access sOffset="0" rule="deny" restriction="truck"/>'
        '<access sOffset="10" rule="allow"><restriction type="bus"/><restriction type="taxi"/></access>'
        '<rule sOffset="5" value="no stopping"/>'
        '<visibility sOffset="0" forward="100" back="50" left="10" right="20"/>'
        "</lane>"
    )
    doc = clean(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    (found,) = doc.roads[0].lane_sections[0].right
    assert (found.direction, found.advisory, found.road_works) == (m.LaneDirection.REVERSED, m.LaneAdvisory.INNER, True)
    (mark,) = found.road_marks
    assert (mark.material, mark.height) == ("paint", 0.02)
    assert mark.type_lines is not None and (mark.type_lines.name, mark.type_lines.width) == ("dashed", 0.15)
    (stripe,) = mark.type_lines.lines
    assert (stripe.length, stripe.space, stripe.t_offset, stripe.s, stripe.rule) == (3.0, 6.0, 0.0, 0.0, "caution")
    assert [(w.ds, w.a) for w in mark.sways] == [(0.0, 0.1)]
    assert [(x.s, x.surface, x.friction, x.roughness) for x in found.materials] == [(0.0, "asphalt", 0.8, 0.1)]
    assert [(a.s, a.rule, a.restriction, a.restrictions) for a in found.access] == [
        (0.0, m.AccessRule.DENY, "truck", ()),
        (10.0, m.AccessRule.ALLOW, None, ("bus", "taxi")),
    ]
    assert [(r.s, r.value) for r in found.rules] == [(5.0, "no stopping")]
    assert [(v.forward, v.back, v.left, v.right) for v in found.visibilities] == [(100.0, 50.0, 10.0, 20.0)]


def test_lane_link_element_and_lanes_records():
    lane = '<lane id="-1" type="driving"><link/><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>'
    offsets = '<laneOffset s="0" a="0.5" b="0" c="0" d="0"/>'
    r = first_road(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"), offsets=offsets))))
    (found,) = r.lane_sections[0].right
    assert found.link is not None and found.link.xml.children == ()  # an empty <link/>: said by its facts
    assert r.lanes is not None and r.lanes.layer is m.LaneLayer.PERMANENT
    assert (r.lanes.lane_offset, r.lanes.lane_sections) == (r.lane_offset, r.lane_sections)
    assert r.lane_sections[0].xml.children == ("center", "right")  # the order of the groups in the file


# ------------------------------------------------------------------------------------------------------ roads
def test_road_types_shapes_surface_and_railroad():
    body = (
        '<type s="0" type="town" country="DE"><speed max="50" unit="km/h"/></type>'
        '<type s="10" type="motorway"><speed max="no limit"/></type>'
        '<lateralProfile><superelevation s="0" a="0" b="0" c="0" d="0"/>'
        '<shape s="0" t="-3" a="0" b="0.02" c="0" d="0"/></lateralProfile>'
        '<surface><CRG file="a.crg" sStart="0" sEnd="10" orientation="same" mode="genuine" hOffset="0.1"/></surface>'
        '<railroad><switch name="w" id="7" position="straight"><mainTrack id="1" s="5" dir="+"/>'
        '<sideTrack id="2" s="0" dir="-"/><partner id="8"/></switch></railroad>'
    )
    r = first_road(xodr(road(body)))
    assert [(t.s, t.type, t.country) for t in r.types] == [(0.0, "town", "DE"), (10.0, "motorway", None)]
    assert r.types[0].speed == m.RoadSpeed(50.0, "km/h", line=3)
    assert r.types[1].speed is not None and r.types[1].speed.max is m.MaxSpeed.NO_LIMIT
    assert [(x.s, x.t, x.b) for x in r.shapes] == [(0.0, -3.0, 0.02)]
    assert r.surface is not None
    (crg,) = r.surface.crgs
    assert (crg.file, crg.mode, crg.orientation, crg.h_offset) == (
        "a.crg",
        m.CrgMode.GENUINE,
        m.CrgOrientation.SAME,
        0.1,
    )
    assert crg.purpose is None and crg.purpose_or_default is m.CrgPurpose.ELEVATION  # the standard's default
    assert r.railroad is not None
    (switch,) = r.railroad.switches
    assert (switch.id, switch.position) == ("7", m.SwitchPosition.STRAIGHT)
    assert switch.main_track == m.SwitchTrack("1", 5.0, m.ElementDir.PLUS, line=3)
    assert switch.partner is not None and switch.partner.id == "8"


def test_cross_section_surface():
    body = (
        '<lateralProfile><crossSectionSurface><tOffset><coefficients s="0" a="0"/></tOffset>'
        '<surfaceStrips><strip id="1"><width><coefficients s="0" a="3"/></width>'
        '<constant><coefficients s="0" a="0.1"/></constant></strip></surfaceStrips></crossSectionSurface>'
        "</lateralProfile>"
    )
    surface = first_road(xodr(road(body))).cross_section_surface
    assert surface is not None and surface.t_offset is not None
    assert [(c.s, c.a) for c in surface.t_offset.coefficients] == [(0.0, 0.0)]
    (strip,) = surface.strips
    assert (strip.id, [p.kind for p in strip.polynomials]) == (1, ["width", "constant"])
    width = strip.polynomial("width")
    assert width is not None and width.coefficients[0].a == 3.0


def test_objects_signals_and_stations_read_as_given():
    body = (
        '<objects><object id="o1" type="pole" s="5" t="-4" zOffset="0" orientation="none" radius="0.1">'
        '<validity fromLane="-1" toLane="x"/></object><tunnel id="t1" s="0" length="10" type="standard"/>'
        '<bridge id="b1" s="20" length="5" type="concrete"/></objects>'
        '<signals><signal id="s1" s="3" t="-2" dynamic="yes" orientation="+" type="206" subtype="-1" country="DE">'
        '<positionRoad roadId="1" s="3" t="-2" zOffset="0" hOffset="0"/><dependency id="s2"/>'
        '<reference elementType="object" elementId="o1"/><semantics><priority type="stop"/></semantics>'
        "</signal></signals>"
    )
    top = (
        '<station id="st" name="Main" type="small"><platform id="p"><segment roadId="1" sStart="0" sEnd="5" '
        'side="left"/></platform></station>'
    )
    doc = clean(xodr(road(body), top, version=(1, 9)))
    (obj,) = doc.roads[0].objects
    assert (obj.id, obj.orientation, obj.radius) == ("o1", m.Orientation.NONE, 0.1)
    (validity,) = obj.validities
    assert (validity.from_lane, validity.to_lane, validity.xml.text("toLane")) == (-1, None, "x")
    assert [t.id for t in doc.roads[0].tunnels] == ["t1"] and [b.id for b in doc.roads[0].bridges] == ["b1"]
    (signal,) = doc.roads[0].signals
    assert (signal.dynamic, signal.orientation, signal.type) == (True, m.Orientation.PLUS, "206")
    assert signal.position_road is not None and signal.position_road.road_id == "1"
    assert [d.id for d in signal.dependencies] == ["s2"]
    assert [(r.element_type, r.element_id) for r in signal.references] == [(m.ReferenceType.OBJECT, "o1")]
    assert signal.semantics is not None and [(i.kind, i.type) for i in signal.semantics.items] == [("priority", "stop")]
    (station,) = doc.stations
    assert (station.id, station.type, station.platforms[0].segments[0].side) == ("st", m.StationType.SMALL, m.Side.LEFT)


# ------------------------------------------------------------------------------------------------------ junctions
def test_junction_parts():
    junction = (
        '<junction id="j" type="virtual" mainRoad="1" sStart="2" sEnd="8" orientation="+">'
        '<connection id="0" incomingRoad="1" connectingRoad="2" contactPoint="start" type="virtual">'
        '<predecessor elementType="road" elementId="1" elementS="2"/><successor elementType="road" elementId="1" '
        'elementS="8"/><laneLink from="-1" to="-1" overlapZone="3"/></connection>'
        '<priority high="1" low="2"/><controller id="c" sequence="1"/>'
        '<boundary><segment type="lane" roadId="1" boundaryLane="-1" sStart="begin" sEnd="4"/>'
        '<segment type="joint" roadId="2" contactPoint="end" transitionLength="-1"/><segment type="x"/></boundary>'
        '<elevationGrid sStart="0" gridSpacing="2"><elevation center="0 0.1" left="a" /></elevationGrid>'
        '<planView><geometry s="0" x="0" y="0" hdg="0" length="4"><line/></geometry></planView></junction>'
    )
    (j,) = clean(xodr(road(), junction, version=(1, 9))).junctions
    assert (j.s_start, j.s_end, j.orientation, j.main_road) == (2.0, 8.0, m.Orientation.PLUS, "1")
    (c,) = j.connections
    assert c.type is m.ConnectionType.VIRTUAL
    assert c.predecessor is not None and (c.predecessor.element_type, c.predecessor.element_s) == (
        m.ElementType.ROAD,
        2.0,
    )
    assert c.lane_links[0].overlap_zone == 3.0
    assert [(p.high, p.low) for p in j.priorities] == [("1", "2")]
    assert [(x.id, x.sequence) for x in j.controllers] == [("c", 1)]
    assert j.boundary is not None
    lane, joint = j.boundary.segments
    assert isinstance(lane, m.LaneSegment) and (lane.s_start, lane.s_end) == (m.ContactPoint.START, 4.0)
    assert isinstance(joint, m.JointSegment) and (joint.contact, joint.transition_length) == (m.ContactPoint.END, 0.0)
    assert [o.type for o in j.boundary.unknown] == ["x"]
    assert j.grid is not None and j.grid.rows[0].center == (0.0, 0.1) and j.grid.rows[0].left is None
    assert j.plan_view is not None and j.plan_view.geometries[0].shapes == ("line",)


# ------------------------------------------------------------------------------------------------------ header
def test_header_georeferences_license_and_regulations():
    header = (
        '<header revMajor="1" revMinor="8"><geoReference><![CDATA[+proj=utm]]></geoReference>'
        "<geoReference>+proj=tmerc</geoReference>"
        '<license name="CC" spdxid="CC-BY-4.0"/><defaultRegulations><roadRegulations type="town"><semantics>'
        '<speed type="maximum" value="50" unit="km/h"/></semantics></roadRegulations></defaultRegulations></header>'
    )
    h = clean(xodr(road(), header=header)).header
    assert h is not None and h.geo_reference == "+proj=utm"
    assert [g.text for g in h.geo_references] == ["+proj=utm", "+proj=tmerc"]
    assert h.license is not None and h.license.spdxid == "CC-BY-4.0"
    assert h.default_regulations is not None
    (regulation,) = h.default_regulations.road_regulations
    assert regulation.semantics is not None
    (speed,) = regulation.semantics.items
    assert (regulation.type, speed.kind, speed.value, speed.unit) == ("town", "speed", 50.0, "km/h")


# ------------------------------------------------------------------------------------------------------ facts
def test_facts_say_given_defaulted_unknown_and_invalid():
    lane = '<lane id="-1" type="driving" level="maybe"><width sOffset="0" a="3" b="0" c="0" d="0"/><vendor/></lane>'
    data = xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>"))))
    doc = read(data).document
    assert doc is not None
    found = doc.roads[0].lane_sections[0].right[0]
    assert found.xml.attributes == ("id", "type", "level")
    assert found.xml.given("level") and not found.xml.given("direction")
    assert found.level is False and found.xml.text("level") == "maybe"  # read as the default, and reported
    assert [(u.tag, u.line) for u in found.xml.unknown] == [("vendor", 3)]
    assert found.xml.children == ("width", "vendor")
    width = found.widths[0]
    assert width.xml.attributes == ("sOffset", "a", "b", "c", "d") and width.xml.unknown == ()


def test_links_the_reader_cannot_read_are_kept_as_written():
    link = '<link><predecessor elementId="7" contactPoint="end"/><successor elementType="road" elementId="2"/></link>'
    result = read(xodr(road(link), road(attrs='id="2" length="10" junction="-1"')))
    assert result.document is not None
    first = result.document.roads[0]
    assert first.predecessor is None and first.successor is not None  # the link without elementType is no link
    (unread,) = first.unread_links
    assert (unread.tag, unread.element_type, unread.element_id, unread.line) == ("predecessor", None, "7", 3)
    assert unread.xml.attributes == ("elementId", "contactPoint")
    assert result.document.roads[1].unread_links == ()
    assert any("elementType" in f.message for f in result.findings)  # and the reader reports it


def test_facts_are_shared_and_left_out_of_equality():
    doc = clean(xodr(road(), road(attrs='id="2" length="10" junction="-1"')))
    first, second = doc.roads
    assert first.plan_view[0].xml is second.plan_view[0].xml  # elements that say the same share their facts
    assert m.Line(0.0, 1.0, 2.0, 0.5, 10.0, line=3) == first.plan_view[0]  # facts are not part of the value


def test_unknown_top_level_elements_are_counted():
    doc = clean(xodr(road(), '<vendorThing a="1"/>', "<vendorThing/>"))
    assert doc.extras == {"vendorThing": 2}
    assert [u.line for u in doc.xml.unknown] == [4, 5]


# ------------------------------------------------------------------------------------------------------ elements
@pytest.mark.corpus
@pytest.mark.parametrize("path", corpus_files()[::8], ids=lambda p: p.name)
def test_element_table_gives_the_xpath_of_each_line(corpus_dir, path):
    """What the xqar report writes as each finding's XMLLocation: the path of the first element on its line."""
    data = path.read_bytes()
    doc = read(data).document
    root, _ = parse(data)
    assert doc is not None and doc.elements is not None and root is not None
    tree = root.getroottree()
    expected: dict[int, str] = {}
    for el in root.iter(etree.Element):
        expected.setdefault(el.sourceline, tree.getpath(el))
    assert len(doc.elements) == sum(1 for _ in root.iter())
    assert {line: doc.elements.xpath(line) for line in expected} == expected
    assert doc.elements.xpath(max(expected) + 1) is None


def test_element_table_numbers_repeated_siblings():
    doc = clean(xodr(road(), road(attrs='id="2" length="10" junction="-1"')))
    assert doc.elements is not None
    assert doc.elements.xpath(3) == "/OpenDRIVE/road[1]"
    assert doc.elements.xpath(2) == "/OpenDRIVE"  # <OpenDRIVE> and <header> share line 2: the first is named


# ------------------------------------------------------------------------------------------------------ loading
def test_a_plain_file_loads_no_model_module_of_rare_subjects():
    """The model's classes are created when first used: reading a file without objects, signals or junction parts
    does not create theirs."""
    code = (
        "import sys\n"
        "from tests.xodrcheck.readerdocs import road, xodr\n"
        "from xodrcheck.reader import read\n"
        "read(xodr(road()))\n"
        "print(' '.join(sorted(k for k in sys.modules if k.startswith('xodrcheck.model.'))))\n"
    )
    repo = Path(__file__).resolve().parents[2]
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=repo)
    out = run.stdout.split()
    assert out == [
        "xodrcheck.model.document",
        "xodrcheck.model.enums",
        "xodrcheck.model.facts",
        "xodrcheck.model.header",
        "xodrcheck.model.ids",
        "xodrcheck.model.junctions",
        "xodrcheck.model.lanes",
        "xodrcheck.model.planview",
        "xodrcheck.model.roads",
    ]


def test_every_public_name_of_the_model_resolves():
    for name in m.__all__:
        assert getattr(m, name) is not None, name
    with pytest.raises(AttributeError):
        m.NotAModelName  # noqa: B018
