"""Rule object-shape-ambiguous: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "object-shape-ambiguous"


def test_radius_and_length():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<object id="1"') and "gives radius and length" in f.message


def test_length_without_width():
    path = fixture(RULE, "fail_half_box.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<object id="2"') and "gives length without width" in f.message
