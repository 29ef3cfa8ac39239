"""Rule parampoly3-not-aligned: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "parampoly3-not-aligned"


def test_curve_starting_off_the_start_point():
    path = fixture(RULE, "fail_offset.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s, f.x, f.y) == ("1", 0.0, 0.0, 0.0)
    assert f.severity is Severity.WARNING and f.line == line_of(path, "<paramPoly3")
    assert "aV=0.5" in f.message and "0.5 m off x, y" in f.message and "bV=" not in f.message


def test_curve_leaving_off_the_heading():
    path = fixture(RULE, "fail_turned.xodr")
    (f,) = findings(path, RULE)
    assert "bV=10 turns its start 5.74 deg off hdg" in f.message and "aV=" not in f.message
