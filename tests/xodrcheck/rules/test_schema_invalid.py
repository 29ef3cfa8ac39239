"""Rule schema-invalid: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "schema-invalid"


def test_unexpected_element_is_reported_at_its_line():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<bogus/>")
    assert "1.7.0" in f.message and "bogus" in f.message


def test_opendrive_18_assertion_is_checked_with_xsd11():
    path = fixture(RULE, "fail_18.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<object ")
    assert "1.8.1" in f.message and "assertion" in f.message
