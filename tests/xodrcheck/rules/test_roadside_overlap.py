"""Rule roadside-overlap: sidewalk-only roads crossing are a warning; side by side they are not."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "roadside-overlap"


def test_two_sidewalks_crossing():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING
    assert (f.road, f.lane) == ("1", -1)
    assert "overlap by 4.0 m2" in f.message  # two 2 m sidewalks crossing square
    assert 0 <= f.x <= 2 and -2 <= f.y <= 0
