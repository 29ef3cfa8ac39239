"""Rule permanent-section-length: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "permanent-section-length"


def test_length_on_a_permanent_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s, f.line) == ("1", 0.0, line_of(path, '<laneSection s="0" length="100"'))
