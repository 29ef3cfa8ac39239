"""Rule spiral-constant-curvature: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture
from xodrcheck.findings import Severity

RULE = "spiral-constant-curvature"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_spiral_with_equal_curvatures():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING
    assert '<arc curvature="0.01"/>' in f.message
