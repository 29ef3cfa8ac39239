"""Rule lane-fold: a 3.5 m lane inside a 2 m radius folds over itself; inside a 20 m radius it does not."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-fold"


def test_lane_wider_than_the_radius_folds():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0)
    assert f.line == line_of(path, '<road id="1"')
    assert "folds over itself" in f.message
