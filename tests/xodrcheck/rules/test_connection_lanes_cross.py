"""Rule connection-lanes-cross: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "connection-lanes-cross"


def test_left_turn_from_the_right_lane_crosses_straight_on():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.severity is Severity.ERROR
    assert "road 10 lane -1" in f.message and "road 12 lane -1" in f.message
    assert f.y == pytest.approx(-1.75, abs=0.01)  # on the straight-on path of lane -1
