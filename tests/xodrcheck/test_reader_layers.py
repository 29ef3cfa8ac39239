"""OpenDRIVE 1.9 lane layers (11.2) in the reader and the lane geometry: ``<lanes layer>``, lane-section ``length``,
lane-link ``layer``, junction lane-link ``fromLayer``/``toLayer``; older versions do not have them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.xodrcheck.readerdocs import CENTER, LINE_GEOMETRY, clean, codes, only, road, section, xodr
from xodrcheck import model as m
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of, temporary_geometry_of
from xodrcheck.reader import read

FEATURES = Path(__file__).parent / "opendrive19" / "features.xodr"
V19 = (1, 9)


def _right(width: float, link: str = "") -> str:
    return (
        f'<right><lane id="-1" type="driving">{link}<width sOffset="0" a="{width}" b="0" c="0" d="0"/></lane></right>'
    )


PERMANENT = f'<lanes layer="permanent">{section(CENTER, _right(3.5))}</lanes>'
#: a temporary layer from s=2 to s=6 (length 4), shifted 0.5 m to the right, its lane 3 m wide
TEMPORARY = (
    '<lanes layer="temporary"><laneOffset s="2" a="-0.5" b="0" c="0" d="0"/>'
    + section(CENTER, _right(3.0), attrs='s="2" length="4"')
    + "</lanes>"
)


def _layered_road(*lanes: str) -> str:
    return road(lanes="".join(lanes))


def test_the_features_document_reads_clean_with_both_layers():
    document = clean(FEATURES.read_bytes())
    road_1 = document.road_by_id["1"]
    assert [(sec.s, sec.length) for sec in road_1.lane_sections] == [(0.0, None), (50.0, None), (150.0, None)]
    layer = road_1.temporary_lanes
    assert layer is not None and [(sec.s, sec.length) for sec in layer.lane_sections] == [(50.0, 100.0)]
    assert [c.a for c in layer.lane_offset] == [-0.25] and road_1.lane_offset == ()
    before, _, after = road_1.lane_sections
    assert before.lane(-1).successors == (-1,) and before.lane(-1).temporary_successors == (-1,)
    assert after.lane(-1).predecessors == (-1,) and after.lane(-1).temporary_predecessors == (-1,)
    temporary_lane = layer.lane_sections[0].lane(-1)
    assert (temporary_lane.predecessors, temporary_lane.successors) == ((-1,), (-1,))  # the default layer: permanent
    assert temporary_lane.temporary_predecessors == temporary_lane.temporary_successors == ()
    (link,) = document.junction_by_id["100"].connections[0].lane_links
    assert (link.from_layer, link.to_layer) == (m.LaneLayer.PERMANENT, m.LaneLayer.PERMANENT)
    assert all(r.temporary_lanes is None for r in document.roads if r.id != "1")


def test_temporary_layer_is_read_with_its_own_offset_and_section_length():
    r = clean(xodr(_layered_road(PERMANENT, TEMPORARY), version=V19)).roads[0]
    assert len(r.lane_sections) == 1 and r.lane_sections[0].lane(-1).widths[0].a == 3.5
    layer = r.temporary_lanes
    assert layer is not None and layer.line > 0
    (sec,) = layer.lane_sections
    assert (sec.s, sec.length, sec.lane(-1).widths[0].a) == (2.0, 4.0, 3.0)
    view = r.temporary_layer()
    assert view is not None and view.lane_sections == layer.lane_sections and view.lane_offset == layer.lane_offset
    assert view.section_end(0) == 6.0 and r.section_end(0) == 10.0


def test_lanes_without_layer_are_the_permanent_layer():
    r = clean(xodr(_layered_road(PERMANENT.replace(' layer="permanent"', ""), TEMPORARY), version=V19)).roads[0]
    assert r.lane_sections[0].lane(-1).widths[0].a == 3.5 and r.temporary_lanes is not None


def test_a_second_lanes_of_the_same_layer_is_reported_and_skipped():
    result = read(xodr(_layered_road(PERMANENT, PERMANENT.replace("3.5", "9")), version=V19))
    assert only(result, "X204").line == 3
    assert result.document.roads[0].lane_sections[0].lane(-1).widths[0].a == 3.5


def test_a_road_with_only_a_temporary_layer_has_no_permanent_lanes():
    result = read(xodr(_layered_road(TEMPORARY), version=V19))
    finding = only(result, "X203")
    assert "permanent" in finding.message
    r = result.document.roads[0]
    assert r.lane_sections == () and r.temporary_lanes is not None


def test_an_unknown_layer_is_read_as_permanent():
    result = read(xodr(_layered_road(PERMANENT.replace("permanent", "provisional")), version=V19))
    finding = only(result, "X206")
    assert "provisional" in finding.message and "permanent" in finding.message
    assert len(result.document.roads[0].lane_sections) == 1


def test_lane_link_layers():
    link = (
        '<link><predecessor id="-1"/><predecessor id="-2" layer="temporary"/>'
        '<successor id="-3" layer="permanent"/><successor id="-4" layer="Temporary"/></link>'
    )
    lanes = f"<lanes>{section(CENTER, _right(3.5, link))}</lanes>"
    lane = clean(xodr(_layered_road(lanes), version=V19)).roads[0].lane_sections[0].lane(-1)
    assert (lane.predecessors, lane.temporary_predecessors) == ((-1,), (-2,))
    assert (lane.successors, lane.temporary_successors) == ((-3,), (-4,))


def test_a_lane_link_with_an_unknown_layer_is_read_as_permanent():
    lanes = "<lanes>" + section(CENTER, _right(3.5, '<link><successor id="-1" layer="x"/></link>')) + "</lanes>"
    result = read(xodr(_layered_road(lanes), version=V19))
    assert codes(result) == ["X206"]
    assert result.document.roads[0].lane_sections[0].lane(-1).successors == (-1,)


def test_junction_lane_link_layers():
    junction = (
        '<junction id="9"><connection id="0" incomingRoad="1" connectingRoad="2" contactPoint="start">'
        '<laneLink from="-1" to="-1" fromLayer="temporary"/><laneLink from="-2" to="-2" toLayer="temporary"/>'
        '<laneLink from="-3" to="-3"/></connection></junction>'
    )
    (connection,) = clean(xodr(road(), junction, version=V19)).junctions[0].connections
    (a, b) = connection.temporary_lane_links  # the permanent-layer rules see only lane_links
    assert (a.from_lane, a.from_layer, a.to_layer) == (-1, m.LaneLayer.TEMPORARY, m.LaneLayer.PERMANENT)
    assert (b.from_lane, b.from_layer, b.to_layer) == (-2, m.LaneLayer.PERMANENT, m.LaneLayer.TEMPORARY)
    (c,) = connection.lane_links
    assert (c.from_lane, c.from_layer, c.to_layer) == (-3, m.LaneLayer.PERMANENT, m.LaneLayer.PERMANENT)


def test_an_invalid_section_length_is_read_as_absent():
    lanes = "<lanes>" + section(CENTER, _right(3.5), attrs='s="0" length="-1"') + "</lanes>"
    result = read(xodr(_layered_road(lanes), version=V19))
    assert only(result, "X206").line == 3
    assert result.document.roads[0].lane_sections[0].length is None


@pytest.mark.parametrize("version", [(1, 7), (1, 8)])
def test_before_1_9_layers_do_not_exist(version):
    link = '<link><successor id="-1" layer="temporary"/></link>'
    lanes = '<lanes layer="temporary">' + section(CENTER, _right(3.5, link), attrs='s="0" length="4"') + "</lanes>"
    result = read(xodr(_layered_road(lanes, PERMANENT), version=version))
    assert codes(result) == ["X204"]  # the second <lanes> repeats the first; layer and length are not read
    r = result.document.roads[0]
    (sec,) = r.lane_sections
    assert sec.length is None and r.temporary_lanes is None
    assert sec.lane(-1).successors == (-1,) and sec.lane(-1).temporary_successors == ()


def test_unknown_versions_are_read_as_1_9():
    result = read(xodr(_layered_road(PERMANENT, TEMPORARY), version=(1, 10)))
    assert codes(result) == ["X202"]
    assert result.document.roads[0].temporary_lanes is not None


# ---------------------------------------------------------------------------------------------------- geometry
def _geometry_doc() -> m.Document:
    return clean(xodr(_layered_road(PERMANENT, TEMPORARY), version=V19))


def test_temporary_geometry_uses_its_own_offset_widths_and_extent():
    document = _geometry_doc()
    permanent = geometry_of(document)["1"]
    temporary = temporary_geometry_of(document)["1"]
    assert list(temporary_geometry_of(document)) == ["1"]
    assert temporary.section_range(0) == (2.0, 6.0) and permanent.section_range(0) == (0.0, 10.0)
    s = np.array([2.0, 4.0, 6.0])
    inner, outer = temporary.inner_outer(0, -1, s)
    np.testing.assert_allclose(inner, -0.5)
    np.testing.assert_allclose(outer, -3.5)
    inner, outer = permanent.inner_outer(0, -1, s)
    np.testing.assert_allclose(outer, -3.5)
    np.testing.assert_allclose(inner, 0.0)
    # the same reference line: the centre of the temporary lane lies 2 m right of it (hdg 0.5 from (1, 2))
    p = temporary.lane_points(0, -1, s)
    np.testing.assert_allclose(p.x, 1 + s * np.cos(0.5) + 2.0 * np.sin(0.5))
    np.testing.assert_allclose(p.y, 2 + s * np.sin(0.5) - 2.0 * np.cos(0.5))


def test_no_temporary_section_before_its_first_or_after_its_length():
    temporary = temporary_geometry_of(_geometry_doc())["1"]
    assert temporary.section_index([0.0, 1.9, 2.0, 6.0, 6.1, 10.0]).tolist() == [-1, -1, 0, 0, -1, -1]
    permanent = geometry_of(_geometry_doc())["1"]
    assert permanent.section_index([0.0, 6.1, 10.0]).tolist() == [0, 0, 0]


def test_a_road_without_temporary_layer_has_no_temporary_geometry():
    document = clean(xodr(road(), version=V19))
    assert len(temporary_geometry_of(document)) == 0
    with pytest.raises(ValueError, match="no temporary lane layer"):
        RoadGeometry(document.roads[0], m.LaneLayer.TEMPORARY)


def test_the_line_geometry_helper_is_what_the_expectations_assume():
    assert 'hdg="0.5"' in LINE_GEOMETRY and 'x="1" y="2"' in LINE_GEOMETRY


# ---------------------------------------------------------------------------------------------------- rules
def _two_sections(temporary_link: str) -> bytes:
    first = section(CENTER, _right(3.5, f'<link><successor id="-1"/>{temporary_link}</link>'))
    second = section(CENTER, _right(3.5, '<link><predecessor id="-1"/></link>'), attrs='s="5"')
    temporary = (
        '<lanes layer="temporary">'
        + section(CENTER, _right(3.0, '<link><predecessor id="-1"/></link>'), attrs='s="5" length="4"')
        + "</lanes>"
    )
    return xodr(road(lanes=f"<lanes>{first}{second}</lanes>{temporary}"), version=V19)


def test_a_section_where_lanes_link_to_the_temporary_layer_is_not_redundant(tmp_path):
    """G901 (redundant-record) merges unchanged lane sections, but a permanent section must start where its lanes
    link to the temporary layer (11.4, road.lane_section.new_lanesec_link_temp_to_perm)."""
    from xodrcheck import check

    path = tmp_path / "map.xodr"
    path.write_bytes(_two_sections(""))
    assert [f.section_s for f in check(path, select=("G901",)).findings] == [5.0]
    path.write_bytes(_two_sections('<successor id="-1" layer="temporary"/>'))
    assert check(path, select=("G901",)).findings == ()
