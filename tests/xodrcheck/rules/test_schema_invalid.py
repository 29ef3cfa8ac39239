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


def test_11_and_12_files_in_no_namespace_are_validated_as_if_in_the_schemas():
    """The 1.1 and 1.2 schemas declare their elements in www.vires.com; files of those versions, as tools write them,
    use no namespace. Validated as written every one failed at its root ("No matching global declaration")."""
    for name in ("pass_11_no_namespace.xodr", "pass_12_no_namespace.xodr"):
        assert findings(fixture(RULE, name), RULE) == []
    path = fixture(RULE, "fail_11_no_namespace.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<header ")
    assert "Element 'header', attribute 'north'" in f.message and "www.vires.com" not in f.message
