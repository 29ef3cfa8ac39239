"""Rule border-crosses-inner: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "border-crosses-inner"


def test_border_crosses_the_lane_0_line():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 1)
    assert f.s == pytest.approx(100.0)
    assert "6.5 m on the inner side" in f.message
