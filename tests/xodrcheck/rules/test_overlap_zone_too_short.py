"""Rule overlap-zone-too-short: the finding each fail fixture gives."""

import math

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "overlap-zone-too-short"


def test_zone_ending_before_the_lanes_part():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.lane) == (U.DIRECT_OVERLAP_COVERAGE, "2", -2)
    assert f.line == line_of(path, '<laneLink from="-2" to="-2"')
    # road 3 (radius 100 m) leaves road 2's lane -2 entirely where it has dropped 3.5 m: after sqrt(2 * 100 * 3.5) m
    parting = math.sqrt(2 * 100 * 3.5)
    assert 15.0 + 50.0 < f.x < parting + 50.0
    assert "beyond their zones" in f.message


def test_zones_reaching_past_the_parting_point_pass():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
    assert findings(fixture("direct-overlap-zones", "pass.xodr"), RULE) == []
