"""Rule connection-overlap: a road outside a four-leg junction lying across its connection lanes is found; the
junction's own conflict areas are not."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.mesh.footprint import conflict_areas, junction_area
from xodrcheck.reader import read

RULE = "connection-overlap"


def test_conflict_areas_of_the_four_leg_junction_are_normal():
    path = fixture(RULE, "pass.xodr")
    assert findings(path, RULE) == []
    document = read(path).document
    conflicts, area = conflict_areas(document), junction_area(document)
    assert set(conflicts) == set(area) == {"100"}
    # the connection lanes cross (left turns cut the straight paths) but cover at most the 20 m x 20 m box
    assert 50 < conflicts["100"] < area["100"] <= 400


def test_foreign_road_across_connection_lanes():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert found
    assert {f.road for f in found} <= {str(r) for r in range(10, 22)}  # the connecting road is named
    assert all("and road 50 overlap" in f.message for f in found)
    assert {f.road for f in found} >= {"13"}  # the straight path from leg 1 runs through road 50's lane


def test_leg_reaching_into_a_connection_it_does_not_join():
    """Road 3 enters junction 100 from the south and ends 2.5 m inside it, across connecting road 10 (from road 1 to
    road 2): a connecting road and a leg it does not join have different junction ids and shall not overlap."""
    path = fixture(RULE, "fail_leg.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10" and "connecting road 10 and road 3 overlap by 17.5 m2" in f.message  # 7 m x 2.5 m
    assert "road 3 is one of its legs, not linked to it" in f.message


def test_connecting_roads_of_two_junctions_overlap():
    from xodrcheck.rules.shared import junction_uids as JU
    from xodrcheck.rules.shared import road_uids as U

    found = findings(fixture(RULE, "fail_two_junctions.xodr"), RULE)
    both = [f for f in found if f.rule_uid == JU.NO_OVERLAP]
    inside = [f for f in found if f.rule_uid == U.OVERLAP_INSIDE_JUNCTION]
    # each overlapping pair is a road of junction 100 on one of junction 200: one finding under each rule
    assert len(both) == len(inside) >= 1 and {f.road for f in both} == {f.road for f in inside}
    assert all(f.message.startswith("junction 100 and junction 200 overlap") for f in both)
    assert not [f for f in findings(fixture(RULE, "fail.xodr"), RULE) if f.rule_uid == JU.NO_OVERLAP]
