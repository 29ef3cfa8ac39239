"""Rule link-contact-point-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "link-contact-point-missing"


def test_road_link_without_contact_point():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, '<successor elementType="road" elementId="2"/>')
