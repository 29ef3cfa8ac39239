"""Rule lane-border-discontinuous: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-border-discontinuous"


def test_width_jumps_at_a_section_boundary():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -1, 50.0, 50.0)
    assert "jump by 1 m" in f.message
    assert f.x == pytest.approx(50.0) and f.y == pytest.approx(-2.5)


def test_full_width_lane_linked_in_place_of_the_continuing_one():
    path = fixture(RULE, "fail_appearing.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -2)
    assert "jump by 3.5 m" in f.message
