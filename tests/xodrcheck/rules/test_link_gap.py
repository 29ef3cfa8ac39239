"""Rule link-gap: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "link-gap"


def test_gap_of_five_centimetres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.severity) == ("1", Severity.ERROR)
    assert f.line == line_of(path, '<successor elementType="road" elementId="2"')
    assert "gap of 0.05 m" in f.message
    assert f.x == pytest.approx(100.0) and f.y == pytest.approx(0.0)
