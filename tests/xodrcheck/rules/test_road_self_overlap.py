"""Rule road-self-overlap: a road curling back over its own start is found; one that comes round beside it is not."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-self-overlap"


def test_road_running_over_its_own_start():
    """A 140 m arc of radius 20 m (circumference 125.7 m): its last 14 m lie on its first, 7 m wide."""
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0) and f.line == line_of(path, '<road id="1"')
    assert "overlaps itself by 100.3 m2" in f.message and "(lane section s=70)" in f.message
    assert 0 <= f.s <= 14.5 and f.y < 3.5


def test_a_lane_folding_over_itself_is_lane_folds_not_this():
    assert findings(fixture("lane-fold", "fail.xodr"), RULE) == []
