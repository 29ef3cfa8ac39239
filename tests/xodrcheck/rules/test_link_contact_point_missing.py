"""Rule link-contact-point-missing: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "link-contact-point-missing"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_road_link_without_contact_point():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, '<successor elementType="road" elementId="2"/>')
