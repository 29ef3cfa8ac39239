"""Rule connection-contact-point: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "connection-contact-point"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_contact_point_end_for_a_road_that_starts_at_the_incoming_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="0"')
    assert "contactPoint should be start" in f.message
