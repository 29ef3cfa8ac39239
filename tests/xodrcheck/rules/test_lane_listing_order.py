"""Rule lane-listing-order: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-listing-order"


def test_right_lanes_listed_outside_in():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0)
    assert f.severity is Severity.WARNING
    assert f.line == line_of(path, '<lane id="-1"')
    assert "after lane -2" in f.message and "(2 1 0 -1 -2)" in f.message


def test_a_lane_on_the_wrong_side_is_left_to_lane_id_sequence():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8").replace('<lane id="-2"', '<lane id="3"')
    from xodrcheck.check import check

    report = check(text.encode(), select=("L017",))
    assert report.findings == ()
