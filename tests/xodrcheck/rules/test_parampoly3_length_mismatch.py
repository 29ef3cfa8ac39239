"""Rule parampoly3-length-mismatch: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "parampoly3-length-mismatch"


def test_normalized_curve_declared_too_long():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.severity is Severity.ERROR
    assert "declared 102 m long" in f.message and "is 100 m long" in f.message


def test_arc_length_range_checked_by_integration():
    path = fixture(RULE, "fail_arclength.xodr")
    (f,) = findings(path, RULE)
    assert "over p in [0, 100] (arcLength)" in f.message
    assert "is 100.6" in f.message  # the arc length of (p, 0.001 p^2) over [0, 100]
