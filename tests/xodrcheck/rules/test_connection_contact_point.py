"""Rule connection-contact-point: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connection-contact-point"


def test_contact_point_end_for_a_road_that_starts_at_the_incoming_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="0"')
    assert "contactPoint should be start" in f.message
