"""Rule link-gap: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.findings import Severity

RULE = "link-gap"


def test_gap_of_five_centimetres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.severity) == ("1", Severity.ERROR)
    assert f.line == line_of(path, '<successor elementType="road" elementId="2"')
    assert "gap of 0.05 m" in f.message
    assert f.x == pytest.approx(100.0) and f.y == pytest.approx(0.0)


def test_lanes_renumbered_at_the_link_are_no_gap():
    """The reference lines meet; road 1's lane 1 ends there and the laneOffset moves by its width (CARLA's Town03 roads
    28/29): the lane-0 lines are 2 m apart but no lane is (K101 compared lane-0 lines and reported a 2 m gap)."""
    path = fixture(RULE, "pass_lane_offset.xodr")
    assert findings(path, RULE) == []
    assert findings(path, "lane-border-gap") == []


def test_a_gap_under_the_error_threshold_names_no_rule_of_the_standard():
    """5 mm: a warning (over position, 1 mm, under gap, 1 cm); ASAM's threshold is not reached, so no UID."""
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('x="100.05"', 'x="100.005"')
    assert 'x="100.005"' in text
    (f,) = [f for f in check(text.encode(), select=("K101",)).findings if f.code == "K101"]
    assert f.severity is Severity.WARNING and f.rule_uid is None
