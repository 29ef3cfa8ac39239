"""Rule curve-local-length-mismatch: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import road_uids as U

RULE = "curve-local-length-mismatch"


@pytest.mark.parametrize(
    ("name", "uid", "severity", "text"),
    [
        ("fail.xodr", U.CURVE_LOCAL_LENGTH_MATCH, Severity.WARNING, "5.578628 m long over p in [0, 1]"),
        ("fail_normalized_range.xodr", U.CURVE_LOCAL_NORMALIZED_RANGE, Severity.ERROR, "the coefficients are for"),
        ("fail_arclength.xodr", U.CURVE_LOCAL_ARC_LENGTH_RANGE, Severity.ERROR, "100 m long over p in [0, 10]"),
        ("fail_arclength_no_length.xodr", U.CURVE_LOCAL_ARC_LENGTH_RANGE, Severity.ERROR, "has no length"),
    ],
)
def test_paramPoly3_curve_of_the_wrong_length(name, uid, severity, text):
    path = fixture(RULE, name)
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.severity, f.road) == (uid, severity, "1")
    assert f.line == line_of(path, "<paramPoly3")
    assert text in f.message
