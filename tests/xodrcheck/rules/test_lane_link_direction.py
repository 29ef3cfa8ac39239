"""Rule lane-link-direction: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-link-direction"


def test_right_lane_continuing_a_left_lane_end_to_start():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted((f.road, f.lane) for f in found) == [("1", -1), ("1", 1)]
    assert all("an end meets a start" in f.message for f in found)


def test_same_side_lanes_linked_where_two_ends_meet():
    path = fixture(RULE, "fail_opposite.xodr")
    found = findings(path, RULE)
    assert sorted((f.road, f.lane) for f in found) == [("1", -1), ("1", 1)]
    assert all("two ends meet" in f.message for f in found)


def test_sidewalk_continuing_on_the_other_side_of_lane_0():
    """A sidewalk, shoulder or median has no direction of travel: CARLA's Town03 (roads 69-70-71) and Town06 (roads
    1-65) link their left sidewalks, shoulders and medians to the next road's right ones (12 findings before)."""
    assert findings(fixture(RULE, "pass_sidewalk.xodr"), RULE) == []


def test_carla_towns_have_no_lane_link_direction_error(corpus_dir):
    for town in ("Town03", "Town06"):
        assert findings(corpus_dir / "carla-towns" / "OpenDrive" / f"{town}.xodr", RULE) == []


def test_direction_attribute_turns_or_opens_a_lane():
    """1.8 @direction (11.3.1): a reversed right lane continues a left lane; a lane open both ways has no direction."""
    assert findings(fixture(RULE, "pass_direction_reversed.xodr"), RULE) == []
    assert findings(fixture(RULE, "pass_direction_both.xodr"), RULE) == []
    (f,) = findings(fixture(RULE, "fail_direction_reversed.xodr"), RULE)
    assert (f.road, f.lane) == ("1", -1)
