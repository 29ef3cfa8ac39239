"""Rule link-kink: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "link-kink"


def test_heading_kink_without_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.severity is Severity.ERROR
    assert "(0.1 rad)" in f.message
