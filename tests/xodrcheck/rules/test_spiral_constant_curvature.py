"""Rule spiral-constant-curvature: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "spiral-constant-curvature"


def test_spiral_with_equal_curvatures():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING
    assert '<arc curvature="0.01"/>' in f.message
