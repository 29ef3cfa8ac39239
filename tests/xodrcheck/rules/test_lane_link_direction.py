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


def test_a_link_to_the_wrong_side_is_reported_once():
    """A lane linked to the lane across lane 0 (a typo, as in ASAM's road_lane_level_true_one_side_lanesection
    example) is this rule's finding; its consequences are not reported again: the border jump (lane-border-
    discontinuous), the crossed links (lane-links-ambiguous), the unreturned link itself (lane-link-not-reciprocal)
    and, across a road link, the border gap (lane-border-gap). Before: 6 errors in the first file, 4 in the others."""
    path = fixture(RULE, "fail_wrong_side_in_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 50.0)
    for sibling in ("lane-border-discontinuous", "lane-links-ambiguous"):
        assert findings(path, sibling) == []
    # lane -1 at s=0 names lane -1 at s=50, which does not name it back: a second fact, reported
    (back,) = findings(path, "lane-link-not-reciprocal")
    assert (back.lane, back.section_s) == (-1, 50.0) and "lane -1's successor is lane -1" in back.message
    for name in ("fail.xodr", "fail_opposite.xodr"):
        assert len(findings(fixture(RULE, name), RULE)) == 2
        assert findings(fixture(RULE, name), "lane-border-gap") == []
