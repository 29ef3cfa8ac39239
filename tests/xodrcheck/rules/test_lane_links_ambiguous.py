"""Rule lane-links-ambiguous: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.check import check

RULE = "lane-links-ambiguous"


def test_split_into_lanes_that_are_not_side_by_side():
    (f,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0)
    assert "-3, -1" in f.message and "not side by side" in f.message


def test_a_split_that_shares_a_lane_with_a_merge():
    """Lane -1 splits into -1 and -2 while lane -2 also leads into -2: which lane continues which is unclear."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    first, second = text.split('<laneSection s="50">')
    first = first.replace(
        '<right><lane id="-1" type="driving" level="false">',
        '<right><lane id="-2" type="driving" level="false"><link><successor id="-2"/></link>'
        '<width sOffset="0" a="1" b="0" c="0" d="0"/></lane><lane id="-1" type="driving" level="false">',
    )
    report = check((first + '<laneSection s="50">' + second).encode(), select=("L025",))
    (f,) = report.findings
    assert f.lane == -1 and "a split and a merge share a lane" in f.message
