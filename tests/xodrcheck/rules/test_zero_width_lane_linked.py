"""Rule zero-width-lane-linked: the finding each fail fixture gives."""

from lxml import etree

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.check import check
from xodrcheck.findings import Severity

RULE = "zero-width-lane-linked"


def test_linking_the_opening_lane_is_an_error_in_17():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1)
    assert f.severity is Severity.ERROR
    assert "lane -2" in f.message and "opens" in f.message


def test_before_17_it_is_an_error_too():
    """Annex F's new_lane_appear (linking the appearing lane) dates from 1.4.0: older files are held to it too."""
    path = fixture(RULE, "fail_14.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.ERROR
    assert f.rule_uid == "asam.net:xodr:1.4.0:road.lane.link.new_lane_appear"


def test_border_lanes_filed_on_the_wrong_side_are_no_crash(tmp_path):
    """Regression (found by fuzzing): a lane described by <border> records and filed in the wrong side's group has
    no place in the road; the rule skips it instead of failing with a KeyError."""
    root = etree.parse(str(fixture(RULE, "fail.xodr"))).getroot()
    for record in root.iter("width"):
        record.tag = "border"
    for section in root.iter("laneSection"):
        right = section.find("right")
        for lane in list(section.find("left")):
            right.append(lane)
    path = tmp_path / "wrong_side.xodr"
    path.write_bytes(etree.tostring(root))
    assert check(path).findings
    assert [f for f in check(path).findings if f.code == "X900"] == []


def test_a_link_to_an_opening_lane_is_not_also_a_border_jump():
    """Lane -1 continues as lane -2 but names the lane opening inside it (lane -1 at s=50): one finding here, not
    also lane-border-discontinuous's 3.5 m jump of lane -1 into lane -1 (before: both)."""
    path = fixture(RULE, "fail_opens_inside.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1) and "which has zero width there (it opens)" in f.message
    assert findings(path, "lane-border-discontinuous") == []
    (unlinked,) = findings(path, "lane-not-continued")
    assert "has no predecessor in the previous lane section" in unlinked.message
