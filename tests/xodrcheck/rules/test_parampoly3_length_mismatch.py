"""Rule parampoly3-length-mismatch: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import road_uids as U

RULE = "parampoly3-length-mismatch"


def test_normalized_curve_declared_too_long_is_a_length_match_warning():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.severity is Severity.WARNING
    assert f.rule_uid == U.PARAMPOLY3_LENGTH_MATCH
    assert "declared 102 m long" in f.message and "is 100 m long" in f.message


def test_arc_length_range_checked_by_integration():
    path = fixture(RULE, "fail_arclength.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.ERROR and f.rule_uid == U.PARAMPOLY3_ARC_LENGTH_RANGE
    assert "over p in [0, 100] (arcLength)" in f.message
    assert "is 100.6" in f.message  # the arc length of (p, 0.001 p^2) over [0, 100]


def test_normalized_curve_written_for_arc_length():
    """u = p over [0, 1] is 1 m long; over [0, @length] it is the declared 100 m: p was not chosen in [0, 1]."""
    path = fixture(RULE, "fail_normalized_range.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.ERROR and f.rule_uid == U.PARAMPOLY3_NORMALIZED_RANGE
    assert "is 1 m long" in f.message and 'for pRange="arcLength"' in f.message
