"""The OpenDRIVE reader on small inline documents: every model field, the standard's defaults, and each reader rule."""

from __future__ import annotations

import gzip
import os

import pytest
from lxml import etree

from tests.xodrcheck.readerdocs import (
    CENTER,
    LANES,
    LINE_GEOMETRY,
    clean,
    first_road,
    lanes_of,
    only,
    road,
    section,
    xodr,
)
from xodrcheck import model as m
from xodrcheck.findings import ReadError, Severity
from xodrcheck.reader import KNOWN_VERSIONS, read
from xodrcheck.rules import xml as R


# ------------------------------------------------------------------------------------------------------------ input
def test_reads_a_path_and_bytes_alike(tmp_path):
    data = xodr(road())
    path = tmp_path / "map.xodr"
    path.write_bytes(data)
    from_path = read(path)
    from_str = read(str(path))
    from_bytes = read(data)
    assert from_path.path == from_str.path == str(path)
    assert from_bytes.path is None
    assert from_path.document.source == str(path)
    assert from_bytes.document.source is None
    assert from_path.document.roads == from_bytes.document.roads == from_str.document.roads


def test_missing_file_is_a_read_error(tmp_path):
    with pytest.raises(ReadError, match="no such file"):
        read(tmp_path / "absent.xodr")


def test_directory_is_a_read_error(tmp_path):
    with pytest.raises(ReadError, match="directory"):
        read(tmp_path)


def test_size_limit_is_a_read_error(tmp_path):
    data = xodr(road())
    path = tmp_path / "map.xodr"
    path.write_bytes(data)
    with pytest.raises(ReadError, match="limit"):
        read(path, max_bytes=len(data) - 1)
    with pytest.raises(ReadError, match="limit"):
        read(data, max_bytes=len(data) - 1)
    assert read(path, max_bytes=len(data)).document is not None


def test_a_pipe_is_read_whole_within_the_limit(tmp_path):
    """Not a regular file: no size to go by, so the reader reads up to the limit (and refuses past it)."""
    import threading

    data = xodr(road())
    fifo = tmp_path / "map.fifo"
    os.mkfifo(fifo)

    def feed() -> None:
        with open(fifo, "wb") as stream:
            stream.write(data)

    for limit, ok in ((len(data), True), (len(data) - 1, False)):
        writer = threading.Thread(target=feed)
        writer.start()
        try:
            if ok:
                assert read(fifo, max_bytes=limit).document.roads == read(data).document.roads
            else:
                with pytest.raises(ReadError, match="limit"):
                    read(fifo, max_bytes=limit)
        finally:
            writer.join()


def test_a_file_that_grew_after_its_stat_is_read_whole(tmp_path, monkeypatch):
    """The reader asks for the stat's size plus one byte; a file longer than its stat said is read on to its end
    (within the limit), not cut at the stat's size."""
    import xodrcheck.reader as reader_module

    data = xodr(road())
    path = tmp_path / "map.xodr"
    path.write_bytes(data)
    real_stat = os.stat

    def stale_stat(p, *args, **kwargs):
        info = real_stat(p, *args, **kwargs)
        if str(p) != str(path):
            return info
        fields = list(info)
        fields[6] = len(data) // 2  # st_size as it was before the writer finished
        return os.stat_result(fields)

    monkeypatch.setattr(reader_module.os, "stat", stale_stat)
    result = read(str(path), max_bytes=len(data))
    whole = read(data)  # the bytes themselves
    assert result.document.roads == whole.document.roads and len(whole.document.roads) == 1
    assert result.findings == whole.findings
    with pytest.raises(ReadError, match="limit"):
        read(str(path), max_bytes=len(data) - 1)


@pytest.mark.parametrize("enabled", [True, False])
def test_reading_leaves_the_garbage_collector_as_it_was(enabled):
    """Reading leaves the cyclic collector as the caller set it."""
    import gc

    was = gc.isenabled()
    try:
        (gc.enable if enabled else gc.disable)()
        assert read(xodr(road())).document is not None
        assert gc.isenabled() is enabled
    finally:
        (gc.enable if was else gc.disable)()


def test_blank_text_is_left_out_only_below_65535_lines():
    """read() parses without the indentation between elements, except in a file long enough that libxml2 needs the
    text nodes for its elements' line numbers; either way the model and its lines are the same."""
    from xodrcheck.reader import read_keeping_tree
    from xodrcheck.reader.xmlsafe import parse

    data = xodr(road())
    short, _ = parse(data, keep_blank_text=False)
    assert all(not (el.tail or "").strip() for el in short.iter()) and short[0].tail is None
    kept, _ = parse(data)
    assert kept[0].tail is not None and not kept[0].tail.strip()
    # past line 65,535 libxml2 finds an element's line through the text nodes beside it: they are kept there
    lanes = "".join(f'\n  <lane id="-{k}" type="driving" level="false">\n  </lane>' for k in range(1, 40001))
    long_doc = xodr(road(lanes=f"<lanes>{section(CENTER, f'<right>{lanes}</right>')}</lanes>"))
    long, _ = parse(long_doc, keep_blank_text=False)
    assert long[0].tail is not None
    lines = [lane.line for lane in read(long_doc).document.roads[0].lane_sections[0].right]
    assert lines[-1] > 65535 and lines == sorted(lines)
    assert read(long_doc).document == read_keeping_tree(long_doc)[0].document


def test_gzip_compressed_file_is_read(tmp_path):
    path = tmp_path / "map.xodrz"
    path.write_bytes(gzip.compress(xodr(road())))
    result = read(path)
    assert result.findings == ()
    assert [r.id for r in result.document.roads] == ["1"]


def test_corrupt_gzip_is_a_finding():
    result = read(gzip.compress(xodr(road()))[:30])
    assert result.document is None
    assert "gzip" in only(result, "X101").message


# ------------------------------------------------------------------------------------------------------------ header
def test_header_fields():
    header = (
        '<header revMajor="1" revMinor="7" name="town" version="2.1" date="2024-01-02" vendor="ACME" '
        'north="10.5" south="-3" east="7" west="-8.25">'
        "<geoReference><![CDATA[ +proj=utm +zone=32 +datum=WGS84 ]]></geoReference>"
        '<offset x="100" y="-200.5" z="3" hdg="0.25"/>'
        "</header>"
    )
    h = clean(xodr(road(), header=header)).header
    assert (h.rev_major, h.rev_minor, h.version_tuple) == (1, 7, (1, 7))
    assert (h.name, h.version, h.date, h.vendor) == ("town", "2.1", "2024-01-02", "ACME")
    assert (h.north, h.south, h.east, h.west) == (10.5, -3.0, 7.0, -8.25)
    assert h.geo_reference == "+proj=utm +zone=32 +datum=WGS84"
    assert h.offset == m.Offset(100.0, -200.5, 3.0, 0.25, line=2)
    assert h.line == 2


def test_header_optional_fields_absent_are_none():
    h = clean(xodr(road(), version=(1, 4))).header
    assert (h.name, h.version, h.date, h.vendor, h.north, h.geo_reference, h.offset) == (None,) * 7


@pytest.mark.parametrize("version", sorted(KNOWN_VERSIONS))
def test_known_versions_read_without_findings(version):
    assert clean(xodr(road(), version=version)).version == version


def test_versions_one_to_nine_are_known():
    assert {(1, minor) for minor in range(1, 10)} == KNOWN_VERSIONS


@pytest.mark.parametrize("version", [(1, 10), (2, 0), (0, 4), (1, -1)])
def test_unknown_version_is_a_warning(version):
    result = read(xodr(road(), version=version))
    finding = only(result, "X202")
    assert finding.severity is Severity.WARNING
    assert f"{version[0]}.{version[1]}" in finding.message
    assert result.document.header.version_tuple == version


def test_version_that_is_not_an_integer():
    result = read(xodr(road(), header='<header revMajor="1" revMinor="seven"/>'))
    finding = only(result, "X206")
    assert 'revMinor="seven"' in finding.message and finding.line == 2
    assert result.document.header.rev_minor is None
    assert result.document.version is None


def test_version_missing():
    result = read(xodr(road(), header='<header revMinor="6"/>'))
    assert "'revMajor'" in only(result, "X205").message
    assert result.document.version is None


def test_missing_header():
    result = read(xodr(road(), header=""))
    finding = only(result, "X203")
    assert "<header>" in finding.message and finding.severity is Severity.ERROR
    assert result.document.header is None
    assert len(result.document.roads) == 1


def test_second_header_is_ignored():
    extra = '<header revMajor="1" revMinor="4"/>'
    result = read(xodr(road(), extra))
    assert only(result, "X204").line == 4
    assert result.document.version == (1, 8)


def test_header_bounds_invalid_read_as_absent():
    result = read(xodr(road(), header='<header revMajor="1" revMinor="6" north="far"/>'))
    assert 'north="far"' in only(result, "X206").message
    assert result.document.header.north is None


def test_offset_with_invalid_value_is_ignored():
    header = '<header revMajor="1" revMinor="6"><offset x="1" y="2" z="zero" hdg="0"/></header>'
    result = read(xodr(road(), header=header))
    assert "the offset is ignored" in only(result, "X206").message
    assert result.document.header.offset is None


# ------------------------------------------------------------------------------------------------------------ roads
def test_road_attributes():
    r = first_road(xodr(road(attrs='id="r7" length="10" junction="-1" name="Main St" rule="LHT"')))
    assert (r.id, r.length, r.junction, r.name, r.rule) == ("r7", 10.0, None, "Main St", m.TrafficRule.LHT)
    assert r.line == 3


def test_road_defaults():
    r = first_road(xodr(road()))
    assert r.rule is m.TrafficRule.RHT  # the standard's default
    assert r.name is None
    assert (r.predecessor, r.successor, r.elevation, r.superelevation, r.lane_offset) == (None, None, (), (), ())
    assert (r.objects, r.signals, r.types, r.shapes, r.surface, r.railroad) == ((), (), (), (), None, None)


def test_road_in_junction():
    assert first_road(xodr(road(attrs='id="1" length="10" junction="5"'))).junction == "5"


def test_road_without_id_is_skipped():
    result = read(xodr(road(attrs='length="10" junction="-1"'), road(attrs='id="2" length="10" junction="-1"')))
    assert "'id'" in only(result, "X205").message
    assert [r.id for r in result.document.roads] == ["2"]


def test_road_length_negative_uses_geometry_sum():
    result = read(xodr(road(attrs='id="1" length="-10" junction="-1"')))
    finding = only(result, "X206")
    assert finding.road == "1" and 'length="-10"' in finding.message and "sum" in finding.message
    assert result.document.roads[0].length == 10.0


def test_road_length_missing_uses_geometry_sum():
    result = read(xodr(road(attrs='id="1" junction="-1"')))
    assert "'length'" in only(result, "X205").message
    assert result.document.roads[0].length == 10.0


def test_road_junction_missing():
    result = read(xodr(road(attrs='id="1" length="10"')))
    assert "'junction'" in only(result, "X205").message
    assert result.document.roads[0].junction is None


def test_road_rule_invalid_reads_rht():
    result = read(xodr(road(attrs='id="1" length="10" junction="-1" rule="middle"')))
    assert 'rule="middle"' in only(result, "X206").message
    assert result.document.roads[0].rule is m.TrafficRule.RHT


def test_objects_signals_and_top_level_elements():
    body = (
        '<objects><object id="a"/><object id="b"/><objectReference id="c"/></objects>'
        '<signals><signal id="s1"/><signal id="s2"/><signal id="s3"/></signals>'
    )
    top = ('<controller id="c1"/>', '<controller id="c2"/>', '<station id="st"/>', '<vendorThing a="1"/>')
    doc = clean(xodr(road(body), *top))
    assert [o.id for o in doc.roads[0].objects] == ["a", "b"]
    assert [r.id for r in doc.roads[0].object_references] == ["c"]
    assert [s.id for s in doc.roads[0].signals] == ["s1", "s2", "s3"]
    assert [c.id for c in doc.controllers] == ["c1", "c2"]
    assert [s.id for s in doc.stations] == ["st"]
    assert doc.extras == {"vendorThing": 1}  # an element that is not OpenDRIVE at the top level


# ------------------------------------------------------------------------------------------------------------ links
def test_road_links():
    link = (
        '<link><predecessor elementType="road" elementId="0" contactPoint="end"/>'
        '<successor elementType="junction" elementId="J1"/></link>'
    )
    r = first_road(xodr(road(link)))
    assert r.predecessor == m.RoadLink(m.ElementType.ROAD, "0", m.ContactPoint.END, line=3)
    assert r.successor == m.RoadLink(m.ElementType.JUNCTION, "J1", None, line=3)


def test_road_link_element_s_and_dir_of_1_8():
    link = '<link><successor elementType="road" elementId="9" elementS="12.5" elementDir="-"/></link>'
    succ = first_road(xodr(road(link))).successor
    assert (succ.element_s, succ.element_dir, succ.contact_point) == (12.5, m.ElementDir.MINUS, None)


def test_road_link_invalid_contact_point_reads_absent():
    link = '<link><predecessor elementType="road" elementId="0" contactPoint="middle"/></link>'
    result = read(xodr(road(link)))
    assert 'contactPoint="middle"' in only(result, "X206").message
    assert result.document.roads[0].predecessor.contact_point is None


def test_road_link_invalid_element_type_is_ignored():
    result = read(xodr(road('<link><predecessor elementType="lane" elementId="0"/></link>')))
    assert "elementType" in only(result, "X206").message
    assert result.document.roads[0].predecessor is None


def test_road_link_missing_element_id_is_ignored():
    result = read(xodr(road('<link><successor elementType="road"/></link>')))
    assert "'elementId'" in only(result, "X205").message
    assert result.document.roads[0].successor is None


def test_repeated_road_predecessor():
    link = (
        '<link><predecessor elementType="road" elementId="a"/>\n<predecessor elementType="road" elementId="b"/></link>'
    )
    result = read(xodr(road(link)))
    assert only(result, "X204").line == 4
    assert result.document.roads[0].predecessor.element_id == "a"


# ------------------------------------------------------------------------------------------------------------ plan view
def plan(*geometries: str) -> str:
    return "<planView>" + "".join(geometries) + "</planView>"


def test_line_geometry():
    g = first_road(xodr(road())).plan_view[0]
    assert g == m.Line(0.0, 1.0, 2.0, 0.5, 10.0, line=3)


def test_every_geometry_kind():
    pv = plan(
        '<geometry s="0" x="0" y="0" hdg="0" length="1"><line/></geometry>',
        '<geometry s="1" x="1" y="0" hdg="0" length="2"><arc curvature="0.05"/></geometry>',
        '<geometry s="3" x="2" y="0" hdg="0" length="3"><spiral curvStart="0" curvEnd="0.1"/></geometry>',
        '<geometry s="6" x="3" y="0" hdg="0" length="4"><poly3 a="0" b="0.1" c="0.01" d="-0.001"/></geometry>',
        '<geometry s="10" x="4" y="0" hdg="0" length="5">'
        '<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0.2" dV="-0.1" pRange="arcLength"/></geometry>',
        '<geometry s="15" x="5" y="0" hdg="0" length="6">'
        '<paramPoly3 aU="1" bU="2" cU="3" dU="4" aV="5" bV="6" cV="7" dV="8" pRange="normalized"/></geometry>',
    )
    r = first_road(xodr(road(plan_view=pv, attrs='id="1" length="21" junction="-1"')))
    line, arc, spiral, poly3, pp_arc, pp_norm = r.plan_view
    assert isinstance(line, m.Line) and line.length == 1.0
    assert isinstance(arc, m.Arc) and (arc.s, arc.curvature) == (1.0, 0.05)
    assert isinstance(spiral, m.Spiral) and (spiral.curv_start, spiral.curv_end) == (0.0, 0.1)
    assert isinstance(poly3, m.Poly3) and (poly3.a, poly3.b, poly3.c, poly3.d) == (0.0, 0.1, 0.01, -0.001)
    assert isinstance(pp_arc, m.ParamPoly3) and pp_arc.p_range is m.PRange.ARC_LENGTH
    assert (pp_arc.cV, pp_arc.dV) == (0.2, -0.1)
    assert pp_norm.p_range is m.PRange.NORMALIZED
    assert (pp_norm.aU, pp_norm.bU, pp_norm.cU, pp_norm.dU, pp_norm.aV, pp_norm.bV, pp_norm.cV, pp_norm.dV) == (
        1.0,
        2.0,
        3.0,
        4.0,
        5.0,
        6.0,
        7.0,
        8.0,
    )


PP3_NO_RANGE = (
    '<geometry s="0" x="0" y="0" hdg="0" length="10">'
    '<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0"/></geometry>'
)


def test_param_poly3_without_prange_in_1_4_is_normalized_with_a_note():
    result = read(xodr(road(plan_view=plan(PP3_NO_RANGE)), version=(1, 4)))
    finding = only(result, "X205")
    assert finding.severity is Severity.INFO and "normalized" in finding.message and "CARLA" in finding.message
    assert result.document.roads[0].plan_view[0].p_range is m.PRange.NORMALIZED


def test_param_poly3_without_prange_in_1_6_is_an_error_read_as_normalized():
    result = read(xodr(road(plan_view=plan(PP3_NO_RANGE)), version=(1, 6)))
    finding = only(result, "X205")
    assert finding.severity is Severity.ERROR and "required since OpenDRIVE 1.5" in finding.message
    assert result.document.roads[0].plan_view[0].p_range is m.PRange.NORMALIZED


def test_param_poly3_with_unknown_prange_is_skipped():
    geometry = PP3_NO_RANGE.replace('dV="0"', 'dV="0" pRange="metres"')
    result = read(xodr(road(plan_view=plan(geometry))))
    assert 'pRange="metres"' in only(result, "X206").message
    assert result.document.roads[0].plan_view == ()


def test_geometry_missing_x_is_skipped_with_where_and_why():
    geometry = '<geometry s="0" y="0" hdg="0" length="10"><line/></geometry>'
    result = read(xodr(road(plan_view=plan(geometry), attrs='id="12" length="10" junction="-1"')))
    finding = only(result, "X205")
    assert finding.message == "road 12: <geometry> at line 3 has no 'x' attribute; the geometry is skipped"
    assert (finding.road, finding.line, finding.severity) == ("12", 3, Severity.ERROR)
    assert result.document.roads[0].plan_view == ()


@pytest.mark.parametrize(
    ("value", "why"),
    [
        ("NaN", "not a finite number"),
        ("inf", "not a finite number"),
        ("-INF", "not a finite number"),
        ("seven", "not a number"),
        ("1,5", "not a number"),
        ("", "not a number"),
    ],
)
def test_geometry_invalid_number_is_skipped(value, why):
    geometry = f'<geometry s="0" x="0" y="0" hdg="{value}" length="10"><line/></geometry>'
    result = read(xodr(road(plan_view=plan(geometry))))
    finding = only(result, "X206")
    assert f'hdg="{value}"' in finding.message and why in finding.message
    assert result.document.roads[0].plan_view == ()


def test_geometry_negative_length_is_skipped():
    geometry = '<geometry s="0" x="0" y="0" hdg="0" length="-3"><line/></geometry>'
    result = read(xodr(road(plan_view=plan(geometry))))
    assert "must be >= 0" in only(result, "X206").message


def test_arc_missing_curvature_is_skipped():
    geometry = '<geometry s="0" x="0" y="0" hdg="0" length="10"><arc/></geometry>'
    result = read(xodr(road(plan_view=plan(geometry))))
    assert "'curvature'" in only(result, "X205").message
    assert result.document.roads[0].plan_view == ()


@pytest.mark.parametrize(
    ("shape", "expect"),
    [("<clothoid/>", "<clothoid>"), ("", "no shape element"), ("<line/><arc curvature='0'/>", "both <line> and <arc>")],
)
def test_unknown_or_missing_geometry_shape(shape, expect):
    geometry = f'<geometry s="0" x="0" y="0" hdg="0" length="10">{shape}</geometry>'
    result = read(xodr(road(plan_view=plan(geometry))))
    assert expect in only(result, "X207").message
    assert result.document.roads[0].plan_view == ()


def test_geometry_user_data_is_not_a_shape():
    geometry = '<geometry s="0" x="0" y="0" hdg="0" length="10"><userData code="x"/><line/></geometry>'
    assert isinstance(first_road(xodr(road(plan_view=plan(geometry)))).plan_view[0], m.Line)


def test_geometries_out_of_order():
    pv = plan(
        '<geometry s="5" x="0" y="0" hdg="0" length="5"><line/></geometry>\n',
        '<geometry s="0" x="0" y="0" hdg="0" length="5"><line/></geometry>',
    )
    result = read(xodr(road(plan_view=pv)))
    finding = only(result, "X209")
    assert finding.line == 4 and finding.road == "1"
    assert [g.s for g in result.document.roads[0].plan_view] == [5.0, 0.0]  # file order kept


def test_plan_view_missing_or_empty():
    result = read(xodr(road(plan_view="")))
    assert "<planView>" in only(result, "X203").message
    result = read(xodr(road(plan_view="<planView/>")))
    assert "no <geometry>" in only(result, "X203").message


def test_repeated_plan_view_reads_the_first():
    pv = plan(LINE_GEOMETRY) + plan('<geometry s="0" x="9" y="9" hdg="0" length="10"><line/></geometry>')
    result = read(xodr(road(plan_view=pv)))
    assert only(result, "X204").road == "1"
    assert result.document.roads[0].plan_view[0].x == 1.0


# ------------------------------------------------------------------------------------------------------------ profiles
def test_elevation_superelevation_and_lane_offset():
    body = (
        '<elevationProfile><elevation s="0" a="1" b="0.1" c="0" d="0"/>'
        '<elevation s="5" a="1.5" b="0" c="0.01" d="0"/></elevationProfile>'
        '<lateralProfile><superelevation s="0" a="0.02" b="0" c="0" d="0"/>'
        '<shape s="0" t="0" a="0" b="0" c="0" d="0"/></lateralProfile>'
    )
    lanes = LANES.replace("<lanes>", '<lanes><laneOffset s="0" a="-1" b="0" c="0" d="0.001"/>')
    r = first_road(xodr(road(body, lanes=lanes)))
    assert r.elevation == (m.Cubic(0.0, 1.0, 0.1, 0.0, 0.0, 3), m.Cubic(5.0, 1.5, 0.0, 0.01, 0.0, 3))
    assert r.superelevation == (m.Cubic(0.0, 0.02, 0.0, 0.0, 0.0, 3),)
    assert r.lane_offset == (m.Cubic(0.0, -1.0, 0.0, 0.0, 0.001, 3),)


def test_profile_record_missing_coefficient_is_skipped():
    body = '<elevationProfile><elevation s="0" a="1" b="0" c="0"/></elevationProfile>'
    result = read(xodr(road(body)))
    assert "'d'" in only(result, "X205").message and "record is skipped" in only(result, "X205").message
    assert result.document.roads[0].elevation == ()


def test_profile_records_out_of_order():
    body = (
        '<elevationProfile><elevation s="50" a="0" b="0" c="0" d="0"/>\n'
        '<elevation s="0" a="0" b="0" c="0" d="0"/></elevationProfile>'
    )
    result = read(xodr(road(body)))
    assert only(result, "X209").line == 4
    assert [c.s for c in result.document.roads[0].elevation] == [50.0, 0.0]


# ------------------------------------------------------------------------------------------------------------ rules
def test_every_reader_rule_is_documented_with_a_pass_and_a_fail():
    assert [r.code for r in R.READER_RULES] == sorted(r.code for r in R.READER_RULES)
    for rule in R.READER_RULES:
        assert rule.check is None
        assert rule.code[0] == "X" and rule.code[1:].isdigit() and len(rule.code) == 4
        assert rule.name == rule.name.lower() and " " not in rule.name
        assert "Passes" in rule.doc and "Fails" in rule.doc, rule.code


def test_every_finding_names_its_location():
    lane = '<lane id="-1" type="driving"><width sOffset="0" a="x" b="0" c="0" d="0"/></lane>'
    result = read(xodr(road(lanes=lanes_of(section(CENTER, f"<right>{lane}</right>")))))
    finding = only(result, "X206")
    assert (finding.road, finding.section_s, finding.lane, finding.line) == ("1", 0.0, -1, 3)
    assert finding.message.startswith("road 1, lane section s=0, lane -1: <width> at line 3 ")


# ------------------------------------------------------------------------------------------------------------ internals
def test_a_short_file_of_many_lines_is_parsed_again_with_its_text_nodes():
    """A file under the size from which lines are counted before the parse (1 MiB) can still have 65,535 lines (blank
    ones, here): the parse without text nodes shows it by its last element's line and is done again with them, so the
    lines past 65,535 are right."""
    from xodrcheck.reader import read_keeping_tree
    from xodrcheck.reader.xmlsafe import COUNT_LINES_FROM, parse

    lanes = "".join(f'\n\n\n\n\n\n\n\n<lane id="-{k}" type="driving" level="false"/>' for k in range(1, 9001))
    doc = xodr(road(lanes=f"<lanes>{section(CENTER, f'<right>{lanes}</right>')}</lanes>"))
    assert len(doc) < COUNT_LINES_FROM and doc.count(b"\n") > 65535
    root, _ = parse(doc, keep_blank_text=False)
    assert root.find(".//right")[0].tail is not None  # parsed again, keeping the text nodes
    without = etree.fromstring(doc, etree.XMLParser(remove_blank_text=True))
    assert without.find(".//right")[-1].sourceline == 65535  # what the first parse saw: the line saturated
    lines = [lane.line for lane in read(doc).document.roads[0].lane_sections[0].right]
    assert lines[-1] > 72000 and lines == sorted(lines)
    assert read(doc).document == read_keeping_tree(doc)[0].document
