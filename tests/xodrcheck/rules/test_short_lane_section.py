"""Rule short-lane-section: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "short-lane-section"


def test_five_millimetre_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s) == ("1", 0.0)
    assert "0.005 m long" in f.message
