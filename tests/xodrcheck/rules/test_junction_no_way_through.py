"""Rule junction-no-way-through: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "junction-no-way-through"


def test_an_approach_whose_connecting_lane_stops_has_no_way_through():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    # at the incoming lane's end, where it enters junction 100
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -1, 0.0, 50.0)
    assert f.severity is Severity.WARNING
    assert "junction 100" in f.message and "road 10 lane -1" in f.message


def test_every_approach_of_the_clean_junction_has_a_way_through():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
