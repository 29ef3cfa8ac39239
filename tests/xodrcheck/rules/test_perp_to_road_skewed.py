"""Rule perp-to-road-skewed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "perp-to-road-skewed"


def test_object_larger_than_the_crest_radius():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.line == line_of(path, 'id="p1"')
    assert "2.83 m across" in f.message and "radius of 2.26 m at s=48.6" in f.message
